// SPDX-License-Identifier: GPL-3.0-or-later
// Every shipped lesson done to its end on the virtual robot from the
// projector view, with only what that screen offers: the step's button that
// carries, holds or lifts the virtual robot, the driving keys, and Enter for
// Safe. The step's words and the yellow line above them never disagree.
// One lesson per run (`lessonToTheEnd:NAME`): each takes half a minute, as a
// step stays up for LessonRunner::kReadSeconds.
#include "lesson_panel.h"
#include "lesson_runner.h"
#include "lesson_step_view.h"
#include "main_window.h"
#include "projector_view.h"
#include "robot_session.h"
#include "shipped_lessons.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>
#include <QPushButton>
#include <QTest>

using namespace std::chrono_literals;

namespace {

constexpr int kStepTimeoutMs = 30000;

struct ProjectorClass {
    MainWindow window;
    ProjectorView *projector = nullptr;

    const LessonRunner &runner() { return window.dock<LessonPanel>()->runner(); }

    bool start(const QString &lesson)
    {
        window.resize(1280, 720);
        window.show();
        window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        if (!QTest::qWaitFor([this] { return window.session().state() == oilink::LinkState::Streaming; }, 10000))
            return false;
        if (!window.dock<LessonPanel>()->openLesson(QStringLiteral(":/lessons/%1.json").arg(lesson)))
            return false;
        window.setProjectorView(true);
        projector = window.projectorView();
        return window.isProjectorView();
    }
    // The step's button, as a teacher presses it.
    bool place()
    {
        QPushButton *button = projector->stepView()->placementButton();
        if (!QTest::qWaitFor([&] { return button->isVisible(); }, 5000))
            return false;
        QTest::mouseClick(button, Qt::LeftButton);
        return true;
    }
    // Enter, while the projector offers Enter Safe.
    bool enterSafe()
    {
        if (window.session().mode().reported() == oi::OiMode::Safe)
            return true;
        if (!QTest::qWaitFor([&] { return projector->enterSafeButton()->isVisible(); }, 5000))
            return false;
        QTest::keyClick(projector, Qt::Key_Return);
        return QTest::qWaitFor([&] { return window.session().mode().reported() == oi::OiMode::Safe; }, 5000);
    }
    // A driving key held until the step's goal is met.
    bool holdUntilMet(Qt::Key key)
    {
        const int step = runner().currentStep();
        QTest::keyPress(projector, key);
        const bool met = QTest::qWaitFor(
            [&] { return runner().currentStep() != step || runner().secondsToRead() > 0; }, kStepTimeoutMs);
        QTest::keyRelease(projector, key);
        return met;
    }
    bool past(int step)
    {
        return QTest::qWaitFor([&] { return runner().currentStep() > step; }, kStepTimeoutMs);
    }
    QString failure(int step)
    {
        return QStringLiteral("stuck at step %1; yellow line: %2; mode %3")
            .arg(step + 1)
            .arg(projector->reasonText())
            .arg(int(window.session().mode().reported().value_or(oi::OiMode::Off)));
    }
};

#define DO(expr)                                                                                                    \
    QVERIFY2(expr, qPrintable(rig.failure(rig.runner().currentStep())))

} // namespace

class TestLessonsOnProjector : public QObject {
    Q_OBJECT
private slots:
    void lessonToTheEnd_data()
    {
        QTest::addColumn<QString>("name");
        for (const QString &path : lesson::shippedLessonPaths()) {
            const QString name = QFileInfo(path).baseName();
            QTest::addRow("%s", qPrintable(name)) << name;
        }
    }

    void lessonToTheEnd()
    {
        QFETCH(QString, name);
        ProjectorClass rig;
        QVERIFY(rig.start(name));

        if (name == "battery_current") {
            DO(rig.past(0)); // standing still, off the dock
            DO(rig.enterSafe());
            DO(rig.holdUntilMet(Qt::Key_Up));
            DO(rig.past(1));
            DO(rig.past(2));
        } else if (name == "bumpers_wheel_drops") {
            DO(rig.place());
            DO(rig.enterSafe());
            DO(rig.holdUntilMet(Qt::Key_Up));
            DO(rig.past(0));
            DO(rig.place());
            DO(rig.holdUntilMet(Qt::Key_Up));
            DO(rig.past(1));
            DO(rig.place());
            DO(rig.holdUntilMet(Qt::Key_Up));
            DO(rig.past(2));
            DO(rig.place()); // lifted: the wheels drop, Safe falls back to Passive
            DO(QTest::qWaitFor([&] { return rig.window.session().mode().ignoresMotion(); }, 5000));
            QVERIFY2(rig.projector->reasonText().contains("This step expects it"), qPrintable(rig.projector->reasonText()));
            DO(rig.past(3));
            DO(rig.place());
            DO(rig.past(4));
        } else if (name == "cliff_sensors") {
            DO(rig.past(0)); // on the floor
            DO(rig.place());
            DO(rig.enterSafe());
            DO(rig.holdUntilMet(Qt::Key_Up));
            DO(rig.past(1));
            // Stopped at the edge in Passive, as the step says: the yellow
            // line does not tell the class to carry it back yet.
            DO(rig.window.session().mode().ignoresMotion());
            const QString reason = rig.projector->reasonText();
            QVERIFY2(reason.contains("cliff") && reason.contains("This step expects it")
                         && !reason.contains("Carry it back"),
                     qPrintable(reason));
            if (const QString dir = qEnvironmentVariable("ROOMBA_SCREENSHOTS"); !dir.isEmpty()) {
                QTRY_VERIFY(rig.projector->stepView()->placementButton()->isVisible());
                rig.window.refreshDisplay();
                QApplication::processEvents();
                QVERIFY(rig.window.grab().save(QDir(dir).filePath("projector-1280x720-lesson.png")));
            }
            DO(rig.place()); // held further over the edge
            DO(rig.past(2));
            DO(rig.place()); // carried back onto the floor
            DO(rig.past(3));
        } else if (name == "light_bumpers_wall") {
            DO(rig.place());
            DO(rig.enterSafe());
            DO(rig.holdUntilMet(Qt::Key_Up));
            DO(rig.past(0));
            DO(rig.holdUntilMet(Qt::Key_Up));
            DO(rig.past(1));
            DO(rig.place());
            DO(rig.holdUntilMet(Qt::Key_Up));
            DO(rig.past(2));
            DO(rig.place());
            DO(rig.past(3));
        } else if (name == "encoders_distance_angle") {
            DO(rig.enterSafe());
            DO(rig.holdUntilMet(Qt::Key_Up));
            DO(rig.past(0));
            DO(rig.holdUntilMet(Qt::Key_Left));
            DO(rig.past(1));
            DO(rig.holdUntilMet(Qt::Key_Left));
            DO(rig.past(2));
        } else if (name == "ir_dock_virtual_wall") {
            DO(rig.place());
            DO(rig.past(0));
            DO(rig.place());
            DO(rig.past(1));
            DO(rig.place());
            DO(rig.enterSafe());
            DO(rig.holdUntilMet(Qt::Key_Up));
            DO(rig.past(2));
        } else {
            QFAIL(qPrintable("no scenario for " + name));
        }
        QVERIFY(rig.runner().isFinished());
        QTRY_VERIFY(rig.projector->headerText().contains("lesson complete"));
    }
};

QTEST_MAIN(TestLessonsOnProjector)
#include "tst_lessons_on_projector.moc"
