// SPDX-License-Identifier: GPL-3.0-or-later
// The drive pad on its own: its texts follow the language, it is reachable
// with Tab and it tells a screen reader what it asks for. Driving through
// the session (mouse, keys, stops) is in tests/app/tst_teleop.cpp.
#include "drive_pad.h"

#include "keyboard_focus.h"
#include "pseudo_translation.h"

#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QPushButton>
#include <QSlider>
#include <QTest>

class TestDrivePad : public QObject {
    Q_OBJECT
private slots:
    void translatesOnTheSpot()
    {
        DrivePad pad;
        pad.resize(320, 380);
        pad.setMapping(DrivePad::Mapping::DriveDirect);
        pad.show();
        QVERIFY(QTest::qWaitForWindowExposed(&pad));
        QWidget *area = pad.padArea();
        QTest::mousePress(area, Qt::LeftButton, {}, pad.areaPointFor({0, 0.8}));
        QVERIFY(!pad.currentCommand().isStop());
        auto *mapping = pad.findChild<QComboBox *>("mapping");
        if (qEnvironmentVariableIsSet("ROOMBA_SCREENSHOTS"))
            QVERIFY(pad.grab().save(QDir(qEnvironmentVariable("ROOMBA_SCREENSHOTS")).filePath("drive_pad_driving.png")));
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            QStringList untranslated = untranslatedTexts(&pad);
            QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
            // The combo keeps its choice and data; the readout follows.
            QCOMPARE(pad.mapping(), DrivePad::Mapping::DriveDirect);
            QCOMPARE(mapping->currentData().toInt(), int(DrivePad::Mapping::DriveDirect));
            QVERIFY(!pad.currentCommand().isStop());
            QVERIFY(area->accessibleDescription().startsWith(kPseudoOpen));

            // Passive mode shows its bar: translated as well.
            pad.setPassive(true);
            QCoreApplication::processEvents();
            untranslated = untranslatedTexts(&pad);
            QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
            if (qEnvironmentVariableIsSet("ROOMBA_SCREENSHOTS"))
                QVERIFY(pad.grab().save(QDir(qEnvironmentVariable("ROOMBA_SCREENSHOTS")).filePath("drive_pad_pseudo.png")));
        }
        QCoreApplication::processEvents();
        QCOMPARE(pad.findChild<QPushButton *>("enterSafe")->text(), QStringLiteral("Enter Safe"));
        QCOMPARE(mapping->itemText(int(DrivePad::Mapping::Drive)), QStringLiteral("Drive (137): speed and radius"));
        QCOMPARE(area->accessibleName(), QStringLiteral("Drive pad"));
    }

    void tabReachesEveryControlInVisualOrder()
    {
        DrivePad pad;
        pad.resize(320, 380);
        pad.show();
        pad.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&pad));
        auto *mapping = pad.findChild<QComboBox *>("mapping");
        auto *speed = pad.findChild<QSlider *>("speedLimit");
        auto *enterSafe = pad.findChild<QPushButton *>("enterSafe");
        // The "Move exactly" row under the pad.
        QWidget *direction = pad.findChild<QWidget *>("moveDirection");
        QWidget *amount = pad.findChild<QWidget *>("moveAmount");
        QWidget *go = pad.findChild<QWidget *>("moveGo");
        QCOMPARE(tabCycle(&pad, mapping), (QList<QWidget *>{mapping, speed, pad.padArea(), direction, amount, go}));

        // Passive: the pad refuses to drive, so Tab goes to Enter Safe instead.
        pad.setPassive(true);
        QCOMPARE(tabCycle(&pad, mapping), (QList<QWidget *>{mapping, speed, enterSafe, direction, amount, go}));
    }

    void describesItsCommand()
    {
        DrivePad pad;
        pad.resize(320, 380);
        pad.show();
        QVERIFY(QTest::qWaitForWindowExposed(&pad));
        QWidget *area = pad.padArea();
        QVERIFY(area->focusPolicy() & Qt::TabFocus);
        QCOMPARE(area->accessibleName(), QStringLiteral("Drive pad"));
        QCOMPARE(area->accessibleDescription(), QStringLiteral("Stopped"));

        QTest::mousePress(area, Qt::LeftButton, {}, pad.areaPointFor({0, 0.9}));
        QCOMPARE(area->accessibleDescription(), DrivePad::spokenDescription(pad.currentCommand()));
        QVERIFY2(area->accessibleDescription().startsWith(QStringLiteral("Forward 1")), qPrintable(area->accessibleDescription()));
        QVERIFY(area->accessibleDescription().endsWith(QStringLiteral(", straight")));
        QTest::mouseMove(area, pad.areaPointFor({-0.5, 0.7}));
        QVERIFY2(area->accessibleDescription().startsWith(QStringLiteral("Forward ")), qPrintable(area->accessibleDescription()));
        QVERIFY2(area->accessibleDescription().contains(QStringLiteral("turning left")), qPrintable(area->accessibleDescription()));
        QCOMPARE(area->accessibleDescription(), DrivePad::spokenDescription(pad.currentCommand()));
        QTest::mouseRelease(area, Qt::LeftButton, {}, pad.areaPointFor({-0.5, 0.7}));
        QCOMPARE(area->accessibleDescription(), QStringLiteral("Stopped"));

        pad.setPassive(true);
        QCOMPARE(area->accessibleDescription(), QStringLiteral("Passive mode: enter Safe to drive"));
    }

    void spokenDescriptions()
    {
        MotionCommand c;
        QCOMPARE(DrivePad::spokenDescription(c), QStringLiteral("Stopped"));
        c.velocity = -150;
        c.radius = -400;
        QCOMPARE(DrivePad::spokenDescription(c), QStringLiteral("Backward 150 mm/s, turning right (radius 400 mm)"));
        c.velocity = 90;
        c.radius = oi::kRadiusTurnInPlaceClockwise;
        QCOMPARE(DrivePad::spokenDescription(c), QStringLiteral("Turning in place clockwise, 90 mm/s"));
        MotionCommand wheels{MotionCommand::Kind::DriveDirect};
        wheels.right = 120;
        wheels.left = -30;
        QCOMPARE(DrivePad::spokenDescription(wheels), QStringLiteral("Right wheel 120 mm/s, left wheel -30 mm/s"));
    }
};

QTEST_MAIN(TestDrivePad)
#include "tst_drive_pad.moc"
