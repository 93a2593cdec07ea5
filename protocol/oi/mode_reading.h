// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_profile.h"
#include "sensor_snapshot.h"

namespace oi {

// Packet 35 (OI mode) as one robot reports it. Some Wi-Fi Roomba 600s report
// their mode one too high: Passive 2, Safe 3, Full 4. That shows when the
// robot reads Safe after Start, which always leaves it in Passive, or reads a
// value above Full; from then on every report of that robot is corrected.
// The one place the correction is made: the link reads every frame and
// reply through it, so whoever reads the mode reads the true one.
class ModeReading {
public:
    // A robot reads a report this long after Start has reached it (frames
    // already on their way may still show the mode before).
    static constexpr long long kStartSettlesMs = 50;

    // Known before (remembered with the robot): corrected from the first report.
    void setOneHigh(bool oneHigh) { m_oneHigh = oneHigh; }
    bool oneHigh() const { return m_oneHigh; }
    // Whether Safe read after Start counts as the sign (a value above Full
    // always does). Off for now: the test fixtures that play a robot already
    // in Safe (tests/common/recording_transport.h) report Safe right after
    // Start too, and must first say their robot was put there.
    void setDetectAfterStart(bool detect) { m_detectAfterStart = detect; }
    // Whether this robot's reports are known to be true or corrected: it
    // reported one too high, or read Passive after a Start it had read.
    // Until then a report of Safe may be a Passive reported one too high.
    bool known() const { return m_oneHigh || m_readPassiveAfterStart; }

    // A command went to the robot at `atMs`: after Start (or cleaning) its
    // next reports must read Passive, until another mode command goes.
    void sent(Command command, long long atMs);
    // Corrects packet 35 in `frame` (read at `atMs`), if it has one. True
    // when this report showed, for the first time, that the robot reports
    // one too high.
    bool read(SensorSnapshot &frame, long long atMs);

private:
    bool m_oneHigh = false;
    bool m_expectPassive = false; // Start went, and no mode command since
    bool m_readPassiveAfterStart = false;
    bool m_detectAfterStart = false;
    long long m_startAtMs = 0;
};

} // namespace oi
