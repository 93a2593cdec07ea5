// SPDX-License-Identifier: GPL-3.0-or-later
#include "telemetry_changes.h"

#include <algorithm>

namespace oilink {

namespace {
// Increments since the last frame (odometry.h), not values.
bool countsSinceLastFrame(int id) { return id == 19 || id == 20; }
} // namespace

TelemetryChanges::Message TelemetryChanges::next(const oi::SensorSnapshot &frame, qint64 nowMs)
{
    Message m{oi::SensorSnapshot(frame.robotProfile()), false};
    if (&m_told.robotProfile() != &frame.robotProfile()) {
        m_told = oi::SensorSnapshot(frame.robotProfile());
        m_untoldSum.fill(0);
        m_keyFrameAtMs.reset();
    }
    m.keyFrame = !m_keyFrameAtMs || nowMs - *m_keyFrameAtMs >= kKeyFrameMs || nowMs < *m_keyFrameAtMs;
    if (m.keyFrame)
        m_keyFrameAtMs = nowMs;

    for (const oi::PacketInfo &p : frame.robotProfile().packets()) {
        if (!frame.has(p.id))
            continue;
        std::int32_t value = frame.raw(p.id);
        if (countsSinceLastFrame(p.id)) {
            // The sum stays within the packet's range: the robot's own
            // counts are, and at most kMeasurementMs of them are summed.
            value = std::clamp(m_untoldSum[p.id] + value, p.min, p.max);
            m_untoldSum[p.id] = value;
        }
        const bool changed = !m_told.has(p.id) || m_told.raw(p.id) != value || countsSinceLastFrame(p.id);
        const bool due = p.bytes == 1 || nowMs - m_toldAtMs[p.id] >= kMeasurementMs;
        const bool tell = m.keyFrame || (changed && due && !(countsSinceLastFrame(p.id) && value == 0));
        if (!tell)
            continue;
        m.packets.set(p.id, value);
        m_told.set(p.id, value);
        m_toldAtMs[p.id] = nowMs;
        if (countsSinceLastFrame(p.id))
            m_untoldSum[p.id] = 0;
    }
    m.send = m.keyFrame || m.packets.packetCount() > 0 || m_framesUnsent + 1 >= kAliveFrames;
    m_framesUnsent = m.send ? 0 : m_framesUnsent + 1;
    return m;
}

} // namespace oilink
