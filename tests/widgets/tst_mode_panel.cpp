// SPDX-License-Identifier: GPL-3.0-or-later
#include "mode_panel.h"
#include "pseudo_translation.h"
#include "sensor_scenes.h"

#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <QTimer>

using namespace oi;

namespace {

// The command a modeRequested() signal asked for, and the demo's number.
Command askedCommand(const QList<QVariant> &signal) { return signal.at(0).value<Command>(); }
int askedDemo(const QList<QVariant> &signal) { return signal.at(1).toInt(); }

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

// The mode a session sees after these frames.
RobotMode modeAfter(std::initializer_list<SensorSnapshot> frames)
{
    RobotMode mode;
    const QDateTime at(QDate(2026, 1, 5), QTime(12, 3, 4));
    for (const SensorSnapshot &frame : frames)
        mode.observe(frame, at.toMSecsSinceEpoch());
    return mode;
}

SensorSnapshot cliffDrop(const RobotProfile &p)
{
    SensorSnapshot dropped = modeSnapshot(p, OiMode::Passive);
    dropped.set(10, 1); // front left
    return dropped;
}

} // namespace

Q_DECLARE_METATYPE(oi::Command)

class TestModePanel : public QObject {
    Q_OBJECT
private slots:
    void buttonsAskForTheirCommand_data()
    {
        QTest::addColumn<QString>("profile");
        QTest::addColumn<QString>("button");
        QTest::addColumn<Command>("command");
        QTest::newRow("start") << "create2" << "start" << Command::Start;
        QTest::newRow("passive") << "create2" << "passive" << Command::Start;
        QTest::newRow("safe") << "create2" << "safe" << Command::Safe;
        QTest::newRow("full") << "create2" << "full" << Command::Full;
        QTest::newRow("stop") << "create2" << "stop" << Command::Stop;
        QTest::newRow("reset") << "roomba500" << "reset" << Command::Reset;
        QTest::newRow("power") << "roomba500" << "power" << Command::Power;
        QTest::newRow("clean") << "create2" << "clean" << Command::Clean;
        QTest::newRow("spot") << "create2" << "spot" << Command::Spot;
        QTest::newRow("max") << "create2" << "max" << Command::Max;
        QTest::newRow("seek dock") << "create2" << "seek-dock" << Command::SeekDock;
        QTest::newRow("cover") << "create1" << "cover" << Command::Cover;
        QTest::newRow("cover and dock") << "create1" << "cover-and-dock" << Command::CoverAndDock;
        QTest::newRow("spot create") << "create1" << "spot" << Command::Spot;
        QTest::newRow("demo") << "create1" << "demo" << Command::Demo;
    }
    // Each button asks for its command (the session sends it: tst_robot_session).
    void buttonsAskForTheirCommand()
    {
        QFETCH(QString, profile);
        QFETCH(QString, button);
        QFETCH(Command, command);
        ModePanel panel;
        panel.setFullModeConfirmation([](QWidget *) { return true; });
        panel.setProfile(*profileByKey(profile.toStdString()));
        QSignalSpy spy(&panel, &ModePanel::modeRequested);
        QPushButton *b = panel.button(button);
        QVERIFY(b);
        QVERIFY(b->isEnabled());
        QTest::mouseClick(b, Qt::LeftButton);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(askedCommand(spy.at(0)), command);
    }

    void demoChoice()
    {
        ModePanel panel;
        panel.setProfile(profile(ProfileId::Create1));
        auto *combo = panel.findChild<QComboBox *>("demoChoice");
        QVERIFY(combo);
        combo->setCurrentIndex(0); // abort
        QSignalSpy spy(&panel, &ModePanel::modeRequested);
        QTest::mouseClick(panel.button("demo"), Qt::LeftButton);
        QCOMPARE(askedCommand(spy.at(0)), Command::Demo);
        QCOMPARE(askedDemo(spy.at(0)), -1);
        combo->setCurrentIndex(10); // Banjo
        QTest::mouseClick(panel.button("demo"), Qt::LeftButton);
        QCOMPARE(askedDemo(spy.at(1)), 9);
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
        QSignalSpy spy(&panel, &ModePanel::modeRequested);
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

    // The question before Full names it as the way off the dock.
    void fullDialogNamesTheWayOffTheDock()
    {
        ModePanel panel;
        panel.show();
        QString text;
        QTimer::singleShot(0, &panel, [&] {
            if (auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget())) {
                text = box->text();
                box->button(QMessageBox::No)->click();
            }
        });
        QSignalSpy spy(&panel, &ModePanel::modeRequested);
        QTest::mouseClick(panel.button("full"), Qt::LeftButton);
        QVERIFY2(text.contains("the way off the dock, where Safe is refused"), qPrintable(text));
        QCOMPARE(spy.count(), 0);
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
        QSignalSpy sent(&panel, &ModePanel::modeRequested);
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
        QCOMPARE(askedCommand(sent.at(0)), Command::Safe);
    }

    void highlightsCurrentMode()
    {
        ModePanel panel;
        QVERIFY(!panel.highlightedMode());
        panel.setMode(modeAfter({modeSnapshot(profile(ProfileId::Create2), OiMode::Full)}));
        QCOMPARE(panel.highlightedMode(), std::optional<OiMode>(OiMode::Full));
        QVERIFY(!panel.button("full")->styleSheet().isEmpty());
        QVERIFY(panel.button("safe")->styleSheet().isEmpty());
        QCOMPARE(panel.findChild<QLabel *>("modeLabel")->text(), QString("Mode: Full"));
    }

    // What the session's mode says is shown, with the step that fixes it,
    // and only under the mode it is about.
    void showsWhyTheModeChanged()
    {
        const RobotProfile &p = profile(ProfileId::Create2);
        ModePanel panel;
        panel.setMode(modeAfter({modeSnapshot(p, OiMode::Safe)}));
        QVERIFY(panel.safetyMessage().isEmpty());
        panel.setMode(modeAfter({modeSnapshot(p, OiMode::Safe), cliffDrop(p)}));
        QCOMPARE(panel.safetyMessage(), QString("A cliff (front left) dropped it to Passive at 12:03:04. Carry it "
                                                "back from the edge, then Enter Safe."));
        QCOMPARE(panel.findChild<QLabel *>("modeLabel")->text(), QString("Mode: Passive"));
        // Back in Safe: the reason goes with the mode it explained.
        panel.setMode(modeAfter({modeSnapshot(p, OiMode::Safe), cliffDrop(p), modeSnapshot(p, OiMode::Safe)}));
        QVERIFY(panel.safetyMessage().isEmpty());
        QCOMPARE(panel.findChild<QLabel *>("modeLabel")->text(), QString("Mode: Safe"));
        // Another robot's mode replaces it whole.
        panel.setMode(modeAfter({modeSnapshot(p, OiMode::Passive)}));
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
        const RobotMode dropped = modeAfter({modeSnapshot(p, OiMode::Safe), cliffDrop(p)});
        panel.setMode(dropped);
        panel.show();
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            panel.setMode(dropped); // the window shows the mode again on a language change
            const QStringList left = untranslatedTexts(&panel);
            QVERIFY2(left.isEmpty(), qPrintable(left.join('\n')));
            QVERIFY(panel.safetyMessage().contains(kPseudoOpen));
            QCOMPARE(panel.findChild<QComboBox *>("demoChoice")->currentData().toInt(), 0);
        }
        QCoreApplication::processEvents();
        panel.setMode(dropped);
        QCOMPARE(panel.button("seek-dock")->text(), QString("Seek Dock"));
        QCOMPARE(panel.findChild<QLabel *>("modeLabel")->text(), QString("Mode: Passive"));
        QVERIFY(panel.safetyMessage().startsWith("A cliff (front left) dropped it to Passive"));
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
        QSignalSpy spy(&panel, &ModePanel::modeRequested);
        panel.button("safe")->setFocus();
        QTest::keyClick(panel.button("safe"), Qt::Key_Space);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(askedCommand(spy.at(0)), Command::Safe);
    }

    void screenshots()
    {
        const RobotProfile &p = profile(ProfileId::Create2);
        ModePanel panel;
        panel.setFirmware("release-3.4.1");
        const RobotMode dropped = modeAfter({modeSnapshot(p, OiMode::Safe), cliffDrop(p)});
        panel.setMode(dropped);
        panel.show();
        sensor_scenes::saveScreenshot(panel, "mode_panel");
        ScopedPseudoTranslation pseudo; // longer texts, as translations are
        QCoreApplication::processEvents();
        panel.setMode(dropped);
        panel.adjustSize();
        sensor_scenes::saveScreenshot(panel, "mode_panel_pseudo");
    }
};

QTEST_MAIN(TestModePanel)
#include "tst_mode_panel.moc"
