// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "battery_health.h"
#include "robot_profile.h"
#include "sensor_snapshot.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QString>
#include <QStringList>

#include <optional>

// One robot's mode as the user sees it: what was asked (the mode commands
// the session sent), what the robot reports (packet 35), and why it changed
// ("A cliff (front left) dropped it to Passive at 12:03:04", "You asked for
// Passive at …"). The session owns one and feeds it; every view reads it
// from the selected session, so no view keeps a copy that could belong to
// another robot. Plain values, no timers: a test feeds frames and times.
class RobotMode {
    Q_DECLARE_TR_FUNCTIONS(RobotMode)
public:
    enum class Cause {
        None,      // nothing to explain
        Asked,     // a command the user sent put it in Passive
        Safety,    // Safe fell back to Passive by itself: a cliff, a wheel drop, the charger
                   // (on the dock, at once: the robot refused Safe); or Safe or Full
                   // for none of those with the battery nearly flat
        NotCharging, // Safe or Full on the charger: the battery drains there
        OwnProgram,  // a cleaning, dock search or demo the user asked for runs, in Passive
    };
    // Passive frames on the charger after Safe was asked before it counts as
    // refused: frames read before the robot had the command say Passive too.
    static constexpr int kRefusedAfterFrames = 5;
    // How long Safe or Full stays on the charger before the warning: driving
    // off the dock in Full takes a moment.
    static constexpr qint64 kNotChargingAfterMs = 2000;

    // A new connection: nothing asked, nothing reported.
    void clear();
    // The user asked for a mode or cleaning command (sent at `at`).
    void asked(oi::Command command, const QDateTime &at);
    // A frame read at `atMs` (milliseconds since the epoch: no time zone is
    // looked up for every frame). Returns true when what this shows changed.
    bool observe(const oi::SensorSnapshot &frame, qint64 atMs);

    // A command the session sent (any, asked by the user or not). A
    // cleaning, demo, dock search or button press, or playing a script that
    // starts one (`scriptStartsOne`), leaves the robot running a command of
    // its own, in Passive, where it ignores Drive; Safe or Full ends that.
    void sent(oi::Command command, bool scriptStartsOne);
    // The robot may be running a command of its own: a stop needs Safe first.
    bool runsOwnCommand() const { return m_ownCommand; }

    std::optional<oi::OiMode> reported() const { return m_reported; }
    std::optional<oi::Command> lastAsked() const { return m_asked; }
    // Passive or Off: the robot ignores motion, LEDs, songs (the documents'
    // "Available in modes: Safe or Full").
    bool ignoresMotion() const;
    Cause cause() const { return m_cause; }
    // Safe fell back to Passive on the charger, and nothing else: on its dock
    // the robot refuses Safe, and Full is the way off the dock.
    bool safeRefusedOnDock() const;

    // Why the robot is in Passive, or that Safe or Full on the dock does
    // not charge it, in a sentence; empty when nothing needs explaining.
    // Only ever about the mode reported now.
    QString reason() const;
    // The same in a few words, for a fleet tile: "cliff (front left)".
    QString shortReason() const;
    // The cause as words a program reads, for the bridge's state
    // (`mode_cause`, docs/mqtt.md): "asked", or "safety" with any of
    // "cliff_left", "cliff_front_left", "cliff_front_right", "cliff_right",
    // "wheel_drop_left", "wheel_drop_right", "wheel_drop_caster", "charger",
    // "battery_low";
    // or "not_charging" (Safe or Full on the dock). Empty when shortReason() is.
    QStringList causeKeys() const;
    // shortReason() of a robot whose causeKeys() are these, in this
    // program's language (a console showing another program's robot).
    // Words it does not know are left out.
    static QString shortReasonOf(const QStringList &causeKeys);
    // reason() and nextStep() together, as every view shows them.
    QString advice() const;
    // The one step that makes it work again, to go with reason():
    // "Carry it back from the edge, then Enter Safe." A cliff whose signals
    // read like a dark rug (darkFloorSignals()) says so, with the way off it.
    QString nextStep() const;
    // A cliff sensor over a drop sees almost nothing (a few counts of 4095);
    // over a dark rug it still sees this much or more, though less than its
    // robot's threshold. Frames read: the cliff, its signal, the wheel drops.
    static constexpr int kDarkFloorSignalFrom = 100;
    static bool darkFloorSignals(const oi::SensorSnapshot &frame);
    // Both wheels dropped, or the caster: picked up. Full mode ignores wheel
    // drops and would drive its wheels in the hands holding it; every path
    // that asks for motion in Full stops it, as the bridge does.
    static bool offTheFloor(const oi::SensorSnapshot &frame);
    // Commands that turn the drive wheels: Drive, Drive Direct, Drive PWM, and
    // Play Script (a Create's script drives).
    static bool drivesWheels(oi::Command command);
    // "the robot is off the floor: Full mode would drive its wheels in your hands"
    static QString offTheFloorWords();
    // The robot reports wheel speeds asked of it (packets 39, 41, 42), by any path.
    static bool wheelsAsked(const oi::SensorSnapshot &frame);
    // Why `command` cannot work in the mode reported now, or empty when it can.
    QString whyNot(oi::Command command) const;
    // Why a lesson goal reading `goalPackets` (packet keys) can no longer be
    // met in this mode, and what to do; empty when it still can. A goal that
    // needs the robot to drive (`drives`) cannot be met while it ignores
    // motion; a cliff goal cannot, once another cliff sensor stopped it.
    QString outOfReach(const QStringList &goalPackets, bool drives) const;
    // True when a safety stop came from a sensor a lesson goal reading
    // `goalPackets` is about (a cliff step's cliff, a wheel drop step's
    // wheels): the stop is what the step shows, not a fault to undo yet.
    bool stopExpectedBy(const QStringList &goalPackets) const;

private:
    static QString causeWordsOf(const QStringList &causeKeys);
    // Bit per cliff sensor (oi::CliffSensor) that a goal reading `goalPackets` reads.
    static std::uint8_t cliffsRead(const QStringList &goalPackets);
    bool causeStillShows(const oi::SensorSnapshot &frame) const;

    std::optional<oi::OiMode> m_reported;
    std::optional<oi::Command> m_asked;
    bool m_askPending = false; // asked, and the robot has not changed mode since
    bool m_ownCommand = false; // see runsOwnCommand()
    Cause m_cause = Cause::None;
    QDateTime m_changedAt;
    // What the frame that showed a safety drop saw.
    std::uint8_t m_cliffs = 0; // bit per oi::CliffSensor
    // The tripped sensors' signals read low but well above a drop's, and no
    // wheel dropped: most likely a dark rug or floor, not an edge.
    bool m_darkFloor = false;
    QString m_cliffSignals; // those signals in words: front left 260
    bool m_wheelDropLeft = false, m_wheelDropRight = false, m_wheelDropCaster = false;
    bool m_charger = false;
    // Safe or Full fell with none of the above and the battery nearly flat
    // (this frame, or the one before, under load).
    std::optional<BatteryHealth::LowBattery> m_lowBattery;
    std::optional<BatteryHealth::LowBattery> m_lowBefore; // the last frame's, in Safe or Full
    int m_passiveOnChargerSinceAsked = 0; // while Safe is asked
    std::optional<qint64> m_onChargerSinceMs; // in Safe or Full
    // Safe or Full on the charger long enough to warn (Cause::NotCharging).
    bool observeCharger(const oi::SensorSnapshot &frame, qint64 atMs);
    // A robot that reports no mode (the SCI has no packet 35): the mode its
    // commands put it in, as its document says, and Passive once Safe meets
    // a wheel drop or the charger. The link's Start leaves it in Passive.
    oi::OiMode m_unreported = oi::OiMode::Passive;
    oi::OiMode unreportedMode(const oi::SensorSnapshot &frame);
};
