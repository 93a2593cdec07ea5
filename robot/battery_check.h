// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "sensor_snapshot.h"

#include <QCoreApplication>
#include <QString>

#include <optional>
#include <vector>

// Judges each frame's battery packets before the robot's model keeps them:
// a charge (25) above the capacity (26), a charge that jumps by tens of
// percent between frames, or a voltage (22) no pack of these robots can
// have cannot be true. Such a packet is not a reading of the battery (a
// glitch of the gauge, a corrupted byte that passed the checksum), so it is
// left out of what is shown, plotted and kept, and said once in words.
class BatteryCheck {
    Q_DECLARE_TR_FUNCTIONS(BatteryCheck)
public:
    // A pack of these robots (12 NiMH cells, or a 4-cell lithium pack) reads
    // between these while it lives; beyond them the reading is not a voltage
    // (0 is taken as no measurement yet).
    static constexpr int kLowestMv = 6000;
    static constexpr int kHighestMv = 21000;
    // No pack gains or loses this much of its capacity between two frames
    // that come within kJumpWithinSeconds of each other.
    static constexpr double kJumpPercent = 20;
    static constexpr double kJumpWithinSeconds = 10;

    struct Verdict {
        std::vector<int> suspect; // the packets that cannot be true
        QString why;              // "the charge 3500 mAh is above the capacity 3000 mAh"
    };

    // The frame's battery packets, read at `seconds`: the ones that cannot
    // be true, and why; nothing when all can.
    std::optional<Verdict> judge(const oi::SensorSnapshot &frame, double seconds);
    // A new connection or a new robot: nothing known about its charge.
    void reset();

    // The sentence for the status bar and the robot card.
    static QString message(const Verdict &verdict);

private:
    struct Charge {
        double percent = 0;
        double seconds = 0;
    };
    std::optional<Charge> m_trusted;  // the last charge believed
    std::optional<Charge> m_doubted;  // a jump not yet confirmed by the next frame
};
