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
// A frame with nothing to tell gives a message (its time alone) only when
// the kAliveFrames - 1 frames before it gave none, so a watcher still sees
// the robot alive twice within a link's 100 ms (every 45 ms at 66.7 Hz),
// with far fewer messages than one a frame.
class TelemetryChanges {
public:
    static constexpr qint64 kKeyFrameMs = 1000;
    static constexpr qint64 kMeasurementMs = 100;
    static constexpr int kAliveFrames = 3;

    struct Message {
        oi::SensorSnapshot packets;
        bool keyFrame = false;
        bool send = true; // false: nothing to tell, and one of the last kAliveFrames - 1 frames was sent
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
    int m_framesUnsent = kAliveFrames; // since the last message sent
};

} // namespace oilink
