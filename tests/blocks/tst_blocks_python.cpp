// SPDX-License-Identifier: GPL-3.0-or-later
// The blocks page's Python generator on ten block programs (programs/*.json,
// as the page saves them): the Python it makes (generate.mjs, in node with
// Blockly's headless workspace) equals programs/*.py, which compile and
// speak the roomba library (check_program.py binds every call to Robot's
// own signature); the page's Robot refuses bad values in the library's words.

#include "process_run.h" // tests/common

#include <QDir>
#include <QFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

namespace {
const QStringList kPrograms = {"square",      "drive_until_bump",   "cliff_safe_wander", "song",
                               "follow_wall", "digits_countdown",   "leds_by_battery",   "turn_to_angle",
                               "arc_figure_eight", "repeat_until_bump"};

QString programFile(const QString &name, const char *suffix)
{
    return QDir(QStringLiteral(BLOCKS_PROGRAMS)).filePath(name + QLatin1String(suffix));
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}
} // namespace

class TestBlocksPython : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_out;

private slots:
    void initTestCase()
    {
        QVERIFY(m_out.isValid());
        if (QStandardPaths::findExecutable(QStringLiteral("node")).isEmpty())
            QSKIP("node is not installed (.ci/install-deps)");
        if (!QFile::exists(QStringLiteral(BLOCKS_PAGE_DIR "/node_modules/blockly/package.json")))
            QSKIP("Blockly is not in " BLOCKS_PAGE_DIR ": npm could not fetch it at build time (see the build's "
                  "warning); build the blocks-page target with the npm registry reachable");
        QStringList arguments = {QStringLiteral(BLOCKS_SOURCE "/generate.mjs"), QStringLiteral(BLOCKS_PAGE_DIR),
                                 m_out.path()};
        for (const QString &name : kPrograms)
            arguments << programFile(name, ".json");
        const ProcessRun node = runProcess(QStringLiteral("node"), arguments, {}, 60000);
        QVERIFY2(node.exitCode == 0, node.err.constData());
    }

    void generatedPythonIsTheGolden_data()
    {
        QTest::addColumn<QString>("name");
        for (const QString &name : kPrograms)
            QTest::newRow(qPrintable(name)) << name;
    }
    // The page shows, and downloads, exactly programs/NAME.py for programs/NAME.json.
    void generatedPythonIsTheGolden()
    {
        QFETCH(QString, name);
        const QByteArray golden = readAll(programFile(name, ".py"));
        QVERIFY2(!golden.isEmpty(), qPrintable(programFile(name, ".py")));
        QCOMPARE(QString::fromUtf8(readAll(QDir(m_out.path()).filePath(name + ".py"))), QString::fromUtf8(golden));
    }

    // Each golden compiles, and every call and reading in it is the library's.
    void goldenPythonSpeaksTheLibrary()
    {
        QStringList files;
        for (const QString &name : kPrograms)
            files << programFile(name, ".py");
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("PYTHONPATH"), QStringLiteral(PYTHON_LIBRARY));
        environment.insert(QStringLiteral("PYTHONDONTWRITEBYTECODE"), QStringLiteral("1"));
        const ProcessRun compiled = runProcess(QStringLiteral(DEBIAN_PYTHON), QStringList{"-m", "py_compile"} + files,
                                               {}, 30000, {}, environment);
        QVERIFY2(compiled.exitCode == 0, compiled.err.constData());
        const ProcessRun checked = runProcess(QStringLiteral(DEBIAN_PYTHON),
                                              QStringList{QStringLiteral(BLOCKS_SOURCE "/check_program.py")} + files,
                                              {}, 30000, {}, environment);
        QVERIFY2(checked.exitCode == 0, (checked.out + checked.err).constData());
    }

    // The page's Robot refuses what the library refuses, in the same words,
    // and plans a move's time as the library (and the bridge) does.
    void pageRobotSaysWhatTheLibrarySays()
    {
        const ProcessRun page = runProcess(QStringLiteral("node"),
                                           {QStringLiteral(BLOCKS_SOURCE "/value_errors.mjs"), QStringLiteral(BLOCKS_PAGE_DIR),
                                            QStringLiteral(PROTOCOL_JSON)},
                                           {}, 30000);
        QVERIFY2(page.exitCode == 0, page.err.constData());
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("PYTHONPATH"), QStringLiteral(PYTHON_LIBRARY));
        environment.insert(QStringLiteral("PYTHONDONTWRITEBYTECODE"), QStringLiteral("1"));
        const ProcessRun library = runProcess(QStringLiteral(DEBIAN_PYTHON),
                                              {QStringLiteral(BLOCKS_SOURCE "/value_errors.py"), QStringLiteral(PROTOCOL_JSON)},
                                              {}, 30000, {}, environment);
        QVERIFY2(library.exitCode == 0, library.err.constData());
        QVERIFY(library.out.count('\n') >= 17);
        QCOMPARE(QString::fromUtf8(page.out), QString::fromUtf8(library.out));
    }
};

QTEST_GUILESS_MAIN(TestBlocksPython)
#include "tst_blocks_python.moc"
