// SPDX-License-Identifier: GPL-3.0-or-later
#include "battery_check.h"

#include <QStringList>

#include <cmath>

std::optional<BatteryCheck::Verdict> BatteryCheck::judge(const oi::SensorSnapshot &frame, double seconds)
{
    Verdict v;
    QStringList why;
    // 0 is no measurement yet (a robot just woken, a frame of zeros), not a voltage.
    if (frame.has(22) && frame.voltageMv() != 0 && (frame.voltageMv() < kLowestMv || frame.voltageMv() > kHighestMv)) {
        v.suspect.push_back(22);
        why << tr("the voltage %1 V is outside what its pack can have (%2 to %3 V)")
                   .arg(frame.voltageMv() / 1000.0, 0, 'f', 1)
                   .arg(kLowestMv / 1000)
                   .arg(kHighestMv / 1000);
    }
    if (frame.has(25) && frame.has(26) && frame.batteryCapacityMah() > 0) {
        const int charge = frame.batteryChargeMah(), capacity = frame.batteryCapacityMah();
        const double percent = 100.0 * charge / capacity;
        if (charge > capacity) {
            v.suspect.push_back(25);
            why << tr("the charge %1 mAh is above the capacity %2 mAh").arg(charge).arg(capacity);
        } else if (m_trusted && seconds - m_trusted->seconds <= kJumpWithinSeconds
                   && std::abs(percent - m_trusted->percent) >= kJumpPercent) {
            // A level the next frame confirms is the gauge's new word (it was
            // reset, or the pack changed): believed from then on.
            if (m_doubted && std::abs(percent - m_doubted->percent) < kJumpPercent / 4) {
                m_trusted = Charge{percent, seconds};
                m_doubted.reset();
            } else {
                v.suspect.push_back(25);
                why << tr("the charge jumped from %1 % to %2 % in %3 s")
                           .arg(std::lround(m_trusted->percent))
                           .arg(std::lround(percent))
                           .arg(QString::number(seconds - m_trusted->seconds, 'g', 3));
                m_doubted = Charge{percent, seconds};
            }
        } else {
            m_trusted = Charge{percent, seconds};
            m_doubted.reset();
        }
    }
    if (v.suspect.empty())
        return std::nullopt;
    v.why = why.join(QStringLiteral("; "));
    return v;
}

void BatteryCheck::reset()
{
    m_trusted.reset();
    m_doubted.reset();
}

QString BatteryCheck::message(const Verdict &verdict)
{
    return tr("Battery reading cannot be true: %1. It is left out of the gauges and plots; if it goes on, "
              "check the battery's seating and contacts.")
        .arg(verdict.why);
}
