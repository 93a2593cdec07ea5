// SPDX-License-Identifier: GPL-3.0-or-later
#include "schedule.h"
#include "text_tokens.h"

#include <vector>

namespace oi {
namespace {

constexpr std::array<std::string_view, 7> kDayNames = {"Sunday",   "Monday", "Tuesday", "Wednesday",
                                                       "Thursday", "Friday", "Saturday"};
constexpr std::array<std::string_view, 7> kDayShortNames = {"sun", "mon", "tue", "wed", "thu", "fri", "sat"};
constexpr std::uint8_t kReservedDayBit = 0x80;

bool isSpace(char c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

std::string_view trimmed(std::string_view text)
{
    while (!text.empty() && isSpace(text.front()))
        text.remove_prefix(1);
    while (!text.empty() && isSpace(text.back()))
        text.remove_suffix(1);
    return text;
}

// Parses 1..maxDigits decimal digits; anything else gives -1.
int smallNumber(std::string_view text, std::size_t maxDigits)
{
    if (text.empty() || text.size() > maxDigits)
        return -1;
    int value = 0;
    for (char c : text) {
        if (c < '0' || c > '9')
            return -1;
        value = value * 10 + (c - '0');
    }
    return value;
}

// '=' joins a day to its time ("wed=15:00"); treating it as a separator lets
// "wed = 15:00" and "wed 15:00" read the same.
constexpr std::string_view kScheduleSeparators = " \t\r\n,=";

std::size_t dayIndex(Weekday day)
{
    return static_cast<std::size_t>(day);
}

} // namespace

std::uint8_t CleaningSchedule::dayBits() const
{
    std::uint8_t bits = 0;
    for (std::size_t i = 0; i < days.size(); ++i) {
        if (days[i])
            bits |= static_cast<std::uint8_t>(1u << i);
    }
    return bits;
}

std::optional<Weekday> parseWeekday(std::string_view text)
{
    text = trimmed(text);
    if (text.size() == 1 && text[0] >= '0' && text[0] <= '6')
        return static_cast<Weekday>(text[0] - '0');
    for (std::size_t i = 0; i < kDayNames.size(); ++i) {
        if (equalsIgnoringCase(text, kDayNames[i]) || equalsIgnoringCase(text, kDayShortNames[i])
            || equalsIgnoringCase(text, kDayShortNames[i].substr(0, 2)))
            return static_cast<Weekday>(i);
    }
    return std::nullopt;
}

std::string_view weekdayName(Weekday day)
{
    return kDayNames[dayIndex(day)];
}

std::string_view weekdayShortName(Weekday day)
{
    return kDayShortNames[dayIndex(day)];
}

Result<ClockTime> parseClockTime(std::string_view text)
{
    text = trimmed(text);
    if (text.empty())
        return OiError::invalid("time", "is empty; use H:MM, HH:MM or a whole hour H");
    const std::size_t colon = text.find(':');
    if (colon != std::string_view::npos && text.find(':', colon + 1) != std::string_view::npos)
        return OiError::invalid("time", quoted(text) + " has more than one ':'; use H:MM or HH:MM");

    const std::string_view hourText = text.substr(0, colon);
    const int hour = smallNumber(hourText, 2);
    if (hour < 0)
        return OiError::invalid("hour", quoted(hourText) + " is not an hour; use one or two digits 0..23");
    if (hour > 23)
        return OiError::outOfRange("hour", hour, 0, 23);

    ClockTime time{hour, 0};
    if (colon == std::string_view::npos)
        return time;

    const std::string_view minuteText = text.substr(colon + 1);
    if (minuteText.size() != 2 || smallNumber(minuteText, 2) < 0)
        return OiError::invalid("minute", quoted(minuteText) + " is not a minute; use two digits 00..59");
    time.minute = smallNumber(minuteText, 2);
    if (time.minute > 59)
        return OiError::outOfRange("minute", time.minute, 0, 59);
    return time;
}

std::string formatClockTime(ClockTime time)
{
    auto twoDigits = [](int value) {
        const std::string digits = std::to_string(value);
        return value >= 0 && value < 10 ? '0' + digits : digits;
    };
    return twoDigits(time.hour) + ':' + twoDigits(time.minute);
}

Result<CleaningSchedule> parseSchedule(std::string_view text)
{
    text = trimmed(text);
    if (text.empty())
        return OiError::invalid("schedule", "is empty; write \"off\" or entries such as \"wed 15:00, fri 10:36\"");
    if (equalsIgnoringCase(text, "off"))
        return CleaningSchedule{};

    const std::vector<std::string_view> tokens = splitTokens(text, kScheduleSeparators);
    CleaningSchedule schedule;
    for (std::size_t i = 0; i < tokens.size(); i += 2) {
        const std::optional<Weekday> day = parseWeekday(tokens[i]);
        if (!day)
            return OiError::invalid("day", quoted(tokens[i]) + " is not a weekday; use e.g. wed, Wednesday, we or 3");
        const std::string dayField(weekdayShortName(*day));
        if (i + 1 >= tokens.size())
            return OiError::invalid(dayField, "has no time; write e.g. \"" + dayField + " 15:00\"");
        std::optional<ClockTime> &slot = schedule.days[dayIndex(*day)];
        if (slot)
            return OiError::invalid(dayField, std::string(weekdayName(*day)) + " is named twice");

        Result<ClockTime> time = parseClockTime(tokens[i + 1]);
        if (!time) {
            // Say which day's time was wrong: "wed minute: 60 is outside 0..59".
            OiError error = time.error();
            error.field = dayField + ' ' + error.field;
            return error;
        }
        slot = *time;
    }
    return schedule;
}

std::string formatSchedule(const CleaningSchedule &schedule)
{
    std::string text;
    for (std::size_t i = 0; i < schedule.days.size(); ++i) {
        if (!schedule.days[i])
            continue;
        if (!text.empty())
            text += ", ";
        text += std::string(kDayShortNames[i]) + ' ' + formatClockTime(*schedule.days[i]);
    }
    return text.empty() ? std::string("off") : text;
}

std::array<std::uint8_t, 15> scheduleBytes(const CleaningSchedule &schedule)
{
    std::array<std::uint8_t, 15> bytes{};
    bytes[0] = schedule.dayBits();
    for (std::size_t i = 0; i < schedule.days.size(); ++i) {
        if (const std::optional<ClockTime> &time = schedule.days[i]) {
            bytes[1 + 2 * i] = static_cast<std::uint8_t>(time->hour);
            bytes[2 + 2 * i] = static_cast<std::uint8_t>(time->minute);
        }
    }
    return bytes;
}

Result<CleaningSchedule> scheduleFromBytes(std::span<const std::uint8_t> fifteenBytes)
{
    if (fifteenBytes.size() != 15)
        return OiError::invalid("schedule", "needs exactly 15 bytes, got " + std::to_string(fifteenBytes.size()));
    const std::uint8_t days = fifteenBytes[0];
    if (days & kReservedDayBit)
        return OiError::invalid("days", "bit 7 is reserved and must be 0, got " + std::to_string(days));

    CleaningSchedule schedule;
    for (std::size_t i = 0; i < schedule.days.size(); ++i) {
        if (!(days & (1u << i)))
            continue;
        const int hour = fifteenBytes[1 + 2 * i];
        const int minute = fifteenBytes[2 + 2 * i];
        const std::string dayField(kDayShortNames[i]);
        if (hour > 23)
            return OiError::outOfRange(dayField + " hour", hour, 0, 23);
        if (minute > 59)
            return OiError::outOfRange(dayField + " minute", minute, 0, 59);
        schedule.days[i] = ClockTime{hour, minute};
    }
    return schedule;
}

} // namespace oi
