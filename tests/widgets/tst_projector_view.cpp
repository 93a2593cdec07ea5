// SPDX-License-Identifier: GPL-3.0-or-later
// The projector view at 1920x1080: large type, white on black, the lesson's
// step or the robot alone; screenshots into ROOMBA_SCREENSHOTS when set.
#include "lesson_file.h"
#include "lesson_runner.h"
#include "lesson_step_view.h"
#include "projector_view.h"
#include "pseudo_translation.h" // tests/common
#include "robot_diagram.h"
#include "robot_session.h"
#include "transport_factory.h"

#include <QDir>
#include <QLabel>
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
