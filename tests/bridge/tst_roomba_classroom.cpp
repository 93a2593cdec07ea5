// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-classroom init: the classroom it writes just works with a real
// mosquitto over TLS (a student logs in with the printed password, a
// bridge with its generated config publishes, the console connects with
// the CA); a wrong CA is refused clearly; a second init and bad names are
// refused, and leave nothing behind.

#include "bridge_rig.h"
#include "fleet_directory.h"

#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>

using namespace mqtt;

class TestRoombaClassroom : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;

    struct Run {
        int status = -1;
        QString out, err;
    };
    static Run classroom(const QStringList &args, const QProcessEnvironment &env = QProcessEnvironment::systemEnvironment())
    {
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(ROOMBA_CLASSROOM_PATH), args);
        Run r;
        if (!p.waitForFinished(60000))
            return r;
        r.status = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
        r.out = QString::fromUtf8(p.readAllStandardOutput());
        r.err = QString::fromUtf8(p.readAllStandardError());
        return r;
    }
    // The password printed for an account: "  ROLE  ACCOUNT  PASSWORD".
    static QString passwordOf(const QString &printed, const QString &account)
    {
        for (const QString &line : printed.split(QLatin1Char('\n'))) {
            const QStringList f = line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
            if (f.size() == 3 && f[1] == account)
                return f[2];
        }
        return {};
    }
    static BrokerAddress tlsAddress(int port, const QString &user, const QString &password, const QString &ca)
    {
        BrokerAddress a;
        a.port = port;
        a.tls = true;
        a.caFile = ca;
        a.username = user;
        a.password = password;
        return a;
    }

private slots:
    void initTestCase() { oilink::registerLinkMetaTypes(); }

    void theClassroomItWritesJustWorks()
    {
        MosquittoBroker broker;
        const QString dir = m_dir.filePath(QStringLiteral("class"));
        const Run init = classroom({"init", dir, "--robots", "r1,r2", "--students", "alice,bob", "--spectators",
                                    "guest", "--port", QString::number(broker.port())});
        QVERIFY2(init.status == 0, qPrintable(init.err));
        for (const char *file : {"mosquitto.conf", "passwords", "acl", "accounts.txt", "ca.crt", "server.crt",
                                 "server.key", "bridges/r1.conf", "bridges/r2.conf", "bridges/ca.crt"})
            QVERIFY2(QFile::exists(QDir(dir).filePath(QLatin1String(file))), file);
        const QString alice = passwordOf(init.out, QStringLiteral("alice"));
        QCOMPARE(alice.size(), 20);
        QVERIFY(passwordOf(init.out, QStringLiteral("bob")) != alice);
        // accounts.txt says the same.
        QFile accounts(QDir(dir).filePath(QStringLiteral("accounts.txt")));
        QVERIFY(accounts.open(QIODevice::ReadOnly));
        QCOMPARE(passwordOf(QString::fromUtf8(accounts.readAll()), QStringLiteral("alice")), alice);
        // The secrets are the owner's alone.
        QCOMPARE(QFile::permissions(QDir(dir).filePath(QStringLiteral("passwords")))
                     & (QFile::ReadOther | QFile::ReadGroup),
                 QFile::Permissions());

        QVERIFY2(broker.startWith(QDir(dir).filePath(QStringLiteral("mosquitto.conf"))), qPrintable(broker.error()));
        const QString ca = QDir(dir).filePath(QStringLiteral("ca.crt"));

        // A student logs in over TLS with the printed password; a wrong one is refused.
        MqttClient student(QStringLiteral("alice"));
        QSignalSpy studentUp(&student, &MqttClient::connected);
        QVERIFY(student.connectToBroker(tlsAddress(broker.port(), QStringLiteral("alice"), alice, ca)));
        QTRY_COMPARE_WITH_TIMEOUT(studentUp.count(), 1, 10000);
        MqttClient guesser(QStringLiteral("bob"));
        QSignalSpy guesserErrors(&guesser, &MqttClient::errorOccurred);
        QVERIFY(guesser.connectToBroker(tlsAddress(broker.port(), QStringLiteral("bob"), QStringLiteral("bob-pw"), ca)));
        QTRY_VERIFY_WITH_TIMEOUT(!guesserErrors.isEmpty(), 10000);
        QVERIFY2(guesserErrors[0][0].toString().contains(QLatin1String("not authorised"))
                     || guesserErrors[0][0].toString().contains(QLatin1String("wrong user name or password")),
                 qPrintable(guesserErrors[0][0].toString()));
        QVERIFY(!guesser.isConnected());

        // A bridge with its generated config (a virtual robot instead of the
        // file's serial port) publishes; the console, as the teacher with
        // the CA, sees it online and its telemetry.
        QProcess bridge;
        bridge.setProcessChannelMode(QProcess::MergedChannels);
        QByteArray said;
        connect(&bridge, &QProcess::readyRead, this, [&] { said += bridge.readAll(); });
        bridge.start(QStringLiteral(ROOMBA_BRIDGE_PATH),
                     {QStringLiteral("--config"), QDir(dir).filePath(QStringLiteral("bridges/r1.conf")), QStringLiteral("--sim")});
        QVERIFY(bridge.waitForStarted());
        FleetDirectory console;
        QSignalSpy frames(&console, &FleetDirectory::telemetryReceived);
        QVERIFY(console.connectToBroker(
            tlsAddress(broker.port(), QStringLiteral("teacher"), passwordOf(init.out, QStringLiteral("teacher")), ca)));
        QTRY_VERIFY_WITH_TIMEOUT(console.robot(QStringLiteral("r1")) && console.robot(QStringLiteral("r1"))->state.online, 15000);
        console.follow(QStringLiteral("r1"), true);
        QTRY_VERIFY_WITH_TIMEOUT(!frames.isEmpty(), 10000);
        QCOMPARE(frames[0][0].toString(), QStringLiteral("r1"));
        // Its stop line logs in with its own account and hears the teacher's
        // stop all, which comes to that connection alone.
        QTRY_VERIFY_WITH_TIMEOUT(said.contains("stop line: listening for stop all and takeovers as bridge-r1-stops"), 10000);
        QVERIFY(console.stopAll());
        QTRY_VERIFY_WITH_TIMEOUT(said.contains("roomba.bridge: stop all"), 10000);
        QVERIFY(bridge.state() == QProcess::Running);
        bridge.terminate();
        QVERIFY(bridge.waitForFinished(10000));
    }

    void aWrongCaIsRefusedClearly()
    {
        MosquittoBroker broker;
        const QString dir = m_dir.filePath(QStringLiteral("ca"));
        const QString other = m_dir.filePath(QStringLiteral("other"));
        const Run init = classroom({"init", dir, "--robots", "r1", "--students", "alice", "--port", QString::number(broker.port())});
        QVERIFY2(init.status == 0, qPrintable(init.err));
        // Another classroom's CA.
        QVERIFY(classroom({"init", other, "--robots", "r1", "--students", "alice"}).status == 0);
        QVERIFY2(broker.startWith(QDir(dir).filePath(QStringLiteral("mosquitto.conf"))), qPrintable(broker.error()));

        const QString wrongCa = QDir(other).filePath(QStringLiteral("ca.crt"));
        MqttClient student(QStringLiteral("alice"));
        QSignalSpy errors(&student, &MqttClient::errorOccurred), up(&student, &MqttClient::connected);
        QVERIFY(student.connectToBroker(
            tlsAddress(broker.port(), QStringLiteral("alice"), passwordOf(init.out, QStringLiteral("alice")), wrongCa)));
        QTRY_VERIFY_WITH_TIMEOUT(!errors.isEmpty(), 10000);
        const QString message = errors[0][0].toString();
        QVERIFY2(message.contains(QStringLiteral("is not signed by the CA in %1").arg(wrongCa))
                     && message.contains(QLatin1String("ca.crt")),
                 qPrintable(message));
        QCOMPARE(up.count(), 0);
    }

    void aSecondInitRefusesAndChangesNothing()
    {
        const QString dir = m_dir.filePath(QStringLiteral("twice"));
        QVERIFY(classroom({"init", dir, "--robots", "r1", "--students", "alice"}).status == 0);
        QFile passwords(QDir(dir).filePath(QStringLiteral("passwords")));
        QVERIFY(passwords.open(QIODevice::ReadOnly));
        const QByteArray before = passwords.readAll();
        passwords.close();

        const Run again = classroom({"init", dir, "--robots", "r1", "--students", "alice"});
        QCOMPARE(again.status, 2);
        QVERIFY2(again.err.contains(QStringLiteral("%1 is not empty").arg(dir)) && again.err.contains(QLatin1String("Choose another folder")),
                 qPrintable(again.err));
        QVERIFY(passwords.open(QIODevice::ReadOnly));
        QCOMPARE(passwords.readAll(), before);
        // Nothing was left beside it either.
        QCOMPARE(QDir(m_dir.path()).entryList({QStringLiteral(".twice-*")}, QDir::AllEntries | QDir::Hidden), QStringList());
    }

    void badRequestsAreRefusedAndWriteNothing_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("robot with a space") << QStringList{"--robots", "r1,r 2", "--students", "alice"}
                                            << "robot 'r 2' (--robots) is not a name: 1 to 64 letters";
        QTest::newRow("student with a slash") << QStringList{"--robots", "r1", "--students", "al/ice"}
                                              << "account 'al/ice' (--students) is not a name";
        QTest::newRow("spectator with a wildcard") << QStringList{"--robots", "r1", "--students", "a", "--spectators", "g+"}
                                                   << "account 'g+' (--spectators) is not a name";
        QTest::newRow("fleet") << QStringList{"--robots", "fleet", "--students", "alice"} << "'fleet' (--robots) cannot name a robot";
        QTest::newRow("a robot twice") << QStringList{"--robots", "r1,r1", "--students", "alice"} << "robot 'r1' (--robots) is named twice";
        QTest::newRow("a student as the teacher") << QStringList{"--robots", "r1", "--students", "teacher"}
                                                  << "the account 'teacher' (--students) is named twice";
        QTest::newRow("a student as a bridge") << QStringList{"--robots", "r1", "--students", "bridge-r1"}
                                               << "the account 'bridge-r1' (--students) is named twice";
        QTest::newRow("no robots") << QStringList{"--students", "alice"} << "name the robots: --robots r1,r2,r3";
        QTest::newRow("no students") << QStringList{"--robots", "r1"} << "name the students: --students alice,bob";
        QTest::newRow("any address") << QStringList{"--robots", "r1", "--students", "a", "--host", "0.0.0.0"}
                                     << "'0.0.0.0' (--host) is not this machine's address";
        QTest::newRow("bad port") << QStringList{"--robots", "r1", "--students", "a", "--port", "x"}
                                  << "--port: 'x' is not a port number";
    }
    void badRequestsAreRefusedAndWriteNothing()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const QString dir = m_dir.filePath(QStringLiteral("bad"));
        const Run r = classroom(QStringList{"init", dir} + args);
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(!QFileInfo::exists(dir));
    }

    void withoutOpensslItSaysWhatToInstall()
    {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("PATH"), m_dir.filePath(QStringLiteral("no-such-bin")));
        const QString dir = m_dir.filePath(QStringLiteral("noopenssl"));
        const Run r = classroom({"init", dir, "--robots", "r1", "--students", "alice"}, env);
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.contains(QLatin1String("openssl makes the broker's certificates and is not installed: apt-get install openssl")),
                 qPrintable(r.err));
        QVERIFY(!QFileInfo::exists(dir));
    }
};

QTEST_GUILESS_MAIN(TestRoombaClassroom)
#include "tst_roomba_classroom.moc"
