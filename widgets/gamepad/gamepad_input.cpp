// SPDX-License-Identifier: GPL-3.0-or-later
#include "gamepad_input.h"

#include <SDL.h>

#include <QDir>
#include <QFileSystemWatcher>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace {

constexpr int kPollIntervalMs = 10;
// Without a pad, polling only notices one plugged in: a quarter of a second
// is soon enough.
constexpr int kNoPadPollIntervalMs = 250;
// A pad's node appears before udev has finished with it and told SDL: after
// a device folder changes, SDL is polled this long before waiting again.
constexpr qint64 kDeviceSettleMs = 2000;

// Starts SDL's game-controller support once for the whole program; the
// answer is an error message, empty on success.
QString startSdl()
{
    static const QString error = [] {
        // Qt handles Ctrl+C and termination; SDL must not take them over.
        SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
        if (SDL_Init(SDL_INIT_GAMECONTROLLER) != 0)
            return QString::fromUtf8(SDL_GetError());
        return QString();
    }();
    return error;
}

double normalizedAxis(Sint16 raw)
{
    return std::clamp(raw / 32767.0, -1.0, 1.0);
}

} // namespace

GamepadInput::GamepadInput(Start start, QObject *parent) : QObject(parent)
{
    m_modeButtons.insert(SDL_CONTROLLER_BUTTON_A, oi::Command::Safe);
    m_modeButtons.insert(SDL_CONTROLLER_BUTTON_Y, oi::Command::Full);
    m_modeButtons.insert(SDL_CONTROLLER_BUTTON_X, oi::Command::Start);

    if (start == Start::Now) {
        startReading(startSdl());
        return;
    }
    // The destructor waits for the thread, so `this` outlives it; a call
    // queued to an object already gone is dropped.
    m_starting = std::thread([this] {
        const QString error = startSdl();
        QMetaObject::invokeMethod(this, [this, error] { startReading(error); }, Qt::QueuedConnection);
    });
}

GamepadInput::~GamepadInput()
{
    if (m_starting.joinable())
        m_starting.join();
    if (m_controller)
        SDL_GameControllerClose(m_controller);
}

void GamepadInput::startReading(const QString &error)
{
    m_error = error;
    m_available = error.isEmpty();
    if (!m_available) {
        emit gamepadChanged(QString()); // the panel says why there is none
        return;
    }
    m_reading = true;
    openFirstGamepad();
    m_timer = new QTimer(this);
    connect(m_timer, &QTimer::timeout, this, &GamepadInput::poll);
    watchDeviceFolders();
}

QStringList GamepadInput::defaultDeviceFolders()
{
#ifdef Q_OS_LINUX
    // /dev as well: /dev/input may not exist until the first input device,
    // and pads read through HIDAPI appear as /dev/hidraw*.
    return {QStringLiteral("/dev/input"), QStringLiteral("/dev")};
#else
    return {};
#endif
}

void GamepadInput::setDeviceFolders(const QStringList &folders)
{
    m_deviceFolders = folders;
    delete m_deviceWatcher;
    m_deviceWatcher = nullptr;
    if (m_reading)
        watchDeviceFolders();
}

void GamepadInput::watchDeviceFolders()
{
    if (!m_deviceWatcher && !m_deviceFolders.isEmpty()) {
        m_deviceWatcher = new QFileSystemWatcher(this);
        connect(m_deviceWatcher, &QFileSystemWatcher::directoryChanged, this, &GamepadInput::onDeviceFolderChanged);
    }
    if (m_deviceWatcher) {
        const QStringList watched = m_deviceWatcher->directories();
        for (const QString &folder : m_deviceFolders) {
            if (!watched.contains(folder) && QDir(folder).exists())
                m_deviceWatcher->addPath(folder);
        }
    }
    schedulePolling();
}

void GamepadInput::onDeviceFolderChanged()
{
    m_sinceDeviceChange.start();
    watchDeviceFolders(); // a folder may have just been made
    poll();
}

int GamepadInput::pollIntervalMs() const
{
    return m_timer && m_timer->isActive() ? m_timer->interval() : 0;
}

void GamepadInput::schedulePolling()
{
    if (!m_timer)
        return;
    const bool watching = m_deviceWatcher && !m_deviceWatcher->directories().isEmpty();
    const bool settling = m_sinceDeviceChange.isValid() && !m_sinceDeviceChange.hasExpired(kDeviceSettleMs);
    int interval = 0; // waiting on the device folders
    if (m_controller)
        interval = kPollIntervalMs;
    else if (!watching || settling)
        interval = kNoPadPollIntervalMs;
    if (interval == 0) {
        m_timer->stop();
        return;
    }
    if (m_timer->interval() != interval || !m_timer->isActive())
        m_timer->start(interval);
}

void GamepadInput::setSpeedLimit(int mmPerSecond)
{
    m_speedLimit = std::clamp(mmPerSecond, 0, kMaxSpeed);
    updateCommand();
}

void GamepadInput::setDeadband(double fraction)
{
    m_deadband = std::clamp(fraction, 0.0, 0.9);
    updateCommand();
}

void GamepadInput::setExpo(double expo)
{
    m_expo = std::clamp(expo, 0.0, 1.0);
    updateCommand();
}

void GamepadInput::takeRole(SDL_GameControllerButton button)
{
    if (button == SDL_CONTROLLER_BUTTON_INVALID)
        return;
    if (m_deadManButton == button) {
        setDeadManHeld(false);
        m_deadManButton = SDL_CONTROLLER_BUTTON_INVALID;
    }
    if (m_stopAllButton == button)
        m_stopAllButton = SDL_CONTROLLER_BUTTON_INVALID;
    m_modeButtons.remove(button);
}

void GamepadInput::setDeadManButton(SDL_GameControllerButton button)
{
    takeRole(button);
    // A new dead-man counts only from its next press.
    setDeadManHeld(false);
    m_deadManButton = button;
    emit mappingChanged();
}

void GamepadInput::setStopAllButton(SDL_GameControllerButton button)
{
    takeRole(button);
    m_stopAllButton = button;
    emit mappingChanged();
}

bool GamepadInput::setModeButton(SDL_GameControllerButton button, oi::Command command)
{
    if (button == SDL_CONTROLLER_BUTTON_INVALID)
        return false;
    if (command != oi::Command::Start && command != oi::Command::Safe && command != oi::Command::Full)
        return false;
    takeRole(button);
    m_modeButtons.insert(button, command);
    emit mappingChanged();
    return true;
}

void GamepadInput::clearModeButton(SDL_GameControllerButton button)
{
    if (m_modeButtons.remove(button) > 0)
        emit mappingChanged();
}

double GamepadInput::shapeAxis(double value, double deadband, double expo)
{
    const double magnitude = std::min(std::abs(value), 1.0);
    if (magnitude <= deadband)
        return 0.0;
    const double s = (magnitude - deadband) / (1.0 - deadband);
    const double out = (1.0 - expo) * s + expo * s * s * s;
    return value < 0 ? -out : out;
}

MotionCommand GamepadInput::driveCommand(double x, double y, int speedLimit, double deadband, double expo)
{
    const double turn = shapeAxis(x, deadband, expo);
    const double forward = shapeAxis(y, deadband, expo);
    MotionCommand command = MotionCommand::stop();
    const int velocity = static_cast<int>(std::lround(forward * speedLimit));
    if (velocity != 0) {
        command.velocity = velocity;
        if (turn == 0.0)
            return command; // straight
        const long radius = std::lround(kArcRadiusAtDiagonal * std::abs(forward) / std::abs(turn));
        const int magnitude = static_cast<int>(std::clamp<long>(radius, kMinArcRadius, kMaxArcRadius));
        // The OI turns left for a positive radius; stick right means right,
        // going forward or backward alike.
        command.radius = turn > 0 ? -magnitude : magnitude;
        return command;
    }
    // Nothing forward: spin on the spot at the sideways speed.
    const int spin = static_cast<int>(std::lround(std::abs(turn) * speedLimit));
    if (spin == 0)
        return command;
    command.velocity = spin;
    command.radius = turn > 0 ? oi::kRadiusTurnInPlaceClockwise : oi::kRadiusTurnInPlaceCounterClockwise;
    return command;
}

QString GamepadInput::buttonName(SDL_GameControllerButton button)
{
    switch (button) {
    case SDL_CONTROLLER_BUTTON_A: return QStringLiteral("A");
    case SDL_CONTROLLER_BUTTON_B: return QStringLiteral("B");
    case SDL_CONTROLLER_BUTTON_X: return QStringLiteral("X");
    case SDL_CONTROLLER_BUTTON_Y: return QStringLiteral("Y");
    case SDL_CONTROLLER_BUTTON_BACK: return tr("Back");
    case SDL_CONTROLLER_BUTTON_GUIDE: return tr("Guide");
    case SDL_CONTROLLER_BUTTON_START: return tr("Start");
    case SDL_CONTROLLER_BUTTON_LEFTSTICK: return tr("Left stick press");
    case SDL_CONTROLLER_BUTTON_RIGHTSTICK: return tr("Right stick press");
    case SDL_CONTROLLER_BUTTON_LEFTSHOULDER: return QStringLiteral("LB");
    case SDL_CONTROLLER_BUTTON_RIGHTSHOULDER: return QStringLiteral("RB");
    case SDL_CONTROLLER_BUTTON_DPAD_UP: return tr("D-pad up");
    case SDL_CONTROLLER_BUTTON_DPAD_DOWN: return tr("D-pad down");
    case SDL_CONTROLLER_BUTTON_DPAD_LEFT: return tr("D-pad left");
    case SDL_CONTROLLER_BUTTON_DPAD_RIGHT: return tr("D-pad right");
    case SDL_CONTROLLER_BUTTON_INVALID: return tr("none");
    default: break;
    }
    const char *name = SDL_GameControllerGetStringForButton(button);
    return name ? QString::fromUtf8(name) : tr("button %1").arg(int(button));
}

QString GamepadInput::modeName(oi::Command command)
{
    switch (command) {
    case oi::Command::Start: return tr("Passive (128)");
    case oi::Command::Safe: return tr("Safe (131)");
    case oi::Command::Full: return tr("Full (132)");
    default: break;
    }
    return tr("command %1").arg(int(command));
}

void GamepadInput::poll()
{
    if (!m_reading)
        return;
    bool stickChanged = false;
    SDL_Event event;
    while (SDL_PollEvent(&event)) {
        switch (event.type) {
        case SDL_CONTROLLERDEVICEADDED:
            if (!m_controller)
                openGamepad(event.cdevice.which);
            break;
        case SDL_CONTROLLERDEVICEREMOVED:
            if (m_controller && event.cdevice.which == m_instance) {
                closeGamepad();
                openFirstGamepad();
            }
            break;
        case SDL_CONTROLLERBUTTONDOWN:
        case SDL_CONTROLLERBUTTONUP:
            if (m_controller && event.cbutton.which == m_instance)
                onButton(static_cast<SDL_GameControllerButton>(event.cbutton.button),
                         event.type == SDL_CONTROLLERBUTTONDOWN);
            break;
        case SDL_CONTROLLERAXISMOTION:
            if (m_controller && event.caxis.which == m_instance)
                stickChanged = true;
            break;
        default: break;
        }
    }
    if (stickChanged)
        readStick();
    updateCommand();
    schedulePolling();
}

void GamepadInput::openFirstGamepad()
{
    for (int i = 0; i < SDL_NumJoysticks() && !m_controller; ++i)
        openGamepad(i);
}

bool GamepadInput::openGamepad(int deviceIndex)
{
    if (m_controller || !SDL_IsGameController(deviceIndex))
        return false;
    SDL_GameController *controller = SDL_GameControllerOpen(deviceIndex);
    if (!controller)
        return false;
    m_controller = controller;
    m_sinceDeviceChange.invalidate(); // what the folder's change brought has come
    m_instance = SDL_JoystickInstanceID(SDL_GameControllerGetJoystick(controller));
    const char *name = SDL_GameControllerName(controller);
    m_name = name && *name ? QString::fromUtf8(name) : tr("Gamepad");
    // A dead-man already down when the pad appears (stuck, or taped down)
    // does not count; driving needs a fresh press.
    m_deadManHeld = false;
    emit gamepadChanged(m_name);
    readStick();
    return true;
}

void GamepadInput::closeGamepad()
{
    setDeadManHeld(false);
    SDL_GameControllerClose(m_controller);
    m_controller = nullptr;
    m_instance = -1;
    m_name.clear();
    if (!m_stick.isNull()) {
        m_stick = QPointF();
        emit stickMoved(m_stick);
    }
    emit gamepadChanged(QString());
}

void GamepadInput::onButton(SDL_GameControllerButton button, bool pressed)
{
    if (button == m_deadManButton) {
        setDeadManHeld(pressed);
        return;
    }
    if (!pressed)
        return;
    if (button == m_stopAllButton) {
        emit stopAllRequested();
        return;
    }
    const auto mode = m_modeButtons.constFind(button);
    if (mode != m_modeButtons.cend())
        emit modeRequested(*mode);
}

void GamepadInput::setDeadManHeld(bool held)
{
    if (held == m_deadManHeld)
        return;
    m_deadManHeld = held;
    emit deadManChanged(held);
    if (!held) {
        // The one stop on release, even if the stick was already centred.
        m_lastCommand = MotionCommand::stop();
        emit motionRequested(m_lastCommand);
    }
}

void GamepadInput::readStick()
{
    if (!m_controller)
        return;
    // SDL's stick y grows downwards; forward is up.
    const QPointF stick(normalizedAxis(SDL_GameControllerGetAxis(m_controller, SDL_CONTROLLER_AXIS_LEFTX)),
                        -normalizedAxis(SDL_GameControllerGetAxis(m_controller, SDL_CONTROLLER_AXIS_LEFTY)));
    if (stick == m_stick)
        return;
    m_stick = stick;
    emit stickMoved(m_stick);
}

void GamepadInput::updateCommand()
{
    if (!m_deadManHeld)
        return; // released: the stop was sent on release
    emitCommand(driveCommand(m_stick.x(), m_stick.y(), m_speedLimit, m_deadband, m_expo));
}

void GamepadInput::emitCommand(const MotionCommand &command)
{
    if (command == m_lastCommand)
        return;
    m_lastCommand = command;
    emit motionRequested(command);
}

#include "moc_gamepad_input.cpp"
