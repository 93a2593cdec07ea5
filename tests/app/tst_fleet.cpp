// SPDX-License-Identifier: GPL-3.0-or-later
// Several robots in one window: driving the selected one, Stop all, the
// robot list, and the list kept between runs.
#include "byte_inspector.h"
#include "command_encoder.h"
#include "connection_checkup.h"
#include "connection_next_steps.h"
#include "doctor_details.h"
#include "connection_bar.h"
#include "drive_pad.h"
#include "led_editor.h"
#include "main_window.h"
#include "mode_panel.h"
#include "motors_panel.h"
#include "projector_view.h"
#include "recording_transport.h"
#include "robot_list.h"
#include "saved_robots.h"
#include "transport_factory.h"
#include "sensor_plots.h"
#include "odometry_map.h"
#include "tcp_robot_server.h"
#include "typed_command_bytes.h"

#include <QDockWidget>
#include <QGroupBox>
#include <QLabel>
#include <QRegularExpression>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QTimer>
#include <QApplication>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QSignalSpy>
#include <QTest>
#include <QToolButton>

#include <map>

namespace {

QString toText(const oi::Bytes &b)
{
    return byteText(QByteArray(reinterpret_cast<const char *>(b.data()), qsizetype(b.size())));
}

QStringList texts(const QList<QByteArray> &writes)
{
    QStringList out;
    for (const QByteArray &w : writes)
        out << byteText(w);
    return out;
}

const oi::CommandEncoder &create2()
{
    static const oi::CommandEncoder encoder(oi::profile(oi::ProfileId::Create2));
    return encoder;
}

// A window whose robots stream in Safe mode on recording transports, one per
// port path, so each robot's bytes can be read apart.
struct FleetRig {
    std::map<QString, Recording> recordings;
    MainWindow window;

    FleetRig()
    {
        for (const char *port : {"/dev/robotA", "/dev/robotB", "/dev/robotC"})
            recordings[port].mode = int(oi::OiMode::Safe);
        window.fleet().setTransportFactory([this](const oilink::LinkSettings &s) -> oilink::Transport * {
            if (const auto r = recordings.find(s.portPath); r != recordings.end())
                return new RecordingTransport(&r->second);
            return transports::createTransport(s, oi::profile(oi::ProfileId::Create2).defaultBaud);
        });
        window.resize(1400, 900);
    }
    Recording &of(const char *port) { return recordings.at(port); }
    // Starts with the saved robots A and B.
    void startWithTwo()
    {
        QSettings settings;
        saveRobots(settings, {SavedRobot{"Ada", {}, oilink::LinkSettings::serial("/dev/robotA", oi::ProfileId::Create2), true},
                              SavedRobot{"Bea", {}, oilink::LinkSettings::serial("/dev/robotB", oi::ProfileId::Create2), true}});
        window.show();
        window.activateWindow();
        window.start();
    }
    bool streaming()
    {
        return QTest::qWaitFor([this] {
            for (RobotSession *r : window.fleet().robots())
                if (!r->isLive() || r->latest().oiMode() != oi::OiMode::Safe)
                    return false;
            return true;
        }, 10000);
    }
    RobotSession *robot(int i) { return window.fleet().robots().value(i); }
    // Forgets what both robots were sent, then holds Up on the drive pad.
    void driveUp()
    {
        window.refreshDisplay();
        window.findChild<QDockWidget *>("driveDock")->raise();
        window.dock<DrivePad>()->padArea()->setFocus();
        of("/dev/robotA").take();
        of("/dev/robotB").take();
        QTest::keyPress(window.dock<DrivePad>()->padArea(), Qt::Key_Up);
    }
    // What Up sends: straight ahead at the pad's speed limit.
    QString driveAhead() const
    {
        return toText(*create2().drive(window.dock<DrivePad>()->speedLimit(), oi::kRadiusStraight));
    }
};

// A Roomba 500 on a TCP bridge: the transport cannot say what it is, and
// the probe finds only "a Roomba 500 or a Create 2".
struct Roomba500OnTcp {
    sim::TcpRobotServer server{oi::profile(oi::ProfileId::Roomba500)};
    Roomba500OnTcp() { QVERIFY(server.listen(QHostAddress::LocalHost, 0)); }
    oilink::LinkSettings unnamed() const { return oilink::LinkSettings::tcp("127.0.0.1", server.serverPort()); }
};

// A robot of the window's list with its checkup, answering the question
// as the test says and counting how often it was asked.
struct CheckedRobot {
    RobotSession session;
    DoctorDetails details;
    int asked = 0;
    ConnectionCheckup checkup;
    explicit CheckedRobot(std::optional<oi::ProfileId> answer)
        : checkup(session, details, [this, answer](const QString &) {
              ++asked;
              return answer;
          })
    {
        session.setName("Rosa");
    }
};

// Safe mode, then the right wheel forward and the left back: a turn clockwise.
void turnClockwise(RobotSession &session)
{
    const oi::CommandEncoder encoder(session.robotProfile());
    const auto bytes = [](const oi::Bytes &b) { return QByteArray(reinterpret_cast<const char *>(b.data()), qsizetype(b.size())); };
    session.send(commandsOf(bytes(*encoder.safe())));
    session.send(commandsOf(bytes(*encoder.driveDirect(100, -100))));
}

} // namespace

class TestFleet : public QObject {
    Q_OBJECT
private slots:
    // A port that is not there: the error names the ports there are.
    void noSuchPortListsThePorts()
    {
        MainWindow window;
        window.show();
        window.start(oilink::LinkSettings::serial("/dev/ttyUSB-none"));
        QTRY_VERIFY_WITH_TIMEOUT(window.dock<ConnectionBar>()->errorText().contains("no such port"), 10000);
        const QString said = window.dock<ConnectionBar>()->errorText();
        QVERIFY2(said.contains("The serial ports on this computer: ") || said.contains("No serial port is on this computer"),
                 qPrintable(said));
        window.session().disconnectFromRobot();
    }

    // What the connection check says to do next, by what failed and where.
    void connectionNextStepsNameWhatToCheck()
    {
        using F = oilink::ConnectionDoctor::Finding;
        oilink::ConnectionDoctor::Report silent;
        silent.finding = F::NothingComesBack;
        const QStringList serial = ConnectionNextSteps::forReport(oilink::LinkSettings::serial("/dev/ttyUSB-none"), silent);
        QVERIFY2(serial.join('\n').contains("/dev/ttyUSB-none does not exist")
                     || serial.join('\n').contains("No serial port is on this computer"),
                 qPrintable(serial.join('\n')));
        QVERIFY(serial.last().contains("press Connect"));
        const QStringList tcp = ConnectionNextSteps::forReport(oilink::LinkSettings::tcp("raspberrypi", 3333), silent);
        QVERIFY2(tcp.join('\n').contains("raspberrypi:3333") && tcp.join('\n').contains("ser2net"), qPrintable(tcp.join('\n')));
        oilink::ConnectionDoctor::Report garbled;
        garbled.finding = F::GarbledAtEveryBaud;
        QVERIFY(ConnectionNextSteps::forReport(oilink::LinkSettings::tcp("raspberrypi", 3333), garbled).join('\n').contains("TTL"));
        oilink::ConnectionDoctor::Report healthy;
        healthy.finding = F::Healthy;
        QVERIFY(ConnectionNextSteps::forReport(oilink::LinkSettings::serial("/dev/ttyUSB0"), healthy).isEmpty());
    }

    void init()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void savedRobotsAreRestoredAndConnected()
    {
        FleetRig rig;
        rig.startWithTwo();
        QCOMPARE(rig.window.fleet().count(), 2);
        QCOMPARE(rig.robot(0)->name(), QString("Ada"));
        QCOMPARE(rig.robot(1)->name(), QString("Bea"));
        QVERIFY(rig.robot(0)->colour() != rig.robot(1)->colour());
        QVERIFY(rig.streaming());
        QCOMPARE(rig.window.fleet().selected(), rig.robot(0));
        QCOMPARE(rig.window.robotList()->count(), 2);
        QVERIFY(rig.window.robotList()->card(0)->isChecked());
        QVERIFY(rig.window.statusText().contains("Ada"));
    }

    // The selected robot connects first; the others once its first frame
    // is on screen, so they do not hold up that picture.
    void theOthersConnectAfterTheSelectedRobotsFirstFrame()
    {
        FleetRig rig;
        rig.startWithTwo();
        QVERIFY(rig.robot(0)->isConnected());
        QVERIFY(!rig.robot(1)->isConnected());
        QVERIFY(rig.window.fleet().hasRobotsWaiting());
        // What the first robot had shown when the second one connected.
        quint64 framesShown = 0;
        QObject context;
        connect(rig.robot(1), &RobotSession::stateChanged, &context, [&](oilink::LinkState state) {
            if (state != oilink::LinkState::Closed && framesShown == 0)
                framesShown = rig.robot(0)->snapshotCount();
        });
        QTRY_VERIFY_WITH_TIMEOUT(rig.robot(1)->isConnected(), 10000);
        QVERIFY(!rig.window.fleet().hasRobotsWaiting());
        QVERIFY(rig.streaming());
        QVERIFY(framesShown > 0);
    }

    // The keys drive the selected robot only; Stop all (Shift+Esc, or the
    // button) stops both. Exact bytes on both transports: the other robot
    // gets nothing but the stop.
    void drivingTheSelectedRobotLeavesTheOtherStill()
    {
        FleetRig rig;
        rig.startWithTwo();
        QVERIFY(rig.streaming());
        QVERIFY(QTest::qWaitForWindowActive(&rig.window));
        rig.driveUp();

        QTRY_VERIFY_WITH_TIMEOUT(rig.of("/dev/robotA").count() >= 1, 5000);
        QCOMPARE(texts(rig.of("/dev/robotA").take()), QStringList{rig.driveAhead()});

        QTest::keyClick(rig.window.dock<DrivePad>()->padArea(), Qt::Key_Escape, Qt::ShiftModifier);
        const QString stop = toText(create2().stopMotion());
        QTRY_VERIFY_WITH_TIMEOUT(rig.of("/dev/robotB").count() >= 1, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(rig.of("/dev/robotA").count() >= 1, 5000);
        QCOMPARE(texts(rig.of("/dev/robotB").take()), QStringList{stop});
        QCOMPARE(texts(rig.of("/dev/robotA").take()), QStringList{stop});
        QTest::keyRelease(rig.window.dock<DrivePad>()->padArea(), Qt::Key_Up);

        // The button does the same, with nothing moving.
        QTest::mouseClick(rig.window.stopAllButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(rig.of("/dev/robotA").count() >= 1 && rig.of("/dev/robotB").count() >= 1, 5000);
        QCOMPARE(texts(rig.of("/dev/robotA").take()), QStringList{stop});
        QCOMPARE(texts(rig.of("/dev/robotB").take()), QStringList{stop});
    }

    void selectingARobotSwitchesEveryDock()
    {
        FleetRig rig;
        rig.startWithTwo();
        QVERIFY(rig.streaming());
        QVERIFY(QTest::qWaitForWindowActive(&rig.window));
        QTest::mouseClick(rig.window.robotList()->card(1), Qt::LeftButton);
        QCOMPARE(rig.window.fleet().selected(), rig.robot(1));
        QVERIFY(rig.window.statusText().contains("Bea"));
        // Named once, above the docks; their tabs keep their short titles.
        QVERIFY(rig.window.findChild<QDockWidget *>("connectionDock")->windowTitle().contains("Bea"));
        QCOMPARE(rig.window.findChild<QDockWidget *>("driveDock")->windowTitle(), QString("Drive"));
        QCOMPARE(rig.window.dock<SensorPlots>()->history(), &rig.robot(1)->history());
        // The map draws the selected robot's path in its colour in the list.
        QCOMPARE(rig.window.dock<OdometryMap>()->odometryColour(), rig.robot(1)->colour());
        QVERIFY(rig.robot(0)->colour() != rig.robot(1)->colour());
        // The inspector shows the selected robot's own recent bytes.
        const RecentBytes &recent = rig.robot(1)->recentBytes();
        QVERIFY(recent.size() > 0);
        QCOMPARE(qint64(rig.window.dock<ByteInspector>()->txBytes() + rig.window.dock<ByteInspector>()->rxBytes()),
                 qint64(recent.size()));
        // The robot nobody looks at keeps a lighter history.
        QVERIFY(!rig.robot(1)->history().isReducedRate());
        QVERIFY(rig.robot(0)->history().isReducedRate());

        rig.driveUp();
        QTRY_VERIFY_WITH_TIMEOUT(rig.of("/dev/robotB").count() >= 1, 5000);
        QCOMPARE(texts(rig.of("/dev/robotB").take()), QStringList{rig.driveAhead()});

        // Switching while driving stops the robot left behind; then Stop all
        // proves nothing else reached the first robot.
        QTest::mouseClick(rig.window.robotList()->card(0), Qt::LeftButton);
        QCOMPARE(rig.window.fleet().selected(), rig.robot(0));
        QTRY_VERIFY_WITH_TIMEOUT(rig.of("/dev/robotB").count() >= 1, 5000);
        const QString stop = toText(create2().stopMotion());
        QCOMPARE(texts(rig.of("/dev/robotB").take()), QStringList{stop});
        rig.window.fleet().stopAll();
        QTRY_VERIFY_WITH_TIMEOUT(rig.of("/dev/robotA").count() >= 1, 5000);
        QCOMPARE(texts(rig.of("/dev/robotA").take()), QStringList{stop});
    }

    void addRenameAndRemoveAreKept()
    {
        {
            FleetRig rig;
            rig.window.show();
            rig.window.start(); // first start: one virtual robot
            QCOMPARE(rig.window.fleet().count(), 1);
            QCOMPARE(rig.robot(0)->settings().transport, oilink::TransportKind::Virtual);
            rig.window.robotList()->addMenu()->actions().at(0)->trigger(); // Virtual robot
            QCOMPARE(rig.window.fleet().count(), 2);
            QCOMPARE(rig.window.fleet().selected(), rig.robot(1));
            QTRY_VERIFY_WITH_TIMEOUT(rig.robot(1)->isLive(), 10000);

            rig.window.robotList()->beginRename(1);
            QLineEdit *editor = rig.window.robotList()->renameEditor();
            QVERIFY(editor->isVisible());
            editor->setText("Table 4");
            QTest::keyClick(editor, Qt::Key_Return);
            QCOMPARE(rig.robot(1)->name(), QString("Table 4"));
            QTRY_COMPARE(rig.window.robotList()->card(1)->values().name, QString("Table 4"));
            rig.window.close();
        }
        {
            FleetRig rig;
            rig.window.show();
            rig.window.start();
            QCOMPARE(rig.window.fleet().count(), 2);
            QCOMPARE(rig.robot(1)->name(), QString("Table 4"));
            QCOMPARE(rig.robot(1)->settings().transport, oilink::TransportKind::Virtual);
            QVERIFY(rig.robot(0)->settings().virtualSeed != rig.robot(1)->settings().virtualSeed);
            rig.window.close();
        }
    }

    void removingARobotLeavesItStoppedInPassive()
    {
        FleetRig rig;
        rig.startWithTwo();
        QVERIFY(rig.streaming());
        QTest::mouseClick(rig.window.robotList()->card(1), Qt::LeftButton);
        rig.of("/dev/robotB").take();
        QTest::mouseClick(rig.window.robotList()->removeButton(), Qt::LeftButton);
        QCOMPARE(rig.window.fleet().count(), 1);
        QCOMPARE(rig.window.fleet().selected(), rig.robot(0));
        const QStringList writes = texts(rig.of("/dev/robotB").take());
        QVERIFY(!writes.isEmpty());
        QCOMPARE(writes.last(), toText(create2().shutdownSequence()));
        // The last robot stays.
        QVERIFY(!rig.window.robotList()->removeButton()->isEnabled());
    }

    // --sim 3: three virtual robots, each its own seed and colour.
    void threeVirtualRobots()
    {
        MainWindow window;
        window.resize(1600, 1000);
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, std::nullopt), 3);
        QCOMPARE(window.fleet().count(), 3);
        QTRY_VERIFY_WITH_TIMEOUT(window.fleet().robots()[0]->isLive() && window.fleet().robots()[1]->isLive()
                                     && window.fleet().robots()[2]->isLive(),
                                 10000);
        QSet<QString> names;
        QSet<std::uint32_t> seeds;
        for (RobotSession *r : window.fleet().robots()) {
            names << r->name();
            seeds << r->settings().virtualSeed;
        }
        QCOMPARE(names.size(), 3);
        QCOMPARE(seeds.size(), 3);
        // Not kept: the command line chose them for this run.
        window.close();
        QCOMPARE(loadSavedRobots(*std::make_unique<QSettings>()).size(), 0);
    }

    // A robot's mode and why it changed travel with it: a cliff drop on
    // robot 1 is said on robot 1's drive pad, modes and projector view, never
    // on robot 2's; Enter Safe in the projector view sends Safe to robot 1.
    void aModeReasonTravelsWithItsRobot()
    {
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2), 2);
        RobotSession *one = window.fleet().robots()[0];
        RobotSession *two = window.fleet().robots()[1];
        QTRY_VERIFY_WITH_TIMEOUT(one->isLive() && two->isLive(), 10000);
        const auto modeOf = [](RobotSession *r) { return r->mode().reported(); };
        QTRY_VERIFY_WITH_TIMEOUT(modeOf(one) == oi::OiMode::Passive, 5000);
        QVERIFY(two->requestMode(oi::Command::Safe));
        QTRY_VERIFY_WITH_TIMEOUT(modeOf(two) == oi::OiMode::Safe, 5000);
        const auto modeLabel = [&window] { return window.dock<ModePanel>()->findChild<QLabel *>("modeLabel")->text(); };
        const auto show = [&window](RobotSession *r) {
            window.fleet().select(r);
            window.refreshDisplay();
        };

        // The Motors and LEDs docks follow the selected robot's mode: what
        // a robot in Passive ignores is disabled with the reason.
        // Their panes are made when the docks are first shown.
        window.findChild<QDockWidget *>("motorsDock")->raise();
        window.findChild<QDockWidget *>("ledsDock")->raise();
        QTRY_VERIFY(window.findChild<MotorsPanel *>() && window.findChild<LedEditor *>());
        auto *vacuum = window.findChild<MotorsPanel *>()->findChild<QGroupBox *>("motorsGroup");
        auto *applyLeds = window.findChild<LedEditor *>()->findChild<QPushButton *>("apply");

        // A Safe robot, then a Passive one that never moved: its own mode, no reason.
        show(two);
        QCOMPARE(modeLabel(), QString("Mode: Safe"));
        QVERIFY(vacuum->isEnabled());
        QVERIFY(!applyLeds->toolTip().contains("Enter Safe first"));
        show(one);
        QCOMPARE(modeLabel(), QString("Mode: Passive"));
        QCOMPARE(window.dock<ModePanel>()->safetyMessage(), QString());
        QCOMPARE(window.dock<DrivePad>()->passiveText(), QString("Passive mode: enter Safe to drive"));
        QVERIFY(!vacuum->isEnabled());
        QVERIFY2(vacuum->toolTip().endsWith("Enter Safe first."), qPrintable(vacuum->toolTip()));
        QVERIFY2(applyLeds->toolTip().endsWith("Enter Safe first."), qPrintable(applyLeds->toolTip()));

        // Robot 1 in Safe, driven by bytes at the stage edge: a cliff drops it to Passive.
        window.room()->moveRobot(window.roomRobot(), {2600, -300, -M_PI / 2, 0});
        QVERIFY(one->requestMode(oi::Command::Safe));
        QTRY_VERIFY_WITH_TIMEOUT(modeOf(one) == oi::OiMode::Safe, 5000);
        const oi::EncodeResult drive = oi::CommandEncoder(one->robotProfile()).drive(100, oi::kRadiusStraight);
        QVERIFY(one->send(commandsOf(QByteArray(reinterpret_cast<const char *>(drive->data()), qsizetype(drive->size())))));
        QTRY_VERIFY_WITH_TIMEOUT(modeOf(one) == oi::OiMode::Passive, 10000);
        window.refreshDisplay();
        QVERIFY2(one->mode().reason().contains(QRegularExpression("^A cliff \\(.+\\) dropped it to Passive at "
                                                                 "\\d\\d:\\d\\d:\\d\\d\\.$")),
                 qPrintable(one->mode().reason()));
        // Stopped half over the edge, the signal reads like a dark rug's: at a
        // real edge the only advice, on every view, is to carry it back.
        QVERIFY2(one->mode().nextStep().startsWith("Carry it back from the edge, then Enter Safe."),
                 qPrintable(one->mode().nextStep()));
        const QString why = one->mode().reason() + ' ' + one->mode().nextStep();
        QVERIFY2(!why.contains("Full"), qPrintable(why));
        QVERIFY2(!window.statusText().contains("Full"), qPrintable(window.statusText()));
        QCOMPARE(window.dock<ModePanel>()->safetyMessage(), why);
        QCOMPARE(modeLabel(), QString("Mode: Passive"));
        QCOMPARE(window.dock<DrivePad>()->passiveText(), why);
        QVERIFY(window.dock<DrivePad>()->findChild<QPushButton *>("enterSafe")->isVisibleTo(window.dock<DrivePad>()));
        QCOMPARE(window.projectorView()->reasonText(), why);
        QVERIFY(window.projectorView()->headerText().contains("Passive"));
        QVERIFY2(window.statusText().contains(why), qPrintable(window.statusText()));
        // Each robot's card, its own mode, with why in a few words.
        QVERIFY2(window.robotList()->card(0)->values().mode.startsWith("Passive: cliff ("),
                 qPrintable(window.robotList()->card(0)->values().mode));
        QCOMPARE(window.robotList()->card(1)->values().mode, QString("Safe"));

        // Robot 2 shows its own: Safe, nothing to explain.
        show(two);
        QCOMPARE(modeLabel(), QString("Mode: Safe"));
        QCOMPARE(window.dock<ModePanel>()->safetyMessage(), QString());
        QCOMPARE(window.dock<DrivePad>()->passiveText(), QString());
        QCOMPARE(window.projectorView()->reasonText(), QString());
        QVERIFY(window.projectorView()->headerText().contains("Safe"));
        QVERIFY(!window.statusText().contains(why));

        // Back to robot 1, in the projector view: Enter Safe sends Safe (131) to it alone.
        show(one);
        window.setProjectorView(true);
        window.refreshDisplay();
        QSignalSpy sentOne(one, &RobotSession::bytesSent);
        QSignalSpy sentTwo(two, &RobotSession::bytesSent);
        const auto sentSafe = [](const QSignalSpy &spy) {
            return std::any_of(spy.cbegin(), spy.cend(),
                               [](const QList<QVariant> &s) { return s.first().toByteArray() == QByteArray(1, char(131)); });
        };
        QPushButton *enterSafe = window.projectorView()->enterSafeButton();
        QVERIFY(enterSafe->isVisible());
        // The Enter key: Safe again, nothing left to explain in it.
        QTest::keyClick(window.projectorView(), Qt::Key_Return);
        QTRY_VERIFY_WITH_TIMEOUT(sentSafe(sentOne), 5000);
        QCOMPARE(one->mode().lastAsked(), std::optional(oi::Command::Safe));
        QTRY_VERIFY_WITH_TIMEOUT(modeOf(one) == oi::OiMode::Safe, 5000);
        window.refreshDisplay();
        QCOMPARE(window.projectorView()->reasonText(), QString());
        QVERIFY(!enterSafe->isVisible());
        // Passive on purpose is said so; the button sends Safe.
        QVERIFY(one->requestMode(oi::Command::Start));
        QTRY_VERIFY_WITH_TIMEOUT(modeOf(one) == oi::OiMode::Passive, 5000);
        window.refreshDisplay();
        QVERIFY2(window.projectorView()->reasonText().startsWith("You asked for Passive at "),
                 qPrintable(window.projectorView()->reasonText()));
        sentOne.clear();
        QTest::mouseClick(enterSafe, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(sentSafe(sentOne), 5000);
        QVERIFY(!sentSafe(sentTwo));
        window.setProjectorView(false);
    }

    // Until someone says which robot it is, its odometry integrates nothing
    // and the map says why; named, it is read as a Roomba 500.
    void anUnnamedRoomba500IsNotIdentified()
    {
        Roomba500OnTcp robot;
        CheckedRobot unanswered(std::nullopt);
        OdometryMap map;
        map.setOdometry(&unanswered.session.odometry());
        unanswered.session.connectTo(robot.unnamed());
        QTRY_COMPARE(unanswered.asked, 1);
        QTRY_VERIFY(unanswered.session.isLive());
        QVERIFY(!unanswered.session.isIdentified());
        QVERIFY(!unanswered.session.odometry().isIdentified());
        turnClockwise(unanswered.session);
        QTRY_VERIFY(unanswered.session.latest().raw(43) != 0);
        QCOMPARE(unanswered.session.odometry().trail().size(), 1);
        QVERIFY(map.poseText().contains("not yet identified"));
        QVERIFY(map.spokenPose().contains("not yet identified"));

        unanswered.session.identifyAs(oi::ProfileId::Roomba500);
        QTRY_COMPARE(unanswered.session.robotProfile().id, oi::ProfileId::Roomba500);
        QVERIFY(unanswered.session.isIdentified());
        QVERIFY(unanswered.session.odometry().isIdentified());
        QVERIFY(map.poseText().startsWith("x "));
        QCOMPARE(unanswered.asked, 1);
    }

    // Asked once, kept for the bridge: a new session (as after a restart,
    // reading the same settings) is not asked, and reads the encoders the
    // Roomba 500's way, so right-forward, left-back turns clockwise.
    void aRoomba500IsAskedAboutOnceAndRemembered()
    {
        Roomba500OnTcp robot;
        {
            CheckedRobot first(oi::ProfileId::Roomba500);
            first.session.connectTo(robot.unnamed());
            QTRY_COMPARE(first.session.robotProfile().id, oi::ProfileId::Roomba500);
            QCOMPARE(first.asked, 1);
            QCOMPARE(first.session.settings().profile, oi::ProfileId::Roomba500);
            QTRY_VERIFY(first.session.isLive());
        }
        CheckedRobot again(oi::ProfileId::Create2);
        again.session.connectTo(robot.unnamed());
        QTRY_COMPARE(again.session.robotProfile().id, oi::ProfileId::Roomba500);
        QTRY_VERIFY(again.session.isLive());
        QVERIFY(again.session.isIdentified());
        QCOMPARE(again.asked, 0);
        turnClockwise(again.session);
        // Counter-clockwise is positive: clockwise goes below zero.
        QTRY_VERIFY_WITH_TIMEOUT(again.session.odometry().pose().thetaRad < -0.3, 10000);
    }

    // The check runs on the port the session holds, through its link: the
    // session is never closed for it, the steps and the finding are shown,
    // and the robot streams again.
    void theCheckRunsThroughTheSessionsLink()
    {
        Roomba500OnTcp robot;
        CheckedRobot rosa(oi::ProfileId::Roomba500);
        oilink::LinkSettings settings = robot.unnamed();
        settings.profile = oi::ProfileId::Roomba500;
        rosa.session.connectTo(settings);
        QTRY_VERIFY(rosa.session.isLive());
        QSignalSpy finished(&rosa.checkup, &ConnectionCheckup::finished);
        QSignalSpy steps(&rosa.session, &RobotSession::connectionCheckStep);
        QSignalSpy states(&rosa.session, &RobotSession::stateChanged);
        rosa.checkup.run();
        QVERIFY(rosa.checkup.isRunning());
        QTRY_COMPARE_WITH_TIMEOUT(finished.size(), 1, 10000);
        const auto report = finished.first().first().value<oilink::ConnectionDoctor::Report>();
        QVERIFY2(report.finding == oilink::ConnectionDoctor::Finding::Healthy, qPrintable(report.summary));
        QCOMPARE(steps.size(), report.steps.size());
        QTRY_VERIFY(rosa.session.isLive());
        QCOMPARE(rosa.session.state(), oilink::LinkState::Streaming);
        for (const QList<QVariant> &s : states)
            QVERIFY(s.first().value<oilink::LinkState>() != oilink::LinkState::Closed);
        QCOMPARE(rosa.session.settings(), settings);
    }

    // The window asks with a dialog that says what the two robots are and
    // what the choice decides; the answer is the saved robot's profile.
    void theWindowAsksWhichRobotItIs()
    {
        Roomba500OnTcp robot;
        QSettings settings;
        saveRobots(settings, {SavedRobot{"Rosa", {}, robot.unnamed(), true}});
        MainWindow window;
        window.show();
        QString asked, cardWhileAsked, statusWhileAsked;
        bool enterChoseOne = true;
        QTimer answer;
        answer.setInterval(20);
        connect(&answer, &QTimer::timeout, &window, [&] {
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            if (!box)
                return;
            asked = box->text();
            cardWhileAsked = window.robotList()->card(0)->values().profile;
            statusWhileAsked = window.statusText();
            // Enter is no answer: a guess would mirror every turn.
            QTest::keyClick(box, Qt::Key_Return);
            enterChoseOne = box->clickedButton() != nullptr;
            for (QAbstractButton *button : box->buttons())
                if (button->text() == QLatin1String("Roomba 500"))
                    button->click();
        });
        answer.start();
        window.start();
        QTRY_VERIFY_WITH_TIMEOUT(!asked.isEmpty(), 10000);
        QVERIFY2(asked.contains("Rosa on 127.0.0.1:") && asked.contains("Create 2") && asked.contains("wheel counts"),
                 qPrintable(asked));
        QVERIFY2(cardWhileAsked.contains("not yet identified"), qPrintable(cardWhileAsked));
        QVERIFY2(statusWhileAsked.contains("not yet identified"), qPrintable(statusWhileAsked));
        QVERIFY(!enterChoseOne);
        RobotSession *rosa = window.fleet().robots().first();
        QTRY_COMPARE(rosa->robotProfile().id, oi::ProfileId::Roomba500);
        QVERIFY(rosa->isIdentified());
        QCOMPARE(window.fleet().saved().first().link.profile, oi::ProfileId::Roomba500);
        QTRY_COMPARE(window.robotList()->card(0)->values().profile, QString("Roomba 500"));
        QTRY_VERIFY2(window.statusText().contains("Roomba 500") && !window.statusText().contains("identified"),
                     qPrintable(window.statusText()));
    }
};

QTEST_MAIN(TestFleet)
#include "tst_fleet.moc"
