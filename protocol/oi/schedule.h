// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "result.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace oi {

// Day codes of Set Day/Time (168) and bit positions of Schedule (167).
enum class Weekday : std::uint8_t { Sunday, Monday, Tuesday, Wednesday, Thursday, Friday, Saturday };

struct ClockTime {
    int hour = 0;   // 0..23
    int minute = 0; // 0..59
    friend bool operator==(const ClockTime &, const ClockTime &) = default;
};

// The weekly cleaning schedule: at most one start time a day.
struct CleaningSchedule {
    std::array<std::optional<ClockTime>, 7> days; // indexed by Weekday
    // Bit n set when day n has a time (bit 0 Sunday .. bit 6 Saturday).
    std::uint8_t dayBits() const;
    bool isOff() const { return dayBits() == 0; }
    friend bool operator==(const CleaningSchedule &, const CleaningSchedule &) = default;
};

// "sun", "Sunday", "SU" or "0".."6".
std::optional<Weekday> parseWeekday(std::string_view text);
std::string_view weekdayName(Weekday day);      // "Sunday"
std::string_view weekdayShortName(Weekday day); // "sun"
// "15:00", "9:05", "15" (whole hour). Refuses 24:00, 12:60, "" and junk.
Result<ClockTime> parseClockTime(std::string_view text);
std::string formatClockTime(ClockTime time); // "09:05"

// Text form: "off", or entries DAY TIME separated by commas or spaces, each
// either "wed 15:00" or "wed=15:00", e.g. "wed 15:00, fri 10:36".
// A day named twice is an error.
Result<CleaningSchedule> parseSchedule(std::string_view text);
std::string formatSchedule(const CleaningSchedule &schedule); // "wed 15:00, fri 10:36" or "off"

// The 15 data bytes of opcode 167 and back. Days without their bit are
// sent as 0:00, as in the document's example.
std::array<std::uint8_t, 15> scheduleBytes(const CleaningSchedule &schedule);
Result<CleaningSchedule> scheduleFromBytes(std::span<const std::uint8_t> fifteenBytes);

} // namespace oi
