// SPDX-License-Identifier: GPL-3.0-or-later
// Driving from the window: the drive pad and the keys down to the exact
// bytes, the stops (release, focus, stale data, Passive mode, Stop All) and
// the rate limit; the sending rules alone on a clock the test advances.
#include "byte_inspector.h"
#include "drive_pad.h"
#include "keyboard_driving.h"
#include "main_window.h"
#include "manual_clock.h"
#include "projector_view.h"
#include "recording_transport.h"
#include "robot_link.h"
#include "robot_mode.h"
#include "plot_stack.h"
#include "sensor_plots.h"
#include "teleop_controller.h"
#include "sent_before_barrier.h"

#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTest>

#include <cmath>
#include <utility>

namespace {

const QString kStop = QStringLiteral("137 0 0 0 0 138 0"); // Create 2: Drive 0,0, motors off

QString driveBytes(int velocity, int radius)
{
    const auto v = quint16(qint16(velocity));
    const auto r = quint16(radius == oi::kRadiusStraight ? 0x8000 : quint16(qint16(radius)));
    return QString("137 %1 %2 %3 %4").arg(v >> 8).arg(v & 0xFF).arg(r >> 8).arg(r & 0xFF);
}

// What the pad's Drive mapping asks for at a knob position, worked out here
// from the rules: speed is the distance times the limit; within 10 degrees
// of ahead or behind is straight, within 10 degrees of the sides turns in
// place, and between the radius falls from 2000 mm to 40 mm.
QString expectedDrive(QPointF k, int limit = DrivePad::kDefaultSpeedLimit)
{
    const int speed = int(std::lround(limit * std::min(1.0, std::hypot(k.x(), k.y()))));
    const double angle = std::abs(std::atan2(k.x(), k.y())) * 180.0 / M_PI;
    if (angle <= 10)
        return driveBytes(speed, oi::kRadiusStraight);
    if (angle >= 170)
        return driveBytes(-speed, oi::kRadiusStraight);
    if (std::abs(angle - 90) <= 10)
        return driveBytes(speed, k.x() > 0 ? -1 : 1);
    const bool forward = angle < 90;
    const double t = ((forward ? angle : 180 - angle) - 10) / 70;
    const int radius = int(std::lround(2000 * std::pow(40.0 / 2000.0, t)));
    return driveBytes(forward ? speed : -speed, k.x() < 0 ? radius : -radius);
}

// The window on a recording transport, streaming in the given mode, active;
// the link's timed rules on `linkClock` when given.
struct Rig {
    Recording recording;
    MainWindow window;
    ManualClock *m_linkClock = nullptr;

    explicit Rig(oi::OiMode mode = oi::OiMode::Safe, ManualClock *linkClock = nullptr)
    {
        recording.mode = int(mode);
        m_linkClock = linkClock;
        if (linkClock)
            window.fleet().setLinkClock(*linkClock);
        window.fleet().setTransportFactory(
            [this](const oilink::LinkSettings &) { return new RecordingTransport(&recording); });
        window.resize(1280, 860);
        window.show();
        window.activateWindow();
        window.start(oilink::LinkSettings::serial("/dev/recording", oi::ProfileId::Create2));
    }
    bool ready()
    {
        if (!QTest::qWaitForWindowActive(&window))
            return false;
        // On the link's clock, the link waits for what its first Starts bring back.
        const bool streaming = QTest::qWaitFor(
            [this] {
                if (m_linkClock && window.session().state() != oilink::LinkState::Streaming)
                    m_linkClock->advance(1);
                return window.session().state() == oilink::LinkState::Streaming
                       && int(window.session().latest().oiMode()) == recording.mode;
            }, 10000);
        window.refreshDisplay();
        window.findChild<QDockWidget *>("driveDock")->raise();
        if (!QTest::qWaitFor([this] { return area()->isVisible(); }, 2000))
            return false;
        pad()->padArea()->setFocus();
        if (!pad()->isPassive() && QApplication::focusWidget() != area())
            return false;
        recording.take(); // Start and the stream request
        return streaming;
    }
    DrivePad *pad() const { return window.dock<DrivePad>(); }
    QWidget *area() const { return window.dock<DrivePad>()->padArea(); }
    QPoint at(QPointF knob) const { return pad()->areaPointFor(knob); }
    QPointF knobAt(QPointF knob) const { return pad()->knobAt(at(knob)); }
    // Waits for exactly one more write and returns it, with anything else
    // written before the barrier (see nothingMore()).
    QString next()
    {
        if (!QTest::qWaitFor([this] { return recording.count() >= 1; }, 5000))
            return QStringLiteral("(nothing written)");
        QStringList out;
        for (const QByteArray &w : sentSoFar())
            out << byteText(w);
        return out.join(" | ");
    }
    // True when nothing more was sent: no command waits on the teleop's
    // timer, and a marker sent now through the same queue to the link is the
    // first thing the robot's side sees.
    bool nothingMore()
    {
        return !window.teleop().hasPendingMotion() && sentSoFar().isEmpty();
    }
    // Everything written before a marker sent now, in order; the marker is
    // not among them.
    QList<QByteArray> sentSoFar()
    {
        const QByteArray &marker = barrierBytes();
        window.session().send(barrierCommand());
        QList<QByteArray> writes;
        const bool seen = QTest::qWaitFor([&] {
            writes += recording.take();
            return writes.contains(marker);
        }, 5000);
        if (!seen)
            return {QByteArray("(no barrier)")};
        writes.resize(writes.indexOf(marker));
        return writes;
    }
};

// What the sending rules drive, without a window or a link: a Create 2 in
// the given mode, streaming, and every write kept.
struct RobotOnTheBench : DriveTarget {
    oi::SensorSnapshot frame;
    oilink::LinkState linkState = oilink::LinkState::Streaming;
    QStringList sent;

    RobotMode robotMode;

    explicit RobotOnTheBench(oi::OiMode mode = oi::OiMode::Safe)
    {
        frame.set(35, int(mode));
        robotMode.observe(frame, QDateTime::currentMSecsSinceEpoch());
    }
    const oi::RobotProfile &robotProfile() const override { return oi::profile(oi::ProfileId::Create2); }
    const oi::SensorSnapshot &latest() const override { return frame; }
    const RobotMode &mode() const override { return robotMode; }
    oilink::LinkState state() const override { return linkState; }
    // The commands as the link would encode them.
    bool sendMotion(const std::vector<oi::OiCommand> &commands) override
    {
        sent << byteText(bytesOfCommands(robotProfile(), commands));
        return true;
    }
    QStringList take() { return std::exchange(sent, {}); }
};

MotionCommand ahead(int velocity) { return MotionCommand{MotionCommand::Kind::Drive, velocity}; }

} // namespace

class TestTeleop : public QObject {
    Q_OBJECT
private slots:
    void init()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    // At most one drive every 15 ms, the latest request winning; nothing
    // when nothing changed; a stop at once, whatever the limit.
    void rateLimitOnTheClock()
    {
        ManualClock clock;
        RobotOnTheBench robot;
        TeleopController teleop(robot, clock);
        teleop.requestMotion(ahead(100));
        QCOMPARE(robot.take(), QStringList{driveBytes(100, oi::kRadiusStraight)});
        teleop.requestMotion(ahead(120));
        clock.advance(5);
        teleop.requestMotion(ahead(140));
        QVERIFY(teleop.hasPendingMotion());
        clock.advance(TeleopController::kMinIntervalMs - 5 - 1);
        QCOMPARE(robot.take(), QStringList());
        clock.advance(1);
        QCOMPARE(robot.take(), QStringList{driveBytes(140, oi::kRadiusStraight)});
        QVERIFY(!teleop.hasPendingMotion());

        // The same command again, later: nothing to send.
        clock.advance(100);
        teleop.requestMotion(ahead(140));
        QCOMPARE(robot.take(), QStringList());
        // A change after a long pause goes at once.
        teleop.requestMotion(ahead(160));
        QCOMPARE(robot.take(), QStringList{driveBytes(160, oi::kRadiusStraight)});
        // A stop right after a drive goes at once too.
        clock.advance(1);
        teleop.requestMotion(MotionCommand::stop());
        QCOMPARE(robot.take(), QStringList{kStop});
    }

    // Letting go of the dead-man stops at once, and a command still
    // waiting on the rate limit never goes out after the stop.
    void deadManReleaseDropsTheWaitingCommand()
    {
        ManualClock clock;
        RobotOnTheBench robot;
        TeleopController teleop(robot, clock);
        QSignalSpy stopped(&teleop, &TeleopController::motionStopped);
        teleop.requestMotion(ahead(100));
        teleop.requestMotion(ahead(200));
        QVERIFY(teleop.hasPendingMotion());
        robot.take();
        teleop.deadManReleased();
        QCOMPARE(robot.take(), QStringList{kStop});
        QCOMPARE(stopped.size(), 1);
        QVERIFY(!teleop.hasPendingMotion());
        clock.advance(1000);
        QCOMPARE(robot.take(), QStringList());
        QVERIFY(!teleop.isMoving());
    }

    // Stale data or a lost link stops the motion; nothing moves again until
    // the data flows.
    void staleOrLostLinkStops_data()
    {
        QTest::addColumn<oilink::LinkState>("state");
        QTest::newRow("stale") << oilink::LinkState::Stale;
        QTest::newRow("lost") << oilink::LinkState::Lost;
    }
    void staleOrLostLinkStops()
    {
        QFETCH(oilink::LinkState, state);
        ManualClock clock;
        RobotOnTheBench robot;
        TeleopController teleop(robot, clock);
        teleop.requestMotion(ahead(100));
        robot.take();
        robot.linkState = state;
        teleop.linkStateChanged(state);
        QCOMPARE(robot.take(), QStringList{kStop});
        clock.advance(100);
        teleop.requestMotion(ahead(100));
        clock.advance(100);
        QCOMPARE(robot.take(), QStringList());
        robot.linkState = oilink::LinkState::Streaming;
        teleop.linkStateChanged(oilink::LinkState::Streaming);
        teleop.requestMotion(ahead(100));
        QCOMPARE(robot.take(), QStringList{driveBytes(100, oi::kRadiusStraight)});
    }

    void padDragSendsExactDriveBytes()
    {
        Rig rig;
        QVERIFY(rig.ready());
        QCOMPARE(rig.pad()->currentCommand(), MotionCommand::stop());

        // Half way up: straight ahead at half the default 200 mm/s.
        QTest::mousePress(rig.area(), Qt::LeftButton, {}, rig.at({0, 0.5}));
        const QString ahead = expectedDrive(rig.knobAt({0, 0.5}));
        QVERIFY2(ahead.startsWith("137 0 100 128 0") || ahead.startsWith("137 0 99 128 0")
                     || ahead.startsWith("137 0 101 128 0"), qPrintable(ahead));
        QCOMPARE(rig.next(), ahead);
        QVERIFY(rig.pad()->currentCommand().velocity > 0);

        // Up and to the right: an arc to the right (a negative radius).
        QTest::mouseMove(rig.area(), rig.at({0.5, 0.5}));
        QCOMPARE(rig.next(), expectedDrive(rig.knobAt({0.5, 0.5})));
        QVERIFY(rig.pad()->currentCommand().radius < 0);

        // Right on the horizontal axis: turn in place, clockwise (ERRATA 14).
        QTest::mouseMove(rig.area(), rig.at({0.6, 0}));
        QCOMPARE(rig.next(), expectedDrive(rig.knobAt({0.6, 0})));
        QCOMPARE(rig.pad()->currentCommand().radius, oi::kRadiusTurnInPlaceClockwise);

        // Down and left: backwards on an arc.
        QTest::mouseMove(rig.area(), rig.at({-0.4, -0.7}));
        QCOMPARE(rig.next(), expectedDrive(rig.knobAt({-0.4, -0.7})));
        QVERIFY(rig.pad()->currentCommand().velocity < 0);

        // Beyond the rim: full speed limit.
        QTest::mouseMove(rig.area(), rig.at({0, 1.0}) - QPoint(0, 40));
        QCOMPARE(rig.next(), driveBytes(200, oi::kRadiusStraight));

        // The dead zone in the middle stops, and so does letting go.
        QTest::mouseMove(rig.area(), rig.at({0.02, 0.02}));
        QCOMPARE(rig.next(), kStop);
        QTest::mouseMove(rig.area(), rig.at({0, 0.5}));
        QCOMPARE(rig.next(), ahead);
        QTest::mouseRelease(rig.area(), Qt::LeftButton, {}, rig.at({0, 0.5}));
        QCOMPARE(rig.next(), kStop);
        QCOMPARE(rig.pad()->knob(), QPointF());
        QCOMPARE(rig.pad()->currentCommand(), MotionCommand::stop());
    }

    void padMappingsPerWheel()
    {
        Rig rig;
        QVERIFY(rig.ready());
        rig.pad()->setMapping(DrivePad::Mapping::DriveDirect);
        rig.pad()->setSpeedLimit(300);
        // Straight ahead at 0.5: both wheels at 150 mm/s (145, right then left).
        QTest::mousePress(rig.area(), Qt::LeftButton, {}, rig.at({0, 0.5}));
        QPointF k = rig.knobAt({0, 0.5});
        int right = int(std::lround(300 * (k.y() - k.x())));
        int left = int(std::lround(300 * (k.y() + k.x())));
        QCOMPARE(rig.next(), QString("145 0 %1 0 %2").arg(right).arg(left));
        QTest::mouseRelease(rig.area(), Qt::LeftButton, {}, rig.at({0, 0.5}));
        QCOMPARE(rig.next(), kStop);

        // Drive PWM: the wheels' share of the limit, in 255ths of full power.
        QVERIFY(rig.pad()->isMappingAvailable(DrivePad::Mapping::DrivePwm));
        rig.pad()->setMapping(DrivePad::Mapping::DrivePwm);
        QTest::mousePress(rig.area(), Qt::LeftButton, {}, rig.at({0.2, 0.6}));
        k = rig.knobAt({0.2, 0.6});
        right = int(std::lround(300 * (k.y() - k.x()) * 255 / 500));
        left = int(std::lround(300 * (k.y() + k.x()) * 255 / 500));
        QCOMPARE(rig.next(), QString("146 0 %1 0 %2").arg(right).arg(left));
        QTest::mouseRelease(rig.area(), Qt::LeftButton, {}, rig.at({0.2, 0.6}));
        QCOMPARE(rig.next(), kStop);

        // The original Create has no Drive PWM: the choice is there, disabled, with the reason.
        rig.pad()->setProfile(oi::profile(oi::ProfileId::Create1));
        QCOMPARE(rig.pad()->mapping(), DrivePad::Mapping::Drive);
        QVERIFY(!rig.pad()->isMappingAvailable(DrivePad::Mapping::DrivePwm));
        QVERIFY(!rig.pad()->mappingDisabledReason(DrivePad::Mapping::DrivePwm).isEmpty());
        QVERIFY(rig.pad()->isMappingAvailable(DrivePad::Mapping::DriveDirect));
        rig.pad()->setProfile(oi::profile(oi::ProfileId::Create2));
        QVERIFY(rig.pad()->isMappingAvailable(DrivePad::Mapping::DrivePwm));
    }

    void keysDriveAndReleaseStops()
    {
        Rig rig;
        QVERIFY(rig.ready());
        QWidget *target = rig.area();
        QTest::keyPress(target, Qt::Key_Up);
        QCOMPARE(rig.next(), driveBytes(200, oi::kRadiusStraight));
        // The pad shows what the keys ask of the robot: its readout, and the
        // knob straight ahead at the speed limit.
        QCOMPARE(rig.pad()->readout(), QString("Drive 200 mm/s, straight"));
        QCOMPARE(rig.pad()->knobFor(rig.pad()->asked()), QPointF(0, 1));
        // Auto-repeat changes nothing.
        for (int i = 0; i < 5; ++i) {
            QKeyEvent release(QEvent::KeyRelease, Qt::Key_Up, Qt::NoModifier, QString(), true);
            QKeyEvent press(QEvent::KeyPress, Qt::Key_Up, Qt::NoModifier, QString(), true);
            QApplication::sendEvent(target, &release);
            QApplication::sendEvent(target, &press);
        }
        QVERIFY(rig.nothingMore());
        // Up and left together: an arc to the left; left alone turns in place.
        QTest::keyPress(target, Qt::Key_A);
        QCOMPARE(rig.next(), driveBytes(200, 500));
        QTest::keyRelease(target, Qt::Key_Up);
        QCOMPARE(rig.next(), driveBytes(200, oi::kRadiusTurnInPlaceCounterClockwise));
        QTest::keyRelease(target, Qt::Key_A);
        QCOMPARE(rig.next(), kStop);
        QCOMPARE(rig.pad()->readout(), QString("Stopped"));

        // Backwards with S, at the pad's speed limit.
        rig.pad()->setSpeedLimit(350);
        QTest::keyPress(target, Qt::Key_S);
        QCOMPARE(rig.next(), driveBytes(-350, oi::kRadiusStraight));
        QTest::keyRelease(target, Qt::Key_S);
        QCOMPARE(rig.next(), kStop);
    }

    // In the byte log the arrows move through the rows, as they did in its
    // text; they drive nothing.
    void theByteLogKeepsItsArrows()
    {
        ByteInspector inspector;
        QWidget *log = inspector.findChild<QWidget *>(QStringLiteral("byteLog"));
        QVERIFY(log);
        QVERIFY(KeyboardDriving::isTextInput(log));
        QVERIFY(!KeyboardDriving::isTextInput(inspector.findChild<QWidget *>(QStringLiteral("packetTable"))));
    }

    void stopAllKeys()
    {
        Rig rig;
        QVERIFY(rig.ready());
        QTest::keyPress(rig.area(), Qt::Key_W);
        QCOMPARE(rig.next(), driveBytes(200, oi::kRadiusStraight));
        QTest::keyClick(rig.area(), Qt::Key_Escape);
        QCOMPARE(rig.next(), kStop);
        // The held key was forgotten: letting go sends nothing more.
        QTest::keyRelease(rig.area(), Qt::Key_W);
        QVERIFY(rig.nothingMore());

        // Space stops from the pad, even with nothing moving...
        QTest::keyClick(rig.area(), Qt::Key_Space);
        QCOMPARE(rig.next(), kStop);
        // ...but inside the plots it pauses them, as it did before.
        SensorPlots *plots = rig.window.dock<SensorPlots>();
        QWidget *inside = nullptr;
        for (QWidget *w : plots->findChildren<QWidget *>())
            if (!inside && w->isVisible() && w->focusPolicy() != Qt::NoFocus)
                inside = w;
        QVERIFY(inside);
        inside->setFocus();
        QVERIFY(QTest::qWaitFor([&] { return plots->isAncestorOf(QApplication::focusWidget()); }, 2000));
        const bool paused = plots->stack()->isPaused();
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Space);
        QVERIFY(rig.nothingMore());
        QCOMPARE(plots->stack()->isPaused(), !paused);
    }

    // F11 puts the window in the projector view and takes it out again; in
    // it the keys still drive, Space and Esc still stop, and Esc leaves it.
    void projectorViewKeepsTheStopKeys()
    {
        Rig rig;
        QVERIFY(rig.ready());
        QTest::keyClick(rig.area(), Qt::Key_F11);
        QVERIFY(rig.window.isProjectorView());
        QVERIFY(rig.window.projectorView()->isVisible());
        QCOMPARE(QApplication::focusWidget(), rig.window.projectorView());
        rig.sentSoFar(); // whatever entering full screen caused
        QWidget *view = rig.window.projectorView();
        QTest::keyPress(view, Qt::Key_W);
        QCOMPARE(rig.next(), driveBytes(200, oi::kRadiusStraight));
        QTest::keyClick(view, Qt::Key_Space);
        QCOMPARE(rig.next(), kStop);
        QVERIFY(rig.window.isProjectorView()); // Space stops and stays
        QTest::keyRelease(view, Qt::Key_W);

        QTest::keyClick(view, Qt::Key_F11);
        QVERIFY(!rig.window.isProjectorView());
        QVERIFY(!(rig.window.windowState() & Qt::WindowFullScreen));
        QTest::keyClick(rig.window.dock<DrivePad>()->padArea(), Qt::Key_F11);
        QVERIFY(rig.window.isProjectorView());
        QVERIFY(rig.window.windowState() & Qt::WindowFullScreen);
        rig.sentSoFar();
        QTest::keyPress(view, Qt::Key_W);
        QCOMPARE(rig.next(), driveBytes(200, oi::kRadiusStraight));
        QTest::keyClick(view, Qt::Key_Escape);
        QCOMPARE(rig.next(), kStop);
        QVERIFY(!rig.window.isProjectorView());
        QVERIFY(!rig.window.projectorAction()->isChecked());
        QTest::keyRelease(view, Qt::Key_W);
    }

    void focusLossStops()
    {
        Rig rig;
        QVERIFY(rig.ready());
        QTest::mousePress(rig.area(), Qt::LeftButton, {}, rig.at({0, 0.7}));
        QCOMPARE(rig.next(), expectedDrive(rig.knobAt({0, 0.7})));

        QWidget other;
        other.resize(200, 100);
        other.show();
        other.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&other));
        QVERIFY(!rig.window.isActiveWindow());
        QCOMPARE(rig.next(), kStop);
        QCOMPARE(rig.pad()->knob(), QPointF());
        // The drag ended with the focus: a move without a new press sends nothing.
        QTest::mouseMove(rig.area(), rig.at({0, 0.3}));
        QVERIFY(rig.nothingMore());
        QTest::mouseRelease(rig.area(), Qt::LeftButton, {}, rig.at({0, 0.3}));
    }

    void rateLimitCoalescesToTheLatest()
    {
        Rig rig;
        QVERIFY(rig.ready());
        QTest::mousePress(rig.area(), Qt::LeftButton, {}, rig.at({0, 0.3}));
        QCOMPARE(rig.next(), expectedDrive(rig.knobAt({0, 0.3})));

        // 100 moves at once, sweeping from ahead towards the right: the
        // first may find the rate limit free, every later one waits and
        // replaces the one waiting.
        QPointF last;
        for (int i = 0; i < 100; ++i) {
            const double a = i * 0.008;
            last = {0.8 * std::sin(a), 0.8 * std::cos(a)};
            QTest::mouseMove(rig.area(), rig.at(last));
        }
        QVERIFY(rig.window.teleop().hasPendingMotion());
        // The last position goes out when the rate limit lets it (the
        // timing itself: rateLimitOnTheClock).
        QTRY_VERIFY(!rig.window.teleop().hasPendingMotion());
        const QList<QByteArray> writes = rig.sentSoFar();
        QVERIFY2(writes.size() <= 2, qPrintable(QString::number(writes.size())));
        for (const QByteArray &w : writes)
            QCOMPARE(w.size(), qsizetype(5));
        QCOMPARE(byteText(writes.last()), expectedDrive(rig.knobAt(last)));

        QTest::mouseRelease(rig.area(), Qt::LeftButton, {}, rig.at(last));
        QCOMPARE(rig.next(), kStop);
    }

    void passiveRefusesMotionAndOffersSafe()
    {
        Rig rig(oi::OiMode::Passive);
        QVERIFY(rig.ready());
        QVERIFY(rig.pad()->isPassive());
        QVERIFY(rig.window.teleop().isPassive());
        auto *enterSafe = rig.pad()->findChild<QPushButton *>("enterSafe");
        QVERIFY(enterSafe && enterSafe->isVisible());
        bool message = false;
        for (QLabel *label : rig.pad()->findChildren<QLabel *>())
            message = message || (label->isVisible() && label->text() == "Passive mode: enter Safe to drive");
        QVERIFY(message);
        if (!qEnvironmentVariableIsEmpty("ROOMBA_SCREENSHOTS"))
            QVERIFY(rig.window.grab().save(
                QDir(qEnvironmentVariable("ROOMBA_SCREENSHOTS")).filePath("dashboard_drive_passive.png")));

        QTest::mousePress(rig.area(), Qt::LeftButton, {}, rig.at({0, 0.6}));
        QTest::mouseMove(rig.area(), rig.at({0.3, 0.6}));
        QTest::mouseRelease(rig.area(), Qt::LeftButton, {}, rig.at({0.3, 0.6}));
        QTest::keyPress(rig.area(), Qt::Key_Up);
        QTest::keyRelease(rig.area(), Qt::Key_Up);
        QVERIFY(rig.nothingMore());
        // The key that could not drive says why, where the driver looks.
        const QString said = rig.window.statusBar()->currentMessage();
        QVERIFY2(said.contains("Not driving") && said.contains("Enter Safe"), qPrintable(said));

        QTest::mouseClick(enterSafe, Qt::LeftButton);
        QCOMPARE(rig.next(), QString("131"));
        rig.recording.mode = int(oi::OiMode::Safe);
        QVERIFY(QTest::qWaitFor([&rig] { rig.window.refreshDisplay(); return !rig.pad()->isPassive(); }, 5000));
        QTest::mousePress(rig.area(), Qt::LeftButton, {}, rig.at({0, 0.6}));
        QCOMPARE(rig.next(), expectedDrive(rig.knobAt({0, 0.6})));
        QTest::mouseRelease(rig.area(), Qt::LeftButton, {}, rig.at({0, 0.6}));
        QCOMPARE(rig.next(), kStop);
    }

    void safeFallingToPassiveStopsAndRecentres()
    {
        Rig rig;
        QVERIFY(rig.ready());
        QTest::mousePress(rig.area(), Qt::LeftButton, {}, rig.at({0.3, 0.6}));
        QCOMPARE(rig.next(), expectedDrive(rig.knobAt({0.3, 0.6})));
        // A cliff: the robot drops to Passive by itself.
        rig.recording.mode = int(oi::OiMode::Passive);
        QVERIFY(QTest::qWaitFor([&rig] { rig.window.refreshDisplay(); return rig.pad()->isPassive(); }, 5000));
        QCOMPARE(rig.next(), kStop);
        QCOMPARE(rig.pad()->knob(), QPointF());
        QTest::mouseRelease(rig.area(), Qt::LeftButton, {}, rig.at({0.3, 0.6}));
        QVERIFY(rig.nothingMore());
    }

    void staleDataStops()
    {
        ManualClock linkClock;
        Rig rig(oi::OiMode::Safe, &linkClock);
        QVERIFY(rig.ready());
        QTest::mousePress(rig.area(), Qt::LeftButton, {}, rig.at({0, 0.5}));
        QCOMPARE(rig.next(), expectedDrive(rig.knobAt({0, 0.5})));
        rig.recording.streaming = false;
        // The link's clock moves on, with no frame: stale (a frame still on
        // its way restarts the watchdog, so it moves again until it is).
        QVERIFY(QTest::qWaitFor([&] {
            linkClock.advance(oilink::RobotLink::kStaleAfterMs);
            return rig.window.session().state() == oilink::LinkState::Stale;
        }, 5000));
        QCOMPARE(rig.next(), kStop);
        QCOMPARE(rig.pad()->knob(), QPointF());
        rig.window.refreshDisplay();
        QVERIFY(!rig.pad()->isEnabled());
        // No motion goes out while the data is stale.
        QTest::mouseRelease(rig.area(), Qt::LeftButton, {}, rig.at({0, 0.5}));
        QTest::mousePress(rig.area(), Qt::LeftButton, {}, rig.at({0, 0.5}));
        QVERIFY(rig.nothingMore());
        QTest::mouseRelease(rig.area(), Qt::LeftButton, {}, rig.at({0, 0.5}));
    }

    // The Drive dock is a tab beside the modes: on a 1280x860 window it makes
    // the window no taller and shows the whole pad (saved into
    // ROOMBA_SCREENSHOTS when set).
    void driveDockFitsTheWindow()
    {
        Rig rig;
        QVERIFY(rig.ready());
        auto *drive = rig.window.findChild<QDockWidget *>("driveDock");
        QVERIFY(drive);
        const int withDrive = rig.window.minimumSizeHint().height();
        drive->hide();
        const int withoutDrive = rig.window.minimumSizeHint().height();
        drive->show();
        QCOMPARE(withDrive, withoutDrive);
        QCOMPARE(rig.window.tabifiedDockWidgets(drive), QList<QDockWidget *>{rig.window.findChild<QDockWidget *>("modeDock")});

        drive->raise();
        QTRY_VERIFY(rig.area()->isVisible());
        QVERIFY2(std::min(rig.area()->width(), rig.area()->height()) >= 200,
                 qPrintable(QString("%1x%2").arg(rig.area()->width()).arg(rig.area()->height())));
        QTest::mousePress(rig.area(), Qt::LeftButton, {}, rig.at({0.35, 0.6}));
        QCOMPARE(rig.next(), expectedDrive(rig.knobAt({0.35, 0.6})));
        rig.window.refreshDisplay();
        if (!qEnvironmentVariableIsEmpty("ROOMBA_SCREENSHOTS"))
            QVERIFY(rig.window.grab().save(QDir(qEnvironmentVariable("ROOMBA_SCREENSHOTS")).filePath("dashboard_drive.png")));
        QTest::mouseRelease(rig.area(), Qt::LeftButton, {}, rig.at({0.35, 0.6}));
        QCOMPARE(rig.next(), kStop);
    }

    void quittingStopsFirst()
    {
        Rig rig;
        QVERIFY(rig.ready());
        QTest::keyPress(rig.area(), Qt::Key_Up);
        QCOMPARE(rig.next(), driveBytes(200, oi::kRadiusStraight));
        rig.window.close();
        // Stop, then the shutdown sequence: pause the stream, stop, Start (Passive).
        QCOMPARE(byteText(rig.recording.take().join()), kStop + " 150 0 " + kStop + " 128");
    }
};

QTEST_MAIN(TestTeleop)
#include "tst_teleop.moc"
