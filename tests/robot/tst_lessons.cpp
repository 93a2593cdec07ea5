// SPDX-License-Identifier: GPL-3.0-or-later
// Lessons without a window: every shipped lesson from its first step to its
// last on a virtual robot the test drives by bytes with a clock it advances,
// the file format's errors, and the texts' translation.
#include "command_encoder.h"
#include "lesson_file.h"
#include "lesson_runner.h"
#include "not_regular_files.h" // tests/common
#include "pseudo_translation.h" // tests/common
#include "robot_mode.h"
#include "robot_odometry.h"
#include "shipped_lessons.h"
#include "stream_packets.h"
#include "stream_parser.h"
#include "virtual_robot.h"
#include "world.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <numbers>

using namespace std::chrono_literals;
using oi::ProfileId;

Q_DECLARE_METATYPE(oi::ProfileId)

namespace {

oi::Pose poseAt(double x, double y, double headingDeg)
{
    oi::Pose p;
    p.xMm = x;
    p.yMm = y;
    p.thetaRad = headingDeg * std::numbers::pi / 180;
    return p;
}

// The classroom, one virtual robot streaming to a parser, odometry and the
// lesson runner, as the dashboard feeds them, on the robot's own clock.
struct Classroom {
    explicit Classroom(const oi::RobotProfile &profile) : robot(profile), encoder(profile), parser(profile)
    {
        robot.setWorld(sim::World::classroom());
        robot.placeAt(poseAt(0, 0, 0));
        odometry.setStart(robot.truePose());
        odometry.reset();
        parser.setSnapshotHandler([this](const oi::SensorSnapshot &s, oi::FrameKind kind) {
            odometry.update(s);
            const double seconds = std::chrono::duration<double>(robot.now()).count();
            if (kind != oi::FrameKind::Stream) {
                angleReads.read(seconds, s.angleDegrees());
                return;
            }
            mode.observe(s, QDateTime(QDate(2026, 1, 5), QTime(12, 0)).addMSecs(qint64(seconds * 1000)).toMSecsSinceEpoch());
            runner.update({seconds, s, odometry.pose(), robot.truePose()});
        });
        send(encoder.start());
        send(encoder.safe());
        // As the session streams: a Create 1 all but its angle, read apart.
        send(encoder.stream(oilink::chooseStreamPackets(profile, robot.baud())));
    }

    // A Create 1's angle, when the session would ask for it
    // (oi::AngleReadSchedule), with the stream paused as the link does.
    void readAngleIfDue()
    {
        const double seconds = std::chrono::duration<double>(robot.now()).count();
        if (robot.robotProfile().id != ProfileId::Create1 || !angleReads.due(seconds))
            return;
        send(encoder.pauseResumeStream(0));
        const std::uint8_t angle[] = {20};
        parser.expectReply(angle);
        send(encoder.sensors(20));
        send(encoder.pauseResumeStream(1));
    }

    void send(const oi::EncodeResult &r)
    {
        QVERIFY2(r.ok(), r.ok() ? "" : r.error().describe().c_str());
        robot.receive(r.value());
        collect();
    }
    void collect() { parser.feed(robot.takeOutput()); }
    void run(sim::Microseconds dt)
    {
        for (; dt > 0us; dt -= 15ms) {
            robot.advance(std::min<sim::Microseconds>(dt, 15ms));
            collect();
            readAngleIfDue();
        }
    }
    // Runs until the lesson has moved past `step`, at most `limit`.
    bool runPast(int step, sim::Microseconds limit = 20s)
    {
        for (sim::Microseconds t = 0us; t < limit && runner.currentStep() <= step; t += 15ms) {
            robot.advance(15ms);
            collect();
            readAngleIfDue();
        }
        return runner.currentStep() > step;
    }
    // Picks the robot up and puts it down somewhere else, as a hand on the map does.
    void carryTo(double x, double y, double headingDeg)
    {
        robot.placeAt(poseAt(x, y, headingDeg));
        odometry.setStart(robot.truePose());
        odometry.reset();
    }
    void drive(int velocity, int radius = oi::kRadiusStraight)
    {
        send(encoder.safe()); // back to Safe, should a safety stop have left it in Passive
        send(encoder.drive(velocity, radius));
    }
    void stop() { send(encoder.drive(0, oi::kRadiusStraight)); }

    sim::VirtualRobot robot;
    oi::CommandEncoder encoder;
    oi::StreamParser parser;
    RobotOdometry odometry;
    oi::AngleReadSchedule angleReads;
    RobotMode mode; // as the session would see it
    LessonRunner runner;
};

Lesson shipped(const QString &name)
{
    QString error;
    const std::optional<Lesson> lesson = loadLessonFile(QStringLiteral(":/lessons/%1.json").arg(name), &error);
    if (!lesson)
        qFatal("%s", qPrintable(error));
    return *lesson;
}

#define PAST(step, ...)                                                                                      \
    QVERIFY2(room.runPast(step __VA_OPT__(, ) __VA_ARGS__),                                                  \
             qPrintable(QStringLiteral("stuck at step %1 of %2").arg(room.runner.currentStep() + 1)          \
                            .arg(room.runner.lesson().steps.size())))

} // namespace

class TestLessons : public QObject {
    Q_OBJECT
private slots:
    void shippedLessonsLoad()
    {
        QCOMPARE(lesson::shippedLessonPaths().size(), 6);
        for (const QString &path : lesson::shippedLessonPaths()) {
            QString error;
            const std::optional<Lesson> lesson = loadLessonFile(path, &error);
            QVERIFY2(lesson, qPrintable(error));
            QVERIFY(!lesson->steps.isEmpty());
            // Distance (19) and angle (20) count only since the last frame:
            // plotted, they read as a flat line near 0 labelled like a total.
            for (const LessonStep &step : lesson->steps)
                QVERIFY2(!step.plot.contains("distance") && !step.plot.contains("angle"), qPrintable(path));
        }
    }

    void shippedLessonPasses_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<ProfileId>("profile");
        for (const QString &path : lesson::shippedLessonPaths()) {
            const QString name = path.section('/', -1).section('.', 0, 0);
            for (ProfileId id : {ProfileId::Create2, ProfileId::Roomba500, ProfileId::Create1})
                if (shipped(name).suits(oi::profile(id)))
                    QTest::addRow("%s-%s", qPrintable(name), oi::profile(id).key.data()) << name << id;
        }
    }

    void shippedLessonPasses()
    {
        QFETCH(QString, name);
        QFETCH(ProfileId, profile);
        Classroom room(oi::profile(profile));
        QSignalSpy done(&room.runner, &LessonRunner::stepDone);
        QSignalSpy finished(&room.runner, &LessonRunner::finished);
        const Lesson lesson = shipped(name);
        room.carryTo(1700, 0, 0); // in the open, out of the dock's reach
        room.runner.start(lesson, oi::profile(profile));
        room.run(100ms);
        QCOMPARE(room.runner.currentStep(), 0); // nothing is done by standing in the open

        if (name == "bumpers_wheel_drops") {
            room.carryTo(0, 1200, 60); // the left wall at the left front
            room.drive(100);
            PAST(0);
            room.carryTo(0, 1200, 120); // and at the right front
            room.drive(100);
            PAST(1);
            room.carryTo(0, 1200, 90); // head on
            room.drive(100);
            PAST(2);
            room.stop();
            room.robot.setWheelsLifted(true, true);
            PAST(3);
            room.robot.setWheelsLifted(false, false);
            room.carryTo(0, 0, 0);
            PAST(4);
        } else if (name == "cliff_sensors") {
            PAST(0);
            room.carryTo(1800, -1100, 0); // facing the stage edge
            room.drive(100);
            PAST(1);
            room.carryTo(room.robot.truePose().xMm + 40, -1100, 0); // held further over the edge
            PAST(2);
            room.carryTo(1500, -1100, 0);
            PAST(3);
        } else if (name == "light_bumpers_wall") {
            room.carryTo(0, 1000, 90); // facing the left wall
            room.drive(50);
            PAST(0);
            PAST(1);
            room.stop();
            room.carryTo(1500, 1500 - 170 - 30, 180); // the wall on its right, 3 cm away
            room.drive(100);
            PAST(2);
            room.carryTo(room.robot.truePose().xMm, 1315, 180); // closer
            PAST(3);
        } else if (name == "encoders_distance_angle") {
            room.drive(200);
            PAST(0);
            room.drive(100, oi::kRadiusTurnInPlaceCounterClockwise);
            PAST(1);
            room.run(1s);
            QVERIFY(room.runner.trueTurnedDegrees()); // the virtual robot's truth beside odometry
            // A Create 1's heading lags a turn by up to one reading of its angle.
            const double lag = profile == ProfileId::Create1 ? oi::AngleReadSchedule::kDegreesPerRead : 0;
            QVERIFY(std::abs(*room.runner.trueTurnedDegrees() - room.runner.turnedDegrees()) < 20 + lag);
            PAST(2);
        } else if (name == "battery_current") {
            PAST(0);
            room.drive(300);
            PAST(1);
            room.stop();
            PAST(2);
        } else if (name == "ir_dock_virtual_wall") {
            room.carryTo(300, 0, 180); // a metre in front of the dock, facing it
            PAST(0);
            room.carryTo(2300, -200, 0); // in the virtual wall's beam
            PAST(1);
            room.carryTo(-770, 0, 180); // on the dock, nose first
            PAST(2);
        } else {
            QFAIL(qPrintable("no scenario for " + name));
        }
        QVERIFY(room.runner.isFinished());
        QCOMPARE(finished.count(), 1);
        QCOMPARE(done.count(), lesson.steps.size());
        for (int i = 0; i < done.count(); ++i)
            QCOMPARE(done.at(i).at(0).toInt(), i);
    }

    // A hold starts again when the condition breaks.
    void holdRestartsWhenBroken()
    {
        const std::optional<Lesson> lesson = lessonFromJson(R"({"format":"roomba-lesson","version":1,
            "title":"t","steps":[{"text":"x","goal":{"packet":"wall_signal","above":100,"for_seconds":0.5}}]})");
        QVERIFY(lesson);
        LessonRunner runner;
        runner.start(*lesson, oi::profile(ProfileId::Create2));
        auto frame = [&](double t, int wall) {
            LessonFrame f;
            f.seconds = t;
            f.snapshot.set(27, wall);
            runner.update(f);
        };
        frame(0.0, 200);
        frame(0.4, 200);
        QCOMPARE(runner.progress(), 0.8);
        frame(0.45, 50); // broken
        frame(0.5, 200);
        frame(0.9, 200);
        QVERIFY(!runner.isFinished());
        QCOMPARE(runner.secondsToRead(), 0.0);
        frame(1.0, 200);
        // Met, and shown until it has been read; met once is met.
        QCOMPARE(runner.progress(), 1.0);
        QCOMPARE(runner.secondsToRead(), LessonRunner::kReadSeconds - 1.0);
        QVERIFY(!runner.isFinished());
        frame(LessonRunner::kReadSeconds - 0.1, 50);
        QVERIFY(!runner.isFinished());
        frame(LessonRunner::kReadSeconds, 50);
        QVERIFY(runner.isFinished());
    }

    // The cliff lesson's first step is true on the floor: it stays up until
    // it has been read, on the robot's clock, then moves on by itself.
    void aStepAlreadyTrueWaitsToBeRead()
    {
        Classroom room(oi::profile(ProfileId::Create2));
        room.carryTo(1700, 0, 0);
        room.runner.start(shipped("cliff_sensors"), oi::profile(ProfileId::Create2));
        room.run(3s); // the goal holds for 2 s: met
        QCOMPARE(room.runner.currentStep(), 0);
        QCOMPARE(room.runner.progress(), 1.0);
        QVERIFY(room.runner.secondsToRead() > 2 && room.runner.secondsToRead() < 3.1);
        room.run(2900ms);
        QCOMPARE(room.runner.currentStep(), 0);
        room.run(200ms);
        QCOMPARE(room.runner.currentStep(), 1);
        QCOMPARE(room.runner.secondsToRead(), 0.0);
    }

    // Driven at the stage edge at an angle, a side cliff sensor finds it
    // first: Safe drops to Passive and the front-sensor goal is out of
    // reach. The lesson says why and what to do.
    void cliffGoalOutOfReachAtAnAngle()
    {
        Classroom room(oi::profile(ProfileId::Create2));
        room.carryTo(1700, 0, 0);
        const Lesson lesson = shipped("cliff_sensors");
        room.runner.start(lesson, oi::profile(ProfileId::Create2));
        PAST(0);
        const LessonGoal &goal = lesson.steps[1].goal;
        const auto outOfReach = [&] {
            return room.mode.outOfReach(lesson::goalPackets(goal), lesson::goalDrives(goal));
        };
        room.carryTo(1850, -1200, 45); // the edge ahead, the robot turned left of it
        room.drive(100);
        QVERIFY(outOfReach().isEmpty());
        for (int i = 0; i < 400 && room.mode.reported() != oi::OiMode::Passive; ++i)
            room.run(15ms);
        QCOMPARE(room.mode.reported(), std::optional(oi::OiMode::Passive));
        QCOMPARE(room.runner.currentStep(), 1); // no front sensor saw the edge
        QVERIFY2(outOfReach().startsWith("Out of reach: A cliff (right) dropped it to Passive at 12:00:"),
                 qPrintable(outOfReach()));
        QVERIFY(outOfReach().contains("drive at the edge head on"));
        // Head on, as it says: the goal is met.
        room.carryTo(1800, -1100, 0);
        room.run(45ms);
        QVERIFY2(outOfReach().isEmpty(), qPrintable(outOfReach())); // back on the floor: nothing in the way
        room.drive(100);
        PAST(1);
    }

    void badFiles_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("expected");
        const QByteArray head = R"({"format":"roomba-lesson","version":1,"title":"T","steps":[)";
        auto step = [&](const QByteArray &goal, const QByteArray &extra = {}) {
            return head + R"({"text":"a","goal":{"packet":"wall","equals":1}},{"text":"b",)" + extra
                   + R"("goal":)" + goal + "}]}";
        };
        QTest::newRow("not json") << QByteArray("{\n\"format\": ") << "line 2";
        QTest::newRow("format") << QByteArray(R"({"format":"roomba-room","version":1})") << "\"format\"";
        QTest::newRow("version") << QByteArray(R"({"format":"roomba-lesson","version":7})") << "\"version\"";
        QTest::newRow("no steps") << QByteArray(R"({"format":"roomba-lesson","version":1,"title":"T","steps":[]})")
                                  << "\"steps\"";
        QTest::newRow("unknown packet") << step(R"({"packet":"bump_lef","bit":"bump_left"})")
                                        << "step 2, \"goal.packet\" \"bump_lef\" is not a packet key";
        QTest::newRow("unknown bit") << step(R"({"packet":"bumps_wheel_drops","bit":"bump_middle"})")
                                     << "step 2, \"goal.bit\"";
        QTest::newRow("two kinds") << step(R"({"packet":"wall","equals":1,"drive_mm":100})") << "step 2, \"goal\"";
        QTest::newRow("no condition") << step(R"({"packet":"wall"})") << "step 2, \"goal\"";
        QTest::newRow("bad hold") << step(R"({"packet":"wall","equals":1,"for_seconds":-1})")
                                  << "step 2, \"goal.for_seconds\"";
        QTest::newRow("bad part") << step(R"({"drive_mm":100})", R"("highlight":["nose"],)")
                                  << "step 2, \"highlight\" \"nose\"";
        QTest::newRow("bad plot") << step(R"({"drive_mm":100})", R"("plot":["driven_mm"],)")
                                  << "step 2, \"plot\" \"driven_mm\"";
        QTest::newRow("unknown field") << step(R"({"turn_degrees":90})", R"("txet":"c",)") << "step 2, \"txet\"";
        QTest::newRow("nested") << step(R"({"any":[{"packet":"wall","equals":1},{"packet":"wall","ir":"dock"}]})")
                                << "step 2, \"goal.any[1].ir\"";
        QTest::newRow("placement without label")
            << step(R"({"drive_mm":100})", R"("virtual_robot":{"forward_mm":40},)") << "step 2, \"virtual_robot.label\"";
        QTest::newRow("placement doing nothing")
            << step(R"({"drive_mm":100})", R"("virtual_robot":{"label":"Carry it"},)")
            << "step 2, \"virtual_robot\" needs \"place\", \"forward_mm\" or \"lift\"";
        QTest::newRow("placement off the map")
            << step(R"({"drive_mm":100})", R"("virtual_robot":{"label":"Carry it","place":[1,2]},)")
            << "step 2, \"virtual_robot.place\" must be [x_mm, y_mm, heading_degrees]";
        QTest::newRow("placement too far")
            << step(R"({"drive_mm":100})", R"("virtual_robot":{"label":"Carry it","forward_mm":9000},)")
            << "step 2, \"virtual_robot.forward_mm\" 9000 must be a number from -2000 to 2000";
        QTest::newRow("placement lift")
            << step(R"({"drive_mm":100})", R"("virtual_robot":{"label":"Lift it","lift":"yes"},)")
            << "step 2, \"virtual_robot.lift\" must be true or false";
        QTest::newRow("bad profile")
            << QByteArray(R"({"format":"roomba-lesson","version":1,"title":"T","profiles":["roomba900"],"steps":[]})")
            << "\"profiles\" \"roomba900\"";
    }

    void badFiles()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, expected);
        QTemporaryDir dir;
        const QString path = dir.filePath("broken_lesson.json");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(json);
        file.close();
        QString error;
        QVERIFY(!loadLessonFile(path, &error));
        QVERIFY2(error.startsWith("broken_lesson.json: "), qPrintable(error));
        QVERIFY2(error.contains(expected), qPrintable(error));
    }

    void missingFileSaysSo()
    {
        QString error;
        QVERIFY(!loadLessonFile("/nonexistent/lesson.json", &error));
        QVERIFY2(error.startsWith("lesson.json: "), qPrintable(error));
    }

    // A lesson someone sent that is a named pipe, a device or too large is
    // refused at once with the file's name and the limit: without the check a
    // pipe blocked the program for good and /dev/zero was read until memory ran out.
    void aFileThatIsNoLessonIsRefusedUnread()
    {
        QTemporaryDir dir;
        const NotRegularFiles no = makeNotRegularFiles(dir.path(), "json");
        QVERIFY(!no.pipe.isEmpty());
        const QString big = dir.filePath("big.json");
        QFile file(big);
        QVERIFY(file.open(QIODevice::WriteOnly) && file.resize(2 << 20));
        file.close();
        QString error;
        QVERIFY(!loadLessonFile(big, &error));
        QCOMPARE(error, QString("big.json: 2 MB, larger than the 1 MB this program reads of such a file"));
        QVERIFY(!loadLessonFile(no.device, &error));
        QCOMPARE(error, QString("zero.json: not a regular file but a device"));
        QVERIFY(!loadLessonFile(no.pipe, &error));
        QCOMPARE(error, QString("pipe.json: not a regular file but a named pipe"));
    }

    // Every text of every shipped lesson is in lesson_texts.cpp, so lupdate
    // finds it and tst_translations catches a missing translation.
    void shippedTextsAreMarkedForTranslation()
    {
        const QStringList marked = lesson::shippedTexts();
        for (const QString &path : lesson::shippedLessonPaths()) {
            const Lesson lesson = *loadLessonFile(path);
            QStringList texts = {lesson.title, lesson.summary};
            for (const LessonStep &step : lesson.steps) {
                texts << step.text;
                if (step.virtualRobot)
                    texts << step.virtualRobot->label;
            }
            for (const QString &text : texts)
                QVERIFY2(marked.contains(text),
                         qPrintable(QStringLiteral("%1: run resources/lessons/lesson_texts.py: %2").arg(path, text)));
        }
    }

    void textsGoThroughTheTranslator()
    {
        const Lesson lesson = shipped("cliff_sensors");
        ScopedPseudoTranslation pseudo;
        QCOMPARE(lesson::translated(lesson.title), kPseudoOpen + lesson.title + kPseudoClose);
        QCOMPARE(lesson::translated(lesson.steps.first().text), kPseudoOpen + lesson.steps.first().text + kPseudoClose);
    }

    // A lesson that needs light bumpers does not suit a Create.
    void lessonsSayWhichRobotsTheySuit()
    {
        QVERIFY(!shipped("light_bumpers_wall").suits(oi::profile(ProfileId::Create1)));
        QVERIFY(shipped("light_bumpers_wall").suits(oi::profile(ProfileId::Create2)));
        QVERIFY(shipped("encoders_distance_angle").suits(oi::profile(ProfileId::Create1)));
    }
};

QTEST_MAIN(TestLessons)
#include "tst_lessons.moc"
