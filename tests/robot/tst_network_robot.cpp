// SPDX-License-Identifier: GPL-3.0-or-later
// A robot on the broker as a RobotSession: its telemetry comes in as stream
// frames, driving takes control, keeps it with a heartbeat and gives it back
// after the stop, commands go as typed ones while the link's own stay here,
// and a sensor query the bridge cannot answer fails with a message. Against
// a real mosquitto and a fake bridge.

#include "fake_bridge.h"
#include "fleet_directory.h"
#include "manual_clock.h"
#include "mosquitto_broker.h"
#include "network_transport.h"
#include "recording_file.h"
#include "robot_session.h"
#include "snapshot_json.h"
#include "transport_factory.h"
#include "typed_command_bytes.h"

#include <QJsonArray>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

// A robot on the broker whose link's bytes are a decoy that reads as no
// command at all: the transport must publish the typed commands the link
// hands it. Were it to read the bytes, nothing would reach the bridge.
class DecoyBytesTransport : public NetworkTransport {
public:
    using NetworkTransport::NetworkTransport;
    bool writeCommands(const std::vector<oi::OiCommand> &commands, const QByteArray &, Origin origin) override
    {
        return NetworkTransport::writeCommands(commands, QByteArray("\xff\xfe no command", 12), origin);
    }
};

class TestNetworkRobot : public QObject {
    Q_OBJECT

private:
    struct Rig {
        MosquittoBroker broker;
        FakeBridge bridge{QStringLiteral("r1")};
        FleetDirectory directory;
        RobotSession session;
        QTimer telemetry; // the bridge's stream, every 15 ms
        oi::ProfileId profile;
        oi::SensorSnapshot values{oi::profile(profile)};
        bool decoyBytes = false; // DecoyBytesTransport

        explicit Rig(oi::ProfileId id = oi::ProfileId::Create2) : profile(id) {}

        bool start()
        {
            if (!broker.start() || !bridge.start(broker.port()))
                return false;
            QJsonObject state = bridge.state();
            state.insert("profile", QString::fromLatin1(oi::profile(profile).key.data(),
                                                        qsizetype(oi::profile(profile).key.size())));
            bridge.publishState(state);
            QSignalSpy appeared(&directory, &FleetDirectory::robotAppeared);
            directory.connectToBroker(*mqtt::BrokerAddress::fromUrl(broker.url(), nullptr));
            if (!appeared.wait(5000))
                return false;
            values.set(7, 0);
            values.set(35, 2); // Safe: motion is allowed
            values.set(22, 15000);
            QObject::connect(&telemetry, &QTimer::timeout, &bridge,
                             [this] { bridge.publishTelemetry(oilink::snapshotToJson(values)); });
            telemetry.start(15);
            session.setTransportFactory([this](const oilink::LinkSettings &s) -> oilink::Transport * {
                if (decoyBytes)
                    return new DecoyBytesTransport(&directory, s.networkRobot, oi::profile(*s.profile));
                return transports::createTransport(s, s.baud, {}, 0, &directory); // as the dashboard makes it
            });
            session.connectTo(oilink::LinkSettings::networkRobotOf(QStringLiteral("r1"), profile));
            // Live, and the first frame in: the robot's mode is known.
            return QTest::qWaitFor([this] { return session.isLive() && session.snapshotCount() > 0; }, 5000);
        }

        // Once the bridge has what the console published so far: a stop all
        // queued behind it has arrived. (Messages from one client arrive in
        // the order they were sent.)
        bool settled()
        {
            const int stops = bridge.stopsReceived();
            QMetaObject::invokeMethod(&directory, [this] { directory.stopAll(); }, Qt::QueuedConnection);
            return QTest::qWaitFor([&] { return bridge.stopsReceived() > stops; }, 5000);
        }
    };

    static bool isStream(const QList<QVariant> &bytesSent)
    {
        return bytesSent[0].toByteArray().startsWith(char(148));
    }

private slots:
    void telemetryComesInAsFrames()
    {
        Rig rig;
        QVERIFY2(rig.start(), qPrintable(rig.broker.error()));
        QSignalSpy frames(&rig.session, &RobotSession::frameReceived);
        rig.values.set(7, 0x03); // both bumpers
        rig.values.set(9, 1);
        QTRY_VERIFY_WITH_TIMEOUT(rig.session.latest().raw(7) == 0x03, 5000);
        QCOMPARE(rig.session.latest().raw(9), 1);
        QCOMPARE(rig.session.latest().raw(22), 15000);
        QCOMPARE(rig.session.robotProfile().id, oi::ProfileId::Create2);
        QVERIFY(frames.count() > 0);
        QCOMPARE(rig.session.statistics().checksumFailures, 0u);
        // Nothing was sent to the robot by looking at it: Start and Stream stay here.
        QVERIFY(rig.bridge.receivedOn(mqtt::topics::Kind::Command).isEmpty());
        QVERIFY(rig.bridge.receivedOn(mqtt::topics::Kind::Control).isEmpty());
    }

    // A recording of a robot on the broker keeps its telemetry as the
    // stream frames it sent, so it replays and exports as a local one does.
    void aRecordingKeepsTheTelemetry()
    {
        Rig rig;
        QVERIFY2(rig.start(), qPrintable(rig.broker.error()));
        QTemporaryDir dir;
        const QString path = dir.filePath("r1.oirec");
        rig.session.startRecording(path);
        rig.values.set(7, 0x03);
        QTRY_VERIFY_WITH_TIMEOUT(rig.session.latest().raw(7) == 0x03, 5000);
        const quint64 seen = rig.session.snapshotCount();
        QTRY_VERIFY_WITH_TIMEOUT(rig.session.snapshotCount() > seen + 2, 5000);
        QSignalSpy status(&rig.session, &RobotSession::recordingStatus);
        rig.session.stopRecording();
        QTRY_VERIFY_WITH_TIMEOUT(!status.isEmpty() && !status.last().at(0).value<oilink::RecordingStatus>().active, 5000);
        QString error;
        const std::optional<oilink::Recording> r = oilink::Recording::load(path, &error);
        QVERIFY2(r, qPrintable(error));
        QVERIFY(!r->damage());
        int bumped = 0, frames = 0;
        r->forEachSnapshot([&](qint64, const oi::SensorSnapshot &s) {
            ++frames;
            bumped += s.raw(7) == 0x03 && s.raw(22) == 15000 && s.raw(35) == 2;
        });
        QVERIFY2(bumped >= 2, qPrintable(QStringLiteral("%1 of %2 frames").arg(bumped).arg(frames)));
    }

    // The drive pad's motion reaches the bridge as the typed command the
    // teleop made, through the link and the transport, with no byte read on
    // the way: MotionCommand, OiCommand, JSON.
    void commandsGoAsTypedJsonWithoutReadingBytes()
    {
        Rig rig;
        rig.decoyBytes = true;
        QVERIFY2(rig.start(), qPrintable(rig.broker.error()));
        QSignalSpy problems(&rig.directory, &FleetDirectory::errorOccurred);
        MotionCommand turn{MotionCommand::Kind::DriveDirect};
        turn.right = 150;
        turn.left = -150;
        rig.session.teleop().requestMotion(turn);
        QVERIFY(rig.session.send(oi::OiCommand{oi::Command::Song, {2}, {60, 32, 64, 16}}));
        QTRY_COMPARE_WITH_TIMEOUT(rig.bridge.receivedOn(mqtt::topics::Kind::Command).size(), 2, 5000);
        const auto commands = rig.bridge.receivedOn(mqtt::topics::Kind::Command);
        QCOMPARE(commands[0].payload.value("command").toString(), QStringLiteral("drive-direct"));
        QCOMPARE(commands[0].payload.value("fields").toObject(), QJsonObject({{"right-velocity", 150}, {"left-velocity", -150}}));
        QCOMPARE(commands[1].payload.value("command").toString(), QStringLiteral("song"));
        QCOMPARE(commands[1].payload.value("data").toArray(), QJsonArray({60, 32, 64, 16}));
        rig.session.teleop().deadManReleased();
        QTRY_VERIFY_WITH_TIMEOUT(rig.bridge.controller().isEmpty(), 5000);
        QCOMPARE(rig.bridge.receivedOn(mqtt::topics::Kind::Command).last().payload.value("command").toString(),
                 QStringLiteral("stop"));
        QVERIFY2(problems.isEmpty(), problems.isEmpty() ? "" : qPrintable(problems.first().first().toString()));
    }

    // The heartbeat that keeps control, and the release after a command
    // other than motion, run on the clock the transport is given.
    void theHeartbeatRunsOnTheClock()
    {
        ManualClock clock;
        FleetDirectory directory; // connected to, never called: no broker needed
        NetworkTransport transport(&directory, QStringLiteral("r1"), oi::profile(oi::ProfileId::Create2), clock);
        QSignalSpy control(&transport, &NetworkTransport::controlPublished);
        transport.open();
        const auto actions = [&control] {
            QStringList out;
            for (const QList<QVariant> &c : control)
                out << c.at(1).toString();
            return out;
        };
        // A song takes control, the heartbeat keeps it, and it goes back once idle.
        transport.writeCommands({oi::OiCommand{oi::Command::Play, {0}, {}}}, QByteArray(), oilink::Transport::Origin::User);
        QCOMPARE(actions(), QStringList{"take"});
        clock.advance(NetworkTransport::kHeartbeatMs - 1);
        QCOMPARE(actions(), QStringList{"take"});
        clock.advance(1);
        QCOMPARE(actions(), (QStringList{"take", "keep"}));
        clock.advance(NetworkTransport::kReleaseIdleMs - NetworkTransport::kHeartbeatMs - 1);
        QVERIFY(!actions().contains("release"));
        QCOMPARE(actions().count("keep"), NetworkTransport::kReleaseIdleMs / NetworkTransport::kHeartbeatMs - 1);
        clock.advance(1);
        QCOMPARE(actions().last(), QStringLiteral("release"));
        transport.close();
    }

    void drivingTakesControlAndGivesItBack()
    {
        Rig rig;
        QVERIFY2(rig.start(), qPrintable(rig.broker.error()));
        MotionCommand forward;
        forward.velocity = 200;
        rig.session.teleop().requestMotion(forward);
        QTRY_COMPARE_WITH_TIMEOUT(rig.bridge.controller(), rig.directory.clientName(), 5000);
        QTRY_COMPARE_WITH_TIMEOUT(rig.bridge.receivedOn(mqtt::topics::Kind::Command).size(), 1, 5000);
        const auto drive = rig.bridge.receivedOn(mqtt::topics::Kind::Command).first();
        QCOMPARE(drive.topic, mqtt::topics::command("r1", rig.directory.clientName()));
        // The typed command, as docs/mqtt.md says.
        QCOMPARE(drive.payload.value("v").toInt(), 2);
        QCOMPARE(drive.payload.value("command").toString(), QStringLiteral("drive"));
        QCOMPARE(drive.payload.value("fields").toObject(),
                 QJsonObject({{"velocity", 200}, {"radius", oi::kRadiusStraight}}));
        // Control was taken before the command.
        QCOMPARE(rig.bridge.received().first().payload.value("action").toString(), QStringLiteral("take"));

        // The heartbeat keeps it while driving.
        QTRY_VERIFY_WITH_TIMEOUT(rig.bridge.receivedOn(mqtt::topics::Kind::Control).size() >= 4, 5000);
        for (const auto &m : rig.bridge.receivedOn(mqtt::topics::Kind::Control).mid(1))
            QCOMPARE(m.payload.value("action").toString(), QStringLiteral("keep"));

        rig.session.teleop().deadManReleased();
        QTRY_VERIFY_WITH_TIMEOUT(rig.bridge.controller().isEmpty(), 5000);
        const auto commands = rig.bridge.receivedOn(mqtt::topics::Kind::Command);
        QCOMPARE(commands.last().payload.value("command").toString(), QStringLiteral("stop"));
        QCOMPARE(rig.bridge.receivedOn(mqtt::topics::Kind::Control).last().payload.value("action").toString(),
                 QStringLiteral("release"));
        // No heartbeat after the release: the next control message is a take.
        const qsizetype controls = rig.bridge.receivedOn(mqtt::topics::Kind::Control).size();
        rig.session.teleop().requestMotion(forward);
        QTRY_VERIFY_WITH_TIMEOUT(rig.bridge.receivedOn(mqtt::topics::Kind::Control).size() > controls, 5000);
        QCOMPARE(rig.bridge.receivedOn(mqtt::topics::Kind::Control)[controls].payload.value("action").toString(),
                 QStringLiteral("take"));
        rig.session.teleop().deadManReleased();
        QTRY_VERIFY_WITH_TIMEOUT(rig.bridge.controller().isEmpty(), 5000);
    }

    // Clean (and Spot, Max, Seek Dock) is the robot's own program: control
    // is kept, heartbeat after heartbeat, past the idle release a song or
    // an LED gets, because the bridge ends the program when control goes
    // back. The driver's stop ends it and gives control back.
    void aCleaningCommandKeepsControlUntilTheStop()
    {
        Rig rig;
        QVERIFY2(rig.start(), qPrintable(rig.broker.error()));
        QVERIFY(rig.session.send(commandsOf(QByteArray(1, char(135))))); // Clean
        QTRY_COMPARE_WITH_TIMEOUT(rig.bridge.controller(), rig.directory.clientName(), 5000);
        QTRY_COMPARE_WITH_TIMEOUT(rig.bridge.receivedOn(mqtt::topics::Kind::Command).size(), 1, 5000);
        QCOMPARE(rig.bridge.receivedOn(mqtt::topics::Kind::Command).first().payload.value("command").toString(),
                 QStringLiteral("clean"));
        // Three times the idle release's worth of heartbeats, and no release among them.
        const int keeps = 3 * NetworkTransport::kReleaseIdleMs / NetworkTransport::kHeartbeatMs;
        QTRY_VERIFY_WITH_TIMEOUT(rig.bridge.receivedOn(mqtt::topics::Kind::Control).size() > keeps, 15000);
        for (const auto &m : rig.bridge.receivedOn(mqtt::topics::Kind::Control).mid(1))
            QCOMPARE(m.payload.value("action").toString(), QStringLiteral("keep"));
        QCOMPARE(rig.bridge.controller(), rig.directory.clientName());
        // Space: the stop goes to the bridge, and control with it.
        rig.session.teleop().stopAll();
        QTRY_VERIFY_WITH_TIMEOUT(rig.bridge.controller().isEmpty(), 5000);
        QCOMPARE(rig.bridge.receivedOn(mqtt::topics::Kind::Command).last().payload.value("command").toString(),
                 QStringLiteral("stop"));
    }

    // Passive (Start alone, from the mode panel) goes to the bridge as a
    // command; the Start the link writes before its Stream stays here.
    void passiveGoesToTheBridge()
    {
        Rig rig;
        QVERIFY2(rig.start(), qPrintable(rig.broker.error()));
        QVERIFY(rig.bridge.receivedOn(mqtt::topics::Kind::Command).isEmpty());
        QVERIFY(rig.session.send(commandsOf(QByteArray(1, char(128)))));
        QTRY_COMPARE_WITH_TIMEOUT(rig.bridge.receivedOn(mqtt::topics::Kind::Command).size(), 1, 5000);
        QCOMPARE(rig.bridge.receivedOn(mqtt::topics::Kind::Command).first().payload.value("command").toString(),
                 QStringLiteral("start"));
        QVERIFY(rig.settled());
        QCOMPARE(rig.bridge.receivedOn(mqtt::topics::Kind::Command).size(), 1);
    }

    void anotherControllerRefusesTheDrive()
    {
        Rig rig;
        QVERIFY2(rig.start(), qPrintable(rig.broker.error()));
        // alice drives r1 already.
        mqtt::MqttClient alice(QStringLiteral("alice"));
        QSignalSpy up(&alice, &mqtt::MqttClient::connected);
        alice.connectToBroker(*mqtt::BrokerAddress::fromUrl(rig.broker.url(), nullptr));
        QVERIFY(up.wait(5000));
        alice.publish(mqtt::topics::control("r1", "alice"), R"({"action":"take"})", 1);
        QTRY_COMPARE_WITH_TIMEOUT(rig.bridge.controller(), QStringLiteral("alice"), 5000);

        QSignalSpy errors(&rig.directory, &FleetDirectory::errorOccurred);
        MotionCommand forward;
        forward.velocity = 100;
        rig.session.teleop().requestMotion(forward);
        QTRY_VERIFY_WITH_TIMEOUT(!errors.isEmpty(), 5000);
        QVERIFY2(errors.first()[0].toString().contains("alice has control"), qPrintable(errors.first()[0].toString()));
        QCOMPARE(rig.bridge.controller(), QStringLiteral("alice"));
    }

    void sensorQueries()
    {
        Rig rig;
        QVERIFY2(rig.start(), qPrintable(rig.broker.error()));
        rig.values.set(7, 0x02);
        QTRY_VERIFY_WITH_TIMEOUT(rig.session.latest().raw(7) == 0x02, 5000);
        // What the telemetry carries is answered from it...
        QSignalSpy replies(&rig.session, &RobotSession::sensorReply);
        rig.session.querySensors({7});
        QTRY_COMPARE_WITH_TIMEOUT(replies.count(), 1, 5000);
        QCOMPARE(replies[0][0].value<oi::SensorSnapshot>().raw(7), 0x02);
        // ...what it does not carry fails, with a reason.
        QSignalSpy directoryErrors(&rig.directory, &FleetDirectory::errorOccurred);
        QSignalSpy linkErrors(&rig.session, &RobotSession::errorOccurred);
        rig.session.querySensors({43});
        QTRY_VERIFY_WITH_TIMEOUT(!directoryErrors.isEmpty() && !linkErrors.isEmpty(), 5000);
        QVERIFY2(directoryErrors[0][0].toString().contains("packet 43"), qPrintable(directoryErrors[0][0].toString()));
        QVERIFY2(linkErrors[0][0].toString().contains("no reply"), qPrintable(linkErrors[0][0].toString()));
        QCOMPARE(replies.count(), 1);
    }

    void aSilentBridgeGoesStale()
    {
        Rig rig;
        QVERIFY2(rig.start(), qPrintable(rig.broker.error()));
        QSignalSpy sent(&rig.session, &RobotSession::bytesSent);
        rig.telemetry.stop();
        QTRY_COMPARE_WITH_TIMEOUT(rig.session.state(), oilink::LinkState::Stale, 5000);
        // With no data for a while the link writes its Start and Stream
        // again; they are the link's own and stay here.
        QTRY_VERIFY_WITH_TIMEOUT(std::any_of(sent.cbegin(), sent.cend(), isStream), 5000);
        rig.telemetry.start(15);
        QTRY_COMPARE_WITH_TIMEOUT(rig.session.state(), oilink::LinkState::Streaming, 5000);
        QVERIFY(rig.settled());
        QVERIFY(rig.bridge.receivedOn(mqtt::topics::Kind::Command).isEmpty());
    }

    // Closing a robot this console does not drive must not stop anyone
    // else's driving, nor send it to Passive: the link's stop and Start on
    // closing stay here.
    void closingLeavesTheRobotAlone()
    {
        Rig rig;
        QVERIFY2(rig.start(), qPrintable(rig.broker.error()));
        QSignalSpy sent(&rig.session, &RobotSession::bytesSent);
        rig.session.closeAndWait();
        QVERIFY(!sent.isEmpty()); // the link's stop and Start were written
        QVERIFY(rig.settled());
        QVERIFY(rig.bridge.receivedOn(mqtt::topics::Kind::Command).isEmpty());
        QVERIFY(rig.bridge.receivedOn(mqtt::topics::Kind::Control).isEmpty());
    }

    // The Create's link ends any script before its Start: that, too, is the
    // link's own, and the Create's commands go as typed ones.
    void aCreateOnTheBroker()
    {
        Rig rig(oi::ProfileId::Create1);
        QSignalSpy errors(&rig.directory, &FleetDirectory::errorOccurred);
        QVERIFY2(rig.start(), qPrintable(rig.broker.error()));
        QVERIFY(rig.session.send(commandsOf(QByteArray::fromHex("9b0a"), oi::profile(oi::ProfileId::Create1)))); // wait-time 1 s: a Create-only command
        QTRY_COMPARE_WITH_TIMEOUT(rig.bridge.receivedOn(mqtt::topics::Kind::Command).size(), 1, 5000);
        const QJsonObject wait = rig.bridge.receivedOn(mqtt::topics::Kind::Command).first().payload;
        QCOMPARE(wait.value("command").toString(), QStringLiteral("wait-time"));
        QCOMPARE(wait.value("fields").toObject(), QJsonObject({{"time", 10}}));
        QVERIFY(rig.settled());
        QCOMPARE(rig.bridge.receivedOn(mqtt::topics::Kind::Command).size(), 1);
        QVERIFY2(errors.isEmpty(), qPrintable(errors.value(0).value(0).toString()));
    }
};

QTEST_GUILESS_MAIN(TestNetworkRobot)
#include "tst_network_robot.moc"
