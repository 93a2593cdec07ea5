// SPDX-License-Identifier: GPL-3.0-or-later
// The projector view at 1920x1080: large type, white on black, the lesson's
// step or the robot alone; screenshots into ROOMBA_SCREENSHOTS when set.
#include "lesson_file.h"
#include "lesson_runner.h"
#include "lesson_step_view.h"
#include "markup_lesson.h" // tests/common
#include "projector_view.h"
#include "pseudo_translation.h" // tests/common
#include "robot_diagram.h"
#include "robot_session.h"
#include "transport_factory.h"

#include <QDir>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

namespace {

void saveShot(QWidget &w, const QString &name)
{
    const QString dir = qEnvironmentVariable("ROOMBA_SCREENSHOTS");
    if (dir.isEmpty())
        return;
    QDir().mkpath(dir);
    QCoreApplication::processEvents();
    QVERIFY(w.grab().save(QDir(dir).filePath(name + ".png")));
}

} // namespace

class TestProjectorView : public QObject {
    Q_OBJECT
private slots:
    void lessonAndRobotAt1920x1080()
    {
        RobotSession robot;
        robot.setName("Robot 1");
        robot.setTransportFactory([](const oilink::LinkSettings &s) { return transports::createTransport(s, s.baud); });
        robot.connectTo(oilink::LinkSettings{});
        QTRY_VERIFY_WITH_TIMEOUT(robot.isLive(), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(robot.snapshotCount() > 200, 20000); // a few seconds to plot

        QWidget window;
        window.resize(1920, 1080);
        ProjectorView view(&window);
        view.setRobot(robot.name(), robot.robotProfile(), &robot.history());
        LessonRunner runner;
        runner.start(*loadLessonFile(":/lessons/cliff_sensors.json"), robot.robotProfile());
        view.setLesson(&runner);
        window.show();
        view.show();
        QCOMPARE(view.size(), QSize(1920, 1080)); // it covers its window
        view.refresh(robot.latest(), robot.isLive());
        QCOMPARE(view.stepView()->headingText(), QString("Step 1 of 4"));
        QCOMPARE(view.stepView()->diagram()->highlightedParts().size(), 4);
        QVERIFY(view.headerText().contains("Cliff sensors"));
        QVERIFY(view.headerText().contains("Robot 1"));

        // Readable from the back row: the step's text at least 30 px high,
        // white on black.
        const auto *text = view.findChild<QLabel *>("lessonStepText");
        QVERIFY(QFontInfo(text->font()).pixelSize() >= 30);
        QCOMPARE(view.palette().color(QPalette::Window), QColor(Qt::black));
        QCOMPARE(text->palette().color(QPalette::WindowText), QColor(Qt::white));
        // Nothing is cut off: the step's text fits in its label.
        QCoreApplication::processEvents();
        QVERIFY(text->heightForWidth(text->width()) <= text->height());
        QVERIFY(view.stepView()->diagram()->height() >= 400);
        saveShot(view, "projector_1920x1080_lesson");

        // No lesson: the robot alone, with its readouts.
        runner.stop();
        view.lessonChanged();
        view.refresh(robot.latest(), robot.isLive());
        QCOMPARE(view.stepView()->headingText(), QString());
        QCOMPARE(view.stepView()->readoutKeys(), ProjectorView::robotReadouts());
        QVERIFY(view.stepView()->readoutText("voltage").endsWith("mV"));
        saveShot(view, "projector_1920x1080_robot");

        ScopedPseudoTranslation pseudo;
        QCoreApplication::processEvents();
        const QStringList untranslated = untranslatedTexts(&view, {"Robot 1", "mV", "mA", "mm/s"});
        QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
        robot.closeAndWait();
    }

    // The header names the mode the session reports; in Passive a line says
    // why, with Enter Safe (the button or the Enter key), and only then.
    // The lesson's title and step from a shared file, on the projector as
    // written: no rich text, so no picture it names is opened.
    void lessonTextIsShownAsWritten()
    {
        QTemporaryDir dir;
        const QString path = writeMarkupLesson(dir.path());
        QVERIFY(!path.isEmpty());
        QWidget window;
        window.resize(1920, 1080);
        ProjectorView view(&window);
        view.setRobot("Robot 1", oi::profile(oi::ProfileId::Create2), nullptr);
        LessonRunner runner;
        runner.start(*loadLessonFile(path), oi::profile(oi::ProfileId::Create2));
        view.setLesson(&runner);
        window.show();
        view.show();
        QStringList wrong;
        QCOMPARE(labelsShowingMarkup(&view, &wrong), (QStringList{"lessonStepText", "projectorHeader"}));
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join('\n')));
    }

    void modeReasonAndEnterSafe_data()
    {
        QTest::addColumn<QSize>("screen");
        QTest::newRow("1280x720") << QSize(1280, 720);
        QTest::newRow("1920x1080") << QSize(1920, 1080);
    }
    void modeReasonAndEnterSafe()
    {
        QFETCH(QSize, screen);
        const oi::RobotProfile &create2 = oi::profile(oi::ProfileId::Create2);
        const auto frame = [&](oi::OiMode mode, bool cliff) {
            oi::SensorSnapshot s(create2);
            s.set(35, int(mode));
            for (int id : {7, 9, 10, 11, 12, 34})
                s.set(id, 0);
            s.set(10, cliff ? 1 : 0);
            return s;
        };
        const QDateTime at(QDate(2026, 1, 5), QTime(12, 3, 4));
        RobotMode mode;
        mode.observe(frame(oi::OiMode::Safe, false), at.toMSecsSinceEpoch());

        QWidget window;
        window.resize(screen);
        ProjectorView view(&window);
        view.setRobot("Robot 1", create2, nullptr);
        window.show();
        view.show();
        QSignalSpy safe(&view, &ProjectorView::safeRequested);
        view.setMode(mode);
        view.refresh(frame(oi::OiMode::Safe, false), true);
        QVERIFY(view.headerText().contains(" · Safe"));
        QCOMPARE(view.reasonText(), QString());
        QVERIFY(!view.enterSafeButton()->isVisible());
        QTest::keyClick(&view, Qt::Key_Return);
        QCOMPARE(safe.count(), 0); // nothing to enter

        mode.observe(frame(oi::OiMode::Passive, true), at.toMSecsSinceEpoch());
        view.setMode(mode);
        QVERIFY(view.headerText().contains(" · Passive"));
        QCOMPARE(view.reasonText(), QString("A cliff (front left) dropped it to Passive at 12:03:04. Carry it back "
                                            "from the edge, then Enter Safe."));
        QVERIFY(view.enterSafeButton()->isVisible());
        QTest::mouseClick(view.enterSafeButton(), Qt::LeftButton);
        QCOMPARE(safe.count(), 1);
        QTest::keyClick(&view, Qt::Key_Return);
        QCOMPARE(safe.count(), 2);
        // The reason and its button fit beside each other, text whole.
        QCoreApplication::processEvents();
        const auto *reason = view.findChild<QLabel *>("projectorReason");
        QVERIFY(reason->heightForWidth(reason->width()) <= reason->height());
        QVERIFY(view.enterSafeButton()->geometry().right() <= view.width());
        saveShot(view, QStringLiteral("projector_%1x%2_passive").arg(screen.width()).arg(screen.height()));

        // No live data: nothing can be entered, and the header says so.
        view.refresh(frame(oi::OiMode::Passive, true), false);
        QVERIFY(!view.enterSafeButton()->isVisible());
        QVERIFY(view.headerText().contains("NO LIVE DATA"));
    }

    // On its dock: Safe refused is said with Full as the way off, and Enter
    // Safe is not offered; Full left on the dock is warned about.
    void dockWordsWithoutEnterSafe()
    {
        const oi::RobotProfile &create2 = oi::profile(oi::ProfileId::Create2);
        const auto frame = [&](oi::OiMode mode) {
            oi::SensorSnapshot s(create2);
            s.set(35, int(mode));
            for (int id : {7, 9, 10, 11, 12})
                s.set(id, 0);
            s.set(34, int(oi::ChargingSource::HomeBase));
            return s;
        };
        const qint64 at = QDateTime(QDate(2026, 1, 5), QTime(12, 3, 4)).toMSecsSinceEpoch();
        RobotMode mode;
        mode.observe(frame(oi::OiMode::Passive), at);
        mode.asked(oi::Command::Safe, QDateTime::fromMSecsSinceEpoch(at));
        for (int i = 0; i < RobotMode::kRefusedAfterFrames; ++i)
            mode.observe(frame(oi::OiMode::Passive), at + 15 * i);

        QWidget window;
        window.resize(1280, 720);
        ProjectorView view(&window);
        view.setRobot("Robot 1", create2, nullptr);
        window.show();
        view.show();
        view.setMode(mode);
        view.refresh(frame(oi::OiMode::Passive), true);
        QCOMPARE(view.reasonText(), QString("The robot is on its dock: Safe mode is refused on the charger (12:03:04). "
                                            "Lift it off the dock, or drive it off in Full (Full does not stop at cliffs or wheel drops)."));
        QVERIFY(!view.enterSafeButton()->isVisible());

        mode.asked(oi::Command::Full, QDateTime::fromMSecsSinceEpoch(at + 1000));
        mode.observe(frame(oi::OiMode::Full), at + 1000);
        mode.observe(frame(oi::OiMode::Full), at + 1000 + RobotMode::kNotChargingAfterMs);
        view.setMode(mode);
        view.refresh(frame(oi::OiMode::Full), true);
        QCOMPARE(view.reasonText(), QString("Full mode on the dock: the battery does not charge, it drains. Enter "
                                            "Passive to charge it, or drive it off the dock."));
        QVERIFY(!view.enterSafeButton()->isVisible());
    }

    // On a 1280×720 projector the type is smaller, in proportion, so that the
    // step, the plot with its time axis and the readouts all fit; the hint
    // sits at the foot, clear of the header.
    void lessonAt1280x720()
    {
        RobotSession robot;
        robot.setName("Robot 1");
        robot.setTransportFactory([](const oilink::LinkSettings &s) { return transports::createTransport(s, s.baud); });
        robot.connectTo(oilink::LinkSettings{});
        QTRY_VERIFY_WITH_TIMEOUT(robot.snapshotCount() > 150, 20000); // a line to plot

        QWidget window;
        window.resize(1920, 1080);
        ProjectorView view(&window);
        view.setRobot(robot.name(), robot.robotProfile(), &robot.history());
        LessonRunner runner;
        runner.start(*loadLessonFile(":/lessons/cliff_sensors.json"), robot.robotProfile());
        view.setLesson(&runner);
        window.show();
        view.show();
        const qreal fullHd = view.scale();
        window.resize(1280, 720);
        QTRY_COMPARE(view.size(), QSize(1280, 720));
        QVERIFY2(view.scale() < fullHd * 0.75, qPrintable(QString::number(view.scale())));
        view.refresh(robot.latest(), robot.isLive());
        QCoreApplication::processEvents();

        const auto *header = view.findChild<QLabel *>("projectorHeader");
        const auto *hint = view.findChild<QLabel *>("projectorHint");
        QVERIFY(!header->geometry().intersects(hint->geometry()));
        QVERIFY(header->heightForWidth(header->width()) <= header->height());
        const auto *text = view.findChild<QLabel *>("lessonStepText");
        QVERIFY(text->heightForWidth(text->width()) <= text->height());
        // Every part whole inside the view: the plot (its time axis at its
        // foot), the readouts, the hint.
        QStringList outside;
        for (const QWidget *w : view.findChildren<QWidget *>()) {
            if (!w->isVisible() || w->isWindow())
                continue;
            const QRect at(w->mapTo(&view, QPoint(0, 0)), w->size());
            if (!view.rect().contains(at))
                outside << QStringLiteral("%1 %2 at %3,%4 %5x%6")
                               .arg(w->metaObject()->className(), w->objectName())
                               .arg(at.x()).arg(at.y()).arg(at.width()).arg(at.height());
        }
        QVERIFY2(outside.isEmpty(), qPrintable(outside.join('\n')));
        saveShot(view, "projector_1280x720_lesson");
        robot.closeAndWait();
    }
};

QTEST_MAIN(TestProjectorView)
#include "tst_projector_view.moc"
