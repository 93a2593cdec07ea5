// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "sensor_snapshot.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QList>
#include <QString>

#include <optional>
#include <vector>

// How worn a robot's pack is, from what the robot streams (packets 22, 23,
// 26): its capacity, counted as the charge that flows (23 over time) while
// the resting voltage moves across part of its range, and its internal
// resistance, the voltage step over the current step when a drive starts or
// stops (the median of several). Plain values on the frames' own clock: a
// test feeds frames and times.
enum class BatteryCondition { Unknown, Good, Worn, Replace };

// One pack's figures, as measured in one session and kept per robot.
struct BatteryMeasurement {
    QDateTime at;
    std::optional<double> capacityMah;    // counted
    int claimedCapacityMah = 0;           // what the robot says it holds (26)
    std::optional<double> resistanceMohm; // the median of the samples
    int resistanceSamples = 0;
    double cycleSeen = 0; // how much of a full charge the count covered, 0 to 1
    friend bool operator==(const BatteryMeasurement &, const BatteryMeasurement &) = default;
};

struct BatteryHealthReport {
    BatteryCondition condition = BatteryCondition::Unknown;
    QString reason;     // the figures that decided, in words
    double confidence = 0; // 0 to 1: how much of a cycle the verdict has seen
    BatteryMeasurement measurement;
    bool fromEarlierSession = false; // measured before this connection (kept)
    bool estimatedFromVoltage = false; // the robot re-seeded its charge from the voltage at boot
    QString trend;      // the capacity over the kept measurements, or empty
};

class BatteryHealth {
    Q_DECLARE_TR_FUNCTIONS(BatteryHealth)
public:
    // A new pack of these robots (12 NiMH cells, with its wiring), and the
    // limits beyond which it is worn or should be replaced.
    static constexpr double kNewPackResistanceMohm = 250;
    static constexpr double kWornCapacity = 0.70, kReplaceCapacity = 0.50;     // of the claimed capacity
    static constexpr double kWornResistance = 2.0, kReplaceResistance = 3.0;   // times a new pack's
    // The pack's resting voltage from flat to full, taken as a straight line
    // between, as the robot's own estimate from voltage takes it.
    static constexpr double kFlatMv = 13100, kFullMv = 16100;
    // A step: the current changes this much between two frames, then holds
    // (within kSteadyMa) after at least kMinStepMa in all, within a second.
    static constexpr double kStepMa = 80, kSteadyMa = 25, kMinStepMa = 200, kStepWithinSeconds = 1;
    static constexpr int kMinResistanceSamples = 3;
    static constexpr int kKeptResistanceSamples = 31;
    // Less than this much of a cycle counted gives no capacity.
    static constexpr double kMinCycleSeen = 0.05;
    // Frames further apart lose the count (the link was down).
    static constexpr double kGapSeconds = 1;
    // Nearly flat: the gauge at or below this, or the voltage under load at or below this.
    static constexpr double kLowPercent = 15;
    static constexpr int kLowMv = 13000;
    // Kept per robot: this many sessions' measurements.
    static constexpr int kKeptMeasurements = 12;

    // A stream frame read at `seconds`.
    void observe(const oi::SensorSnapshot &frame, double seconds);
    // The robot printed "estimate-battery-level-from-voltage" as it booted:
    // its charge (25) is a guess from the voltage until a full charge.
    void bootTextSeen() { m_estimatedFromVoltage = true; }
    bool estimatedFromVoltage() const { return m_estimatedFromVoltage; }
    // A new connection: the count starts again; what is kept stays.
    void restart();
    // The measurements kept for this robot, oldest first (from the settings).
    void setKept(const QList<BatteryMeasurement> &kept);
    const QList<BatteryMeasurement> &kept() const { return m_kept; }
    // Keeps this connection's figures as its entry of kept() (one per
    // connection, the newest kKeptMeasurements).
    void keep(const BatteryMeasurement &m);
    // This connection's figures so far (dated `at`).
    BatteryMeasurement measurement(const QDateTime &at = QDateTime::currentDateTime()) const;
    // The verdict: this connection's when it has seen enough, else the last kept one.
    BatteryHealthReport report(const QDateTime &at = QDateTime::currentDateTime()) const;

    static BatteryCondition judge(const BatteryMeasurement &m, QString *reason = nullptr);
    // "good", "worn", "replace", "unknown": for programs (roomba-ctl, the bridge).
    static QString conditionKey(BatteryCondition condition);
    static std::optional<BatteryCondition> conditionOfKey(const QString &key);
    // "Good", "Worn", "Replace", "Not measured yet", in the user's language.
    static QString conditionWords(BatteryCondition condition);
    // "30 % of a cycle seen, 12 resistance samples"
    static QString confidenceWords(const BatteryMeasurement &m);
    // The kept capacities as a line: "2950 mAh (2026-11-02), 2400 mAh (2026-12-02)"; empty under two.
    static QString trendWords(const QList<BatteryMeasurement> &kept);

    // A battery nearly flat, from a frame: its gauge (25/26) and voltage (22).
    struct LowBattery {
        double percent = 0; // the gauge's; -1 when the frame has none
        double volts = 0;
    };
    static std::optional<LowBattery> nearlyFlat(const oi::SensorSnapshot &frame);
    // "battery nearly flat (8 %, 12.9 V): the robot leaves Safe or Full by itself under load; charge it"
    static QString nearlyFlatWords(const LowBattery &low);
    // What a charging fault (packet 21 = 5) usually is, and what to do.
    static QString chargingFaultWords();

private:
    struct Reading {
        double mv = 0, ma = 0, seconds = 0, countedMah = 0;
    };
    double restingFraction(const Reading &r) const;
    std::optional<double> medianResistance() const;
    void noteStep(const Reading &now, bool steady);

    std::optional<Reading> m_last;
    bool m_lastSteady = false;
    std::optional<Reading> m_stepFrom;       // the steady frame before a current step
    std::vector<double> m_resistanceSamples; // mΩ, the newest kKeptResistanceSamples
    std::size_t m_totalSamples = 0;
    double m_countedMah = 0;                 // charge in (+) and out (-) since the count began
    std::optional<Reading> m_first, m_latest; // steady readings that span the count
    int m_claimedMah = 0;
    bool m_estimatedFromVoltage = false;
    QList<BatteryMeasurement> m_kept;
    bool m_keptThisConnection = false; // kept()'s last entry is this connection's
};
