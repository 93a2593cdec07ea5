// SPDX-License-Identifier: GPL-3.0-or-later
// The blocks page end to end: a classroom that roomba-classroom init wrote,
// its mosquitto over TLS, roomba-bridge --sim as r1 and roomba-classroom
// serve with the page the build made; Debian's Chromium (page_check.js,
// playwright-core) signs alice in from her link, runs the square and the
// teacher's Stop all, and the page's Stop button, end a running program
// with the library's words on the block that ran.

#include "blocks_hub_rig.h"  // tests/bridge
#include "classroom_accounts.h"
#include "fleet_topics.h"
#include "mosquitto_broker.h"
#include "mqtt_client.h"
#include "npm_packages.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QTemporaryDir>

using namespace mqtt;

class TestBlocksPage : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    MosquittoBroker m_broker;
    ServeProcess m_hub;
    QProcess m_bridge;
    QByteArray m_bridgeSaid;
    MqttClient m_teacher{QStringLiteral("teacher")};
    QList<QJsonObject> m_aliceReplies;
    bool m_online = false;
    QString m_controller;     // who holds r1, from its state
    QStringList m_controllers; // each one its state said
    QString m_class, m_accounts, m_checkDir;

    QStringList checkArguments(const char *scenario, const char *program) const
    {
        return {QDir(m_checkDir).filePath(QStringLiteral("page_check.js")), QLatin1String(scenario),
                QStringLiteral("https://127.0.0.1:%1").arg(m_hub.port()), QStringLiteral("user=alice"),
                QStringLiteral("password=") + passwordIn(m_accounts, QStringLiteral("alice")),
                QStringLiteral("program=" BLOCKS_PROGRAMS "/") + QLatin1String(program)};
    }
    ProcessRun runChecking(const char *scenario, const char *program)
    {
        QProcess check;
        check.setWorkingDirectory(m_checkDir);
        check.start(QStringLiteral("node"), checkArguments(scenario, program));
        if (!check.waitForStarted() || !QTest::qWaitFor([&] { return check.state() == QProcess::NotRunning; }, 70000))
            return {};
        return {check.exitStatus() == QProcess::NormalExit ? check.exitCode() : -1, check.readAllStandardOutput(),
                check.readAllStandardError()};
    }
    static QJsonObject lastLine(const QByteArray &out)
    {
        return jsonObjectOf(QString::fromUtf8(out.trimmed().split('\n').constLast()));
    }

private slots:
    void initTestCase()
    {
        QVERIFY2(QFile::exists(QStringLiteral("/usr/bin/chromium")),
                 "Debian's chromium is not installed (.ci/install-deps installs it)");
        if (!QFile::exists(QStringLiteral(BLOCKS_PAGE_DIR "/node_modules/blockly/package.json")))
            QSKIP("Blockly is not in " BLOCKS_PAGE_DIR ": npm could not fetch it at build time (see the build's warning)");
        m_checkDir = QStringLiteral(PAGE_CHECK_DIR);
        const NpmInstall npm = installNpmPackages(m_checkDir, QStringLiteral(BLOCKS_SOURCE),
                                                  {"package.json", "page_check.js"}, {"playwright-core"});
        if (!npm.unreachable.isEmpty())
            QSKIP(qPrintable(QStringLiteral("npm cannot reach its registry (%1): no browser drives the page")
                                 .arg(npm.unreachable)));
        QVERIFY2(npm.error.isEmpty(), qPrintable(npm.error));

        // Run as root, init hands the broker to the mosquitto user, which must reach the classroom.
        QFile::setPermissions(m_dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner | QFile::ReadGroup
                                                | QFile::ExeGroup | QFile::ReadOther | QFile::ExeOther);
        m_class = m_dir.filePath(QStringLiteral("class"));
        const ProcessRun init = runProcess(QStringLiteral(ROOMBA_CLASSROOM_PATH),
                                           {"init", m_class, "--robots", "r1", "--students", "alice", "--port",
                                            QString::number(m_broker.port())});
        QVERIFY2(init.exitCode == 0, init.err.constData());
        m_accounts = accountsIn(m_class);
        QVERIFY(!m_accounts.isEmpty());
        QVERIFY2(m_broker.startWith(QDir(m_class).filePath(QStringLiteral("mosquitto.conf"))), qPrintable(m_broker.error()));

        m_bridge.setProcessChannelMode(QProcess::MergedChannels);
        connect(&m_bridge, &QProcess::readyRead, this, [this] { m_bridgeSaid += m_bridge.readAll(); });
        m_bridge.start(QStringLiteral(ROOMBA_BRIDGE_PATH),
                       {QStringLiteral("--config"), QDir(m_class).filePath(QStringLiteral("bridges/r1.conf")),
                        QStringLiteral("--sim")});
        QVERIFY(m_bridge.waitForStarted());
        // The teacher watches what the bridge answers alice, and sends Stop all.
        connect(&m_teacher, &MqttClient::messageReceived, this, [this](const QString &topic, const QByteArray &payload) {
            const QJsonObject o = QJsonDocument::fromJson(payload).object();
            if (topic == topics::reply(QStringLiteral("r1"), QStringLiteral("alice")))
                m_aliceReplies << o;
            else if (topic == topics::state(QStringLiteral("r1"))) {
                m_online = o.value(QLatin1String("online")).toBool()
                           && o.value(QLatin1String("link")) == QLatin1String("streaming");
                m_controller = o.value(QLatin1String("controller")).toString();
                m_controllers << m_controller;
            }
        });
        m_teacher.subscribe(topics::reply(QStringLiteral("r1"), QStringLiteral("alice")));
        m_teacher.subscribe(topics::state(QStringLiteral("r1")));
        const QString ca = QDir(m_class).filePath(QStringLiteral("ca.crt"));
        QVERIFY(m_teacher.connectToBroker(
            classroomBroker(m_broker.port(), QStringLiteral("teacher"), passwordIn(m_accounts, QStringLiteral("teacher")), ca)));
        QTRY_VERIFY2_WITH_TIMEOUT(m_online, m_bridgeSaid.constData(), 30000);
        QVERIFY2(m_hub.start({m_class, "--page", BLOCKS_PAGE_DIR}), m_hub.said().constData());
    }

    // The square's Python on the page is the golden file; the bridge answers
    // its eight moves as done; the page's own odometry ends where it started.
    void theSquareRunsFromThePage()
    {
        m_aliceReplies.clear();
        // Run with the event loop going, so that the teacher hears the bridge meanwhile.
        const ProcessRun r = runChecking("square", "square.json");
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject seen = lastLine(r.out);
        qInfo("%s", r.out.trimmed().constData());
        QVERIFY2(seen.value(QLatin1String("problems")).toArray().isEmpty(), r.out.constData());
        QVERIFY2(seen.value(QLatin1String("ended")).isNull(), (r.out + m_bridgeSaid.right(3000)).constData());
        QFile golden(QStringLiteral(BLOCKS_PROGRAMS "/square.py"));
        QVERIFY(golden.open(QIODevice::ReadOnly));
        QCOMPARE(seen.value(QLatin1String("python")).toString(), QString::fromUtf8(golden.readAll()));

        int straights = 0, turns = 0;
        double turned = 0; // what the bridge measured, beside the page's own odometry
        for (const QJsonObject &reply : m_aliceReplies) {
            if (!reply.contains(QLatin1String("seconds")))
                continue; // not a move's answer
            QVERIFY2(reply.value(QLatin1String("ok")).toBool(), QJsonDocument(reply).toJson().constData());
            const double distance = reply.value(QLatin1String("distance_mm")).toDouble();
            const double angle = reply.value(QLatin1String("angle_deg")).toDouble();
            turned += angle;
            if (std::abs(distance - 500) < 5 && std::abs(angle) < 2)
                ++straights;
            else if (std::abs(angle - 90) < 2 && std::abs(distance) < 5)
                ++turns;
        }
        QByteArray replies;
        for (const QJsonObject &reply : m_aliceReplies)
            replies += QJsonDocument(reply).toJson(QJsonDocument::Compact) + '\n';
        QVERIFY2(straights == 4, replies.constData());
        QCOMPARE(turns, 4);
        const QJsonObject pose = seen.value(QLatin1String("pose")).toObject();
        qInfo("the moves turned %.2f degrees in all", turned);
        QVERIFY2(std::hypot(pose.value(QLatin1String("x_mm")).toDouble(), pose.value(QLatin1String("y_mm")).toDouble()) < 30,
                 r.out.constData());
        QVERIFY2(std::abs(pose.value(QLatin1String("heading_deg")).toDouble()) < 5, r.out.constData());
        QVERIFY2(std::abs(turned - 360) < 3, qPrintable(QString::number(turned)));
    }

    // Stop all while the page's program waits for the bumper: the program ends
    // with the library's words, on the block that was running.
    void stopAllEndsTheProgramWithItsWordsOnTheBlock()
    {
        QProcess check;
        QByteArray out, err;
        connect(&check, &QProcess::readyReadStandardOutput, this, [&] { out += check.readAllStandardOutput(); });
        connect(&check, &QProcess::readyReadStandardError, this, [&] { err += check.readAllStandardError(); });
        check.setWorkingDirectory(m_checkDir);
        check.start(QStringLiteral("node"), checkArguments("stop-all", "drive_until_bump.json")
                                                << QStringLiteral("out=%1").arg(m_checkDir));
        QTRY_VERIFY2_WITH_TIMEOUT(out.contains("{\"running\":true}") || check.state() == QProcess::NotRunning,
                                  "no answer from page_check.js", 60000);
        QVERIFY2(out.contains("{\"running\":true}"), err.constData());
        QVERIFY(m_teacher.publish(topics::stopAll(), "{\"client\": \"teacher\"}", 1));
        QTRY_VERIFY_WITH_TIMEOUT(check.state() == QProcess::NotRunning, 40000);
        QVERIFY2(check.exitCode() == 0, err.constData());
        const QJsonObject seen = lastLine(out);
        qInfo("%s", out.trimmed().constData());
        const QString words = QStringLiteral("Stopped: Stop all: your teacher stopped every robot, r1 too. Your program "
                                             "ends here; run it again when your teacher says so.");
        QCOMPARE(seen.value(QLatin1String("blockType")).toString(), QStringLiteral("roomba_wait_until"));
        QCOMPARE(seen.value(QLatin1String("lastEnd")).toObject().value(QLatin1String("words")).toString(), words);
        QVERIFY2(seen.value(QLatin1String("bubbles")).toArray().contains(words), out.constData());
        QCOMPARE(seen.value(QLatin1String("status")).toString(), words);
        // The teacher's view heard how it ended.
        QVERIFY2(m_hub.waitToSay(words.toUtf8().left(40)), m_hub.said().constData());
    }

    // The page's Stop button, as Ctrl-C in Python: the robot stops, the
    // program ends with Ctrl-C's words on its block, control goes back.
    void theStopButtonEndsTheProgram()
    {
        m_controllers.clear();
        const ProcessRun r = runChecking("stop-button", "drive_until_bump.json");
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject seen = lastLine(r.out);
        const QString words = QStringLiteral("Stopped with the Stop button: the robot was stopped.");
        QCOMPARE(seen.value(QLatin1String("blockType")).toString(), QStringLiteral("roomba_wait_until"));
        QCOMPARE(seen.value(QLatin1String("status")).toString(), words);
        QVERIFY2(seen.value(QLatin1String("bubbles")).toArray().contains(words), r.out.constData());
        QVERIFY2(m_controllers.contains(QStringLiteral("alice")), qPrintable(m_controllers.join(',')));
        QTRY_VERIFY_WITH_TIMEOUT(m_controller.isEmpty(), 10000);
    }

    // The block sets the teacher chose (serve --blocks), and only those, with
    // numbers and variables always.
    void onlyTheTeachersBlockSetsAreShown()
    {
        QCOMPARE(lastLine(runChecking("toolbox", "square.json").out).value(QLatin1String("categories")).toArray(),
                 QJsonArray({"Move", "Sensors", "Sound", "Lights", "Control", "Numbers", "Variables"}));
        ServeProcess chosen;
        QVERIFY2(chosen.start({m_class, "--page", BLOCKS_PAGE_DIR, "--blocks", "move,sound"}), chosen.said().constData());
        QStringList arguments = checkArguments("toolbox", "square.json");
        arguments[2] = QStringLiteral("https://127.0.0.1:%1").arg(chosen.port());
        QProcess check;
        check.setWorkingDirectory(m_checkDir);
        check.start(QStringLiteral("node"), arguments);
        QTRY_VERIFY_WITH_TIMEOUT(check.state() == QProcess::NotRunning, 60000);
        const QByteArray out = check.readAllStandardOutput();
        QVERIFY2(check.exitCode() == 0, check.readAllStandardError().constData());
        QCOMPARE(lastLine(out).value(QLatin1String("categories")).toArray(),
                 QJsonArray({"Move", "Sound", "Numbers", "Variables"}));
    }

    // The page at a laptop's and a projector's size, signed in with a program
    // (PNGs in the check's folder, for docs/images): no error on the page.
    void screenshotsAtLaptopAndProjectorSizes()
    {
        QStringList arguments = checkArguments("screenshots", "cliff_safe_wander.json");
        arguments << QStringLiteral("out=%1").arg(m_checkDir);
        QProcess check;
        check.setWorkingDirectory(m_checkDir);
        check.start(QStringLiteral("node"), arguments);
        QVERIFY(check.waitForFinished(60000));
        const QByteArray out = check.readAllStandardOutput();
        QVERIFY2(check.exitCode() == 0, check.readAllStandardError().constData());
        QVERIFY2(lastLine(out).value(QLatin1String("problems")).toArray().isEmpty(), out.constData());
        for (const char *name : {"blocks-1280x720.png", "blocks-1920x1080.png"})
            QVERIFY2(QFileInfo(QDir(m_checkDir).filePath(QLatin1String(name))).size() > 10000, name);
    }

    void cleanupTestCase()
    {
        m_hub.stop();
        m_bridge.terminate();
        m_bridge.waitForFinished(10000);
    }
};

QTEST_GUILESS_MAIN(TestBlocksPage)
#include "tst_blocks_page.moc"
