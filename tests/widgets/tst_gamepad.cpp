// SPDX-License-Identifier: GPL-3.0-or-later
#include "gamepad_input.h"
#include "gamepad_panel.h"

#include "pseudo_translation.h"

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include <QDir>
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace oi;

namespace {

// A pad on SDL's virtual joystick driver, laid out as a game controller so
// SDL maps it by itself: joystick axis/button n is controller axis/button n.
class VirtualPad {
public:
    explicit VirtualPad(const char *name = "Test Pad")
    {
        SDL_VirtualJoystickDesc desc;
        SDL_zero(desc);
        desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
        desc.type = SDL_JOYSTICK_TYPE_GAMECONTROLLER;
        desc.naxes = SDL_CONTROLLER_AXIS_MAX;
        desc.nbuttons = SDL_CONTROLLER_BUTTON_DPAD_RIGHT + 1;
        desc.axis_mask = (1u << SDL_CONTROLLER_AXIS_MAX) - 1;
        desc.button_mask = (1u << (SDL_CONTROLLER_BUTTON_DPAD_RIGHT + 1)) - 1;
        desc.name = name;
        const int index = SDL_JoystickAttachVirtualEx(&desc);
        if (index < 0)
            qFatal("cannot attach a virtual pad: %s", SDL_GetError());
        m_joystick = SDL_JoystickOpen(index);
        if (!m_joystick)
            qFatal("cannot open the virtual pad: %s", SDL_GetError());
        m_instance = SDL_JoystickInstanceID(m_joystick);
    }
    ~VirtualPad() { detach(); }

    void setStick(int x, int y)
    {
        SDL_JoystickSetVirtualAxis(m_joystick, SDL_CONTROLLER_AXIS_LEFTX, Sint16(x));
        SDL_JoystickSetVirtualAxis(m_joystick, SDL_CONTROLLER_AXIS_LEFTY, Sint16(y));
    }
    void setButton(SDL_GameControllerButton button, bool pressed)
    {
        SDL_JoystickSetVirtualButton(m_joystick, button, pressed ? 1 : 0);
    }
    void detach()
    {
        if (!m_joystick)
            return;
        SDL_JoystickClose(m_joystick);
        m_joystick = nullptr;
        for (int i = 0; i < SDL_NumJoysticks(); ++i) {
            if (SDL_JoystickGetDeviceInstanceID(i) == m_instance) {
                SDL_JoystickDetachVirtual(i);
                break;
            }
        }
    }

private:
    SDL_Joystick *m_joystick = nullptr;
    SDL_JoystickID m_instance = -1;
};

MotionCommand drive(int velocity, int radius)
{
    MotionCommand c;
    c.velocity = velocity;
    c.radius = radius;
    return c;
}

MotionCommand motionAt(const QSignalSpy &spy, qsizetype i)
{
    return qvariant_cast<MotionCommand>(spy.at(i).at(0));
}

void saveScreenshot(QWidget &widget, const QString &name)
{
    static QTemporaryDir scratch;
    QString dir = qEnvironmentVariable("ROOMBA_SCREENSHOTS");
    if (dir.isEmpty())
        dir = scratch.path();
    QDir().mkpath(dir);
    const QPixmap shot = widget.grab();
    QVERIFY(!shot.isNull());
    QVERIFY(shot.save(QDir(dir).filePath(name + ".png")));
}

} // namespace

class TestGamepad : public QObject {
    Q_OBJECT
private slots:
    void initTestCase()
    {
        // Only the pads this test attaches: no HID or Steam pads of the machine.
        SDL_SetHint(SDL_HINT_JOYSTICK_HIDAPI, "0");
        QCOMPARE(SDL_Init(SDL_INIT_GAMECONTROLLER), 0);
        GamepadInput input;
        QVERIFY2(input.isAvailable(), qPrintable(input.errorString()));
        QVERIFY2(!input.hasGamepad(), "a real gamepad is plugged in; unplug it to run these tests");
    }

    // The window starts SDL beside its first frame: a pad plugged in before
    // is opened once SDL has started, and drives as one found at once would.
    void padPluggedInBeforeABackgroundStartIsOpened()
    {
        VirtualPad pad("Early Pad");
        GamepadInput input(GamepadInput::Start::InBackground);
        QSignalSpy changed(&input, &GamepadInput::gamepadChanged);
        QSignalSpy stopAll(&input, &GamepadInput::stopAllRequested);
        GamepadPanel panel;
        panel.setInput(&input);
        QTRY_COMPARE(changed.count(), 1);
        QCOMPARE(changed.at(0).at(0).toString(), QStringLiteral("Early Pad"));
        QVERIFY(input.isAvailable());
        QVERIFY(input.hasGamepad());
        QCOMPARE(panel.statusText(), QStringLiteral("Early Pad"));
        pad.setButton(SDL_CONTROLLER_BUTTON_B, true);
        input.poll();
        QCOMPARE(stopAll.count(), 1);
    }

    void noGamepadPanelSaysSo()
    {
        GamepadPanel bare;
        QCOMPARE(bare.statusText(), QStringLiteral("No gamepad connected — plug one in to drive with it"));

        GamepadInput input;
        QVERIFY(!input.hasGamepad());
        QCOMPARE(input.gamepadName(), QString());
        GamepadPanel panel;
        panel.setInput(&input);
        panel.resize(460, 220);
        QCOMPARE(panel.statusText(), QStringLiteral("No gamepad connected — plug one in to drive with it"));
        QVERIFY(!panel.findChild<QWidget *>(QStringLiteral("stickView"))->isEnabled());
        QCOMPARE(panel.mappingText(),
                 QStringLiteral("Hold RB to drive · B: Stop All · A: Safe (131) · X: Passive (128) · Y: Full (132)"));
        saveScreenshot(panel, QStringLiteral("gamepad_panel_none"));
    }

    void shapeAxis()
    {
        QCOMPARE(GamepadInput::shapeAxis(0.15, 0.15, 0.5), 0.0);
        QCOMPARE(GamepadInput::shapeAxis(-0.1, 0.15, 0.5), 0.0);
        QCOMPARE(GamepadInput::shapeAxis(1.0, 0.15, 0.5), 1.0);
        QCOMPARE(GamepadInput::shapeAxis(-1.0, 0.15, 0.5), -1.0);
        // s = (0.575 - 0.15) / 0.85 = 0.5; 0.5·0.5 + 0.5·0.125
        QCOMPARE(GamepadInput::shapeAxis(0.575, 0.15, 0.5), 0.3125);
        QCOMPARE(GamepadInput::shapeAxis(-0.575, 0.15, 0.5), -0.3125);
        QCOMPARE(GamepadInput::shapeAxis(0.5, 0.0, 0.0), 0.5);
    }

    void drivesOnlyWhileDeadManHeld_data()
    {
        QTest::addColumn<int>("x");
        QTest::addColumn<int>("y");
        QTest::addColumn<bool>("moves");
        QTest::addColumn<int>("velocity");
        QTest::addColumn<int>("radius");
        // Half a stick is 0.500015; past the 0.15 deadband 0.41178; expo 0.5
        // makes it 0.24080: 48 mm/s at the 200 mm/s limit.
        QTest::newRow("full forward") << 0 << -32768 << true << 200 << kRadiusStraight;
        QTest::newRow("half forward") << 0 << -16384 << true << 48 << kRadiusStraight;
        QTest::newRow("full reverse") << 0 << 32767 << true << -200 << kRadiusStraight;
        // 250 mm · 1.0 / 0.24080 = 1038 mm, to the right.
        QTest::newRow("forward, half right") << 16384 << -32768 << true << 200 << -1038;
        // y 24000/32767 → 0.50348 → -101 mm/s; 250 · 0.50348 / 0.24080 = 523.
        QTest::newRow("reverse, half left") << -16384 << 24000 << true << -101 << 523;
        QTest::newRow("spin right") << 32767 << 0 << true << 200 << kRadiusTurnInPlaceClockwise;
        QTest::newRow("spin left, y in deadband") << -16384 << -4000 << true << 48
                                                  << kRadiusTurnInPlaceCounterClockwise;
        QTest::newRow("inside deadband") << 3000 << -4000 << false << 0 << kRadiusStraight;
    }
    void drivesOnlyWhileDeadManHeld()
    {
        QFETCH(int, x);
        QFETCH(int, y);
        QFETCH(bool, moves);
        QFETCH(int, velocity);
        QFETCH(int, radius);
        VirtualPad pad;
        GamepadInput input;
        QVERIFY(input.hasGamepad());
        QSignalSpy motion(&input, &GamepadInput::motionRequested);
        QSignalSpy deadMan(&input, &GamepadInput::deadManChanged);

        pad.setStick(x, y);
        input.poll();
        input.poll();
        QCOMPARE(motion.count(), 0); // stick pushed, dead-man not held
        QVERIFY(!input.isDeadManHeld());

        pad.setButton(SDL_CONTROLLER_BUTTON_RIGHTSHOULDER, true);
        input.poll();
        QCOMPARE(deadMan.count(), 1);
        QCOMPARE(deadMan.at(0).at(0).toBool(), true);
        QCOMPARE(motion.count(), moves ? 1 : 0);
        if (moves) {
            QCOMPARE(motionAt(motion, 0), drive(velocity, radius));
            QCOMPARE(input.command(), drive(velocity, radius));
        }
        input.poll(); // nothing changed: no repeat
        QCOMPARE(motion.count(), moves ? 1 : 0);

        const qsizetype before = motion.count();
        pad.setButton(SDL_CONTROLLER_BUTTON_RIGHTSHOULDER, false);
        input.poll();
        QCOMPARE(deadMan.count(), 2);
        QCOMPARE(deadMan.at(1).at(0).toBool(), false);
        QCOMPARE(motion.count(), before + 1);
        QCOMPARE(motionAt(motion, before), MotionCommand::stop());

        // Released: the stick asks for nothing.
        pad.setStick(-32768, -32768);
        input.poll();
        input.poll();
        QCOMPARE(motion.count(), before + 1);
    }

    void stickChangesAreSentOnceEach()
    {
        VirtualPad pad;
        GamepadInput input;
        QSignalSpy motion(&input, &GamepadInput::motionRequested);
        pad.setButton(SDL_CONTROLLER_BUTTON_RIGHTSHOULDER, true);
        input.poll();
        QCOMPARE(motion.count(), 0); // centred: already stopped
        pad.setStick(0, -32768);
        input.poll();
        pad.setStick(0, -32768);
        input.poll();
        pad.setStick(1000, -32768); // inside the deadband sideways: same command
        input.poll();
        QCOMPARE(motion.count(), 1);
        pad.setStick(0, 0);
        input.poll();
        QCOMPARE(motion.count(), 2);
        QCOMPARE(motionAt(motion, 1), MotionCommand::stop());
    }

    void shapingApplies()
    {
        VirtualPad pad;
        GamepadInput input;
        QCOMPARE(input.speedLimit(), 200);
        QCOMPARE(input.deadband(), 0.15);
        QCOMPARE(input.expo(), 0.5);
        QSignalSpy motion(&input, &GamepadInput::motionRequested);
        pad.setButton(SDL_CONTROLLER_BUTTON_RIGHTSHOULDER, true);
        pad.setStick(0, -16384);
        input.poll();
        QCOMPARE(motionAt(motion, motion.count() - 1), drive(48, kRadiusStraight));
        input.setSpeedLimit(100); // 0.24080 · 100
        QCOMPARE(motionAt(motion, motion.count() - 1), drive(24, kRadiusStraight));
        input.setExpo(0.0); // 0.41178 · 100
        QCOMPARE(motionAt(motion, motion.count() - 1), drive(41, kRadiusStraight));
        input.setDeadband(0.0); // 0.500015 · 100
        QCOMPARE(motionAt(motion, motion.count() - 1), drive(50, kRadiusStraight));
        input.setSpeedLimit(9000);
        QCOMPARE(input.speedLimit(), GamepadInput::kMaxSpeed);
        QCOMPARE(motion.count(), 5);
    }

    void buttonsAskForStopAllAndModes()
    {
        VirtualPad pad;
        GamepadInput input;
        QSignalSpy stopAll(&input, &GamepadInput::stopAllRequested);
        QSignalSpy mode(&input, &GamepadInput::modeRequested);
        QSignalSpy motion(&input, &GamepadInput::motionRequested);
        const auto tap = [&](SDL_GameControllerButton b) {
            pad.setButton(b, true);
            input.poll();
            pad.setButton(b, false);
            input.poll();
        };
        tap(SDL_CONTROLLER_BUTTON_B);
        QCOMPARE(stopAll.count(), 1);
        QCOMPARE(mode.count(), 0);
        tap(SDL_CONTROLLER_BUTTON_A);
        tap(SDL_CONTROLLER_BUTTON_Y);
        tap(SDL_CONTROLLER_BUTTON_X);
        QCOMPARE(mode.count(), 3);
        QCOMPARE(qvariant_cast<Command>(mode.at(0).at(0)), Command::Safe);
        QCOMPARE(qvariant_cast<Command>(mode.at(1).at(0)), Command::Full);
        QCOMPARE(qvariant_cast<Command>(mode.at(2).at(0)), Command::Start);
        tap(SDL_CONTROLLER_BUTTON_DPAD_UP); // no role
        QCOMPARE(stopAll.count(), 1);
        QCOMPARE(mode.count(), 3);
        QCOMPARE(motion.count(), 0);

        GamepadPanel panel;
        panel.setInput(&input);
        QSignalSpy mapping(&input, &GamepadInput::mappingChanged);
        QVERIFY(input.setModeButton(SDL_CONTROLLER_BUTTON_DPAD_UP, Command::Full));
        QVERIFY(!input.setModeButton(SDL_CONTROLLER_BUTTON_DPAD_DOWN, Command::Drive));
        input.setStopAllButton(SDL_CONTROLLER_BUTTON_A); // A was Safe
        input.clearModeButton(SDL_CONTROLLER_BUTTON_Y);
        QCOMPARE(mapping.count(), 3);
        QCOMPARE(input.stopAllButton(), SDL_CONTROLLER_BUTTON_A);
        QCOMPARE(input.modeButtons().size(), 2);
        QCOMPARE(panel.mappingText(),
                 QStringLiteral("Hold RB to drive · A: Stop All · X: Passive (128) · D-pad up: Full (132)"));
        tap(SDL_CONTROLLER_BUTTON_A);
        tap(SDL_CONTROLLER_BUTTON_B);
        tap(SDL_CONTROLLER_BUTTON_Y);
        tap(SDL_CONTROLLER_BUTTON_DPAD_UP);
        QCOMPARE(stopAll.count(), 2);
        QCOMPARE(mode.count(), 4);
        QCOMPARE(qvariant_cast<Command>(mode.at(3).at(0)), Command::Full);

        // A new dead-man button: the old one no longer drives.
        input.setDeadManButton(SDL_CONTROLLER_BUTTON_LEFTSHOULDER);
        pad.setStick(0, -32768);
        pad.setButton(SDL_CONTROLLER_BUTTON_RIGHTSHOULDER, true);
        input.poll();
        QCOMPARE(motion.count(), 0);
        pad.setButton(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, true);
        input.poll();
        QCOMPARE(motion.count(), 1);
        QCOMPARE(motionAt(motion, 0), drive(200, kRadiusStraight));
        QVERIFY(panel.deadManText().startsWith(QStringLiteral("Dead-man (LB) held")));
    }

    void hotplug()
    {
        GamepadInput input;
        GamepadPanel panel;
        panel.setInput(&input);
        panel.resize(460, 220);
        QSignalSpy changed(&input, &GamepadInput::gamepadChanged);
        QSignalSpy motion(&input, &GamepadInput::motionRequested);
        QSignalSpy deadMan(&input, &GamepadInput::deadManChanged);
        QVERIFY(panel.statusText().startsWith(QStringLiteral("No gamepad connected")));

        VirtualPad pad("Hotplug Pad");
        input.poll();
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed.at(0).at(0).toString(), QStringLiteral("Hotplug Pad"));
        QCOMPARE(panel.statusText(), QStringLiteral("Hotplug Pad"));
        QVERIFY(panel.findChild<QWidget *>(QStringLiteral("stickView"))->isEnabled());

        pad.setStick(16384, -32768);
        pad.setButton(SDL_CONTROLLER_BUTTON_RIGHTSHOULDER, true);
        input.poll();
        QCOMPARE(motion.count(), 1);
        QCOMPARE(motionAt(motion, 0), drive(200, -1038));
        QCOMPARE(panel.commandText(), QStringLiteral("Forward, arcing right: Drive 200 mm/s, radius -1038 mm"));
        QCOMPARE(panel.deadManText(), QStringLiteral("Dead-man (RB) held: driving"));
        saveScreenshot(panel, QStringLiteral("gamepad_panel_driving"));

        pad.detach(); // unplugged while driving
        input.poll();
        QCOMPARE(motion.count(), 2);
        QCOMPARE(motionAt(motion, 1), MotionCommand::stop());
        QCOMPARE(deadMan.count(), 2);
        QCOMPARE(deadMan.at(1).at(0).toBool(), false);
        QCOMPARE(changed.count(), 2);
        QCOMPARE(changed.at(1).at(0).toString(), QString());
        QVERIFY(!input.hasGamepad());
        QCOMPARE(input.stick(), QPointF());
        QCOMPARE(panel.statusText(), QStringLiteral("No gamepad connected — plug one in to drive with it"));
        QCOMPARE(panel.commandText(), QStringLiteral("Stop: Drive 0 mm/s"));
        input.poll();
        QCOMPARE(motion.count(), 2);
    }

    // Without a pad nothing polls SDL: the device folders are watched, and a
    // node appearing there brings the pad in.
    void noPadWaitsOnTheDeviceFolders()
    {
        QTemporaryDir devices;
        QVERIFY(devices.isValid());
        GamepadInput input;
        input.setDeviceFolders({devices.path()});
        QCOMPARE(input.pollIntervalMs(), 0);

        VirtualPad pad("Plugged Pad");
        QFile node(devices.filePath(QStringLiteral("event7")));
        QVERIFY(node.open(QIODevice::WriteOnly));
        QTRY_VERIFY(input.hasGamepad());
        QCOMPARE(input.gamepadName(), QStringLiteral("Plugged Pad"));
        QCOMPARE(input.pollIntervalMs(), 10);

        pad.detach();
        QTRY_VERIFY(!input.hasGamepad()); // seen by the 10 ms poll
        QCOMPARE(input.pollIntervalMs(), 0);
    }

    // A node without a pad (a serial adapter, a pad udev is still setting up)
    // polls SDL for a while, then waits again.
    void aDeviceFolderChangePollsForAWhile()
    {
        QTemporaryDir devices;
        GamepadInput input;
        input.setDeviceFolders({devices.path()});
        QFile node(devices.filePath(QStringLiteral("ttyUSB0")));
        QVERIFY(node.open(QIODevice::WriteOnly));
        QTRY_COMPARE(input.pollIntervalMs(), 250);
        QVERIFY(!input.hasGamepad());
        QTRY_COMPARE_WITH_TIMEOUT(input.pollIntervalMs(), 0, 10000);
    }

    // Where no folder can be watched, SDL is polled as before.
    void unwatchableFoldersFallBackToPolling()
    {
        GamepadInput input;
        input.setDeviceFolders({QStringLiteral("/no/such/folder")});
        QCOMPARE(input.pollIntervalMs(), 250);
        input.setDeviceFolders({});
        QCOMPARE(input.pollIntervalMs(), 250);
    }

    void translatesOnTheSpot()
    {
        VirtualPad pad;
        GamepadInput input;
        QVERIFY(input.hasGamepad());
        GamepadPanel panel;
        panel.setInput(&input);
        panel.resize(460, 220);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        pad.setButton(SDL_CONTROLLER_BUTTON_RIGHTSHOULDER, true);
        pad.setStick(0, -32768);
        input.poll();
        QVERIFY(input.isDeadManHeld());
        // The pad's name comes from the device and stays as it is.
        const QStringList allowed{QStringLiteral("Test Pad")};
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            const QStringList untranslated = untranslatedTexts(&panel, allowed);
            QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
            QVERIFY(panel.commandText().startsWith(kPseudoOpen));
            QVERIFY(panel.deadManText().startsWith(kPseudoOpen));
            saveScreenshot(panel, QStringLiteral("gamepad_panel_pseudo"));
        }
        QCoreApplication::processEvents();
        QVERIFY2(panel.deadManText().startsWith(QStringLiteral("Dead-man (RB) held")), qPrintable(panel.deadManText()));
        QCOMPARE(panel.statusText(), QStringLiteral("Test Pad"));

        // Without a pad, the message saying so follows the language too.
        pad.detach();
        input.poll();
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            const QStringList untranslated = untranslatedTexts(&panel);
            QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join('\n')));
        }
        QCoreApplication::processEvents();
        QCOMPARE(panel.statusText(), QStringLiteral("No gamepad connected — plug one in to drive with it"));
    }

    // The panel has nothing to press; its painted stick speaks for itself.
    void stickViewIsAccessible()
    {
        VirtualPad pad;
        GamepadInput input;
        GamepadPanel panel;
        panel.setInput(&input);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QWidget *stick = panel.findChild<QWidget *>(QStringLiteral("stickView"));
        QCOMPARE(stick->accessibleName(), QStringLiteral("Left stick"));
        QCOMPARE(stick->accessibleDescription(), QStringLiteral("0% right, 0% forward"));
        pad.setStick(32767, -32768);
        input.poll();
        QCOMPARE(stick->accessibleDescription(), QStringLiteral("100% right, 100% forward"));
        // Nothing in the panel takes the focus from the keyboard.
        for (QWidget *w : panel.findChildren<QWidget *>())
            QVERIFY2(!(w->focusPolicy() & Qt::TabFocus), qPrintable(w->objectName()));
    }

    void describeCommands()
    {
        QCOMPARE(GamepadPanel::describe(MotionCommand::stop()), QStringLiteral("Stop: Drive 0 mm/s"));
        QCOMPARE(GamepadPanel::describe(drive(-120, kRadiusStraight)),
                 QStringLiteral("Reverse: Drive -120 mm/s, straight"));
        QCOMPARE(GamepadPanel::describe(drive(80, kRadiusTurnInPlaceCounterClockwise)),
                 QStringLiteral("Spin counter-clockwise: Drive 80 mm/s, radius 1"));
        QCOMPARE(GamepadPanel::describe(drive(-101, 523)),
                 QStringLiteral("Reverse, arcing left: Drive -101 mm/s, radius 523 mm"));
    }
};

QTEST_MAIN(TestGamepad)
#include "tst_gamepad.moc"
