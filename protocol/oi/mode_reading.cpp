// SPDX-License-Identifier: GPL-3.0-or-later
#include "mode_reading.h"

#include "command_modes.h"

namespace oi {

namespace {
constexpr int kPassive = static_cast<int>(OiMode::Passive);
constexpr int kSafe = static_cast<int>(OiMode::Safe);
constexpr int kFull = static_cast<int>(OiMode::Full);
} // namespace

void ModeReading::sent(Command command, long long atMs)
{
    if (entersPassive(command)) {
        m_expectPassive = true;
        m_startAtMs = atMs;
        return;
    }
    switch (command) {
    case Command::Control:
    case Command::Safe:
    case Command::Full:
    case Command::Power:
    case Command::Stop:
    case Command::Reset:
        m_expectPassive = false;
        break;
    default:
        break;
    }
}

bool ModeReading::read(SensorSnapshot &frame, long long atMs)
{
    if (!frame.has(35))
        return false;
    const int reported = frame.raw(35);
    bool found = false;
    if (!m_oneHigh) {
        if (reported > kFull) {
            found = true;
        } else if (m_expectPassive && reported == kSafe && m_detectAfterStart) {
            // Right after Start a frame sent before it may still read Safe:
            // shown as the Passive that Start gives, but taken as the sign
            // only once Start has surely been read.
            if (atMs - m_startAtMs < kStartSettlesMs) {
                frame.set(35, kPassive);
                return false;
            }
            found = true;
        }
        m_oneHigh = found;
        if (m_expectPassive && reported == kPassive && atMs - m_startAtMs >= kStartSettlesMs)
            m_readPassiveAfterStart = true;
    }
    if (m_oneHigh && reported > 0)
        frame.set(35, reported - 1);
    return found;
}

} // namespace oi
