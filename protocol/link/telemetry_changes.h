// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "sensor_snapshot.h"

#include <QtGlobal>

#include <array>

namespace oilink {

// What each telemetry message carries, so a robot costs little on a
// classroom's Wi-Fi and no event is lost:
//  - every second, every packet (a key frame);
//  - in between, each one-byte packet (bumps, cliffs, wheel drops, buttons,
//    IR characters, the mode, the charging state) in the first frame it
//    changes in;
//  - each two-byte packet (a measurement) when it has changed, at most once
//    every kMeasurementMs;
//  - distance and angle, which count since the last frame, summed over the
//    frames not yet told, so that odometry from the messages adds up.
// A frame with nothing to tell still gives a message (its time alone), so
// a watcher sees the robot is alive at the frame rate.
class TelemetryChanges {
public:
    static constexpr qint64 kKeyFrameMs = 1000;
    static constexpr qint64 kMeasurementMs = 100;

    struct Message {
        oi::SensorSnapshot packets;
        bool keyFrame = false;
    };

    // The packets to tell for `frame`, read at `nowMs` (any steady clock).
    Message next(const oi::SensorSnapshot &frame, qint64 nowMs);
    // The next message is a key frame (a new watcher, a reconnect).
    void restart() { m_keyFrameAtMs.reset(); }

private:
    oi::SensorSnapshot m_told;
    std::array<qint64, oi::kMaxPacketId + 1> m_toldAtMs{};
    std::array<std::int32_t, oi::kMaxPacketId + 1> m_untoldSum{};
    std::optional<qint64> m_keyFrameAtMs;
};

} // namespace oilink
