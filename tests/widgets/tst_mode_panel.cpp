// SPDX-License-Identifier: GPL-3.0-or-later
#include "mode_panel.h"
#include "pseudo_translation.h"
#include "sensor_scenes.h"

#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

using namespace oi;

namespace {

QString bytesText(const QList<QVariant> &signal)
{
    QStringList parts;
    for (char c : signal.at(0).toByteArray())
        parts << QString::number(static_cast<unsigned char>(c));
    return parts.join(' ');
}

SensorSnapshot modeSnapshot(const RobotProfile &p, OiMode mode)
{
    SensorSnapshot s(p);
    s.set(35, int(mode));
    for (int id = 7; id <= 14; ++id)
        s.set(id, 0);
    s.set(34, 0);
    return s;
}

// The widgets Tab visits from `first` until focus comes round again.
QList<QWidget *> tabWalk(QWidget *window, QWidget *first)
{
    window->activateWindow();
    if (!QTest::qWaitForWindowActive(window))
        return {};
    first->setFocus(Qt::TabFocusReason);
    QList<QWidget *> seen;
    while (QWidget *w = QApplication::focusWidget()) {
        if (seen.contains(w) || seen.size() > 100)
            break;
        seen << w;
        QTest::keyClick(w, Qt::Key_Tab);
    }
    return seen;
}

} // namespace

class TestModePanel : public QObject {
    Q_OBJECT
private slots:
    void buttonsSendExactBytes_data()
    {
        QTest::addColumn<QString>("profile");
        QTest::addColumn<QString>("button");
        QTest::addColumn<QString>("bytes");
        QTest::newRow("start") << "create2" << "start" << "128";
        QTest::newRow("passive") << "create2" << "passive" << "128";
        QTest::newRow("safe") << "create2" << "safe" << "131";
        QTest::newRow("full") << "create2" << "full" << "132";
        QTest::newRow("stop") << "create2" << "stop" << "173";
        QTest::newRow("reset") << "roomba500" << "reset" << "7";
        QTest::newRow("power") << "roomba500" << "power" << "133";
        QTest::newRow("clean") << "create2" << "clean" << "135";
        QTest::newRow("spot") << "create2" << "spot" << "134";
        QTest::newRow("max") << "create2" << "max" << "136";
        QTest::newRow("seek dock") << "create2" << "seek-dock" << "143";
        QTest::newRow("cover") << "create1" << "cover" << "135";
        QTest::newRow("cover and dock") << "create1" << "cover-and-dock" << "143";
        QTest::newRow("spot create") << "create1" << "spot" << "134";
        QTest::newRow("demo") << "create1" << "demo" << "136 0";
    }
    void buttonsSendExactBytes()
    {
        QFETCH(QString, profile);
        QFETCH(QString, button);
        QFETCH(QString, bytes);
        ModePanel panel;
        panel.setFullModeConfirmation([](QWidget *) { return true; });
        panel.setProfile(*profileByKey(profile.toStdString()));
        QSignalSpy spy(&panel, &ModePanel::sendRequested);
        QPushButton *b = panel.button(button);
        QVERIFY(b);
        QVERIFY(b->isEnabled());
        QTest::mouseClick(b, Qt::LeftButton);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(bytesText(spy.at(0)), bytes);
    }

    void demoChoice()
    {
        ModePanel panel;
        panel.setProfile(profile(ProfileId::Create1));
        auto *combo = panel.findChild<QComboBox *>("demoChoice");
        QVERIFY(combo);
        combo->setCurrentIndex(0); // abort
        QSignalSpy spy(&panel, &ModePanel::sendRequested);
        QTest::mouseClick(panel.button("demo"), Qt::LeftButton);
        QCOMPARE(bytesText(spy.at(0)), QString("136 255"));
        combo->setCurrentIndex(10); // Banjo
        QTest::mouseClick(panel.button("demo"), Qt::LeftButton);
        QCOMPARE(bytesText(spy.at(1)), QString("136 9"));
    }

    void fullAsksFirst()
    {
        ModePanel panel;
        int asked = 0;
        bool answer = false;
        panel.setFullModeConfirmation([&](QWidget *) {
            ++asked;
            return answer;
        });
        QSignalSpy spy(&panel, &ModePanel::sendRequested);
        QTest::mouseClick(panel.button("full"), Qt::LeftButton);
        QCOMPARE(asked, 1);
        QCOMPARE(spy.count(), 0);
        answer = true;
        QTest::mouseClick(panel.button("full"), Qt::LeftButton);
        QCOMPARE(asked, 2);
        QCOMPARE(spy.count(), 1);
        // Safe does not ask.
        QTest::mouseClick(panel.button("safe"), Qt::LeftButton);
        QCOMPARE(asked, 2);
        QCOMPARE(spy.count(), 2);
    }

    void missingCommandsDisabledWithReason()
    {
        ModePanel panel;
        panel.setProfile(profile(ProfileId::Create1));
        for (const char *name : {"reset", "stop", "power", "clean", "max", "seek-dock"}) {
            QVERIFY2(!panel.button(name)->isEnabled(), name);
            QVERIFY2(panel.button(name)->toolTip().contains("is not available on the Create"), name);
        }
        QVERIFY(panel.button("demo")->isEnabled());
        panel.setProfile(profile(ProfileId::Create2));
        QVERIFY(panel.button("seek-dock")->isEnabled());
        QVERIFY(!panel.button("demo")->isEnabled());
        QVERIFY(panel.button("demo")->toolTip().contains("not available on the Roomba 600 / Create 2"));
    }

    // Without a robot to reach, nothing is accepted silently: every button
    // is disabled and says why; with one again, they work as before.
    void noRobotToCommandDisablesEveryButton()
    {
        ModePanel panel;
        QSignalSpy sent(&panel, &ModePanel::sendRequested);
        const QString why = "Not connected: connect to the robot first.";
        panel.setUnavailable(why);
        for (const char *name : {"start", "passive", "safe", "full", "stop", "clean", "seek-dock"}) {
            QVERIFY2(!panel.button(name)->isEnabled(), name);
            QCOMPARE(panel.button(name)->toolTip(), why);
        }
        QTest::mouseClick(panel.button("safe"), Qt::LeftButton);
        QCOMPARE(sent.count(), 0);
        // A command the profile lacks still says that first.
        panel.setProfile(profile(ProfileId::Create1));
        QVERIFY(panel.button("clean")->toolTip().contains("is not available on the Create"));

        panel.setProfile(profile(ProfileId::Create2));
        panel.setUnavailable({});
        QVERIFY(panel.button("safe")->isEnabled());
        QTest::mouseClick(panel.button("safe"), Qt::LeftButton);
        QCOMPARE(sent.count(), 1);
        QCOMPARE(bytesText(sent.at(0)), QString("131"));
    }

    void highlightsCurrentMode()
    {
        ModePanel panel;
        QVERIFY(!panel.highlightedMode());
        panel.setSnapshot(modeSnapshot(profile(ProfileId::Create2), OiMode::Full));
        QCOMPARE(panel.highlightedMode(), std::optional<OiMode>(OiMode::Full));
        QVERIFY(!panel.button("full")->styleSheet().isEmpty());
        QVERIFY(panel.button("safe")->styleSheet().isEmpty());
        QCOMPARE(panel.findChild<QLabel *>("modeLabel")->text(), QString("Mode: Full"));
    }

    void explainsSafetyDrop_data()
    {
        QTest::addColumn<int>("packet");
        QTest::addColumn<int>("value");
        QTest::addColumn<QString>("reason");
        QTest::newRow("cliff") << 10 << 1 << "(cliff)";
        QTest::newRow("wheel drop") << 7 << 0x08 << "(wheel drop)";
        QTest::newRow("charger") << 34 << 0x02 << "(charger)";
    }
    void explainsSafetyDrop()
    {
        QFETCH(int, packet);
        QFETCH(int, value);
        QFETCH(QString, reason);
        const RobotProfile &p = profile(ProfileId::Create2);
        ModePanel panel;
        panel.setSnapshot(modeSnapshot(p, OiMode::Safe));
        QVERIFY(panel.safetyMessage().isEmpty());
        SensorSnapshot dropped = modeSnapshot(p, OiMode::Passive);
        dropped.set(packet, value);
        panel.setSnapshot(dropped);
        QVERIFY2(panel.safetyMessage().contains(reason), qPrintable(panel.safetyMessage()));
        QVERIFY(panel.safetyMessage().contains("left Safe mode by itself"));
        // Asking for Safe again clears it.
        QTest::mouseClick(panel.button("safe"), Qt::LeftButton);
        QVERIFY(panel.safetyMessage().isEmpty());
    }

    void requestedPassiveIsNotASafetyDrop()
    {
        const RobotProfile &p = profile(ProfileId::Create2);
        ModePanel panel;
        panel.setSnapshot(modeSnapshot(p, OiMode::Safe));
        QTest::mouseClick(panel.button("passive"), Qt::LeftButton);
        panel.setSnapshot(modeSnapshot(p, OiMode::Passive));
        QVERIFY(panel.safetyMessage().isEmpty());
    }

    void firmwareShown()
    {
        ModePanel panel;
        panel.setFirmware("release-3.4.1");
        QCOMPARE(panel.findChild<QLabel *>("firmwareLabel")->text(), QString("Firmware: release-3.4.1"));
    }

    void translatesOnTheSpot()
    {
        const RobotProfile &p = profile(ProfileId::Create2);
        ModePanel panel;
        panel.setProfile(profile(ProfileId::Create1)); // some buttons disabled, with a reason
        panel.setFirmware("release-3.4.1");
        panel.setSnapshot(modeSnapshot(p, OiMode::Safe));
        SensorSnapshot dropped = modeSnapshot(p, OiMode::Passive);
        dropped.set(10, 1);
        panel.setSnapshot(dropped);
        panel.show();
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            const QStringList left = untranslatedTexts(&panel);
            QVERIFY2(left.isEmpty(), qPrintable(left.join('\n')));
            QVERIFY(panel.safetyMessage().contains(kPseudoOpen));
            QCOMPARE(panel.findChild<QComboBox *>("demoChoice")->currentData().toInt(), 0);
        }
        QCoreApplication::processEvents();
        QCOMPARE(panel.button("seek-dock")->text(), QString("Seek Dock"));
        QCOMPARE(panel.findChild<QLabel *>("modeLabel")->text(), QString("Mode: Passive"));
        QVERIFY(panel.safetyMessage().startsWith("The robot left Safe mode by itself (cliff)"));
        QVERIFY(panel.button("stop")->toolTip().contains("is not available on the Create"));
    }

    void keyboardReachesEveryControl()
    {
        ModePanel panel;
        panel.show();
        // Tab visits every enabled control in reading order (rows left to right).
        for (const char *key : {"create1", "create2"}) {
            panel.setProfile(*profileByKey(key));
            QStringList expected;
            for (const char *name : {"start", "passive", "safe", "full", "stop", "reset", "power", "clean", "spot",
                                     "max", "seek-dock", "cover", "cover-and-dock", "demoChoice", "demo"}) {
                QWidget *w = panel.findChild<QWidget *>(name);
                QVERIFY2(w, name);
                QVERIFY2(w->focusPolicy() & Qt::TabFocus, name);
                if (w->isEnabled())
                    expected << name;
            }
            QStringList visited;
            for (QWidget *w : tabWalk(&panel, panel.findChild<QWidget *>(expected.first())))
                visited << w->objectName();
            QCOMPARE(visited, expected);
        }
        // Space on the focused button sends its command.
        QSignalSpy spy(&panel, &ModePanel::sendRequested);
        panel.button("safe")->setFocus();
        QTest::keyClick(panel.button("safe"), Qt::Key_Space);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(bytesText(spy.at(0)), QString("131"));
    }

    void screenshots()
    {
        const RobotProfile &p = profile(ProfileId::Create2);
        ModePanel panel;
        panel.setFirmware("release-3.4.1");
        panel.setSnapshot(modeSnapshot(p, OiMode::Safe));
        SensorSnapshot dropped = modeSnapshot(p, OiMode::Passive);
        dropped.set(10, 1);
        panel.setSnapshot(dropped);
        panel.show();
        sensor_scenes::saveScreenshot(panel, "mode_panel");
        ScopedPseudoTranslation pseudo; // longer texts, as translations are
        QCoreApplication::processEvents();
        panel.adjustSize();
        sensor_scenes::saveScreenshot(panel, "mode_panel_pseudo");
    }
};

QTEST_MAIN(TestModePanel)
#include "tst_mode_panel.moc"
