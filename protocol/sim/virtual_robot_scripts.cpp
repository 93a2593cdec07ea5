// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's scripts (Create 1): Script (152), Play Script (153),
// Show Script (154) and the waits (155-158) that hold commands back.
#include "virtual_robot.h"

#include "virtual_robot_state.h"

#include <algorithm>
#include <cmath>

namespace sim {
namespace {

using oi::Command;
using oi::OiMode;

constexpr std::size_t kMaxScriptBytes = 100;

} // namespace

bool VirtualRobot::State::scriptCommand(const oi::OiCommand &c, bool fromScript)
{
    const std::vector<int> &f = c.fields;
    switch (c.command) {
    case Command::Script:
        // ERRATA 11: the length counts bytes, at most 100; 0 clears.
        if (c.data.size() <= kMaxScriptBytes)
            script = c.data;
        return true;
    case Command::PlayScript:
        if (fromScript && !serialIn.empty()) {
            scriptBehindSerial = true; // played again once the waiting bytes are read
            return true;
        }
        // Sent by a client, the script goes in front of anything not yet read.
        scriptIn.assign(script.begin(), script.end());
        if (fromScript)
            scriptYield = true;
        return true;
    case Command::ShowScript: {
        streaming = false; // the Create document: it halts the stream first
        oi::Bytes out{static_cast<std::uint8_t>(script.size())};
        out.insert(out.end(), script.begin(), script.end());
        emit(out);
        return true;
    }
    case Command::WaitTime:
        wait = Wait{Command::WaitTime, now + Microseconds(std::int64_t(f[0]) * 100'000), 0, 0, 0};
        return true;
    case Command::WaitDistance:
        distanceMm = 0; // the Create document: it resets the distance packet
        wait = Wait{Command::WaitDistance, {}, double(f[0]), 0, 0};
        return true;
    case Command::WaitAngle:
        angleRaw = 0;
        wait = Wait{Command::WaitAngle, {}, double(f[0]), 0, 0};
        return true;
    case Command::WaitEvent: {
        // ERRATA 12: 1..22, or the negative for "not".
        const int event = f[0];
        if (event != 0 && std::abs(event) <= oi::kWaitEventCount)
            wait = Wait{Command::WaitEvent, {}, 0, 0, event};
        return true;
    }
    default:
        return false;
    }
}

void VirtualRobot::State::endScript()
{
    scriptIn.clear();
    scriptBehindSerial = false;
}

bool VirtualRobot::State::eventHappening(int event)
{
    const int which = std::abs(event);
    bool on = false;
    const std::uint8_t buttons = heldButtons | pushedButtons;
    switch (which) {
    case 1: on = wheelDropLeft() || wheelDropRight() || wheelDropCaster(); break;
    case 2: on = wheelDropCaster(); break;
    case 3: on = wheelDropLeft(); break;
    case 4: on = wheelDropRight(); break;
    case 5:
    case 6:
    case 7: {
        const ObstacleContact o = obstacles();
        on = which == 5 ? (o.bumpLeft || o.bumpRight) : which == 6 ? o.bumpLeft : o.bumpRight;
        break;
    }
    case 8: on = infrared().virtualWall; break;
    case 9: on = wallSeen(obstacles().wallDistanceMm); break;
    case 10: {
        const auto &c = floorContact().cliff;
        on = std::any_of(c.begin(), c.end(), [](bool b) { return b; });
        break;
    }
    case 11:
    case 12:
    case 13:
    case 14: on = floorContact().cliff[std::size_t(which - 11)]; break;
    case 15: on = onDock(); break;
    case 16: on = buttons & oi::bit::ButtonAdvance; break;
    case 17: on = buttons & oi::bit::ButtonPlay; break;
    case 22: on = mode == OiMode::Passive; break;
    default: on = false; break; // 18..21: nothing is wired to the cargo bay inputs
    }
    return event > 0 ? on : !on;
}

bool VirtualRobot::State::waitOver()
{
    switch (wait->kind) {
    case Command::WaitTime:
        return now >= wait->until;
    case Command::WaitDistance:
    case Command::WaitAngle:
        return wait->target >= 0 ? wait->progress >= wait->target : wait->progress <= wait->target;
    default:
        return eventHappening(wait->event);
    }
}

// --- The public face ---

oi::Bytes VirtualRobot::script() const { return m_state->script; }

} // namespace sim
