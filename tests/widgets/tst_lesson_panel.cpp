// SPDX-License-Identifier: GPL-3.0-or-later
// The lesson panel: a step turns green when the robot's frames meet its goal
// and the lesson moves on; a bad lesson file gives a clear error and leaves
// the panel as it was; every text goes through the translator; and a
// screenshot of each shipped lesson's first step on a live virtual robot.
#include "lesson_panel.h"
#include "lesson_step_view.h"
#include "markup_lesson.h" // tests/common
#include "pseudo_translation.h" // tests/common
#include "robot_diagram.h"
#include "robot_session.h"
#include "sensor_plots.h"
#include "shipped_lessons.h"
#include "transport_factory.h"

#include <QComboBox>
#include <QDir>
#include <QListWidget>
#include <QTemporaryDir>
#include <QTest>

namespace {

const QString kBumpers = QStringLiteral(":/lessons/bumpers_wheel_drops.json");

oi::SensorSnapshot frameWith(std::initializer_list<std::pair<int, int>> values)
{
    oi::SensorSnapshot s(oi::profile(oi::ProfileId::Create2));
    for (const oi::PacketInfo &p : s.robotProfile().packets())
        s.set(p.id, 0);
    for (const auto &[id, v] : values)
        s.set(id, v);
    return s;
}

void saveShot(QWidget &w, const QString &name)
{
    const QString dir = qEnvironmentVariable("ROOMBA_SCREENSHOTS");
    if (dir.isEmpty())
        return;
    QDir().mkpath(dir);
    QCoreApplication::processEvents(); // lay out what the step added
    QVERIFY(w.grab().save(QDir(dir).filePath(name + ".png")));
}

} // namespace

class TestLessonPanel : public QObject {
    Q_OBJECT

    // Opens the bumpers lesson on `robot`, and its first step (Bump Left) is met and read.
    static void passFirstBumperStep(LessonPanel &panel, RobotSession &robot)
    {
        panel.setRobot(&robot);
        QVERIFY(panel.openLesson(kBumpers));
        emit robot.frameReceived(1.0, frameWith({{7, oi::bit::BumpLeft}}));
        emit robot.frameReceived(1.0 + LessonRunner::kReadSeconds, frameWith({}));
        QCOMPARE(panel.runner().currentStep(), 1);
    }
private slots:
    // No fresh data (a replay that ended, a quiet link): the diagram's STALE
    // banner and the plot's badge say the same, and both come back together.
    void staleDataReadsTheSameInEveryView()
    {
        LessonStepView view;
        const oi::SensorSnapshot frame = frameWith({});
        view.refresh(frame, false, nullptr);
        QVERIFY(!view.diagram()->isStale());
        QCOMPARE(view.plots()->statusText(), QStringLiteral("Live"));
        view.refresh(frame, true, nullptr);
        QVERIFY(view.diagram()->isStale());
        QCOMPARE(view.plots()->statusText(), QStringLiteral("Not live: no fresh data"));
        view.refresh(frame, false, nullptr);
        QVERIFY(!view.diagram()->isStale());
        QCOMPARE(view.plots()->statusText(), QStringLiteral("Live"));
    }

    void stepTurnsGreenAndLessonMovesOn()
    {
        RobotSession robot;
        RobotLesson lesson;
        LessonPanel panel(lesson);
        panel.setRobot(&robot);
        QVERIFY(panel.openLesson(kBumpers));
        QCOMPARE(panel.stepList()->count(), 5);
        QCOMPARE(panel.stepView()->headingText(), QStringLiteral("Step 1 of 5"));
        QCOMPARE(panel.stepView()->diagram()->highlightedParts(), QStringList{"bump_left"});
        QVERIFY(panel.stepView()->goalText().contains("Bump Left on"));

        emit robot.frameReceived(1.0, frameWith({{7, oi::bit::BumpRight}})); // the wrong half
        QCOMPARE(panel.runner().currentStep(), 0);
        emit robot.frameReceived(1.1, frameWith({{7, oi::bit::BumpLeft}}));
        // Met, and left up until it has been read.
        QCOMPARE(panel.runner().currentStep(), 0);
        panel.show();
        panel.refresh();
        QCOMPARE(panel.stepView()->progressText(), QStringLiteral("Done · next in 6 s"));
        emit robot.frameReceived(1.0 + LessonRunner::kReadSeconds, frameWith({}));
        QCOMPARE(panel.runner().currentStep(), 1);
        QListWidgetItem *first = panel.stepList()->item(0);
        QVERIFY(first->text().startsWith(QStringLiteral("✔")));
        QCOMPARE(first->background().color(), QColor(0x1b, 0x5e, 0x20));
        QVERIFY(panel.stepList()->item(1)->text().startsWith(QStringLiteral("▶")));
        QCOMPARE(panel.stepView()->headingText(), QStringLiteral("Step 2 of 5"));
        QCOMPARE(panel.stepView()->diagram()->highlightedParts(), QStringList{"bump_right"});

        // The rest, to the end, each step read for its time: the last holds for a second.
        double t = 10;
        for (int bits : std::initializer_list<int>{oi::bit::BumpRight, oi::bit::BumpRight | oi::bit::BumpLeft,
                                                   oi::bit::WheelDropLeft | oi::bit::WheelDropRight}) {
            emit robot.frameReceived(t, frameWith({{7, bits}}));
            emit robot.frameReceived(t + LessonRunner::kReadSeconds, frameWith({}));
            t += 10;
        }
        QCOMPARE(panel.runner().currentStep(), 4);
        emit robot.frameReceived(t, frameWith({}));
        emit robot.frameReceived(t + 0.9, frameWith({}));
        panel.refresh();
        QCOMPARE(panel.stepView()->progressText(), QStringLiteral("90 %"));
        emit robot.frameReceived(t + LessonRunner::kReadSeconds - 0.1, frameWith({}));
        QCOMPARE(panel.runner().currentStep(), 4);
        emit robot.frameReceived(t + LessonRunner::kReadSeconds, frameWith({}));
        QVERIFY(panel.runner().isFinished());
        QVERIFY(panel.noticeText().contains("Lesson complete"));
        for (int i = 0; i < 5; ++i)
            QVERIFY(panel.stepList()->item(i)->text().startsWith(QStringLiteral("✔")));
    }

    // The step list wraps each step's first sentence whole, never cuts it.
    // The lesson is the robots', not the panel's: a panel made again (the
    // dock closed and opened) finds it at the same step, and a second panel
    // shows the same.
    void theLessonOutlivesItsPanel()
    {
        RobotSession robot;
        RobotLesson lesson;
        {
            LessonPanel panel(lesson);
            passFirstBumperStep(panel, robot);
        }
        QCOMPARE(lesson.runner().currentStep(), 1);
        QCOMPARE(lesson.robot(), &robot);
        LessonPanel again(lesson), second(lesson);
        for (LessonPanel *panel : {&again, &second}) {
            QCOMPARE(panel->lessonPath(), kBumpers);
            QCOMPARE(panel->stepList()->count(), 5);
            QVERIFY(panel->stepList()->item(0)->text().startsWith(QStringLiteral("✔")));
            QCOMPARE(panel->stepView()->headingText(), QStringLiteral("Step 2 of 5"));
        }
        // Frames still reach the lesson with no panel in between; both panels follow.
        emit robot.frameReceived(10.0, frameWith({{7, oi::bit::BumpRight}}));
        emit robot.frameReceived(10.0 + LessonRunner::kReadSeconds, frameWith({}));
        QCOMPARE(again.stepView()->headingText(), QStringLiteral("Step 3 of 5"));
        QCOMPARE(second.stepView()->headingText(), QStringLiteral("Step 3 of 5"));
    }

    void stepListShowsWholeSentences()
    {
        RobotLesson lesson;
        LessonPanel panel(lesson);
        panel.resize(700, 500);
        panel.show();
        QVERIFY(panel.openLesson(QStringLiteral(":/lessons/cliff_sensors.json")));
        QVERIFY(panel.stepList()->item(0)->text().endsWith(
            QStringLiteral("1. Under the front of the robot, four cliff sensors shine infrared light at the floor "
                           "and measure how much comes back")));
        QCoreApplication::processEvents();
        const QListWidget *list = panel.stepList();
        for (int i = 0; i < list->count(); ++i) {
            const QListWidgetItem *item = list->item(i);
            QVERIFY(!item->text().contains(QStringLiteral("…")));
            // Tall enough for every wrapped line.
            const QRect rect = list->visualItemRect(item);
            const QRect needed = list->fontMetrics().boundingRect(QRect(0, 0, rect.width(), 10000),
                                                                  Qt::TextWordWrap, item->text());
            QVERIFY2(rect.height() >= needed.height(), qPrintable(item->text()));
        }
    }

    void badLessonFileLeavesThePanelAsItWas()
    {
        RobotSession robot;
        RobotLesson lesson;
        LessonPanel panel(lesson);
        passFirstBumperStep(panel, robot);

        QTemporaryDir dir;
        const QString path = dir.filePath("my_lesson.json");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(R"({"format":"roomba-lesson","version":1,"title":"Mine",
                      "steps":[{"text":"Drive","goal":{"drive_mm":"far"}}]})");
        file.close();
        QString error;
        QVERIFY(!panel.openLesson(path, &error));
        QVERIFY2(panel.errorText().contains("my_lesson.json: step 1, \"goal.drive_mm\""), qPrintable(panel.errorText()));
        QCOMPARE(panel.lessonPath(), kBumpers);
        QCOMPARE(panel.runner().currentStep(), 1);
        QCOMPARE(panel.runner().lesson().title, QStringLiteral("Bumpers and wheel drops"));
        QCOMPARE(panel.chooser()->currentData().toString(), kBumpers);
        QCOMPARE(panel.stepView()->headingText(), QStringLiteral("Step 2 of 5"));
        QVERIFY(panel.stepList()->item(0)->text().startsWith(QStringLiteral("✔")));

        // A good file then opens, and the error goes.
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(R"({"format":"roomba-lesson","version":1,"title":"Mine",
                      "steps":[{"text":"Drive","goal":{"drive_mm":500}}]})");
        file.close();
        QVERIFY(panel.openLesson(path));
        QVERIFY(panel.errorText().isEmpty());
        QCOMPARE(panel.chooser()->currentText(), QStringLiteral("Mine (my_lesson.json)"));
    }

    // A lesson file is shared: what its texts hold is shown as written, never
    // as rich text, which opens the files its pictures name (a named pipe
    // froze the window for good, /dev/zero filled its memory).
    void lessonTextIsShownAsWritten()
    {
        QTemporaryDir dir;
        const QString path = writeMarkupLesson(dir.path());
        QVERIFY(!path.isEmpty());
        RobotLesson lesson;
        LessonPanel panel(lesson);
        panel.resize(1200, 800);
        panel.show();
        QVERIFY(panel.openLesson(path));
        QStringList wrong;
        QCOMPARE(labelsShowingMarkup(&panel, &wrong), (QStringList{"lessonStepText", "lessonSummary"}));
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join('\n')));
    }

    void chooserOpensAShippedLesson()
    {
        RobotLesson lesson;
        LessonPanel panel(lesson);
        QCOMPARE(panel.chooser()->count(), 1 + lesson::shippedLessonPaths().size());
        QVERIFY(!panel.runner().isRunning());
        const int cliffs = panel.chooser()->findData(":/lessons/cliff_sensors.json");
        panel.chooser()->setCurrentIndex(cliffs);
        emit panel.chooser()->activated(cliffs);
        QCOMPARE(panel.runner().lesson().title, QStringLiteral("Cliff sensors"));
        panel.chooser()->setCurrentIndex(0);
        emit panel.chooser()->activated(0);
        QVERIFY(!panel.runner().isRunning());
    }

    void everyTextIsTranslated()
    {
        RobotSession robot;
        RobotLesson lesson;
        LessonPanel panel(lesson);
        panel.setRobot(&robot);
        panel.resize(1200, 800);
        panel.show();
        QVERIFY(panel.openLesson(":/lessons/encoders_distance_angle.json"));
        panel.refresh();
        ScopedPseudoTranslation pseudo;
        QCoreApplication::processEvents();
        panel.refresh();
        const QStringList untranslated = untranslatedTexts(&panel, {"mm", "°"});
        QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
        QVERIFY(panel.stepView()->stepText().startsWith(kPseudoOpen));
        QVERIFY(panel.stepList()->item(0)->text().contains(kPseudoOpen));
        QVERIFY(panel.chooser()->itemText(1).startsWith(kPseudoOpen));
    }

    // Each shipped lesson's first step on a live virtual robot, for looking at.
    void firstStepsOnAVirtualRobot()
    {
        RobotSession robot;
        robot.setTransportFactory([](const oilink::LinkSettings &s) { return transports::createTransport(s, s.baud); });
        robot.connectTo(oilink::LinkSettings{});
        QTRY_VERIFY_WITH_TIMEOUT(robot.isLive(), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(robot.snapshotCount() > 200, 20000); // a few seconds to plot
        RobotLesson lesson;
        LessonPanel panel(lesson);
        panel.setRobot(&robot);
        panel.resize(1400, 900);
        panel.show();
        for (const QString &path : lesson::shippedLessonPaths()) {
            // The virtual robot starts in sight of its dock, which would pass
            // the IR lesson's first step before the picture is taken.
            const QSignalBlocker holdFrames(&robot);
            QVERIFY(panel.openLesson(path));
            QCOMPARE(panel.runner().currentStep(), 0);
            panel.refresh();
            for (const QString &key : panel.stepView()->readoutKeys())
                QVERIFY2(!panel.stepView()->readoutText(key).isEmpty(), qPrintable(key));
            saveShot(panel, "lesson_" + path.section('/', -1).section('.', 0, 0));
        }
        robot.closeAndWait();
    }
};

QTEST_MAIN(TestLessonPanel)
#include "tst_lesson_panel.moc"
