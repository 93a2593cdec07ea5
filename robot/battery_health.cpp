// SPDX-License-Identifier: GPL-3.0-or-later
#include "battery_health.h"

#include <QStringList>

#include <algorithm>
#include <cmath>

void BatteryHealth::observe(const oi::SensorSnapshot &frame, double seconds)
{
    if (frame.has(26) && frame.batteryCapacityMah() > 0)
        m_claimedMah = frame.batteryCapacityMah();
    // The charger found the pack full: the gauge knows it again.
    if (frame.has(21) && frame.chargingState() == oi::ChargingState::Trickle)
        m_estimatedFromVoltage = false;
    // 0 V is no measurement yet (a robot just woken), not a voltage.
    if (!frame.has(22) || !frame.has(23) || frame.voltageMv() == 0)
        return;
    Reading now{double(frame.voltageMv()), double(frame.currentMa()), seconds, m_countedMah};
    if (m_last) {
        const double dt = seconds - m_last->seconds;
        // Frames read in one go share a time (dt 0); time going back is a replay's jump.
        if (dt < 0 || dt > kGapSeconds) {
            // Charge that flowed while nothing was read cannot be counted: the count starts again.
            m_first.reset();
            m_latest.reset();
            m_stepFrom.reset();
            m_last.reset();
        } else {
            m_countedMah += (now.ma + m_last->ma) / 2 * dt / 3600;
            now.countedMah = m_countedMah;
        }
    }
    const bool steady = m_last && std::abs(now.ma - m_last->ma) <= kSteadyMa;
    noteStep(now, steady);
    // The span of the count, between steady readings (a reading in a step
    // mixes two currents).
    if (steady && !m_stepFrom) {
        if (!m_first)
            m_first = now;
        else
            m_latest = now;
    }
    m_last = now;
    m_lastSteady = steady;
}

void BatteryHealth::noteStep(const Reading &now, bool steady)
{
    if (!m_last)
        return;
    if (!m_stepFrom) {
        if (m_lastSteady && std::abs(now.ma - m_last->ma) >= kStepMa)
            m_stepFrom = m_last;
        return;
    }
    if (now.seconds - m_stepFrom->seconds > kStepWithinSeconds) {
        m_stepFrom.reset(); // it never settled: no sample
        return;
    }
    if (!steady)
        return;
    const double stepMa = now.ma - m_stepFrom->ma;
    if (std::abs(stepMa) >= kMinStepMa) {
        // mV per mA is ohms.
        const double mohm = (now.mv - m_stepFrom->mv) / stepMa * 1000;
        if (mohm > 0 && mohm < 10000) {
            if (m_resistanceSamples.size() == std::size_t(kKeptResistanceSamples))
                m_resistanceSamples.erase(m_resistanceSamples.begin());
            m_resistanceSamples.push_back(mohm);
            ++m_totalSamples;
        }
    }
    m_stepFrom.reset();
}

void BatteryHealth::restart()
{
    m_last.reset();
    m_lastSteady = false;
    m_stepFrom.reset();
    m_resistanceSamples.clear();
    m_totalSamples = 0;
    m_countedMah = 0;
    m_first.reset();
    m_latest.reset();
    m_claimedMah = 0;
    m_estimatedFromVoltage = false;
    m_keptThisConnection = false;
}

void BatteryHealth::setKept(const QList<BatteryMeasurement> &kept)
{
    m_kept = kept;
    m_keptThisConnection = false;
}

void BatteryHealth::keep(const BatteryMeasurement &m)
{
    if (m_keptThisConnection && !m_kept.isEmpty())
        m_kept.last() = m;
    else
        m_kept.append(m);
    m_keptThisConnection = true;
    while (m_kept.size() > kKeptMeasurements)
        m_kept.removeFirst();
}

std::optional<double> BatteryHealth::medianResistance() const
{
    if (m_resistanceSamples.size() < std::size_t(kMinResistanceSamples))
        return std::nullopt;
    std::vector<double> sorted = m_resistanceSamples;
    const auto middle = sorted.begin() + std::ptrdiff_t(sorted.size() / 2);
    std::nth_element(sorted.begin(), middle, sorted.end());
    return *middle;
}

double BatteryHealth::restingFraction(const Reading &r) const
{
    // The voltage less the pack's own drop at that current (negative discharging).
    const double mohm = medianResistance().value_or(kNewPackResistanceMohm);
    return (r.mv - mohm / 1000 * r.ma - kFlatMv) / (kFullMv - kFlatMv);
}

BatteryMeasurement BatteryHealth::measurement(const QDateTime &at) const
{
    BatteryMeasurement m;
    m.at = at;
    m.claimedCapacityMah = m_claimedMah;
    m.resistanceMohm = medianResistance();
    m.resistanceSamples = int(m_totalSamples);
    if (m_first && m_latest) {
        const double moved = restingFraction(*m_latest) - restingFraction(*m_first);
        const double counted = m_latest->countedMah - m_first->countedMah;
        m.cycleSeen = std::min(1.0, std::abs(moved));
        // Charge out while the voltage fell, or in while it rose.
        if (std::abs(moved) >= kMinCycleSeen && counted * moved > 0)
            m.capacityMah = counted / moved;
    }
    return m;
}

BatteryCondition BatteryHealth::judge(const BatteryMeasurement &m, QString *reason)
{
    QStringList worse, fine;
    BatteryCondition condition = BatteryCondition::Unknown;
    const auto note = [&](BatteryCondition c, const QString &words) {
        if (c > condition)
            condition = c;
        (c == BatteryCondition::Good ? fine : worse) << words;
    };
    if (m.capacityMah && m.claimedCapacityMah > 0) {
        const double share = *m.capacityMah / m.claimedCapacityMah;
        const QString words = tr("holds %1 of the %2 mAh it claims (%3 %)")
                                  .arg(std::lround(*m.capacityMah))
                                  .arg(m.claimedCapacityMah)
                                  .arg(std::lround(100 * share));
        note(share < kReplaceCapacity ? BatteryCondition::Replace
             : share < kWornCapacity  ? BatteryCondition::Worn
                                      : BatteryCondition::Good,
             words);
    }
    if (m.resistanceMohm) {
        const double times = *m.resistanceMohm / kNewPackResistanceMohm;
        const QString words = tr("resistance %1 mΩ, %2 times a new pack's")
                                  .arg(std::lround(*m.resistanceMohm))
                                  .arg(QString::number(times, 'f', 1));
        note(times >= kReplaceResistance ? BatteryCondition::Replace
             : times >= kWornResistance  ? BatteryCondition::Worn
                                         : BatteryCondition::Good,
             words);
    }
    if (reason) {
        if (condition == BatteryCondition::Unknown)
            *reason = tr("it needs a drive started and stopped a few times, and part of a discharge or a charge");
        else
            *reason = (worse.isEmpty() ? fine : worse + fine).join(tr("; "));
        if (condition != BatteryCondition::Unknown && !m.capacityMah)
            *reason += tr("; capacity not measured yet");
    }
    return condition;
}

BatteryHealthReport BatteryHealth::report(const QDateTime &at) const
{
    BatteryHealthReport r;
    r.estimatedFromVoltage = m_estimatedFromVoltage;
    r.trend = trendWords(m_kept);
    const BatteryMeasurement now = measurement(at);
    // The last measurement of an earlier connection, if any.
    const qsizetype earlier = m_kept.size() - (m_keptThisConnection ? 2 : 1);
    const BatteryMeasurement *before = earlier >= 0 ? &m_kept[earlier] : nullptr;
    QString reason;
    const BatteryCondition condition = judge(now, &reason);
    // This connection's figures win once they have seen as much of a
    // cycle as the kept ones did (or a third of one).
    constexpr double kEnoughCycle = 0.3;
    const bool useNow = condition != BatteryCondition::Unknown
                        && (!before || judge(*before) == BatteryCondition::Unknown
                            || now.cycleSeen >= std::min(before->cycleSeen, kEnoughCycle));
    if (useNow || !before) {
        r.condition = condition;
        r.reason = reason;
        r.measurement = now;
    } else {
        r.condition = judge(*before, &r.reason);
        r.measurement = *before;
        r.fromEarlierSession = true;
    }
    r.confidence = r.measurement.cycleSeen;
    return r;
}

QString BatteryHealth::conditionKey(BatteryCondition condition)
{
    switch (condition) {
    case BatteryCondition::Good: return QStringLiteral("good");
    case BatteryCondition::Worn: return QStringLiteral("worn");
    case BatteryCondition::Replace: return QStringLiteral("replace");
    case BatteryCondition::Unknown: break;
    }
    return QStringLiteral("unknown");
}

std::optional<BatteryCondition> BatteryHealth::conditionOfKey(const QString &key)
{
    for (BatteryCondition c : {BatteryCondition::Unknown, BatteryCondition::Good, BatteryCondition::Worn,
                               BatteryCondition::Replace})
        if (conditionKey(c) == key)
            return c;
    return std::nullopt;
}

QString BatteryHealth::conditionWords(BatteryCondition condition)
{
    switch (condition) {
    case BatteryCondition::Good: return tr("Good");
    case BatteryCondition::Worn: return tr("Worn");
    case BatteryCondition::Replace: return tr("Replace");
    case BatteryCondition::Unknown: break;
    }
    return tr("Not measured yet");
}

QString BatteryHealth::confidenceWords(const BatteryMeasurement &m)
{
    return tr("%1 % of a cycle seen, %2 resistance samples")
        .arg(std::lround(100 * m.cycleSeen))
        .arg(m.resistanceSamples);
}

QString BatteryHealth::trendWords(const QList<BatteryMeasurement> &kept)
{
    QStringList parts;
    for (const BatteryMeasurement &m : kept)
        if (m.capacityMah)
            parts << tr("%1 mAh (%2)").arg(std::lround(*m.capacityMah)).arg(m.at.date().toString(Qt::ISODate));
    return parts.size() < 2 ? QString() : parts.join(tr(", "));
}

std::optional<BatteryHealth::LowBattery> BatteryHealth::nearlyFlat(const oi::SensorSnapshot &frame)
{
    const std::optional<double> percent = frame.has(25) ? frame.batteryPercent() : std::nullopt;
    const int mv = frame.has(22) ? frame.voltageMv() : 0;
    const bool lowVoltage = mv != 0 && mv <= kLowMv;
    if (!lowVoltage && !(percent && *percent <= kLowPercent))
        return std::nullopt;
    return LowBattery{percent.value_or(-1), mv / 1000.0};
}

QString BatteryHealth::nearlyFlatWords(const LowBattery &low)
{
    const QString figures = low.percent >= 0 ? tr("%1 %, %2 V").arg(std::lround(low.percent)).arg(low.volts, 0, 'f', 1)
                                             : tr("%1 V").arg(low.volts, 0, 'f', 1);
    return tr("battery nearly flat (%1): the robot leaves Safe or Full by itself under load; charge it").arg(figures);
}

QString BatteryHealth::chargingFaultWords()
{
    return tr("Charging fault: the robot will not charge. Usually the charging contacts are dirty (on the robot or "
              "the dock), the supply is not the robot's own, or the pack was run deeply flat (Safe or Full left on "
              "the dock drains it). Clean the contacts, reseat the pack, then reset the charger: hold Spot and "
              "Dock together for 10 seconds, and put it back on the dock.");
}
