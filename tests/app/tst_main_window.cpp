// SPDX-License-Identifier: GPL-3.0-or-later
// The assembled window: connecting to the virtual robot, mode buttons down
// to the bytes, settings, and a bad port.
#include "profile_probe.h"
#include "main_window.h"
#include "comparison_bar.h"
#include "crowded_recording.h" // tests/common
#include "marker_actions.h"
#include "marker_list.h"
#include "marker_note_editor.h"
#include "run_comparison.h"
#include "recording_actions.h"
#include "room_actions.h"
#include "connection_bar.h"
#include "drive_pad.h"
#include "robot_list.h"
#include "mode_panel.h"
#include "lesson_panel.h"
#include "lesson_runner.h"
#include "lesson_step_view.h"
#include "projector_view.h"
#include "recording_transport.h"
#include "robot_diagram.h"
#include "robot_view.h"
#include "odometry_map.h"
#include "display_tick.h"
#include "on_screen.h"
#include "byte_inspector.h"
#include "plot_stack.h"
#include "sensor_plots.h"
#include "pseudo_translation.h"
#include "recording_file.h"
#include "replay_bar.h"
#include "schedule_editor.h"
#include "script_editor.h"
#include "transport.h"
#include "firmware_reading.h"
#include "sensor_gauges.h"
#include "value_gauge.h"
#include "virtual_transport.h"
#include "typed_command_bytes.h"

#include <QComboBox>
#include <QLineEdit>
#include <QTableWidget>
#include <QDir>
#include <QFile>
#include <cmath>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QToolBar>
#include <QToolButton>
#include <QPointer>
#include <QSet>
#include <QApplication>
#include <QFileDialog>
#include <QLabel>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QMutex>
#include <QAbstractItemView>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTimer>
#include <QSignalSpy>
#include <QTest>

namespace {

QString text(const QByteArray &bytes) { return byteText(bytes); }

// ROOMBA_SCREENSHOTS when set, else `scratch`.
QString screenshotDir(const QTemporaryDir &scratch)
{
    const QString dir = qEnvironmentVariableIsEmpty("ROOMBA_SCREENSHOTS") ? scratch.path()
                                                                           : qEnvironmentVariable("ROOMBA_SCREENSHOTS");
    QDir().mkpath(dir);
    return dir;
}

// The virtual robot, with every byte sent to it recorded.
class RecordedVirtualRobot : public sim::VirtualTransport {
public:
    RecordedVirtualRobot(Recording *recording, const oilink::LinkSettings &settings)
        : VirtualTransport(settings.virtualRobot, settings.virtualSeed), m_recording(recording)
    {
    }
    bool write(const QByteArray &bytes) override
    {
        {
            QMutexLocker lock(&m_recording->mutex);
            m_recording->writes << bytes;
            m_recording->times << Recording::Clock::now();
        }
        return VirtualTransport::write(bytes);
    }

private:
    Recording *m_recording;
};

// A dock that only a row of the dock table adds: it says which robot and
// profile it was shown, and keeps the display frames of its ticks.
class CountingView : public QLabel, public RobotView {
    Q_OBJECT
public:
    using QLabel::QLabel;
    void showProfile(const oi::RobotProfile &profile) override { shownProfile = profile.id; }
    void tick(quint64 frame) override { ticks << frame; }
    QString shownRobot;
    std::optional<oi::ProfileId> shownProfile;
    QList<quint64> ticks;

protected:
    void showRobot(RobotSession &robot) override { shownRobot = robot.name(); }
};

const DockRow kCountingRow{.objectName = "countingDock",
                           .title = "Counting",
                           .area = Qt::BottomDockWidgetArea,
                           .make =
                               [](const DockContext &c) {
                                   auto *view = new CountingView(c.window);
                                   return DockPane{view, view};
                               },
                           .lazy = true,
                           .refreshEveryFrames = 4};

QMenu *viewMenu(MainWindow &window)
{
    for (QAction *entry : window.menuBar()->actions())
        if (entry->menu() && entry->menu()->title() == "&View")
            return entry->menu();
    return nullptr;
}

} // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
private slots:
    void init()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void firstStartStreamsFromTheVirtualRobot()
    {
        MainWindow window;
        window.resize(1200, 800);
        window.show();
        window.start();
        QTRY_VERIFY_WITH_TIMEOUT(window.session().snapshotCount() > 10, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        window.refreshDisplay();
        QVERIFY(window.statusText().contains("streaming"));
        QVERIFY(!window.statusText().contains("NO LIVE DATA"));
        QTRY_VERIFY_WITH_TIMEOUT(window.statusText().contains("frames/s"), 10000);

        // Safe mode, as the robot reports it back.
        QTest::mouseClick(window.dock<ModePanel>()->button("safe"), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(window.session().latest().oiMode(), oi::OiMode::Safe, 10000);
        window.refreshDisplay();
        QCOMPARE(window.dock<ModePanel>()->highlightedMode(), std::optional<oi::OiMode>(oi::OiMode::Safe));

        QTest::mouseClick(window.dock<ConnectionBar>()->findChild<QPushButton *>("disconnect"), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Closed, 10000);
        window.refreshDisplay();
        QVERIFY(window.statusText().contains("NO LIVE DATA"));
        // A closed link has no frame rate.
        QVERIFY2(window.statusText().contains("Link: closed") && !window.statusText().contains("frames/s"),
                 qPrintable(window.statusText()));
    }

    // A robot at rest streams the same values: the display slows to its
    // quiet pace while the frames still come in, and the first frame that
    // differs (the mode the robot reports) wakes it and is shown.
    void displayRestsWithTheRobot()
    {
        MainWindow window;
        window.resize(1200, 800);
        window.show();
        window.start();
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        DisplayTick &tick = DisplayTick::instance();
        QTRY_VERIFY_WITH_TIMEOUT(tick.isQuiet(), 10000);
        const quint64 frames = window.session().snapshotCount();
        QTRY_VERIFY_WITH_TIMEOUT(window.session().snapshotCount() > frames + 10, 10000);

        QTest::mouseClick(window.dock<ModePanel>()->button("safe"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!tick.isQuiet(), 10000);
        QTRY_COMPARE_WITH_TIMEOUT(window.dock<ModePanel>()->highlightedMode(), std::optional<oi::OiMode>(oi::OiMode::Safe),
                                  10000);
        window.close();
    }

    // Clean on the virtual robot: it runs its own program, and the window
    // says what is happening and how to end it, on every view, for as long
    // as it runs, and only that; after Disconnect no mode is shown at all.
    void cleanRunsTheRobotsOwnProgram()
    {
        MainWindow window;
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        window.room()->moveRobot(window.roomRobot(), {0, 0, 0, 0});
        QTRY_VERIFY_WITH_TIMEOUT(window.room()->robot(window.roomRobot())->pose.xMm == 0, 10000);
        QTest::mouseClick(window.dock<ModePanel>()->button("clean"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(window.room()->robot(window.roomRobot())->pose.xMm > 100, 10000);
        QCOMPARE(window.session().mode().reported(), std::optional(oi::OiMode::Passive));
        const QString cleaning = "Cleaning (its own program) · Space stops it";
        window.refreshDisplay();
        QCOMPARE(window.dock<ModePanel>()->safetyMessage(), cleaning);
        QCOMPARE(window.dock<DrivePad>()->passiveText(), cleaning);
        QVERIFY2(window.statusText().contains(cleaning), qPrintable(window.statusText()));
        QVERIFY2(!window.statusText().contains("You asked for Passive"), qPrintable(window.statusText()));
        // No other message is put over it.
        QCOMPARE(window.statusBar()->currentMessage(), QString());
        // Space, as said, ends the program (Drive alone is ignored in Passive): Safe, and still.
        window.robotDiagram()->setFocus();
        QTest::keyClick(window.robotDiagram(), Qt::Key_Space);
        QTRY_COMPARE_WITH_TIMEOUT(window.session().mode().reported(), std::optional(oi::OiMode::Safe), 10000);
        window.refreshDisplay();
        QCOMPARE(window.dock<ModePanel>()->safetyMessage(), QString());
        const quint64 frames = window.session().snapshotCount();
        const double x = window.room()->robot(window.roomRobot())->pose.xMm;
        QTRY_VERIFY_WITH_TIMEOUT(window.session().snapshotCount() > frames + 20, 10000);
        QCOMPARE(window.room()->robot(window.roomRobot())->pose.xMm, x);

        // Disconnected, the robot's mode is not known: nothing shows one as current.
        QTest::mouseClick(window.dock<ConnectionBar>()->findChild<QPushButton *>("disconnect"), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Closed, 10000);
        window.refreshDisplay();
        QCOMPARE(window.dock<ModePanel>()->highlightedMode(), std::nullopt);
        QCOMPARE(window.findChild<QLabel *>("modeLabel")->text(), QString("Mode: unknown"));
        QTRY_COMPARE_WITH_TIMEOUT((window.refreshDisplay(), window.robotList()->card(0)->values().mode), QString(), 5000);
    }

    // A view behind another dock's tab keeps what comes and draws none of
    // it, and keeps no timer: the inspector renders nothing, the map does
    // not tick. Each catches up and ticks when its tab comes up, and stops
    // soon after it goes down.
    void tabbedAwayViewsWaitForTheirTab()
    {
        MainWindow window;
        window.resize(1400, 900);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(window.session().snapshotCount() > 10, 10000);
        // Behind the plots' tab: visible to Qt, nothing of it on screen.
        ByteInspector *inspector = window.dock<ByteInspector>();
        const QAbstractItemModel *log = inspector->findChild<QAbstractItemView *>("byteLog")->model();
        const DisplayTick &tick = DisplayTick::instance();
        const OdometryMap *map = window.dock<OdometryMap>();
        QVERIFY(inspector->isVisible());
        QVERIFY(!isOnScreen(inspector));
        QVERIFY(!isOnScreen(window.dock<OdometryMap>()));
        QVERIFY(isOnScreen(window.dock<SensorPlots>()));
        const qsizetype entries = inspector->lastEntries(1000).size();
        QTRY_VERIFY_WITH_TIMEOUT(inspector->lastEntries(1000).size() > entries + 10, 10000);
        QCOMPARE(log->rowCount(), 0);
        QCOMPARE(inspector->packetTable()->model()->rowCount(), 0);
        QVERIFY(!tick.hasFrameFor(inspector));
        QVERIFY(!tick.isListening(map));

        // Its tab comes up: it shows what it kept, and renders what comes.
        window.findChild<QDockWidget *>("inspectorDock")->raise();
        QTRY_VERIFY(isOnScreen(inspector));
        QTRY_VERIFY(log->rowCount() > 10);
        QTRY_VERIFY(inspector->packetTable()->model()->rowCount() > 10);
        const int rows = log->rowCount();
        QTRY_VERIFY(log->rowCount() > rows);
        QVERIFY(!isOnScreen(window.dock<SensorPlots>()));

        // Each stops at its first tick behind another tab.
        window.findChild<QDockWidget *>("mapDock")->raise();
        QTRY_VERIFY(isOnScreen(window.dock<OdometryMap>()));
        QVERIFY(tick.isListening(map));
        QTRY_VERIFY(!tick.hasFrameFor(inspector));
        window.findChild<QDockWidget *>("plotsDock")->raise();
        QTRY_VERIFY(!isOnScreen(window.dock<OdometryMap>()));
        QTRY_VERIFY(!tick.isListening(map));
    }

    void modeButtonsSendExactBytes()
    {
        Recording recording;
        MainWindow window;
        window.fleet().setTransportFactory(
            [&recording](const oilink::LinkSettings &) { return new RecordingTransport(&recording); });
        oilink::LinkSettings settings = oilink::LinkSettings::serial("/dev/recording", oi::ProfileId::Create2);
        window.show();
        window.start(settings);
        // Opening sends a stop, the Starts that finish a command an earlier
        // program left half sent, then a stop and Start, then the stream.
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        const QList<QByteArray> opening = recording.take();
        QVERIFY(opening.size() >= 3);
        QCOMPARE(text(opening.at(0)), QString("137 0 0 0 0 138 0"));
        QCOMPARE(opening.at(1), QByteArray(qsizetype(oilink::ProfileProbe::finishingStarts().size()), char(128)));
        QCOMPARE(text(opening.at(2)), QString("137 0 0 0 0 138 0 128"));
        window.dock<ModePanel>()->setFullModeConfirmation([](QWidget *) { return true; });
        const std::pair<const char *, const char *> buttons[] = {
            {"safe", "131"}, {"full", "132"}, {"passive", "128"}, {"seek-dock", "143"}, {"stop", "173"}};
        for (const auto &[name, bytes] : buttons) {
            QTest::mouseClick(window.dock<ModePanel>()->button(name), Qt::LeftButton);
            QTRY_COMPARE_WITH_TIMEOUT(recording.count(), qsizetype(1), 5000);
            QCOMPARE(text(recording.take().first()), QString(bytes));
        }
        // The editors send through the same session.
        // An editor's pane is made when its dock is first shown.
        window.findChild<QDockWidget *>("scheduleDock")->raise();
        ScheduleEditor *schedule = nullptr;
        QTRY_VERIFY((schedule = window.findChild<ScheduleEditor *>()));
        oi::CleaningSchedule example;
        example.days[int(oi::Weekday::Wednesday)] = oi::ClockTime{15, 0};
        example.days[int(oi::Weekday::Friday)] = oi::ClockTime{10, 36};
        schedule->setSchedule(example);
        schedule->sendSchedule();
        QTRY_COMPARE_WITH_TIMEOUT(recording.count(), qsizetype(1), 5000);
        QCOMPARE(text(recording.take().first()), QString("167 40 0 0 0 0 0 0 15 0 0 0 10 36 0 0"));
        // Closing leaves the robot stopped and in Passive mode.
        window.session().closeAndWait();
        QCOMPARE(text(recording.take().join()), QString("150 0 137 0 0 0 0 138 0 128"));
        // No link now: the mode buttons are off and say why, and send nothing.
        window.refreshDisplay();
        QVERIFY(!window.dock<ModePanel>()->button("safe")->isEnabled());
        QVERIFY2(window.dock<ModePanel>()->button("safe")->toolTip().contains("Not connected"),
                 qPrintable(window.dock<ModePanel>()->button("safe")->toolTip()));
        QTest::mouseClick(window.dock<ModePanel>()->button("safe"), Qt::LeftButton);
        QCOMPARE(recording.count(), qsizetype(0));
    }

    // Robot → Read firmware version… on the virtual robot: it asks first,
    // saying the robot will be reset; declined, nothing is sent; agreed, a
    // Reset (7) goes out and the banner's version and its corrections show.
    // The robot goes silent right after its Clean/Power button was held:
    // switched off. The connection bar says so with a Wake button beside
    // the words; pressed, it pulses the BRC pin, and once the robot listens
    // the link sends Start and the stream again.
    void wakeButtonSwitchesOnARobotSwitchedOffAtItsButton()
    {
        Recording recording;
        recording.brcInReach = true;
        recording.mode = 1;
        MainWindow window;
        window.fleet().setTransportFactory(
            [&recording](const oilink::LinkSettings &) { return new RecordingTransport(&recording); });
        window.show();
        window.start(oilink::LinkSettings::serial("/dev/recording", oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        QVERIFY(!window.dock<ConnectionBar>()->wakeOffered());
        recording.buttons = oi::bit::ButtonClean;
        QTRY_VERIFY_WITH_TIMEOUT(window.session().latest().button(oi::Button::Clean), 5000);
        const int pullsBeforeOff = recording.brcPulls;
        recording.streaming = false; // switched off
        QTRY_VERIFY_WITH_TIMEOUT(window.dock<ConnectionBar>()->wakeOffered(), 5000);
        QVERIFY2(window.dock<ConnectionBar>()->errorText().contains("switched off at its power button"),
                 qPrintable(window.dock<ConnectionBar>()->errorText()));
        QCOMPARE(recording.brcPulls, pullsBeforeOff); // no pulse of the link's own
        recording.take();
        QPushButton *wake = window.dock<ConnectionBar>()->findChild<QPushButton *>("wake");
        QVERIFY(wake && wake->isVisible());
        QTest::mouseClick(wake, Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(recording.brcPulls, pullsBeforeOff + 1, 5000);
        // Awake: Start and Stream follow.
        QTRY_VERIFY_WITH_TIMEOUT(text(recording.written()).contains(QString("128 148")), 5000);
        recording.buttons = 0;
        recording.streaming = true;
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(!window.dock<ConnectionBar>()->wakeOffered(), 5000);
    }

    void readFirmwareVersionOnTheVirtualRobot()
    {
        Recording recording;
        MainWindow window;
        window.fleet().setTransportFactory(
            [&recording](const oilink::LinkSettings &s) { return new RecordedVirtualRobot(&recording, s); });
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        auto *menu = window.findChild<QMenu *>("robotMenu");
        QVERIFY(menu);
        QAction *read = window.firmwareReading()->action();
        QVERIFY(menu->actions().contains(read));
        QCOMPARE(read->text(), QString("Read &firmware version…"));

        QString asked;
        window.firmwareReading()->setConfirmation([&asked](QWidget *, const QString &question) {
            asked = question;
            return false;
        });
        read->trigger();
        QVERIFY2(asked.contains("reset (Reset, opcode 7)") && asked.contains("reboots"), qPrintable(asked));
        QVERIFY(!window.session().firmware().isReading());
        QVERIFY(!window.firmwareReading()->answer());

        window.firmwareReading()->setConfirmation([](QWidget *, const QString &) { return true; });
        recording.take();
        read->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(recording.written().contains(char(7)), 5000);
        QCOMPARE(text(recording.take().first()), QString("7"));
        QTRY_VERIFY_WITH_TIMEOUT(window.firmwareReading()->answer(), 5000);
        const QString answer = window.firmwareReading()->answer()->text();
        QVERIFY2(answer.contains("runs release-3.8.2 (version 3.8.2)"), qPrintable(answer));
        QVERIFY2(answer.contains("nothing needs correcting"), qPrintable(answer));
        QVERIFY2(answer.contains("r3_robot/tags/release-3.8.2"), qPrintable(answer));
        QCOMPARE(window.session().firmwareRelease(), QString("release-3.8.2"));
        QVERIFY(!window.dock<SensorGauges>()->gauge("requested_radius")->isGreyed());
    }

    // Firmware before 3.3.0 reports the requested radius wrongly: once the
    // banner says so, the gauge greys and says why.
    void oldFirmwareGreysTheRadiusGauge()
    {
        Recording recording;
        std::atomic<RecordingTransport *> transport{nullptr};
        MainWindow window;
        window.fleet().setTransportFactory([&](const oilink::LinkSettings &) {
            auto *t = new RecordingTransport(&recording);
            transport = t;
            return t;
        });
        window.show();
        window.start(oilink::LinkSettings::serial("/dev/recording", oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        ValueGauge *radius = window.dock<SensorGauges>()->gauge("requested_radius");
        QVERIFY(!radius->isGreyed());
        window.firmwareReading()->setConfirmation([](QWidget *, const QString &) { return true; });
        window.firmwareReading()->action()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(recording.written().contains(char(7)), 5000);
        QMetaObject::invokeMethod(transport.load(), [t = transport.load()] {
            t->inject("bl-start\r\nr3_robot/tags/release-3.2.9:4975 CLEAN\r\n");
        });
        QTRY_VERIFY_WITH_TIMEOUT(window.firmwareReading()->answer(), 5000);
        QVERIFY2(window.firmwareReading()->answer()->text().contains("greyed"),
                 qPrintable(window.firmwareReading()->answer()->text()));
        QVERIFY(radius->isGreyed());
        QVERIFY(radius->toolTip().contains("before 3.3.0"));
    }

    // The virtual robot pushed against a wall, then stopped by Safe mode at
    // the edge of a drop-off: what the window shows, saved as screenshots
    // (into ROOMBA_SCREENSHOTS when set).
    void wallAndCliff()
    {
        MainWindow window;
        window.resize(1400, 900);
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        // Put down by hand in the window's room; the robot's thread takes
        // it before the next command reaches it.
        const auto placeRobot = [&window](oi::Pose pose) { window.room()->moveRobot(window.roomRobot(), pose); };
        const oi::CommandEncoder encoder(oi::profile(oi::ProfileId::Create2));
        const auto send = [&window](const oi::EncodeResult &bytes) {
            QVERIFY(window.session().send(commandsOf(QByteArray(reinterpret_cast<const char *>(bytes->data()),
                                                                qsizetype(bytes->size())))));
        };
        QTemporaryDir scratch;
        const QString dir = screenshotDir(scratch);

        // 30 cm from the front wall, facing it, in Full mode: drive until it bumps.
        placeRobot({2700, 0, 0, 0});
        send(encoder.full());
        send(encoder.drive(150, oi::kRadiusStraight));
        QTRY_VERIFY_WITH_TIMEOUT(window.session().latest().bumpLeft() && window.session().latest().bumpRight(), 10000);
        window.refreshDisplay();
        QVERIFY(window.grab().save(QDir(dir).filePath("dashboard_wall.png")));

        // Facing the stage edge in Safe mode: the robot stops at the cliff and
        // drops to Passive, and the window says why.
        send(encoder.drive(0, 0));
        placeRobot({2600, -300, -M_PI / 2, 0});
        send(encoder.safe());
        send(encoder.drive(100, oi::kRadiusStraight));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().latest().oiMode(), oi::OiMode::Passive, 10000);
        QTRY_VERIFY_WITH_TIMEOUT((window.refreshDisplay(), window.dock<ModePanel>()->safetyMessage().contains("cliff")), 5000);
        const oi::SensorSnapshot &s = window.session().latest();
        QVERIFY(s.cliff(oi::CliffSensor::FrontLeft) || s.cliff(oi::CliffSensor::FrontRight)
                || s.cliff(oi::CliffSensor::Left) || s.cliff(oi::CliffSensor::Right));
        QVERIFY(window.grab().save(QDir(dir).filePath("dashboard_cliff.png")));
        // The projector view says it too, with Enter Safe.
        window.setProjectorView(true);
        QTRY_VERIFY_WITH_TIMEOUT((window.refreshDisplay(), window.projectorView()->reasonText().contains("cliff")), 5000);
        QVERIFY(window.grab().save(QDir(dir).filePath("projector_cliff.png")));
        window.setProjectorView(false);

        // The map shows the virtual robot's true pose beside the odometry.
        window.findChild<QDockWidget *>("mapDock")->raise();
        QTRY_VERIFY_WITH_TIMEOUT(window.dock<OdometryMap>()->poseText().contains("drift"), 5000);

        // Each editor in its tab.
        for (const char *dock : {"songsDock", "ledsDock", "scheduleDock", "scriptDock", "inspectorDock", "motorsDock",
                                 "mapDock", "gamepadDock", "driveDock"}) {
            window.findChild<QDockWidget *>(dock)->raise();
            QTRY_VERIFY(window.findChild<QDockWidget *>(dock)->widget()->isVisible());
            QVERIFY(window.grab().save(QDir(dir).filePath(QString("dashboard_%1.png").arg(dock))));
        }
    }

    // A lesson in the window on the virtual robot: its goal met by driving,
    // the true pose beside odometry, and the projector view at 1920x1080
    // with the lesson and with the robot alone (screenshots into
    // ROOMBA_SCREENSHOTS when set).
    void lessonAndProjectorView()
    {
        MainWindow window;
        window.resize(1920, 1080);
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        QTemporaryDir scratch;
        const QString dir = screenshotDir(scratch);

        LessonPanel *lessons = window.dock<LessonPanel>();
        window.findChild<QDockWidget *>("lessonDock")->raise();
        QVERIFY(lessons->openLesson(":/lessons/encoders_distance_angle.json"));
        const oi::CommandEncoder encoder(oi::profile(oi::ProfileId::Create2));
        const auto send = [&window](const oi::EncodeResult &bytes) {
            QVERIFY(window.session().send(commandsOf(QByteArray(reinterpret_cast<const char *>(bytes->data()),
                                                                qsizetype(bytes->size())))));
        };
        window.room()->moveRobot(window.roomRobot(), {0, 0, 0, 0});
        send(encoder.safe());
        send(encoder.drive(400, oi::kRadiusStraight));
        QTRY_COMPARE_WITH_TIMEOUT(lessons->runner().currentStep(), 1, 10000);
        send(encoder.drive(200, oi::kRadiusTurnInPlaceCounterClockwise));
        QTRY_VERIFY_WITH_TIMEOUT(lessons->runner().turnedDegrees() > 30, 10000);
        send(encoder.drive(0, 0));
        QVERIFY(lessons->runner().trueTurnedDegrees()); // the room's truth, on the virtual robot
        QTRY_VERIFY_WITH_TIMEOUT((window.refreshDisplay(), window.refreshDisplay(),
                                  !lessons->stepView()->readoutText("true_turned_deg").startsWith("—")), 5000);
        QVERIFY(window.grab().save(QDir(dir).filePath("dashboard_lesson.png")));

        // The projector view: the lesson's step and its views, full screen.
        window.projectorAction()->trigger();
        QVERIFY(window.isProjectorView());
        ProjectorView *projector = window.projectorView();
        QCOMPARE(projector->stepView()->headingText(), QString("Step 2 of 3"));
        QTRY_COMPARE(projector->size(), window.size());
        window.refreshDisplay();
        window.refreshDisplay();
        QVERIFY(projector->headerText().contains("Encoders, distance and angle"));
        QVERIFY(projector->grab().save(QDir(dir).filePath("projector_lesson.png")));

        // Without a lesson: the robot alone.
        lessons->closeLesson();
        QCOMPARE(projector->stepView()->headingText(), QString());
        window.refreshDisplay();
        window.refreshDisplay();
        QVERIFY(!projector->stepView()->readoutText("voltage").isEmpty());
        QVERIFY(projector->grab().save(QDir(dir).filePath("projector_robot.png")));
        window.projectorAction()->trigger();
        QVERIFY(!window.isProjectorView());
    }

    // The cliff lesson's front-sensor step, driven at the stage edge at an
    // angle: a side sensor stops the robot first, and the lesson says why
    // its goal is out of reach and what to do.
    void cliffLessonSaysWhyItsGoalIsOutOfReach()
    {
        QTemporaryDir scratch;
        const QString dir = screenshotDir(scratch);
        MainWindow window;
        window.resize(1280, 720);
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        LessonPanel *lessons = window.dock<LessonPanel>();
        window.findChild<QDockWidget *>("lessonDock")->raise();
        QVERIFY(lessons->openLesson(":/lessons/cliff_sensors.json"));
        lessons->nextStep();
        QCOMPARE(lessons->runner().currentStep(), 1);

        window.room()->moveRobot(window.roomRobot(), {1850, -1200, M_PI / 4, 0});
        QVERIFY(window.session().requestMode(oi::Command::Safe));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().mode().reported(), std::optional(oi::OiMode::Safe), 5000);
        window.refreshDisplay();
        window.refreshDisplay();
        QCOMPARE(lessons->stepView()->outOfReachText(), QString());
        const oi::EncodeResult drive = oi::CommandEncoder(window.session().robotProfile()).drive(100, oi::kRadiusStraight);
        QVERIFY(window.session().send(commandsOf(QByteArray(reinterpret_cast<const char *>(drive->data()), qsizetype(drive->size())))));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().mode().reported(), std::optional(oi::OiMode::Passive), 10000);
        QTRY_VERIFY_WITH_TIMEOUT((window.refreshDisplay(), !lessons->stepView()->outOfReachText().isEmpty()), 5000);
        const QString why = lessons->stepView()->outOfReachText();
        QVERIFY2(why.startsWith("Out of reach: A cliff (right) dropped it to Passive at "), qPrintable(why));
        QVERIFY(why.contains("drive at the edge head on"));
        QCOMPARE(lessons->runner().currentStep(), 1);
        QVERIFY(window.grab().save(QDir(dir).filePath("lesson_out_of_reach.png")));
    }

    // A Create script uploaded to the virtual robot runs with its wait, in
    // Safe asked for it from Passive, and Show Script reads back what was sent.
    void createScriptOnTheVirtualRobot()
    {
        MainWindow window;
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create1, oi::ProfileId::Create1));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(window.session().robotProfile().id, oi::ProfileId::Create1, 10000);
        window.findChild<QDockWidget *>("scriptDock")->raise();
        ScriptEditor *editor = nullptr;
        QTRY_VERIFY((editor = window.findChild<ScriptEditor *>()));
        QVERIFY(editor->disabledReason().isEmpty());
        editor->setScriptText("drive 200 straight\nwait-distance 300\ndrive 0 0");
        editor->reassemble();
        QVERIFY2(editor->errorText().isEmpty(), qPrintable(editor->errorText()));

        // Played in Passive: the robot's session enters Safe first.
        QTRY_COMPARE_WITH_TIMEOUT(window.session().mode().reported(), std::optional(oi::OiMode::Passive), 10000);
        QTest::mouseClick(editor->button("upload"), Qt::LeftButton);
        QTest::mouseClick(editor->button("play"), Qt::LeftButton);
        QCOMPARE(window.session().mode().lastAsked(), std::optional(oi::Command::Safe));
        // It drives, then the wait ends and it stops.
        QTRY_COMPARE_WITH_TIMEOUT(window.session().latest().requestedVelocity(), 200, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(window.session().latest().requestedVelocity(), 0, 10000);

        QTest::mouseClick(editor->button("show"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(editor->showScriptText().contains("matches what was sent"), 10000);
        QVERIFY(editor->showScriptText().contains("drive 200 straight; wait-distance 300; drive 0 0"));
        // And the stream comes back.
        const quint64 count = window.session().snapshotCount();
        QTRY_VERIFY_WITH_TIMEOUT(window.session().snapshotCount() > count + 10, 10000);
    }

    // The teacher moves a wall on the map toward the virtual robot: the room
    // changes for the robot at once and its light bumpers see the wall; Undo
    // puts the wall back. Screenshots into ROOMBA_SCREENSHOTS when set.
    void editingTheRoomOnTheMap()
    {
        MainWindow window;
        window.resize(1400, 900);
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        // Facing the classroom's left wall (y = 1500) from 600 mm: out of the light bumpers' reach.
        window.room()->moveRobot(window.roomRobot(), {500, 900, M_PI / 2, 0});
        QTRY_COMPARE_WITH_TIMEOUT(window.session().latest().lightBumpSignal(oi::LightBumper::CenterLeft), 0, 5000);

        window.findChild<QDockWidget *>("mapDock")->raise();
        OdometryMap *map = window.dock<OdometryMap>();
        QTRY_VERIFY(map->isVisible());
        map->setScale(0.12);
        map->setViewCentreMm({1000, 1100}); // the wall and where it goes, in a map of any height
        window.refreshDisplay();
        QVERIFY(map->world());
        QTest::mouseClick(map->findChild<QPushButton *>("editRoom"), Qt::LeftButton);
        QVERIFY(map->isEditing());

        // Take the wall by its middle and bring it 250 mm nearer.
        const QPoint from = map->widgetPointFor({1000, 1500}).toPoint();
        const QPoint to = map->widgetPointFor({1000, 1250}).toPoint();
        QVERIFY(map->mapRect().contains(from));
        QTest::mousePress(map, Qt::LeftButton, Qt::NoModifier, from);
        QTest::mouseMove(map, (from + to) / 2);
        QTest::mouseMove(map, to);
        QTest::mouseRelease(map, Qt::LeftButton, Qt::NoModifier, to);
        const sim::Segment moved = window.room()->world().walls[2];
        QCOMPARE(moved.y1, 1250.0);
        QCOMPARE(moved.y2, 1250.0);
        QTRY_VERIFY_WITH_TIMEOUT(window.session().latest().lightBumpSignal(oi::LightBumper::CenterLeft) > 0, 5000);
        QVERIFY(window.session().latest().lightBumpSignal(oi::LightBumper::CenterRight) > 0);
        window.refreshDisplay();
        QTRY_COMPARE(map->world()->walls[2], moved);
        QCOMPARE(map->selectedItem(), (sim::WorldItem{sim::WorldPart::Wall, 2}));
        if (qEnvironmentVariableIsSet("ROOMBA_SCREENSHOTS")) {
            const QDir dir(qEnvironmentVariable("ROOMBA_SCREENSHOTS"));
            QVERIFY(window.grab().save(dir.filePath("room_robot_by_moved_wall_window.png")));
            QVERIFY(map->grab().save(dir.filePath("room_robot_by_moved_wall.png")));
            // The File menu with the rooms, and the shipped rooms beside it.
            QMenu *file = qobject_cast<QMenu *>(window.roomActions()->openAction()->associatedObjects().value(0));
            QVERIFY(file);
            file->popup(window.mapToGlobal(QPoint(0, 0)));
            QVERIFY(QTest::qWaitForWindowExposed(file));
            QVERIFY(file->grab().save(dir.filePath("room_file_menu.png")));
            file->close();
            window.roomActions()->shippedMenu()->popup(window.mapToGlobal(QPoint(0, 0)));
            QVERIFY(QTest::qWaitForWindowExposed(window.roomActions()->shippedMenu()));
            QVERIFY(window.roomActions()->shippedMenu()->grab().save(dir.filePath("room_shipped_menu.png")));
            window.roomActions()->shippedMenu()->close();
        }

        // One drag, one Undo.
        window.roomActions()->undoAction()->trigger();
        QCOMPARE(window.room()->world(), sim::World::classroom());
        QTRY_COMPARE_WITH_TIMEOUT(window.session().latest().lightBumpSignal(oi::LightBumper::CenterLeft), 0, 5000);
    }

    // A dock tabbed behind another at start has its pane made when it is
    // first shown, which then shows the selected robot as one made at start
    // would; a layout saved with its tab raised makes it at the next start.
    // The projector view too is made when first needed.
    void lazyDockMadeWhenFirstShown()
    {
        {
            MainWindow window;
            window.show();
            window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create1, oi::ProfileId::Create1));
            QTRY_COMPARE_WITH_TIMEOUT(window.session().robotProfile().id, oi::ProfileId::Create1, 10000);
            QVERIFY(!window.findChild<ScriptEditor *>());
            QVERIFY(!window.findChild<ProjectorView *>()); // made at the first F11
            window.findChild<QDockWidget *>("scriptDock")->raise();
            auto *editor = window.findChild<ScriptEditor *>();
            QVERIFY(editor);
            QTRY_VERIFY(editor->isVisible());
            QCOMPARE(editor->disabledReason(), QString()); // a Create 1's scripts, not a Create 2's refusal
            window.close();
        }
        MainWindow again;
        again.show();
        again.start();
        QTRY_VERIFY(again.findChild<ScriptEditor *>());
        QVERIFY(!again.findChild<ScheduleEditor *>());
    }

    // A dock added by its row alone: an entry in the View menu, a place in
    // the saved layout, its pane made when first shown and showing the
    // selected robot, and its view ticked as often as the row says.
    void aDockAddedByItsRowAlone()
    {
        {
            MainWindow window(dashboardDocks() << kCountingRow);
            window.show();
            window.start();
            QAction *entry = window.findChild<QAction *>("countingDockViewAction");
            QVERIFY(entry);
            QVERIFY(viewMenu(window)->actions().contains(entry));
            QCOMPARE(entry->text(), QString("Counting"));
            QVERIFY(!window.dock<CountingView>()); // tabbed behind the plots at first
            entry->trigger();
            auto *view = window.dock<CountingView>();
            QVERIFY(view);
            QCOMPARE(view->shownRobot, window.session().name());
            QCOMPARE(view->shownProfile, std::optional(window.session().robotProfile().id));
            DisplayTick::instance().setQuiet(false); // a frame a tick
            view->ticks.clear();
            for (int i = 0; i < 8; ++i)
                window.refreshDisplay();
            QCOMPARE(view->ticks.size(), 2);
            QCOMPARE(view->ticks[1] - view->ticks[0], quint64(4));
            window.close();
        }
        // The layout saved with its tab in front: restored so, and made at start.
        MainWindow again(dashboardDocks() << kCountingRow);
        again.show();
        again.start();
        QTRY_VERIFY(again.dock<CountingView>());
        QVERIFY(again.findChild<QDockWidget *>("countingDock")->isVisible());
    }

    void settingsRestore()
    {
        {
            MainWindow window;
            window.show();
            window.start();
            window.findChild<QDockWidget *>("inspectorDock")->hide();
            ConnectionRequest r;
            r.transport = ConnectionRequest::Transport::Virtual;
            r.profile = oi::ProfileId::Create1;
            // The robot is reconnected there, and that is what is kept.
            emit window.dock<ConnectionBar>()->connectRequested(r);
            window.close();
        }
        MainWindow again;
        again.show();
        again.start();
        QVERIFY(again.findChild<QDockWidget *>("inspectorDock")->isHidden());
        QCOMPARE(again.dock<ConnectionBar>()->request().profile, std::optional<oi::ProfileId>(oi::ProfileId::Create1));
        QTRY_COMPARE_WITH_TIMEOUT(again.session().robotProfile().id, oi::ProfileId::Create1, 10000);
        again.resetLayout();
        QVERIFY(!again.findChild<QDockWidget *>("inspectorDock")->isHidden());
    }

    void badPortGivesOneClearError()
    {
        MainWindow window;
        window.show();
        window.start(oilink::LinkSettings::serial("/dev/roomba-does-not-exist", oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(!window.dock<ConnectionBar>()->errorText().isEmpty(), 10000);
        const QString error = window.dock<ConnectionBar>()->errorText();
        QVERIFY2(error.contains("/dev/roomba-does-not-exist"), qPrintable(error));
        // One line; the connection check then says why in the status bar.
        QCOMPARE(error.count('\n'), 0);
        QVERIFY(window.session().snapshotCount() == 0);
    }

    void recordThenReplayInTheWindow()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("class.oirec");
        MainWindow window;
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        window.startRecording(path);
        QTRY_VERIFY_WITH_TIMEOUT(window.session().recording().active, 10000);
        QVERIFY(window.recordAction()->isChecked());
        QTRY_VERIFY_WITH_TIMEOUT(window.session().recording().bytesWritten > 20000, 20000);
        window.stopRecording();
        QTRY_VERIFY_WITH_TIMEOUT(!window.session().recording().active, 10000);
        QVERIFY(!window.recordAction()->isChecked());
        QTRY_VERIFY2_WITH_TIMEOUT(window.statusBar()->currentMessage().contains("Recording saved")
                                      && window.statusBar()->currentMessage().contains("class.oirec"),
                                  qPrintable(window.statusBar()->currentMessage()), 10000);

        // File → Export recording as MCAP… sits beside the CSV export, and
        // what it runs writes an MCAP file of the recording.
        auto *exportMcap = window.findChild<QAction *>("exportMcapAction");
        QVERIFY(exportMcap);
        QVERIFY(window.menuBar()->actions().first()->menu()->actions().contains(exportMcap));
        QVERIFY(!exportMcap->text().isEmpty());
        const QString mcapPath = dir.filePath("class.mcap");
        QString damage;
        QCOMPARE(RecordingActions::exportRecordingMcap(path, mcapPath, mcap::Compression::Lz4, &damage), QString());
        QCOMPARE(damage, QString());
        QFile mcapFile(mcapPath);
        QVERIFY(mcapFile.open(QIODevice::ReadOnly));
        QVERIFY(mcapFile.readAll().startsWith("\x89MCAP0\r\n"));

        QString error;
        QVERIFY(!window.openRecording(dir.filePath("missing.oirec"), &error));
        QVERIFY2(error.contains("missing.oirec"), qPrintable(error));
        QVERIFY(window.openRecording(path, &error));
        QVERIFY(window.replayBar()->isVisible());
        QVERIFY(!window.recordAction()->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(window.replayBar()->position().frameCount > 50, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(window.session().snapshotCount() > 5, 10000);
        window.refreshDisplay();
        QVERIFY2(window.statusText().contains("REPLAY"), qPrintable(window.statusText()));
        // Recorded data is never called live, even while it plays.
        QCOMPARE(window.dock<SensorPlots>()->statusText(), QStringLiteral("Replay, not live"));
        QTRY_COMPARE_WITH_TIMEOUT((window.refreshDisplay(), window.robotList()->card(int(window.fleet().indexOf(&window.session())))->values().link),
                                  QStringLiteral("replaying"), 5000);
        // A replay has no robot to command: the mode buttons say so, the
        // projector view offers no Enter Safe, and none is sent.
        QCOMPARE(window.session().mode().reported(), std::optional(oi::OiMode::Passive));
        QVERIFY(!window.projectorView()->enterSafeButton()->isVisibleTo(window.projectorView()));
        QVERIFY(!window.session().requestMode(oi::Command::Safe));
        QVERIFY(!window.dock<ModePanel>()->button("safe")->isEnabled());
        QVERIFY2(window.dock<ModePanel>()->button("safe")->toolTip().contains("recording"),
                 qPrintable(window.dock<ModePanel>()->button("safe")->toolTip()));

        // Pause, then a frame forward and back with the bar's own buttons.
        auto *playPause = window.replayBar()->findChild<QToolButton *>("replayPlayPause");
        QTRY_VERIFY_WITH_TIMEOUT(window.replayBar()->position().playing, 10000);
        QTest::mouseClick(playPause, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!window.replayBar()->position().playing, 10000);
        const int paused = window.replayBar()->position().frame;
        QTest::mouseClick(window.replayBar()->findChild<QToolButton *>("replayStepForward"), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(window.replayBar()->position().frame, paused + 1, 10000);
        const quint64 before = window.session().snapshotCount();
        QTest::mouseClick(window.replayBar()->findChild<QToolButton *>("replayStepBack"), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(window.replayBar()->position().frame, paused, 10000);
        QTRY_COMPARE_WITH_TIMEOUT(window.session().snapshotCount(), before + 1, 10000);

        // At ten times the speed the history still runs on the recording's clock.
        auto *speed = window.replayBar()->findChild<QComboBox *>("replaySpeed");
        const int tenfold = speed->findData(10.0);
        QVERIFY(tenfold >= 0);
        speed->setCurrentIndex(tenfold);
        emit speed->activated(tenfold);
        QSignalSpy errors(&window.session(), &RobotSession::errorOccurred);
        QTest::mouseClick(playPause, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(window.replayBar()->position().finished, 20000);
        QCOMPARE(window.replayBar()->position().speed, 10.0);
        // At the end the diagram's banner, the gauges' banner, the plots'
        // badge and the status bar say together that the replay has ended.
        QTRY_VERIFY_WITH_TIMEOUT(window.robotDiagram()->isStale(), 10000);
        window.refreshDisplay();
        QCOMPARE(window.dock<SensorPlots>()->statusText(), QStringLiteral("Replay finished"));
        QVERIFY2(window.statusText().contains("REPLAY FINISHED"), qPrintable(window.statusText()));
        auto *banner = window.findChild<QLabel *>("staleBanner");
        QVERIFY(banner && banner->isVisible());
        QVERIFY2(banner->text().contains("recording has ended"), qPrintable(banner->text()));
        // The end is said as the end and nothing else (the link's side, on a
        // clock the test advances, is tst_recording's aReplaysEndIsNotARobotAsleep).
        QVERIFY2(errors.isEmpty(), qPrintable(errors.isEmpty() ? QString() : errors.first().first().toString()));
        QCOMPARE(window.dock<ConnectionBar>()->errorText(), QString());
        QTRY_COMPARE_WITH_TIMEOUT((window.refreshDisplay(), window.robotList()->card(int(window.fleet().indexOf(&window.session())))->values().link),
                                  QStringLiteral("replay finished"), 5000);
        QVERIFY2(window.statusText().contains("Link: replay finished"), qPrintable(window.statusText()));
        const double duration = window.replayBar()->position().durationUs / 1e6;
        QVERIFY2(std::abs(window.history().newestTime() - duration) < 0.15,
                 qPrintable(QString("newest sample at %1 s, recording %2 s long").arg(window.history().newestTime()).arg(duration)));
        // A step back starts the history afresh instead of running time backwards.
        QTest::mouseClick(window.replayBar()->findChild<QToolButton *>("replayStepBack"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(window.history().newestTime() < duration - 0.001, 10000);
        QVERIFY(window.history().oldestTime() >= window.history().newestTime() - 0.05);

        // File → Export recording as CSV… on a replay: a Save dialog for the
        // replayed file, where a typed name is written.
        // The dialog opens in the recording's folder: a name typed there is enough.
        const QString csv = dir.filePath("typed.csv");
        QString dialogTitle;
        bool dialogSaves = false;
        QTimer typeName;
        typeName.setInterval(20);
        connect(&typeName, &QTimer::timeout, &window, [&] {
            auto *dialog = qobject_cast<QFileDialog *>(QApplication::activeModalWidget());
            if (!dialog)
                return;
            typeName.stop();
            dialogTitle = dialog->windowTitle();
            dialogSaves = dialog->acceptMode() == QFileDialog::AcceptSave;
            auto *name = dialog->findChild<QLineEdit *>("fileNameEdit");
            QVERIFY(name);
            name->selectAll();
            QTest::keyClicks(name, QStringLiteral("typed.csv"));
            QTest::keyClick(name, Qt::Key_Return);
        });
        typeName.start();
        window.findChild<QAction *>("exportCsvAction")->trigger();
        QVERIFY2(dialogSaves, qPrintable(dialogTitle));
        QVERIFY2(dialogTitle.contains("class.oirec") && dialogTitle.contains("CSV"), qPrintable(dialogTitle));
        QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(csv), 10000);
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = file.readAll().split('\n');
        QVERIFY(lines.first().startsWith("time_s,bumps_wheel_drops"));
        QVERIFY2(!lines.first().contains("unused"), lines.first().constData()); // reserved bytes, always 0
        QCOMPARE(lines.size() - 2, window.replayBar()->position().frameCount); // header, trailing newline
        // A bad source leaves no file behind.
        const QString none = dir.filePath("none.csv");
        QVERIFY(!RecordingActions::exportRecordingCsv(dir.filePath("missing.oirec"), none).isEmpty());
        QVERIFY(!QFile::exists(none));
    }

    // M while recording: a marker on the frame on screen, its note typed in
    // the toolbar; the list and the plots show it. Replayed, the bar has its
    // ticks and full stop jumps to the next; compared with itself at a
    // marker, the second run lines up exactly; closing clears the overlay.
    // A replayed file that adds more markers than a recording holds: the
    // first 1,000 on the plots and in the list, said once how many were left
    // out, and M adds none.
    void aReplayWithTooManyMarkersSaysSo()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("crowded.oirec");
        QVERIFY(writeCrowdedRecording(path, oilink::kMaxMarkers + 40));
        MainWindow window;
        QSignalSpy said(window.markerActions(), &MarkerActions::message);
        window.show();
        window.start(oilink::LinkSettings::replayOf(path, oi::ProfileId::Create2, 115200, {7}));
        QTRY_COMPARE_WITH_TIMEOUT(window.dock<SensorPlots>()->stack()->markers().size(), oilink::kMaxMarkers, 10000);
        QCOMPARE(window.markerActions()->list()->table()->rowCount(), oilink::kMaxMarkers);
        QCOMPARE(said.size(), 1);
        QCOMPARE(said[0][0].toString(),
                 QString("crowded.oirec: 40 markers beyond the first 1000 were left out: a recording holds at most 1000"));
        QCOMPARE(window.markerActions()->drop(), 0);
        QCOMPARE(said.last()[0].toString(), QString("A recording holds at most 1000 markers."));
        QCOMPARE(window.session().markers().list().size(), oilink::kMaxMarkers);
    }

    void markersAndComparisonInTheWindow()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("marked.oirec");
        MainWindow window;
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QVERIFY(QTest::qWaitForWindowActive(&window));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        MarkerActions *markers = window.markerActions();
        // Not recording: M says what to do and keeps nothing.
        QTest::keyClick(window.robotDiagram(), Qt::Key_M);
        QVERIFY(window.session().markers().list().isEmpty());
        QVERIFY2(window.statusBar()->currentMessage().contains("Record"),
                 qPrintable(window.statusBar()->currentMessage()));

        window.startRecording(path);
        QTRY_VERIFY_WITH_TIMEOUT(window.session().recording().active, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(window.history().newestTime() > window.session().recording().startedSeconds + 0.3, 10000);
        QTest::keyClick(window.robotDiagram(), Qt::Key_M);
        QCOMPARE(window.session().markers().list().size(), 1);
        QLineEdit *note = markers->noteEditor()->field();
        QTRY_VERIFY(note->isVisible() && note->hasFocus());
        QTest::keyClicks(note, "hit the table leg");
        QTest::keyClick(note, Qt::Key_Return);
        QCOMPARE(window.session().markers().list().first().note, QString("hit the table leg"));
        QTRY_VERIFY(!note->isVisible()); // the toolbar lays itself out anew
        QCOMPARE(window.dock<SensorPlots>()->stack()->markers().size(), 1);
        QCOMPARE(window.dock<SensorPlots>()->stack()->markers().first().label, QString("hit the table leg"));
        QCOMPARE(window.dock<SensorPlots>()->stack()->markers().first().seconds,
                 window.session().markers().seconds(window.session().markers().list().first()));
        QCOMPARE(markers->list()->table()->item(0, 1)->text(), QString("hit the table leg"));
        for (int i = 0; i < 2; ++i) {
            const double after = window.history().newestTime() + 0.3;
            QTRY_VERIFY_WITH_TIMEOUT(window.history().newestTime() > after, 10000);
            QVERIFY(markers->drop() > 0);
        }
        QTRY_VERIFY_WITH_TIMEOUT(window.history().newestTime() > window.session().markers().seconds(
                                     window.session().markers().list().last()) + 0.3, 10000);
        window.stopRecording();
        QTRY_VERIFY_WITH_TIMEOUT(!window.session().recording().active, 10000);
        const QList<oilink::RecordingMarker> made = window.session().markers().list();
        QCOMPARE(made.size(), 3);

        QString error;
        QVERIFY2(window.openRecording(path, &error), qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(window.replayBar()->markers().size(), 3, 10000);
        QCOMPARE(window.replayBar()->markers().first().label, QString("hit the table leg"));
        QVERIFY(window.replayBar()->tickX(made[0].timeUs / 1e6) < window.replayBar()->tickX(made[2].timeUs / 1e6));
        QCOMPARE(markers->list()->markers(), made);
        // Paused at the start, full stop goes to the first marker.
        window.session().controlReplay(oilink::ReplayCommand::pause());
        window.session().controlReplay(oilink::ReplayCommand::seek(0));
        QTRY_VERIFY_WITH_TIMEOUT(!window.replayBar()->position().playing && window.replayBar()->position().positionUs == 0, 10000);
        QTest::keyClick(window.robotDiagram(), Qt::Key_Period);
        QTRY_COMPARE_WITH_TIMEOUT(window.replayBar()->position().positionUs, made[0].timeUs, 10000);
        QTest::mouseClick(window.replayBar()->findChild<QToolButton *>("replayNextMarker"), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(window.replayBar()->position().positionUs, made[1].timeUs, 10000);

        // The same file beside itself, lined up at the marker both hold: no shift.
        RunComparison *comparison = window.runComparison();
        QVERIFY(!comparison->open(dir.filePath("missing.oirec"), &error));
        QVERIFY2(error.contains("missing.oirec"), qPrintable(error));
        QVERIFY2(comparison->open(path, &error), qPrintable(error));
        QTRY_VERIFY(comparison->bar()->isVisible());
        QCOMPARE(window.dock<SensorPlots>()->stack()->comparisonHistory(), &comparison->run()->history());
        QVERIFY(!window.dock<OdometryMap>()->comparisonPath().isEmpty());
        QCOMPARE(comparison->sharedMarkers(), (QStringList{"hit the table leg", "#2", "#3"}));
        QComboBox *align = comparison->bar()->alignment();
        QCOMPARE(align->count(), 4);
        align->setCurrentIndex(1);
        emit align->activated(1);
        QCOMPARE(comparison->alignedAt(), QString("hit the table leg"));
        QCOMPARE(window.dock<SensorPlots>()->stack()->comparisonShiftSeconds(), 0.0);
        QTest::mouseClick(comparison->bar()->closeButton(), Qt::LeftButton);
        QCOMPARE(window.dock<SensorPlots>()->stack()->comparisonHistory(), nullptr);
        QVERIFY(window.dock<OdometryMap>()->comparisonPath().isEmpty());
        QTRY_VERIFY(!comparison->bar()->isVisible());
    }

    // A lesson step done while the robot records drops a marker naming the
    // step; without a recording it drops none.
    void lessonStepsAreMarkedWhileRecording()
    {
        QTemporaryDir dir;
        MainWindow window;
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        LessonRunner runner;
        window.markerActions()->markStepsOf(runner);
        Lesson lesson;
        lesson.steps = {LessonStep{}, LessonStep{}};
        for (LessonStep &step : lesson.steps)
            step.goal.kind = LessonGoal::Kind::All; // all of no goals: met at once
        // Each step is shown for its reading time before it is done.
        const double start = window.history().newestTime();
        const auto frame = [&](int read) {
            // A little over each reading time: sums of seconds are not exact.
            return LessonFrame{start + read * (LessonRunner::kReadSeconds + 0.1), window.session().latest(), {}, {}};
        };
        runner.start(lesson, window.session().robotProfile());
        runner.update(frame(0));
        runner.update(frame(1));
        QCOMPARE(runner.currentStep(), 1);
        QVERIFY(window.session().markers().list().isEmpty());

        window.startRecording(dir.filePath("lesson.oirec"));
        QTRY_VERIFY_WITH_TIMEOUT(window.session().recording().active, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(window.history().newestTime() > window.session().recording().startedSeconds, 10000);
        runner.update(frame(2)); // the second step shown...
        QVERIFY(!runner.isFinished());
        runner.update(frame(3)); // ...and read
        QVERIFY(runner.isFinished());
        QCOMPARE(window.session().markers().list().size(), 1);
        QCOMPARE(window.session().markers().list().first().note, QString("Lesson step 2 done"));
    }

    void languageSwitchesOnTheSpot()
    {
        MainWindow window;
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        auto *modes = window.findChild<QDockWidget *>("modeDock");
        QCOMPARE(modes->windowTitle(), QString("Modes"));

        // From the View menu, as a user does it.
        QAction *deutsch = nullptr;
        for (QAction *a : window.languageMenu()->actions())
            if (a->data().toString() == "de")
                deutsch = a;
        QVERIFY(deutsch);
        deutsch->trigger();
        QCOMPARE(window.language(), QString("de"));
        QCOMPARE(modes->windowTitle(), QString("Modi"));
        QVERIFY(deutsch->isChecked());
        QCOMPARE(QSettings().value("language").toString(), QString("de"));
        window.refreshDisplay();
        QVERIFY2(!window.statusText().contains("streaming"), qPrintable(window.statusText()));

        window.setLanguage("es");
        QCOMPARE(window.language(), QString("es"));
        QCOMPARE(modes->windowTitle(), QString("Modos"));

        window.setLanguage("en");
        QCOMPARE(modes->windowTitle(), QString("Modes"));
        window.refreshDisplay();
        QVERIFY(window.statusText().contains("streaming"));
        window.setLanguage(QString()); // the system's, which is English here
    }

    void linkErrorsSpeakTheLanguage()
    {
        MainWindow window;
        window.show();
        window.setLanguage("de");
        window.start(oilink::LinkSettings::serial("/dev/roomba-does-not-exist", oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(!window.dock<ConnectionBar>()->errorText().isEmpty(), 10000);
        const QString error = window.dock<ConnectionBar>()->errorText();
        QVERIFY2(error.contains("/dev/roomba-does-not-exist: Anschluss nicht vorhanden"), qPrintable(error));
        window.setLanguage(QString());
    }

    void f6VisitsEveryDock()
    {
        MainWindow window;
        window.resize(1400, 950);
        window.show();
        window.activateWindow();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_COMPARE_WITH_TIMEOUT(window.session().state(), oilink::LinkState::Streaming, 10000);
        const QList<QDockWidget *> docks = window.findChildren<QDockWidget *>();
        QSet<QDockWidget *> visited;
        for (int i = 0; i < docks.size(); ++i) {
            QWidget *focus = QApplication::focusWidget() ? QApplication::focusWidget() : &window;
            QTest::keyClick(focus, Qt::Key_F6);
            QDockWidget *dock = nullptr;
            for (QDockWidget *d : docks)
                if (d->isAncestorOf(QApplication::focusWidget()))
                    dock = d;
            QVERIFY2(dock, qPrintable(QString("F6 press %1 left the focus outside every dock").arg(i + 1)));
            QVERIFY2(dock->isVisible(), qPrintable(dock->objectName()));
            visited << dock;
        }
        QCOMPARE(visited.size(), docks.size());
        // Shift+F6 goes back the same way.
        QDockWidget *last = nullptr;
        for (QDockWidget *d : docks)
            if (d->isAncestorOf(QApplication::focusWidget()))
                last = d;
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_F6, Qt::ShiftModifier);
        QVERIFY(!last->isAncestorOf(QApplication::focusWidget()));
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_F6);
        QVERIFY(last->isAncestorOf(QApplication::focusWidget()));
    }

    // Every text in the whole window goes through a translator and is set
    // again when the language changes.
    void everyVisibleTextIsTranslatable()
    {
        MainWindow window;
        window.resize(1400, 950);
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(window.session().snapshotCount() > 10, 10000);
        window.refreshDisplay();
        // Brand names, languages in their own words, and the example songs'
        // titles, which are the files' content.
        const QStringList never{"Roomba 600 / Create 2", "Roomba 500", "Create", "Roomba 400-series (SCI, 2005)",
                                "English", "Deutsch", "Español", "C major scale", "Charge fanfare", "Happy birthday", "Ode to joy"};
        QStringList missed;
        {
            ScopedPseudoTranslation pseudo;
            QApplication::processEvents();
            window.refreshDisplay();
            for (QDockWidget *dock : window.findChildren<QDockWidget *>()) {
                dock->show();
                dock->raise();
                QApplication::processEvents();
                missed += untranslatedTexts(dock, never);
            }
            missed += untranslatedTexts(window.recordingToolBar(), never);
            for (QMenu *menu : window.findChildren<QMenu *>())
                for (QAction *a : menu->actions())
                    if (!a->isSeparator() && !never.contains(a->text()) && looksUntranslated(a->text()))
                        missed << "menu action: " + a->text();
        }
        missed.removeDuplicates();
        QVERIFY2(missed.isEmpty(), qPrintable(missed.join('\n')));
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_main_window.moc"
