// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "command_encoder.h"
#include "motion_command.h"

#include <QList>
#include <QMap>
#include <QObject>
#include <QPointF>
#include <QElapsedTimer>
#include <QString>
#include <QStringList>

#include <SDL_gamecontroller.h>

#include <thread>

class QFileSystemWatcher;
class QTimer;

// One gamepad, read through SDL's game-controller API, turned into what the
// robot is asked to do. The left stick drives, but only while the dead-man
// button is held; letting go of it (or unplugging the pad while it is held)
// asks for a stop once and then nothing. Other buttons can ask for Stop All or
// a mode change.
//
// SDL is polled every 10 ms on the thread that owns this object while a pad
// is open. Without one, the device folders are watched instead (/dev/input
// and /dev on Linux): a pad plugged in adds a node there, and SDL is then
// polled every 250 ms for a couple of seconds while the system sets it up.
// Where no folder can be watched, SDL is polled every 250 ms. SDL has one
// event queue per program, so keep one GamepadInput at a time.
class GamepadInput : public QObject {
    Q_OBJECT
public:
    static constexpr int kDefaultSpeedLimit = 200; // mm/s
    static constexpr int kMaxSpeed = 500;          // the OI's Drive limit, mm/s
    static constexpr double kDefaultDeadband = 0.15;
    static constexpr double kDefaultExpo = 0.5;
    // Arc radius (mm) when the stick is pushed as far sideways as forward;
    // the radius scales with forward / sideways.
    static constexpr int kArcRadiusAtDiagonal = 250;
    // Arcs are held between these; the OI takes at most 2000.
    static constexpr int kMinArcRadius = 20;
    static constexpr int kMaxArcRadius = 2000;

    // Now: SDL starts, and a pad already plugged in is open, before the
    // constructor returns. InBackground: SDL starts on a thread of its own
    // (it looks for devices, which takes milliseconds) and the pads are
    // opened on this object's thread once it has; gamepadChanged() says so.
    enum class Start { Now, InBackground };

    explicit GamepadInput(QObject *parent = nullptr) : GamepadInput(Start::Now, parent) {}
    explicit GamepadInput(Start start, QObject *parent = nullptr);
    ~GamepadInput() override;

    // False when SDL could not start its game-controller support; then no
    // gamepad is ever seen and errorString() says why.
    bool isAvailable() const { return m_available; }
    QString errorString() const { return m_error; }

    bool hasGamepad() const { return m_controller != nullptr; }
    QString gamepadName() const { return m_name; } // empty when none

    // Left stick, -1..1 each way: x to the right, y forward. Raw, before the
    // deadband and expo.
    QPointF stick() const { return m_stick; }
    bool isDeadManHeld() const { return m_deadManHeld; }
    // How often SDL is polled now, in ms; 0 while it waits on the device
    // folders for a pad to be plugged in.
    int pollIntervalMs() const;
    // The folders where a pad plugged in adds a node. Folders that do not
    // exist yet are watched for once one of the others changes; when none
    // can be watched, SDL is polled every 250 ms instead.
    void setDeviceFolders(const QStringList &folders);
    QStringList deviceFolders() const { return m_deviceFolders; }
    static QStringList defaultDeviceFolders();

    // The last command asked for (a stop until the stick drives).
    MotionCommand command() const { return m_lastCommand; }

    // Shaping. Values outside the ranges below are brought into them.
    void setSpeedLimit(int mmPerSecond); // 0..kMaxSpeed
    int speedLimit() const { return m_speedLimit; }
    void setDeadband(double fraction); // 0..0.9 of full scale
    double deadband() const { return m_deadband; }
    void setExpo(double expo); // 0 (linear) .. 1 (cubic)
    double expo() const { return m_expo; }

    // Button roles. A button has at most one role: giving it one takes away
    // the one it had. SDL_CONTROLLER_BUTTON_INVALID means "no button".
    void setDeadManButton(SDL_GameControllerButton button);
    SDL_GameControllerButton deadManButton() const { return m_deadManButton; }
    void setStopAllButton(SDL_GameControllerButton button);
    SDL_GameControllerButton stopAllButton() const { return m_stopAllButton; }
    // command: Start (Passive), Safe or Full; anything else is refused.
    bool setModeButton(SDL_GameControllerButton button, oi::Command command);
    void clearModeButton(SDL_GameControllerButton button);
    QMap<SDL_GameControllerButton, oi::Command> modeButtons() const { return m_modeButtons; }

    // The Drive command for a shaped stick position (x right, y forward,
    // each -1..1), without the dead-man rule.
    static MotionCommand driveCommand(double x, double y, int speedLimit, double deadband, double expo);
    // Deadband, rescaled so the output still starts at 0, then expo.
    static double shapeAxis(double value, double deadband, double expo);

    // "A", "RB", "D-pad up", ...
    static QString buttonName(SDL_GameControllerButton button);
    // "Passive (128)", "Safe (131)", "Full (132)".
    static QString modeName(oi::Command command);

public slots:
    // Reads every pending SDL event and acts on it. Called by the timer;
    // tests call it directly.
    void poll();

signals:
    void motionRequested(const MotionCommand &command);
    void deadManChanged(bool held);
    void stopAllRequested();
    void modeRequested(oi::Command command);
    void gamepadChanged(const QString &name);
    void stickMoved(QPointF stick);
    void mappingChanged();

private:
    // SDL has started (`error` empty) or could not: the pads are read from now on.
    void startReading(const QString &error);
    // A device folder changed: a pad may be coming.
    void onDeviceFolderChanged();
    void watchDeviceFolders();
    // Starts, re-times or stops the poll timer for what is plugged in now.
    void schedulePolling();
    void openFirstGamepad();
    bool openGamepad(int deviceIndex);
    void closeGamepad();
    void onButton(SDL_GameControllerButton button, bool pressed);
    void setDeadManHeld(bool held);
    void readStick();
    void updateCommand();
    void emitCommand(const MotionCommand &command);
    void takeRole(SDL_GameControllerButton button);

    bool m_available = true; // until SDL says otherwise
    bool m_reading = false;
    QString m_error;
    std::thread m_starting; // SDL starting in the background
    QTimer *m_timer = nullptr;
    QStringList m_deviceFolders = defaultDeviceFolders();
    QFileSystemWatcher *m_deviceWatcher = nullptr;
    QElapsedTimer m_sinceDeviceChange; // invalid until a device folder changes
    SDL_GameController *m_controller = nullptr;
    SDL_JoystickID m_instance = -1;
    QString m_name;
    QPointF m_stick;
    bool m_deadManHeld = false;
    MotionCommand m_lastCommand = MotionCommand::stop();
    int m_speedLimit = kDefaultSpeedLimit;
    double m_deadband = kDefaultDeadband;
    double m_expo = kDefaultExpo;
    SDL_GameControllerButton m_deadManButton = SDL_CONTROLLER_BUTTON_RIGHTSHOULDER;
    SDL_GameControllerButton m_stopAllButton = SDL_CONTROLLER_BUTTON_B;
    QMap<SDL_GameControllerButton, oi::Command> m_modeButtons;
};
