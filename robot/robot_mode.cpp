// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_mode.h"

#include "command_catalog.h"
#include "command_modes.h"

#include <algorithm>

namespace {

constexpr oi::CliffSensor kCliffs[] = {oi::CliffSensor::Left, oi::CliffSensor::FrontLeft, oi::CliffSensor::FrontRight,
                                       oi::CliffSensor::Right};
// The packet keys of the cliff flags, in kCliffs' order; a goal on a cliff
// signal ("cliff_front_left_signal") reads the same sensor.
constexpr const char *kCliffKeys[] = {"cliff_left", "cliff_front_left", "cliff_front_right", "cliff_right"};

std::uint8_t cliffBits(const oi::SensorSnapshot &frame)
{
    std::uint8_t bits = 0;
    for (int i = 0; i < 4; ++i)
        if (frame.cliff(kCliffs[i]))
            bits |= std::uint8_t(1u << i);
    return bits;
}

bool charging(const oi::SensorSnapshot &frame)
{
    const oi::ChargingState state = frame.chargingState();
    return frame.has(21)
           && (state == oi::ChargingState::FullCharging || state == oi::ChargingState::Trickle
               || state == oi::ChargingState::Reconditioning);
}

bool onCharger(const oi::SensorSnapshot &frame)
{
    return frame.chargingSource(oi::ChargingSource::HomeBase)
           || frame.chargingSource(oi::ChargingSource::InternalCharger);
}

} // namespace

bool RobotMode::offTheFloor(const oi::SensorSnapshot &frame)
{
    return (frame.wheelDropLeft() && frame.wheelDropRight()) || frame.wheelDropCaster();
}

bool RobotMode::drivesWheels(oi::Command command)
{
    using C = oi::Command;
    return command == C::Drive || command == C::DriveDirect || command == C::DrivePwm || command == C::PlayScript;
}

bool RobotMode::wheelsAsked(const oi::SensorSnapshot &frame)
{
    return frame.raw(39) != 0 || frame.raw(41) != 0 || frame.raw(42) != 0;
}

QString RobotMode::offTheFloorWords()
{
    return tr("the robot is off the floor: Full mode would drive its wheels in your hands");
}

bool RobotMode::darkFloorSignals(const oi::SensorSnapshot &frame)
{
    if (frame.wheelDropLeft() || frame.wheelDropRight() || frame.wheelDropCaster() || !cliffBits(frame))
        return false;
    for (oi::CliffSensor c : kCliffs)
        if (frame.cliff(c) && (!frame.has(28 + int(c)) || frame.cliffSignal(c) < kDarkFloorSignalFrom))
            return false;
    return true;
}

void RobotMode::clear() { *this = RobotMode(); }

void RobotMode::asked(oi::Command command, const QDateTime &at)
{
    m_asked = command;
    m_askPending = true;
    m_passiveOnChargerSinceAsked = 0;
    m_changedAt = at;
    // Asking again is the answer to what was shown: a new request starts afresh.
    m_cause = oi::startsCleaning(command) ? Cause::OwnProgram : Cause::None;
}

void RobotMode::sent(oi::Command command, bool scriptStartsOne)
{
    if (oi::startsCleaning(command) || command == oi::Command::Buttons
        || (command == oi::Command::PlayScript && scriptStartsOne))
        m_ownCommand = true;
    else if (command == oi::Command::Safe || command == oi::Command::Full)
        m_ownCommand = false;
    if (command == oi::Command::Safe || command == oi::Command::Control)
        m_unreported = oi::OiMode::Safe;
    else if (command == oi::Command::Full)
        m_unreported = oi::OiMode::Full;
    else if (oi::entersPassive(command) || command == oi::Command::Power || command == oi::Command::Baud)
        m_unreported = oi::OiMode::Passive;
}

oi::OiMode RobotMode::unreportedMode(const oi::SensorSnapshot &frame)
{
    // SCI: in Safe, a wheel drop or a powered charger stops the motors and
    // reverts to Passive (a cliff does only while driving forward, which a
    // frame does not show).
    constexpr int kNotCharging = 0, kChargingError = 5;
    const bool charger = frame.has(21) && frame.raw(21) != kNotCharging && frame.raw(21) != kChargingError;
    if (m_unreported == oi::OiMode::Safe
        && (frame.wheelDropLeft() || frame.wheelDropRight() || frame.wheelDropCaster() || charger))
        m_unreported = oi::OiMode::Passive;
    return m_unreported;
}

bool RobotMode::ignoresMotion() const
{
    return m_reported == oi::OiMode::Passive || m_reported == oi::OiMode::Off;
}

bool RobotMode::causeStillShows(const oi::SensorSnapshot &frame) const
{
    return (m_cliffs & cliffBits(frame)) || (m_wheelDropLeft && frame.wheelDropLeft())
           || (m_wheelDropRight && frame.wheelDropRight()) || (m_wheelDropCaster && frame.wheelDropCaster())
           || (m_charger && onCharger(frame)) || (m_lowBattery && !charging(frame));
}

bool RobotMode::observe(const oi::SensorSnapshot &frame, qint64 atMs)
{
    if (!frame.has(35) && !frame.robotProfile().packet(35)) {
        oi::SensorSnapshot withMode = frame;
        withMode.set(35, static_cast<std::int32_t>(unreportedMode(frame)));
        return observe(withMode, atMs);
    }
    if (!frame.has(35))
        return false;
    const oi::OiMode mode = frame.oiMode();
    const std::optional<oi::OiMode> before = m_reported;
    // Under load, before a fall: the frame that shows Passive has the load off.
    const std::optional<BatteryHealth::LowBattery> lowBefore = m_lowBefore;
    m_lowBefore = mode == oi::OiMode::Safe || mode == oi::OiMode::Full ? BatteryHealth::nearlyFlat(frame) : std::nullopt;
    const Cause causeBefore = m_cause;
    if (before == mode) {
        // A safety reason lasts as long as what caused it.
        if (m_cause == Cause::Safety && !causeStillShows(frame))
            m_cause = Cause::None;
        // On the dock Safe falls back to Passive before a frame can show it.
        if (mode == oi::OiMode::Passive && m_askPending && m_asked == oi::Command::Safe && onCharger(frame)
            && ++m_passiveOnChargerSinceAsked >= kRefusedAfterFrames) {
            m_askPending = false;
            m_cause = Cause::Safety;
            m_changedAt = QDateTime::fromMSecsSinceEpoch(atMs);
            m_cliffs = 0;
            m_wheelDropLeft = m_wheelDropRight = m_wheelDropCaster = false;
            m_charger = true;
            m_lowBattery.reset();
        }
        observeCharger(frame, atMs);
        return m_cause != causeBefore;
    }
    m_reported = mode;
    m_cause = Cause::None;
    m_onChargerSinceMs.reset();
    observeCharger(frame, atMs);
    if (mode == oi::OiMode::Passive) {
        if (m_askPending && m_asked && oi::entersPassive(*m_asked)) {
            m_cause = oi::startsCleaning(*m_asked) ? Cause::OwnProgram : Cause::Asked;
        } else if (before == oi::OiMode::Safe || before == oi::OiMode::Full) {
            m_cause = Cause::Safety;
            m_changedAt = QDateTime::fromMSecsSinceEpoch(atMs);
            m_cliffs = cliffBits(frame);
            m_darkFloor = darkFloorSignals(frame);
            QStringList signalWords;
            const QString names[] = {tr("left"), tr("front left"), tr("front right"), tr("right")};
            for (int i = 0; i < 4; ++i)
                if ((m_cliffs & (1u << i)) && frame.has(28 + i))
                    signalWords << QStringLiteral("%1 %2").arg(names[i]).arg(frame.cliffSignal(kCliffs[i]));
            m_cliffSignals = signalWords.join(tr(", "));
            m_wheelDropLeft = frame.wheelDropLeft();
            m_wheelDropRight = frame.wheelDropRight();
            m_wheelDropCaster = frame.wheelDropCaster();
            m_charger = onCharger(frame);
            m_lowBattery.reset();
            if (!m_cliffs && !m_wheelDropLeft && !m_wheelDropRight && !m_wheelDropCaster && !m_charger)
                m_lowBattery = lowBefore ? lowBefore : BatteryHealth::nearlyFlat(frame);
            // Full has no safety stops: it falls by itself only for its battery.
            if (before == oi::OiMode::Full && !m_lowBattery)
                m_cause = Cause::None;
        }
    }
    m_askPending = false;
    return true;
}

bool RobotMode::observeCharger(const oi::SensorSnapshot &frame, qint64 atMs)
{
    if (m_reported != oi::OiMode::Safe && m_reported != oi::OiMode::Full)
        return false;
    if (!onCharger(frame)) {
        m_onChargerSinceMs.reset();
        if (m_cause == Cause::NotCharging)
            m_cause = Cause::None;
        return false;
    }
    if (!m_onChargerSinceMs)
        m_onChargerSinceMs = atMs;
    if (atMs - *m_onChargerSinceMs >= kNotChargingAfterMs)
        m_cause = Cause::NotCharging;
    return m_cause == Cause::NotCharging;
}

// The only cause of a fall back is the charger: the dock refused Safe.
bool RobotMode::safeRefusedOnDock() const
{
    return m_cause == Cause::Safety && m_charger && !m_cliffs && !m_wheelDropLeft && !m_wheelDropRight
           && !m_wheelDropCaster;
}

QStringList RobotMode::causeKeys() const
{
    if (m_cause == Cause::NotCharging && !ignoresMotion())
        return {QStringLiteral("not_charging")};
    if (m_reported != oi::OiMode::Passive || m_cause == Cause::None)
        return {};
    if (m_cause == Cause::Asked || m_cause == Cause::OwnProgram)
        return {QStringLiteral("asked")};
    QStringList keys{QStringLiteral("safety")};
    for (int i = 0; i < 4; ++i)
        if (m_cliffs & (1u << i))
            keys << QLatin1String(kCliffKeys[i]);
    if (m_wheelDropLeft)
        keys << QStringLiteral("wheel_drop_left");
    if (m_wheelDropRight)
        keys << QStringLiteral("wheel_drop_right");
    if (m_wheelDropCaster)
        keys << QStringLiteral("wheel_drop_caster");
    if (m_charger)
        keys << QStringLiteral("charger");
    if (m_lowBattery)
        keys << QStringLiteral("battery_low");
    return keys;
}

QString RobotMode::causeWordsOf(const QStringList &keys)
{
    QStringList parts;
    const QString cliffNames[] = {tr("left"), tr("front left"), tr("front right"), tr("right")};
    QStringList cliffs;
    for (int i = 0; i < 4; ++i)
        if (keys.contains(QLatin1String(kCliffKeys[i])))
            cliffs << cliffNames[i];
    if (!cliffs.isEmpty())
        parts << tr("cliff (%1)").arg(cliffs.join(tr(", ")));
    QStringList wheels;
    if (keys.contains(QLatin1String("wheel_drop_left")))
        wheels << tr("left");
    if (keys.contains(QLatin1String("wheel_drop_right")))
        wheels << tr("right");
    if (keys.contains(QLatin1String("wheel_drop_caster")))
        wheels << tr("caster");
    if (!wheels.isEmpty())
        parts << tr("wheel drop (%1)").arg(wheels.join(tr(", ")));
    if (keys.contains(QLatin1String("charger")))
        parts << tr("charger");
    if (keys.contains(QLatin1String("battery_low")))
        parts << tr("battery nearly flat");
    if (keys.contains(QLatin1String("not_charging")))
        parts << tr("on the dock, not charging");
    return parts.join(tr(" and "));
}

QString RobotMode::reason() const
{
    if (m_cause == Cause::NotCharging && m_reported == oi::OiMode::Full)
        return tr("Full mode on the dock: the battery does not charge, it drains.");
    if (m_cause == Cause::NotCharging && m_reported == oi::OiMode::Safe)
        return tr("Safe mode on the dock: the battery does not charge, it drains.");
    if (m_reported != oi::OiMode::Passive)
        return {};
    const QString time = m_changedAt.toString(QStringLiteral("HH:mm:ss"));
    if (safeRefusedOnDock())
        return tr("The robot is on its dock: Safe mode is refused on the charger (%1).").arg(time);
    switch (m_cause) {
    case Cause::None:
    case Cause::NotCharging:
        return {};
    case Cause::Asked:
        return tr("You asked for Passive at %1.").arg(time);
    case Cause::OwnProgram:
        // Said for as long as it runs: the stop keys end it (TeleopController::stopAll()).
        return m_asked == oi::Command::SeekDock ? tr("Seeking its dock (its own program) · Space stops it")
               : m_asked == oi::Command::Demo   ? tr("Running a demo (its own program) · Space stops it")
                                                : tr("Cleaning (its own program) · Space stops it");
    case Cause::Safety: {
        if (m_lowBattery) {
            QString words = BatteryHealth::nearlyFlatWords(*m_lowBattery);
            words[0] = words[0].toUpper();
            return tr("%1 (it fell to Passive at %2).").arg(words, time);
        }
        const QString words = causeWordsOf(causeKeys());
        return words.isEmpty() ? tr("A safety stop dropped it to Passive at %1.").arg(time)
                               : tr("A %1 dropped it to Passive at %2.").arg(words, time);
    }
    }
    return {};
}

QString RobotMode::shortReason() const
{
    if (m_cause == Cause::OwnProgram && m_reported == oi::OiMode::Passive)
        return m_asked == oi::Command::SeekDock ? tr("seeking its dock")
               : m_asked == oi::Command::Demo   ? tr("running a demo")
                                                : tr("cleaning");
    return shortReasonOf(causeKeys());
}

QString RobotMode::advice() const
{
    const QString why = reason(), step = nextStep();
    return why.isEmpty() || step.isEmpty() ? why : why + QLatin1Char(' ') + step;
}

QString RobotMode::shortReasonOf(const QStringList &causeKeys)
{
    if (causeKeys.isEmpty())
        return {};
    if (causeKeys.contains(QLatin1String("asked")))
        return tr("asked for");
    if (causeKeys == QStringList{QStringLiteral("safety"), QStringLiteral("charger")})
        return tr("Safe refused on the dock");
    const QString words = causeWordsOf(causeKeys);
    return words.isEmpty() ? tr("safety stop") : words;
}

QString RobotMode::nextStep() const
{
    if (m_cause == Cause::NotCharging && !ignoresMotion())
        return tr("Enter Passive to charge it, or drive it off the dock.");
    if (!ignoresMotion() || m_cause == Cause::OwnProgram)
        return {}; // a program of its own: reason() says how to stop it
    if (safeRefusedOnDock())
        return tr("Lift it off the dock, or drive it off in Full (Full does not stop at cliffs or wheel drops).");
    if (m_cause == Cause::Safety) {
        // A robot that stops half over an edge reads like one on a dark rug,
        // so the only advice is to carry it: Full would drive it off an edge.
        if (m_cliffs && m_darkFloor)
            return tr("Carry it back from the edge, then Enter Safe. Its cliff signals read %1 of 4095, as over a "
                      "dark rug: if you can see the floor under it, carry it to a lighter floor, then Enter Safe.")
                .arg(m_cliffSignals);
        if (m_cliffs)
            return tr("Carry it back from the edge, then Enter Safe.");
        if (m_wheelDropLeft || m_wheelDropRight || m_wheelDropCaster)
            return tr("Put it back on its wheels, then Enter Safe.");
        if (m_lowBattery)
            return tr("Put it on its dock in Passive to charge it; it drives again once charged.");
    }
    return tr("Enter Safe to drive.");
}

QString RobotMode::whyNot(oi::Command command) const
{
    if (!ignoresMotion() || !oi::needsSafeOrFull(command))
        return {};
    const oi::CommandSpec &spec = oi::commandSpec(command);
    const QString name = QString::fromUtf8(spec.title.data(), qsizetype(spec.title.size()));
    // The same reasons as oi::whyNotInPassive(), in the user's language.
    if (command == oi::Command::PlayScript)
        return tr("%1 needs Safe or Full mode: in Passive the Create ignores the script's Drive, so a wait never "
                  "ends. Enter Safe first.").arg(name);
    return tr("%1 needs Safe or Full mode: the robot ignores it in Passive. Enter Safe first.").arg(name);
}

std::uint8_t RobotMode::cliffsRead(const QStringList &goalPackets)
{
    std::uint8_t read = 0;
    for (int i = 0; i < 4; ++i)
        for (const QString &key : goalPackets)
            if (key == QLatin1String(kCliffKeys[i]) || key.startsWith(QLatin1String(kCliffKeys[i]) + '_'))
                read |= std::uint8_t(1u << i);
    return read;
}

bool RobotMode::stopExpectedBy(const QStringList &goalPackets) const
{
    if (!ignoresMotion() || m_cause != Cause::Safety)
        return false;
    if (cliffsRead(goalPackets) & m_cliffs)
        return true;
    const bool wheelDropped = m_wheelDropLeft || m_wheelDropRight || m_wheelDropCaster;
    return wheelDropped && goalPackets.contains(QLatin1String("bumps_wheel_drops"));
}

QString RobotMode::outOfReach(const QStringList &goalPackets, bool drives) const
{
    if (!ignoresMotion())
        return {};
    if (m_cause == Cause::Safety && m_cliffs) {
        const std::uint8_t read = cliffsRead(goalPackets);
        QStringList goalCliffs;
        const QString names[] = {tr("left"), tr("front left"), tr("front right"), tr("right")};
        for (int i = 0; i < 4; ++i)
            if (read & (1u << i))
                goalCliffs << names[i];
        // Another cliff sensor stopped the robot before the goal's own reached the edge.
        if (read && !(read & m_cliffs))
            return tr("Out of reach: %1 The goal needs the %2 cliff sensor to reach the edge first. Carry the robot "
                      "back from the edge, Enter Safe, and drive at the edge head on.")
                .arg(reason(), goalCliffs.join(tr(" or ")));
    }
    if (!drives)
        return {};
    const QString why = reason();
    return tr("Out of reach: the robot does not drive in Passive mode. %1").arg((why.isEmpty() ? QString() : why + ' ') + nextStep());
}
