// SPDX-License-Identifier: GPL-3.0-or-later
#include "pose_report.h"

#include <cmath>
#include <numbers>

void PoseReport::sample(const oi::Pose &now)
{
    m_turnedRad += std::remainder(now.thetaRad - m_last.thetaRad, 2 * std::numbers::pi);
    m_last = now;
}

QString PoseReport::line(double seconds) const
{
    const double dx = m_last.xMm - m_start.xMm, dy = m_last.yMm - m_start.yMm;
    const double across = -dx * std::sin(m_start.thetaRad) + dy * std::cos(m_start.thetaRad);
    const auto f = [](double v) { return QString::number(v, 'f', 1); };
    return QStringLiteral("pose t=%1 s x=%2 mm y=%3 mm heading=%4 deg from_start=%5 mm off_line=%6 mm turned=%7 deg")
        .arg(f(seconds), f(m_last.xMm), f(m_last.yMm), f(m_last.thetaRad * 180 / std::numbers::pi),
             f(std::hypot(dx, dy)), f(across), f(m_turnedRad * 180 / std::numbers::pi));
}
