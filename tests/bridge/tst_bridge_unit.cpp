// SPDX-License-Identifier: GPL-3.0-or-later
// The systemd unit roomba-bridge@.service as shipped, run as systemd would
// run it on a robot's Pi, set up as docs/classroom.md says: the config made by
// roomba-classroom init (root's, mode 0600) and ca.crt copied into
// /etc/roomba-bridge/. systemd is not this machine's init, so the test does
// what systemd does: as root, copies each LoadCredential= file into a fresh
// directory that only the service's user reads, then runs ExecStart= (%i,
// %d and $CREDENTIALS_DIRECTORY filled in) as a user of no account and no
// groups, as DynamicUser= makes one. The bridge must come online on a real
// mosquitto over TLS. Root only: it skips otherwise.
//
// ROOMBA_BRIDGE_UNIT names another unit file to run instead (an older one,
// say).

#include "bridge_rig.h"

#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <pwd.h>
#include <unistd.h>

using namespace mqtt;

namespace {

// A uid in systemd's range for dynamic users (61184 to 65519) that no
// account has.
uid_t dynamicUid()
{
    for (uid_t uid = 61184 + 4242; uid < 65519; ++uid)
        if (!::getpwuid(uid))
            return uid;
    return 0;
}

struct Unit {
    QList<QPair<QString, QString>> credentials; // id, path
    QStringList execStart;
    QString error;
};

// The settings the test needs, with the instance filled in; whatever the
// test cannot do as systemd would is an error.
Unit readUnit(const QByteArray &text, const QString &instance)
{
    Unit unit;
    QString section;
    for (QString line : QString::fromUtf8(text).split(QLatin1Char('\n'))) {
        line = line.trimmed();
        if (line.isEmpty() || line.startsWith(QLatin1Char('#')) || line.startsWith(QLatin1Char(';')))
            continue;
        if (line.startsWith(QLatin1Char('['))) {
            section = line;
            continue;
        }
        if (section != QLatin1String("[Service]"))
            continue;
        const qsizetype eq = line.indexOf(QLatin1Char('='));
        const QString key = line.left(eq).trimmed();
        QString value = line.mid(eq + 1).trimmed();
        value.replace(QLatin1String("%i"), instance);
        if (key == QLatin1String("LoadCredential")) {
            const qsizetype colon = value.indexOf(QLatin1Char(':'));
            if (colon < 0) {
                unit.error = QStringLiteral("LoadCredential=%1 names no file").arg(value);
                return unit;
            }
            unit.credentials.append({value.left(colon), value.mid(colon + 1)});
        } else if (key == QLatin1String("ExecStart")) {
            if (value.contains(QLatin1Char('"')) || value.contains(QLatin1Char('\''))) {
                unit.error = QStringLiteral("ExecStart= with quotes: not read here");
                return unit;
            }
            unit.execStart = value.split(QLatin1Char(' '), Qt::SkipEmptyParts);
        } else if (key == QLatin1String("User") || key == QLatin1String("Group")) {
            unit.error = QStringLiteral("%1= is set: the test runs it as DynamicUser= would").arg(key);
            return unit;
        }
    }
    if (unit.execStart.isEmpty())
        unit.error = QStringLiteral("no ExecStart=");
    return unit;
}

bool writeFile(const QString &path, const QByteArray &contents, QFile::Permissions permissions)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(contents) == contents.size()
           && f.setPermissions(permissions);
}

QByteArray readFile(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

struct Run {
    int status = -1;
    QString out;
};

Run run(const QString &program, const QStringList &args)
{
    QProcess p;
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(program, args);
    if (!p.waitForFinished(60000))
        return {-1, QStringLiteral("%1 did not finish: %2").arg(program, p.errorString())};
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(p.readAll())};
}

constexpr QFile::Permissions kRootOnly = QFile::ReadOwner | QFile::WriteOwner;
constexpr QFile::Permissions kEveryoneEnters = QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner
                                               | QFile::ReadGroup | QFile::ExeGroup | QFile::ReadOther
                                               | QFile::ExeOther;

} // namespace

class TestBridgeUnit : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    uid_t m_uid = 0;

    QString path(const QString &name) const { return m_dir.filePath(name); }
    QString unitPath() const
    {
        const QString given = qEnvironmentVariable("ROOMBA_BRIDGE_UNIT");
        return given.isEmpty() ? QStringLiteral(ROOMBA_MQTT_DIR "/roomba-bridge@.service") : given;
    }
    // /etc/roomba-bridge/... on the Pi is this test's etc/roomba-bridge/.
    QString onThePi(QString file) const
    {
        return file.replace(QRegularExpression(QStringLiteral("^/etc/roomba-bridge/")),
                            path(QStringLiteral("etc/roomba-bridge/")));
    }

    // A bridge run as the unit says, with a virtual robot: systemd's part,
    // then ExecStart= as the dynamic user. `dropIn` is added to the unit as
    // `systemctl edit` would.
    void startAsSystemdWould(QProcess &bridge, const QString &instance, const QByteArray &dropIn = {})
    {
        const Unit unit = readUnit(readFile(unitPath()) + "\n[Service]\n" + dropIn, instance);
        QVERIFY2(unit.error.isEmpty(), qPrintable(unit.error));
        // A fresh credentials directory, the service user's alone: each
        // credential copied by root, as systemd does, into a file only that
        // user reads.
        const QString credentials = path(QStringLiteral("credentials/roomba-bridge@%1.service").arg(instance));
        QVERIFY(QDir().mkpath(credentials));
        for (const auto &[id, source] : unit.credentials) {
            QVERIFY2(QFileInfo(source).isAbsolute(), qPrintable(source));
            QFile from(onThePi(source));
            QVERIFY2(from.open(QIODevice::ReadOnly), qPrintable(QStringLiteral("LoadCredential=%1:%2: %3 (systemd: status 243)")
                                                                     .arg(id, source, from.errorString())));
            const QString to = QDir(credentials).filePath(id);
            QVERIFY(writeFile(to, from.readAll(), QFile::ReadOwner));
            QCOMPARE(::chown(QFile::encodeName(to).constData(), m_uid, m_uid), 0);
        }
        QCOMPARE(::chown(QFile::encodeName(credentials).constData(), m_uid, m_uid), 0);
        QVERIFY(QFile::setPermissions(credentials, QFile::ReadOwner | QFile::ExeOwner));

        QStringList command;
        for (QString word : unit.execStart) {
            word.replace(QLatin1String("${CREDENTIALS_DIRECTORY}"), credentials)
                .replace(QLatin1String("$CREDENTIALS_DIRECTORY"), credentials)
                .replace(QLatin1String("%d"), credentials);
            QVERIFY2(!word.contains(QLatin1Char('%')) && !word.contains(QLatin1Char('$')), qPrintable(word));
            command << onThePi(word);
        }
        QCOMPARE(command.first(), QStringLiteral("/usr/bin/roomba-bridge"));
        command.first() = QStringLiteral(ROOMBA_BRIDGE_PATH);
        command << QStringLiteral("--sim"); // for the robot's serial port

        QProcessEnvironment env;
        env.insert(QStringLiteral("PATH"), QStringLiteral("/usr/local/bin:/usr/bin:/bin"));
        env.insert(QStringLiteral("LANG"), QStringLiteral("C.UTF-8"));
        env.insert(QStringLiteral("CREDENTIALS_DIRECTORY"), credentials);
        // A sanitizer build's bridge reads its options (suppressions among
        // them) as every other process of the run does.
        const QProcessEnvironment outside = QProcessEnvironment::systemEnvironment();
        for (const QString &key : outside.keys())
            if (key.endsWith(QLatin1String("SAN_OPTIONS")) || key == QLatin1String("QT_NO_GLIB"))
                env.insert(key, outside.value(key));
        bridge.setProcessEnvironment(env);
        bridge.setProcessChannelMode(QProcess::MergedChannels);
        bridge.start(QStringLiteral("setpriv"),
                     QStringList{QStringLiteral("--reuid=%1").arg(m_uid), QStringLiteral("--regid=%1").arg(m_uid),
                                 QStringLiteral("--clear-groups"), QStringLiteral("--no-new-privs"), QStringLiteral("--")}
                         + command);
        QVERIFY(bridge.waitForStarted());
    }

private slots:
    void initTestCase()
    {
        if (::geteuid() != 0)
            QSKIP("needs root: it copies root's 0600 files as systemd does and runs the bridge as another user");
        if (QStandardPaths::findExecutable(QStringLiteral("setpriv")).isEmpty())
            QSKIP("needs setpriv (util-linux) to run the bridge as another user");
        m_uid = dynamicUid();
        QVERIFY(m_uid != 0);
        // Every user may pass through to the credentials directory, as
        // through /run.
        QVERIFY(QFile::setPermissions(m_dir.path(), kEveryoneEnters));
    }

    // systemd-analyze verify has nothing to say of the unit (with the
    // program it starts where this build has it).
    void systemdFindsNothingWrong()
    {
        const QString analyze = QStandardPaths::findExecutable(QStringLiteral("systemd-analyze"));
        if (analyze.isEmpty())
            QSKIP("no systemd-analyze here");
        const QString dir = path(QStringLiteral("verify"));
        QVERIFY(QDir().mkpath(dir));
        const QString unit = QDir(dir).filePath(QStringLiteral("roomba-bridge@r1.service"));
        QVERIFY(writeFile(unit,
                          readFile(unitPath()).replace("/usr/bin/roomba-bridge", QByteArray(ROOMBA_BRIDGE_PATH)),
                          kRootOnly));
        const Run verify = run(analyze, {QStringLiteral("verify"), QStringLiteral("--man=no"), unit});
        QVERIFY2(verify.status == 0 && !verify.out.contains(QLatin1String("roomba-bridge@")), qPrintable(verify.out));
    }

    // docs/classroom.md, "For a real classroom network", step 3, with a virtual robot
    // (--sim) for the serial port; then with a client certificate the
    // config names, added as the unit's comment says.
    void theReadmeSetUpComesOnline_data()
    {
        QTest::addColumn<bool>("clientCertificate");
        QTest::newRow("as init wrote it") << false;
        QTest::newRow("with certfile and keyfile") << true;
    }
    void theReadmeSetUpComesOnline()
    {
        QFETCH(bool, clientCertificate);
        MosquittoBroker broker;
        const QString classroom = path(QStringLiteral("classroom-%1").arg(QTest::currentDataTag()).replace(QLatin1Char(' '), QLatin1Char('-')));
        const Run init = run(QStringLiteral(ROOMBA_CLASSROOM_PATH),
                             {QStringLiteral("init"), classroom, QStringLiteral("--robots"), QStringLiteral("r1"),
                              QStringLiteral("--students"), QStringLiteral("alice"), QStringLiteral("--port"),
                              QString::number(broker.port())});
        QVERIFY2(init.status == 0, qPrintable(init.out));
        QVERIFY2(broker.startWith(QDir(classroom).filePath(QStringLiteral("mosquitto.conf"))), qPrintable(broker.error()));

        // The Pi's /etc/roomba-bridge/, as root copies the two files there.
        const QString etc = path(QStringLiteral("etc/roomba-bridge"));
        QDir(etc).removeRecursively();
        QVERIFY(QDir().mkpath(etc));
        QVERIFY(QFile::setPermissions(path(QStringLiteral("etc")), kEveryoneEnters));
        QVERIFY(QFile::setPermissions(etc, kEveryoneEnters));
        QByteArray config = readFile(QDir(classroom).filePath(QStringLiteral("bridges/r1.conf")));
        QVERIFY(config.contains("cafile = ca.crt"));
        QVERIFY(writeFile(QDir(etc).filePath(QStringLiteral("ca.crt")),
                          readFile(QDir(classroom).filePath(QStringLiteral("bridges/ca.crt"))), kRootOnly));
        QByteArray dropIn;
        if (clientCertificate) {
            const QString key = QDir(etc).filePath(QStringLiteral("r1.key"));
            const QString request = path(QStringLiteral("r1.csr"));
            const Run req = run(QStringLiteral("openssl"),
                                {QStringLiteral("req"), QStringLiteral("-new"), QStringLiteral("-newkey"),
                                 QStringLiteral("ec"), QStringLiteral("-pkeyopt"),
                                 QStringLiteral("ec_paramgen_curve:prime256v1"), QStringLiteral("-nodes"),
                                 QStringLiteral("-keyout"), key, QStringLiteral("-subj"),
                                 QStringLiteral("/CN=bridge-r1"), QStringLiteral("-out"), request});
            QVERIFY2(req.status == 0, qPrintable(req.out));
            const Run sign = run(QStringLiteral("openssl"),
                                 {QStringLiteral("x509"), QStringLiteral("-req"), QStringLiteral("-in"), request,
                                  QStringLiteral("-CA"), QDir(classroom).filePath(QStringLiteral("ca.crt")),
                                  QStringLiteral("-CAkey"), QDir(classroom).filePath(QStringLiteral("ca.key")),
                                  QStringLiteral("-CAcreateserial"), QStringLiteral("-days"), QStringLiteral("2"),
                                  QStringLiteral("-out"), QDir(etc).filePath(QStringLiteral("r1.crt"))});
            QVERIFY2(sign.status == 0, qPrintable(sign.out));
            QVERIFY(QFile::setPermissions(key, kRootOnly));
            QVERIFY(QFile::setPermissions(QDir(etc).filePath(QStringLiteral("r1.crt")), kRootOnly));
            config += "certfile = r1.crt\nkeyfile = r1.key\n";
            dropIn = "LoadCredential=r1.crt:/etc/roomba-bridge/r1.crt\n"
                     "LoadCredential=r1.key:/etc/roomba-bridge/r1.key\n";
        }
        QVERIFY(writeFile(QDir(etc).filePath(QStringLiteral("r1.conf")), config, kRootOnly));

        // The user the bridge runs as cannot read root's files itself: the
        // config read straight from /etc/roomba-bridge fails.
        {
            QProcess direct;
            direct.setProcessChannelMode(QProcess::MergedChannels);
            direct.start(QStringLiteral("setpriv"),
                         {QStringLiteral("--reuid=%1").arg(m_uid), QStringLiteral("--regid=%1").arg(m_uid),
                          QStringLiteral("--clear-groups"), QStringLiteral("--"), QStringLiteral(ROOMBA_BRIDGE_PATH),
                          QStringLiteral("--config"), QDir(etc).filePath(QStringLiteral("r1.conf")),
                          QStringLiteral("--name"), QStringLiteral("r1"), QStringLiteral("--sim")});
            QVERIFY(direct.waitForFinished(10000));
            const QString said = QString::fromUtf8(direct.readAll());
            QCOMPARE(direct.exitCode(), 2);
            QVERIFY2(said.contains(QLatin1String("Permission denied")), qPrintable(said));
        }

        QProcess bridge;
        QByteArray log;
        connect(&bridge, &QProcess::readyRead, this, [&] { log += bridge.readAll(); });
        startAsSystemdWould(bridge, QStringLiteral("r1"), dropIn);
        if (QTest::currentTestFailed())
            return;
        // The teacher sees it online over TLS.
        BrokerAddress teacher;
        teacher.host = QStringLiteral("127.0.0.1");
        teacher.port = broker.port();
        teacher.tls = true;
        teacher.caFile = QDir(classroom).filePath(QStringLiteral("ca.crt"));
        teacher.username = QStringLiteral("teacher");
        // accounts.txt: a line an account, "ROLE NAME PASSWORD".
        for (const QString &line : QString::fromUtf8(readFile(QDir(classroom).filePath(QStringLiteral("accounts.txt"))))
                                       .split(QLatin1Char('\n'))) {
            const QStringList f = line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
            if (f.size() == 3 && f[1] == teacher.username)
                teacher.password = f[2];
        }
        QVERIFY(!teacher.password.isEmpty());
        ConsoleClient watcher(QStringLiteral("teacher"), teacher);
        QTRY_VERIFY2_WITH_TIMEOUT(
            (watcher.on(topics::state(QStringLiteral("r1"))).size() > 0
             && watcher.lastState(QStringLiteral("r1")).value(QLatin1String("online")).toBool())
                || bridge.state() == QProcess::NotRunning,
            log.constData(), 20000);
        QVERIFY2(bridge.state() == QProcess::Running, log.constData());
        // Its stop line logs in with the config's second account.
        QTRY_VERIFY2_WITH_TIMEOUT(log.contains("stop line: listening for stop all and takeovers as bridge-r1-stops"),
                                  log.constData(), 10000);
        bridge.terminate();
        QVERIFY(bridge.waitForFinished(10000));
        log += bridge.readAll();
        QVERIFY2(bridge.exitCode() == 128 + 15, log.right(4000).constData());
    }
};

QTEST_GUILESS_MAIN(TestBridgeUnit)
#include "tst_bridge_unit.moc"
