// SPDX-License-Identifier: GPL-3.0-or-later
// The fleet console in the window, against a real mosquitto and a dozen
// fake bridges: every robot gets a live tile, a killed bridge's tile goes
// offline, a click makes that robot the selected one, and Stop all reaches
// every bridge as well as the local robot. Screenshots of the fleet view go
// into ROOMBA_SCREENSHOTS when set.

#include "broker_dialog.h"
#include "command_encoder.h"
#include "fleet_tile.h"
#include "fake_bridge.h"
#include "fleet_console.h"
#include "fleet_view.h"
#include "main_window.h"
#include "mosquitto_broker.h"
#include "saved_brokers.h"
#include "snapshot_json.h"
#include "typed_command_bytes.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QGuiApplication>
#include <QLabel>
#include <QLineEdit>
#include <QScreen>
#include <QSignalSpy>
#include <QStatusBar>
#include <QDir>
#include <QProcess>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <memory>
#include <vector>

namespace {

QJsonObject telemetry(int bumps, std::initializer_list<int> cliffs, int mode = 2)
{
    oi::SensorSnapshot s(oi::profile(oi::ProfileId::Create2));
    s.set(7, bumps);
    for (int id : {9, 10, 11, 12})
        s.set(id, 0);
    for (int id : cliffs)
        s.set(id, 1);
    s.set(35, mode);
    s.set(22, 15600);
    return oilink::snapshotToJson(s);
}

// Into ROOMBA_SCREENSHOTS, when set.
void saveShot(QWidget &widget, const char *name)
{
    const QString dir = qEnvironmentVariable("ROOMBA_SCREENSHOTS");
    if (dir.isEmpty())
        return;
    QDir().mkpath(dir);
    widget.grab().save(QDir(dir).filePath(QString::fromLatin1(name)));
}

} // namespace

class TestFleetConsole : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    // Connected to a broker at quit: connected again at the next start,
    // where no password needs asking for.
    void reconnectsToTheLastBrokerAtStart()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        FakeBridge bridge(QStringLiteral("r1"));
        QVERIFY(bridge.start(broker.port()));
        bridge.publishState(bridge.state("safe", 80));
        const mqtt::BrokerAddress address = *mqtt::BrokerAddress::fromUrl(broker.url(), nullptr);
        {
            QSettings settings;
            saveBrokers(settings, {SavedBroker{address, false}});
        }
        {
            MainWindow window;
            window.start();
            QVERIFY(!window.fleetView()->tile("r1")); // not connected before
            QVERIFY(window.connectToBroker(address));
            QTRY_VERIFY_WITH_TIMEOUT(window.fleetView()->tile("r1"), 5000);
            window.close();
        }
        MainWindow again;
        again.start();
        QTRY_VERIFY_WITH_TIMEOUT(again.fleetView()->tile("r1"), 5000);
        again.close();

        // A login whose password was not kept is not tried.
        mqtt::BrokerAddress withLogin = address;
        withLogin.username = QStringLiteral("teacher");
        {
            QSettings settings;
            saveBrokers(settings, {SavedBroker{withLogin, false}});
            settings.setValue("brokers/connectedAtQuit", true); // as `again` left it
        }
        MainWindow asking;
        asking.start();
        QVERIFY(!asking.findChild<QAction *>("disconnectBrokerAction")->isEnabled());
        QVERIFY(asking.fleetView()->tiles().isEmpty());
        // Not forgotten: the fleet view offers that class, naming the account,
        // and its button asks for the password of that login.
        FleetView &view = *asking.fleetView();
        QVERIFY(view.isVisible());
        QVERIFY2(view.brokerLabel()->text().contains(address.displayUrl())
                     && view.brokerLabel()->text().contains(QStringLiteral("teacher")),
                 qPrintable(view.brokerLabel()->text()));
        QCOMPARE(view.connectButton()->text(), QStringLiteral("Reconnect…"));
        QTest::mouseClick(view.connectButton(), Qt::LeftButton);
        BrokerDialog *dialog = nullptr;
        QTRY_VERIFY((dialog = asking.findChild<BrokerDialog *>()) && dialog->isVisible());
        QCOMPARE(dialog->findChild<QLineEdit *>("brokerUser")->text(), QStringLiteral("teacher"));
        dialog->reject();
        asking.close();
    }

    // A refused password: asked again at once, naming the account, and not
    // tried again meanwhile; once right, the status bar forgets the refusal.
    void aRefusedPasswordIsAskedAgainNotRetried()
    {
        MosquittoBroker broker(QStringLiteral("allow_anonymous false\npassword_file %DIR%/passwords\n"));
        QVERIFY(broker.addUser(QStringLiteral("teacher"), QStringLiteral("right")));
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        mqtt::BrokerAddress wrong = *mqtt::BrokerAddress::fromUrl(broker.url(), nullptr);
        wrong.username = QStringLiteral("teacher");
        wrong.password = QStringLiteral("wrong");

        MainWindow window;
        window.show();
        window.start();
        QSignalSpy said(&window.fleetConsole()->directory(), &FleetDirectory::errorOccurred);
        QVERIFY(window.connectToBroker(wrong));
        BrokerDialog *dialog = nullptr;
        QTRY_VERIFY_WITH_TIMEOUT((dialog = window.findChild<BrokerDialog *>()) && dialog->isVisible(), 5000);
        QVERIFY2(dialog->notice().contains(QStringLiteral("\"teacher\"")), qPrintable(dialog->notice()));
        QCOMPARE(dialog->findChild<QLineEdit *>("brokerUser")->text(), QStringLiteral("teacher"));
        QVERIFY(window.statusBar()->currentMessage().contains(QStringLiteral("refused")));

        // A client with the same wrong login, retrying every second, is the
        // clock: after three of its refusals the window has had just its one.
        mqtt::MqttClient clock(QStringLiteral("clock"));
        QSignalSpy ticks(&clock, &mqtt::MqttClient::errorOccurred);
        QVERIFY(clock.connectToBroker(wrong));
        QTRY_VERIFY_WITH_TIMEOUT(ticks.count() >= 3, 10000);
        int refusals = 0;
        for (const QList<QVariant> &args : said)
            refusals += args[0].toString().contains(QStringLiteral("refused")) ? 1 : 0;
        QCOMPARE(refusals, 1);
        clock.disconnectFromBroker();

        // The password typed again: connected, the refusal gone from the status bar.
        auto *password = dialog->findChild<QLineEdit *>("brokerPassword");
        QVERIFY(password->hasFocus());
        QTest::keyClicks(password, QStringLiteral("right"));
        QTest::keyClick(password, Qt::Key_Return);
        QTRY_VERIFY_WITH_TIMEOUT(window.fleetView()->brokerText().contains(QStringLiteral("speaking as")), 5000);
        QVERIFY2(!window.statusBar()->currentMessage().contains(QStringLiteral("refused")),
                 qPrintable(window.statusBar()->currentMessage()));
        window.close();
    }

    // The broker goes away: every tile says so, not that its robot is lost;
    // it comes back, and so do the tiles, by themselves.
    void aBrokerOutageIsNotDeadRobots()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        FakeBridge bridge(QStringLiteral("r1"));
        QVERIFY(bridge.start(broker.port()));
        // As roomba-bridge does: its state again on every connection.
        connect(&bridge.client(), &mqtt::MqttClient::connected, &bridge, [&bridge] { bridge.publishState(); });
        bridge.publishState();
        MainWindow window;
        window.start();
        QVERIFY(window.connectToBroker(*mqtt::BrokerAddress::fromUrl(broker.url(), nullptr)));
        FleetView &view = *window.fleetView();
        QTRY_VERIFY_WITH_TIMEOUT(view.tile("r1") && view.tile("r1")->values().online, 5000);
        QCOMPARE(view.tile("r1")->statusText(), QStringLiteral("ONLINE"));

        broker.stop();
        QTRY_COMPARE_WITH_TIMEOUT(view.tile("r1")->linkText(), QStringLiteral("broker unreachable"), 5000);
        QVERIFY(view.tile("r1")->statusText() != QStringLiteral("OFFLINE"));
        QVERIFY(!view.tile("r1")->linkText().contains(QStringLiteral("lost")));

        QVERIFY2(broker.start(), qPrintable(broker.error()));
        QTRY_COMPARE_WITH_TIMEOUT(view.tile("r1")->statusText(), QStringLiteral("ONLINE"), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(view.tile("r1")->linkText().startsWith(QStringLiteral("link streaming")), 5000);
        window.close();
    }

    // A broker that is down: the fleet view says so within seconds and what
    // to check; once the broker is up, it connects and says so instead.
    void aBrokerThatIsDownIsSaidSoThenComesUp()
    {
        MosquittoBroker broker; // its port, not started yet
        MainWindow window;
        window.start();
        QVERIFY(window.connectToBroker(*mqtt::BrokerAddress::fromUrl(broker.url(), nullptr)));
        QTRY_VERIFY_WITH_TIMEOUT(window.fleetView()->brokerText().contains(QStringLiteral("No MQTT broker answers")),
                                 5000);
        QVERIFY2(window.fleetView()->brokerText().contains(QStringLiteral("not connected")),
                 qPrintable(window.fleetView()->brokerText()));
        // The long message takes lines, not width: the window stays on the screen.
        const int screenWidth = window.fleetView()->screen()->availableGeometry().width();
        QCoreApplication::processEvents();
        QVERIFY2(window.fleetView()->minimumSizeHint().width() <= screenWidth,
                 qPrintable(QString::number(window.fleetView()->minimumSizeHint().width())));
        QVERIFY2(window.fleetView()->frameGeometry().width() <= screenWidth,
                 qPrintable(QString::number(window.fleetView()->frameGeometry().width())));
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        QTRY_VERIFY_WITH_TIMEOUT(window.fleetView()->brokerText().contains(QStringLiteral("speaking as")), 20000);
        window.close();
    }

    // A bridge that dies is named, not the robot's link: killed while its
    // robot drove (the robot may drive on; its driver was cut off), and
    // killed with the robot standing.
    void aKilledBridgeIsNamedAndItsRobotMayDriveOn()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        FakeBridge r3(QStringLiteral("r3"));
        QVERIFY(r3.start(broker.port()));
        r3.publishState();
        // r1 and r2's bridges: processes of their own, killed as a crash would.
        std::vector<std::unique_ptr<QProcess>> bridgeProcesses;
        const auto bridgeProcess = [&](const QString &name) {
            auto process = std::make_unique<QProcess>();
            process->start("/usr/bin/stdbuf", {"-oL", "/usr/bin/mosquitto_sub", "-d", "-p", QString::number(broker.port()),
                                               "-h", "127.0.0.1", "-t", "x", "--will-topic", "roomba/" + name + "/state",
                                               "--will-payload", QStringLiteral(R"({"online":false,"name":"%1"})").arg(name),
                                               "--will-retain"});
            QByteArray said;
            const bool up = process->waitForStarted()
                            && QTest::qWaitFor([&] { return (said += process->readAllStandardOutput()).contains("CONNACK"); },
                                               5000);
            bridgeProcesses.push_back(std::move(process));
            return up;
        };
        QVERIFY(bridgeProcess("r1"));
        QVERIFY(bridgeProcess("r2"));
        r3.publishRaw("roomba/r1/state", R"({"online":true,"name":"r1","mode":"safe","link":"streaming",)"
                                         R"("battery_percent":80,"controller":"alice","program":"square.py"})", true);
        r3.publishRaw("roomba/r2/state", R"({"online":true,"name":"r2","mode":"safe","link":"streaming","battery_percent":70})",
                      true);
        MainWindow window;
        window.start();
        QSignalSpy said(window.fleetConsole(), &FleetConsole::message);
        QVERIFY(window.connectToBroker(*mqtt::BrokerAddress::fromUrl(broker.url(), nullptr)));
        FleetView &view = *window.fleetView();
        QTRY_VERIFY_WITH_TIMEOUT(view.tile("r1") && view.tile("r2") && view.tile("r3"), 5000);
        // r1 drives at 200 mm/s (packets 39, 41, 42: the drive it was asked for).
        QJsonObject driving = telemetry(0, {});
        for (const char *key : {"requested_velocity", "requested_right_velocity", "requested_left_velocity"})
            driving[key] = 200;
        r3.publishRaw("roomba/r1/telemetry", QJsonDocument(driving).toJson(QJsonDocument::Compact));
        r3.publishRaw("roomba/r2/telemetry", QJsonDocument(telemetry(0, {})).toJson(QJsonDocument::Compact));
        QTRY_COMPARE_WITH_TIMEOUT(view.tile("r1")->controlText(), QStringLiteral("alice's program square.py"), 5000);
        QTRY_VERIFY_WITH_TIMEOUT(window.fleetConsole()->directory().robot("r1")->latest.raw(41) == 200, 5000);

        bridgeProcesses[0]->kill();
        QTRY_COMPARE_WITH_TIMEOUT(view.tile("r1")->statusText(), QStringLiteral("OFFLINE"), 5000);
        const FleetTile &r1 = *view.tile("r1");
        QCOMPARE(r1.modeOnlyText(), QStringLiteral("MAY STILL BE MOVING"));
        QCOMPARE(r1.hazardText(), QStringLiteral("pick it up, switch it off"));
        QVERIFY2(r1.linkText().startsWith(QStringLiteral("bridge offline since ")), qPrintable(r1.linkText()));
        QCOMPARE(r1.controlText(), QStringLiteral("alice's program cut off"));
        QTRY_VERIFY_WITH_TIMEOUT(!said.isEmpty(), 5000);
        const QString r1Said = said.last().at(0).toString();
        QVERIFY2(r1Said.startsWith(QStringLiteral("r1's bridge went offline at "))
                     && r1Said.contains(QStringLiteral("while the robot was driving, cutting off alice's program square.py"))
                     && r1Said.contains(QStringLiteral("A real robot keeps its last drive when its bridge dies: pick it "
                                                       "up and hold its power button to switch it off")),
                 qPrintable(r1Said));
        QVERIFY(r1.toolTip().contains(r1Said));

        bridgeProcesses[1]->kill();
        QTRY_COMPARE_WITH_TIMEOUT(view.tile("r2")->statusText(), QStringLiteral("OFFLINE"), 5000);
        const FleetTile &r2 = *view.tile("r2");
        QVERIFY2(r2.linkText().startsWith(QStringLiteral("bridge offline since ")), qPrintable(r2.linkText()));
        QCOMPARE(r2.controlText(), QStringLiteral("nobody in control"));
        QVERIFY(r2.modeOnlyText() != QStringLiteral("MAY STILL BE MOVING"));
        QTRY_VERIFY_WITH_TIMEOUT(said.last().at(0).toString().startsWith(QStringLiteral("r2's bridge went offline")), 5000);
        QVERIFY2(said.last().at(0).toString().contains(QStringLiteral("(the broker is fine): check the bridge on the "
                                                                      "computer beside the robot")),
                 qPrintable(said.last().at(0).toString()));
        saveShot(view, "fleet_bridges_killed.png");

        window.close();
    }

    // The broker shuts down: the header says so at once, and what to check
    // within seconds; r1's bridge, whose last will the broker sends as it
    // goes, is not called offline.
    void aBrokerShutDownIsNotItsBridgesGone()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        FakeBridge r1(QStringLiteral("r1"));
        QVERIFY(r1.start(broker.port()));
        r1.publishState();
        MainWindow window;
        window.start();
        QSignalSpy said(window.fleetConsole(), &FleetConsole::message);
        QVERIFY(window.connectToBroker(*mqtt::BrokerAddress::fromUrl(broker.url(), nullptr)));
        FleetView &view = *window.fleetView();
        QTRY_VERIFY_WITH_TIMEOUT(view.tile("r1") && view.tile("r1")->values().online, 5000);

        broker.stop();
        QTRY_VERIFY_WITH_TIMEOUT(view.brokerText().contains(QStringLiteral("connection lost at ")), 2000);
        QVERIFY(view.tile("r1")->values().online);
        QTRY_VERIFY_WITH_TIMEOUT(view.brokerText().contains(QStringLiteral("stopped answering at")), 6000);
        QVERIFY2(view.brokerText().contains(QStringLiteral("is it still running (a classroom's, on the teacher's "
                                                           "machine), and is this computer still on its network?")),
                 qPrintable(view.brokerText()));
        QCOMPARE(view.tile("r1")->statusText(), QStringLiteral("NO BROKER"));
        QVERIFY(view.tile("r1")->values().online);
        QCOMPARE(view.tile("r1")->linkText(), QStringLiteral("broker unreachable"));
        for (const QList<QVariant> &args : said)
            QVERIFY2(!args.at(0).toString().contains(QStringLiteral("r1's bridge")), qPrintable(args.at(0).toString()));
        saveShot(view, "fleet_broker_killed.png");
        window.close();
    }

    void aClassroomOnOneBroker()
    {
        MosquittoBroker broker;
        QVERIFY2(broker.start(), qPrintable(broker.error()));
        std::vector<std::unique_ptr<FakeBridge>> bridges;
        for (int i = 1; i <= 12; ++i) {
            bridges.push_back(std::make_unique<FakeBridge>(QStringLiteral("robot-%1").arg(i)));
            FakeBridge &b = *bridges.back();
            QVERIFY(b.start(broker.port()));
            QJsonObject state = b.state(i % 4 == 0 ? "full" : "safe", 95 - 6 * i);
            if (i == 3)
                state["controller"] = "alice";
            if (i >= 11)
                state = {{"online", false}, {"name", b.robot()}};
            b.publishState(state);
        }

        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        window.start();
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        RobotSession *local = window.fleet().selected();
        QVERIFY(window.connectToBroker(*mqtt::BrokerAddress::fromUrl(broker.url(), nullptr)));
        FleetView &view = *window.fleetView();
        QVERIFY(view.isVisible());
        QVERIFY(view.isWindow());
        // The broker's twelve beside the window's own robot.
        QTRY_COMPARE_WITH_TIMEOUT(view.tiles().size(), 13, 5000);
        QVERIFY(view.tile(local->name()));
        QCOMPARE(view.tile(local->name())->values().controller, QString("this window"));

        // Telemetry and stats: one bumped, one at a cliff, every tile live.
        for (const auto &b : bridges) {
            const int n = b->robot().section('-', 1).toInt();
            if (n >= 11)
                continue;
            b->publishTelemetry(telemetry(n == 2 ? 0x02 : 0, n == 5 ? std::initializer_list<int>{9, 10}
                                                                     : std::initializer_list<int>{}));
            b->publishStats({{"frames", 1000 * n}, {"frames_per_second", 66.4}});
        }
        QTRY_VERIFY_WITH_TIMEOUT(view.tile("robot-2")->values().bumpLeft, 5000);
        QTRY_COMPARE_WITH_TIMEOUT(view.tile("robot-5")->values().cliffs, 2, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(view.tile("robot-10")->values().framesPerSecond == 66, 5000);
        for (int i = 1; i <= 10; ++i) {
            const FleetTile *t = view.tile(QStringLiteral("robot-%1").arg(i));
            QVERIFY(t->values().online);
            QVERIFY(t->values().linkHealthy);
        }
        QCOMPARE(view.tile("robot-3")->controlText(), QStringLiteral("driven by alice"));
        QVERIFY(!view.tile("robot-11")->values().online);

        // A bridge that is killed: its tile goes offline (its last will).
        QProcess dying;
        dying.start("/usr/bin/stdbuf", {"-oL", "/usr/bin/mosquitto_sub", "-d", "-p", QString::number(broker.port()), "-h",
                                        "127.0.0.1", "-t", "x", "--will-topic", "roomba/robot-13/state",
                                        "--will-payload", R"({"online":false,"name":"robot-13"})", "--will-retain"});
        QVERIFY(dying.waitForStarted());
        QByteArray said;
        QTRY_VERIFY_WITH_TIMEOUT((said += dying.readAllStandardOutput()).contains("CONNACK"), 5000);
        bridges.front()->publishRaw("roomba/robot-13/state",
                                    R"({"online":true,"name":"robot-13","mode":"passive","link":"streaming","battery_percent":40})",
                                    true);
        QTRY_VERIFY_WITH_TIMEOUT(view.tile("robot-13") && view.tile("robot-13")->values().online, 5000);
        dying.kill();
        dying.waitForFinished();
        QTRY_VERIFY_WITH_TIMEOUT(!view.tile("robot-13")->values().online, 10000);
        QCOMPARE(view.tile("robot-13")->statusText(), QStringLiteral("OFFLINE"));

        QTemporaryDir scratch;
        const QString dir = qEnvironmentVariableIsEmpty("ROOMBA_SCREENSHOTS") ? scratch.path()
                                                                               : qEnvironmentVariable("ROOMBA_SCREENSHOTS");
        QDir().mkpath(dir);
        // Tiles sized to the screen: larger on the larger one, all in view.
        view.resize(1600, 1000);
        QTRY_VERIFY(view.columns() >= 3);
        const qreal smaller = view.tileScale();
        QVERIFY(view.grab().save(QDir(dir).filePath("fleet_1600x1000.png")));
        view.resize(1920, 1080);
        QTRY_VERIFY(view.tileScale() > smaller);
        QVERIFY(view.columns() >= 3);
        QVERIFY(view.grab().save(QDir(dir).filePath("fleet_1920x1080.png")));

        // A click on a tile: that robot joins the window's robots, selected,
        // and the docks show it from its telemetry.
        FakeBridge &one = *bridges.front();
        QTimer stream;
        connect(&stream, &QTimer::timeout, &one, [&one] { one.publishTelemetry(telemetry(0x01, {})); });
        stream.start(15);
        QTest::mouseClick(view.tile("robot-1"), Qt::LeftButton);
        QCOMPARE(window.fleet().count(), 2);
        RobotSession *remote = window.fleet().selected();
        QCOMPARE(remote->settings().transport, oilink::TransportKind::Network);
        QCOMPARE(remote->name(), QStringLiteral("robot-1"));
        QVERIFY(view.tile("robot-1")->isChecked());
        QTRY_VERIFY_WITH_TIMEOUT(remote->isLive() && remote->latest().raw(7) == 0x01, 5000);
        window.refreshDisplay();
        QVERIFY(window.statusText().contains("robot-1"));
        // Its rate is the bridge's messages, which tell only what changed,
        // and a bridge has no checksums of its own to count.
        QTRY_VERIFY_WITH_TIMEOUT(window.statusText().contains("messages/s from the bridge"), 5000);
        QVERIFY(!window.statusText().contains("checksum failures"));
        // A second click finds the same robot.
        QTest::mouseClick(view.tile("robot-1"), Qt::LeftButton);
        QCOMPARE(window.fleet().count(), 2);
        QVERIFY(view.grab().save(QDir(dir).filePath("fleet_selected.png")));
        QVERIFY(window.grab().save(QDir(dir).filePath("dashboard_network_robot.png")));

        // The local robot drives; Stop all stops it and every bridge.
        window.fleet().select(local);
        window.refreshDisplay();
        QVERIFY(window.statusText().contains("frames/s"));
        // A clean line: checksum failures are said once there are any.
        QVERIFY(!window.statusText().contains("checksum failures"));
        MotionCommand forward;
        forward.velocity = 150;
        const oi::EncodeResult safe = oi::CommandEncoder(local->robotProfile()).safe();
        QVERIFY(local->send(commandsOf(QByteArray(reinterpret_cast<const char *>(safe->data()), qsizetype(safe->size())))));
        QTRY_VERIFY_WITH_TIMEOUT(local->latest().raw(35) == 2, 5000);
        local->teleop().requestMotion(forward);
        QTRY_COMPARE_WITH_TIMEOUT(local->latest().raw(39), 150, 5000);
        QTest::mouseClick(window.stopAllButton(), Qt::LeftButton);
        for (const auto &b : bridges) {
            QTRY_VERIFY_WITH_TIMEOUT(!b->receivedOn(mqtt::topics::Kind::StopAll).isEmpty(), 5000);
            QCOMPARE(b->receivedOn(mqtt::topics::Kind::StopAll).first().payload.value("client").toString(),
                     window.fleetConsole()->directory().clientName());
        }
        QTRY_COMPARE_WITH_TIMEOUT(local->latest().raw(39), 0, 5000);
        QVERIFY(!local->teleop().isMoving());
        stream.stop();
    }
};

QTEST_MAIN(TestFleetConsole)
#include "tst_fleet_console.moc"
