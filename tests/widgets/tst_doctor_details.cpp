// SPDX-License-Identifier: GPL-3.0-or-later
#include "doctor_details.h"
#include "sensor_scenes.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QTest>

class TestDoctorDetails : public QObject {
    Q_OBJECT
private slots:
    void oneLineAndWhatWasTried()
    {
        QWidget window;
        auto *details = new DoctorDetails(&window);
        auto *layout = new QHBoxLayout(&window);
        layout->addWidget(details, 1); // as in the status bar
        window.resize(720, 60);
        window.show();
        QVERIFY(!details->isVisible()); // nothing to say yet
        details->start();
        QVERIFY(details->isVisible());
        auto *line = details->findChild<QLabel *>("doctorSummary");
        auto *button = details->findChild<QPushButton *>("doctorDetailsButton");
        QCOMPARE(line->text(), QStringLiteral("Checking the connection…"));
        QVERIFY(!button->isEnabled());
        details->addStep(QStringLiteral("At 115200 baud: nothing comes back, with or without Start."));
        details->addStep(QStringLiteral("Pulsed the BRC pin to wake the robot."));
        details->addStep(QStringLiteral("At 115200 baud it answers after the pulse."));
        details->finish(QStringLiteral("The robot was asleep; a BRC pulse woke it."));
        QCOMPARE(line->text(), QStringLiteral("The robot was asleep; a BRC pulse woke it."));
        QVERIFY(button->isEnabled());
        // A status bar may cut the line: the tooltip has all of it, and the steps.
        QVERIFY(line->toolTip().startsWith(QStringLiteral("The robot was asleep; a BRC pulse woke it.\n\nAt 115200 baud")));
        sensor_scenes::saveScreenshot(window, QStringLiteral("doctor_line"));

        QTest::mouseClick(button, Qt::LeftButton);
        QWidget *view = details->detailsView();
        QTRY_VERIFY(view->isVisible());
        auto *steps = view->findChild<QListWidget *>();
        QCOMPARE(steps->count(), 3);
        QCOMPARE(steps->item(1)->text(), QStringLiteral("Pulsed the BRC pin to wake the robot."));
        sensor_scenes::saveScreenshot(*view, QStringLiteral("doctor_details"));

        details->clear();
        QVERIFY(!details->isVisible());
        QVERIFY(details->steps().isEmpty());
    }

    // A port that cannot even be opened: nothing was tried, so no empty box
    // under "What was tried"; what to do next is there instead.
    void nextStepsInsteadOfAnEmptyList()
    {
        DoctorDetails details;
        details.start();
        const QStringList next{QStringLiteral("/dev/ttyUSB7 does not exist."), QStringLiteral("Then press Connect to try again.")};
        details.finish(QStringLiteral("/dev/ttyUSB7: No such file or directory"), next);
        QCOMPARE(details.nextSteps(), next);
        QWidget *view = details.detailsView();
        view->show();
        auto *nextLabel = view->findChild<QLabel *>("doctorNextSteps");
        QVERIFY(nextLabel->isVisible());
        QVERIFY2(nextLabel->text().startsWith(QStringLiteral("What to do next:")), qPrintable(nextLabel->text()));
        QVERIFY(nextLabel->text().contains(next[0]));
        QVERIFY(!view->findChild<QListWidget *>()->isVisible());
        for (QLabel *label : view->findChildren<QLabel *>())
            QVERIFY2(!(label->isVisible() && label->text() == QStringLiteral("What was tried:")), "an empty list's heading shows");
        auto *line = details.findChild<QLabel *>("doctorSummary");
        QVERIFY2(line->toolTip().contains(next[0]), qPrintable(line->toolTip()));
        sensor_scenes::saveScreenshot(*view, QStringLiteral("doctor_next_steps"));
    }

    // One line per robot: only the selected robot's shows, and it keeps
    // its finding while another robot is selected.
    void shownOnlyForTheSelectedRobot()
    {
        QWidget window;
        auto *layout = new QHBoxLayout(&window);
        auto *first = new DoctorDetails(&window);
        auto *second = new DoctorDetails(&window);
        layout->addWidget(first, 1);
        layout->addWidget(second, 1);
        window.show();
        second->setShownRobot(false);
        first->finish(QStringLiteral("Nothing comes back."));
        second->finish(QStringLiteral("The robot was asleep."));
        QVERIFY(first->isVisible());
        QVERIFY(!second->isVisible());

        first->setShownRobot(false);
        second->setShownRobot(true);
        QVERIFY(!first->isVisible());
        QVERIFY(second->isVisible());
        QCOMPARE(first->summary(), QStringLiteral("Nothing comes back."));
        second->clear();
        QVERIFY(!second->isVisible()); // nothing to say
    }
};

QTEST_MAIN(TestDoctorDetails)
#include "tst_doctor_details.moc"
