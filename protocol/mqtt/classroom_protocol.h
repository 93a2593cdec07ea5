// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

// The classroom protocol's table (protocol/mqtt/classroom_protocol.json,
// docs/mqtt.md "The protocol's table"): the moves with a goal and their
// fields' ranges, the words a stopped move's reply gives, the heartbeat and
// the lease, and the figures of a move's time. The Python library reads the
// same file. CMake writes classroom_protocol_table.h from it; what the
// programs look up here is found when they are compiled, or they are not.
namespace classroom {

struct GoalField {
    std::string_view field;
    double min, max;
    std::string_view unit; // as the bridge's errors name it: "mm", "degrees/s"
};

struct GoalCommand {
    std::string_view command;
    std::span<const GoalField> fields;
};

struct StopReasonRow {
    std::string_view stop;
    bool freesControl; // the move stopped because its client lost control
};

} // namespace classroom

#include "classroom_protocol_table.h"

namespace classroom {

using namespace table;

// The table's row for `command`, or null.
constexpr const GoalCommand *goalCommand(std::string_view command)
{
    for (const GoalCommand &row : kGoalCommands)
        if (row.command == command)
            return &row;
    return nullptr;
}

constexpr GoalKind kindOf(const GoalCommand &row) { return GoalKind(&row - kGoalCommands); }

// A field of a goal command the table has; anything else does not compile.
// (A loop over the rows, not goalCommand(): a pointer's test against null
// is no constant expression under UndefinedBehaviorSanitizer's GCC.)
consteval GoalField goalField(std::string_view command, std::string_view field)
{
    for (const GoalCommand &row : kGoalCommands)
        if (row.command == command)
            for (const GoalField &f : row.fields)
                if (f.field == field)
                    return f;
    throw "no such goal field in classroom_protocol.json";
}

constexpr bool isStopReason(std::string_view word)
{
    for (const StopReasonRow &row : kStopReasons)
        if (row.stop == word)
            return true;
    return false;
}

// The `stop` of a move's reply: one of the table's words, checked when the
// program is compiled (StopReason("timeout")).
class StopReason {
public:
    consteval StopReason(const char *word) : m_word(word)
    {
        if (!isStopReason(word))
            throw "not a stop reason of classroom_protocol.json";
    }
    // No stop: the move reached its goal.
    consteval StopReason(std::nullptr_t) : m_word(nullptr) {}
    // The word, or null for no stop.
    const char *word() const { return m_word; }

private:
    const char *m_word;
};

} // namespace classroom
