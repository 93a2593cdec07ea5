// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_catalog.h"

#include "oi_command.h"
#include "script_assembler.h"
#include "seven_segment_font.h"

#include <charconv>
#include <climits>

namespace oi {
namespace {

using C = Command;

// The fixed fields of each typed command, in byte order.
constexpr std::string_view kBaudFields[] = {"baud-code"};
constexpr std::string_view kDemoFields[] = {"demo"};
constexpr std::string_view kDriveFields[] = {"velocity", "radius"};
constexpr std::string_view kMotorsFields[] = {"motor-bits"};
constexpr std::string_view kLowSideDriversFields[] = {"driver-bits"};
constexpr std::string_view kLedsFields[] = {"led-bits", "power-led-colour", "power-led-intensity"};
constexpr std::string_view kSongNumberFields[] = {"song-number"};
constexpr std::string_view kSensorsFields[] = {"packet-id"};
constexpr std::string_view kPwmMotorsFields[] = {"main-brush-pwm", "side-brush-pwm", "vacuum-pwm"};
constexpr std::string_view kPwmLowSideDriversFields[] = {
    "low-side-driver-2-duty-cycle", "low-side-driver-1-duty-cycle", "low-side-driver-0-duty-cycle"};
constexpr std::string_view kDriveDirectFields[] = {"right-velocity", "left-velocity"};
constexpr std::string_view kDrivePwmFields[] = {"right-pwm", "left-pwm"};
constexpr std::string_view kDigitalOutputsFields[] = {"output-bits"};
constexpr std::string_view kPauseResumeStreamFields[] = {"stream-state"};
constexpr std::string_view kSendIrFields[] = {"ir-byte"};
constexpr std::string_view kWaitTimeFields[] = {"time"};
constexpr std::string_view kWaitDistanceFields[] = {"distance"};
constexpr std::string_view kWaitAngleFields[] = {"angle"};
constexpr std::string_view kWaitEventFields[] = {"event"};
constexpr std::string_view kSchedulingLedsFields[] = {"weekday-led-bits", "scheduling-led-bits"};
constexpr std::string_view kDigitFields[] = {"digit-3", "digit-2", "digit-1", "digit-0"};
constexpr std::string_view kButtonsFields[] = {"button-bits"};
constexpr std::string_view kScheduleFields[] = {
    "days",          "sunday-hour",    "sunday-minute",    "monday-hour",   "monday-minute",
    "tuesday-hour",  "tuesday-minute", "wednesday-hour",   "wednesday-minute", "thursday-hour",
    "thursday-minute", "friday-hour",  "friday-minute",    "saturday-hour", "saturday-minute"};
constexpr std::string_view kSetDayTimeFields[] = {"day", "hour", "minute"};

// In the order of the Command enum, so commandSpec() can index it.
constexpr CommandSpec kSpecs[] = {
    {C::Reset, 7, "reset", "Reset", "", ""},
    {C::Start, 128, "start", "Start", "", ""},
    {C::Baud, 129, "baud", "Baud", "b", "CODE (0..11) | BPS", kBaudFields},
    {C::Control, 130, "control", "Control", "", ""},
    {C::Safe, 131, "safe", "Safe", "", ""},
    {C::Full, 132, "full", "Full", "", ""},
    {C::Power, 133, "power", "Power", "", ""},
    {C::Spot, 134, "spot", "Spot", "", ""},
    {C::Clean, 135, "clean", "Clean", "", ""},
    {C::Cover, 135, "cover", "Cover", "", ""},
    {C::Max, 136, "max", "Max", "", ""},
    {C::Demo, 136, "demo", "Demo", "c", "DEMO (-1..9)", kDemoFields},
    {C::Drive, 137, "drive", "Drive", "ww", "VELOCITY RADIUS|straight|cw|ccw", kDriveFields},
    {C::Motors, 138, "motors", "Motors", "b", "MOTOR-BITS", kMotorsFields},
    {C::LowSideDrivers, 138, "low-side-drivers", "Low Side Drivers", "b", "DRIVER-BITS", kLowSideDriversFields},
    {C::Leds, 139, "leds", "LEDs", "bbb", "LED-BITS POWER-COLOR POWER-INTENSITY", kLedsFields},
    {C::Song, 140, "song", "Song", "*", "SLOT NOTE:DURATION... | SLOT LENGTH NOTE DURATION...", kSongNumberFields},
    {C::Play, 141, "play", "Play", "b", "SLOT", kSongNumberFields},
    {C::Sensors, 142, "sensors", "Sensors", "b", "PACKET-ID", kSensorsFields},
    {C::SeekDock, 143, "seek-dock", "Seek Dock", "", ""},
    {C::CoverAndDock, 143, "cover-and-dock", "Cover and Dock", "", ""},
    {C::PwmMotors, 144, "pwm-motors", "PWM Motors", "ccb", "MAIN-BRUSH SIDE-BRUSH VACUUM", kPwmMotorsFields},
    {C::PwmLowSideDrivers, 144, "pwm-low-side-drivers", "PWM Low Side Drivers", "bbb",
     "DRIVER-2 DRIVER-1 DRIVER-0", kPwmLowSideDriversFields},
    {C::DriveDirect, 145, "drive-direct", "Drive Direct", "ww", "RIGHT-VELOCITY LEFT-VELOCITY", kDriveDirectFields},
    {C::DrivePwm, 146, "drive-pwm", "Drive PWM", "ww", "RIGHT-PWM LEFT-PWM", kDrivePwmFields},
    {C::DigitalOutputs, 147, "digital-outputs", "Digital Outputs", "b", "OUTPUT-BITS", kDigitalOutputsFields},
    {C::Stream, 148, "stream", "Stream", "*", "COUNT PACKET-ID..."},
    {C::QueryList, 149, "query-list", "Query List", "*", "COUNT PACKET-ID..."},
    {C::PauseResumeStream, 150, "pause-resume-stream", "Pause/Resume Stream", "b", "0|1", kPauseResumeStreamFields},
    {C::SendIr, 151, "send-ir", "Send IR", "b", "BYTE", kSendIrFields},
    {C::Script, 152, "script", "Script", "*", "\"COMMAND ARGS; ...\" | LENGTH BYTE..."},
    {C::PlayScript, 153, "play-script", "Play Script", "", ""},
    {C::ShowScript, 154, "show-script", "Show Script", "", ""},
    {C::WaitTime, 155, "wait-time", "Wait Time", "b", "TENTHS", kWaitTimeFields},
    {C::WaitDistance, 156, "wait-distance", "Wait Distance", "w", "MM", kWaitDistanceFields},
    {C::WaitAngle, 157, "wait-angle", "Wait Angle", "w", "DEGREES", kWaitAngleFields},
    {C::WaitEvent, 158, "wait-event", "Wait Event", "c", "EVENT (1..22, -1..-22, or a name)", kWaitEventFields},
    {C::SchedulingLeds, 162, "scheduling-leds", "Scheduling LEDs", "bb",
     "WEEKDAY-BITS SCHEDULING-BITS", kSchedulingLedsFields},
    {C::DigitLedsRaw, 163, "digit-leds-raw", "Digit LEDs Raw", "bbbb", "DIGIT-3 DIGIT-2 DIGIT-1 DIGIT-0", kDigitFields},
    {C::DigitLedsAscii, 164, "digit-leds-ascii", "Digit LEDs ASCII", "bbbb",
     "TEXT | CODE-3 CODE-2 CODE-1 CODE-0", kDigitFields},
    {C::Buttons, 165, "buttons", "Buttons", "b", "BUTTON-BITS", kButtonsFields},
    {C::Schedule, 167, "schedule", "Schedule", "bbbbbbbbbbbbbbb",
     "off | \"DAY HH:MM, ...\" | DAYS SUN-HOUR SUN-MINUTE ... SAT-MINUTE", kScheduleFields},
    {C::SetDayTime, 168, "set-day-time", "Set Day/Time", "bbb", "DAY HOUR MINUTE | DAY HH:MM", kSetDayTimeFields},
    {C::Stop, 173, "stop", "Stop", "", ""},
};
static_assert(std::size(kSpecs) == kCommandCount);

std::string joined(std::span<const std::string> args, char separator = ' ')
{
    std::string out;
    for (const std::string &a : args) {
        if (!out.empty())
            out += separator;
        out += a;
    }
    return out;
}

OiError wrongCount(const CommandSpec &spec, std::size_t got)
{
    std::string usage = spec.usage.empty() ? "no arguments" : std::string(spec.usage);
    return OiError::invalid(std::string(spec.name), "takes " + usage + "; got "
                                                        + std::to_string(got) + " argument"
                                                        + (got == 1 ? "" : "s"));
}

// Parses every argument as a number that fits an int.
Result<std::vector<int>> numbers(const CommandSpec &spec, std::span<const std::string> args)
{
    std::vector<int> out;
    for (std::size_t i = 0; i < args.size(); ++i) {
        long long v = 0;
        if (!parseInteger(args[i], v) || v < INT_MIN || v > INT_MAX)
            return OiError::invalid(std::string(spec.name) + " argument " + std::to_string(i + 1),
                                    "'" + args[i] + "' is not a number");
        out.push_back(static_cast<int>(v));
    }
    return out;
}

// The fixed-layout commands: exactly one number per layout character.
Result<std::vector<int>> fixedNumbers(const CommandSpec &spec, std::span<const std::string> args)
{
    if (args.size() != spec.layout.size())
        return wrongCount(spec, args.size());
    return numbers(spec, args);
}

// COUNT ID... as the document orders stream and query-list bytes.
Result<std::vector<int>> countedIds(const CommandSpec &spec, std::span<const std::string> args)
{
    auto values = numbers(spec, args);
    if (!values)
        return values;
    if (values->empty())
        return wrongCount(spec, 0);
    const int count = values->front();
    if (count < 0 || static_cast<std::size_t>(count) != values->size() - 1) {
        OiError e = OiError::invalid("number of packets",
                                     std::to_string(count) + " does not match the "
                                         + std::to_string(values->size() - 1)
                                         + " packet ids that follow");
        e.value = count;
        return e;
    }
    return std::vector<int>(values->begin() + 1, values->end());
}

EncodeResult encodeSong(const CommandEncoder &encoder, const CommandSpec &spec,
                        std::span<const std::string> args)
{
    if (args.size() < 2)
        return wrongCount(spec, args.size());
    long long slot = 0;
    if (!parseInteger(args[0], slot) || slot < INT_MIN || slot > INT_MAX)
        return OiError::invalid("song number", "'" + args[0] + "' is not a number");
    const auto rest = args.subspan(1);
    auto plain = numbers(spec, rest);
    if (!plain) {
        auto song = parseSong(joined(rest));
        if (!song)
            return song.error();
        return encoder.song(static_cast<int>(slot), *song);
    }
    // SLOT LENGTH NOTE DURATION ..., in the document's byte order.
    const std::vector<int> &v = *plain;
    const std::size_t notes = (v.size() - 1) / 2;
    if (v.size() % 2 == 0 || v[0] < 0 || static_cast<std::size_t>(v[0]) != notes) {
        OiError e = OiError::invalid("song length", std::to_string(v[0]) + " does not match the "
                                                        + std::to_string(v.size() - 1)
                                                        + " note bytes that follow");
        e.value = v[0];
        return e;
    }
    Song song;
    for (std::size_t i = 0; i < notes; ++i) {
        const int note = v[1 + 2 * i], duration = v[2 + 2 * i];
        const std::string which = "note " + std::to_string(i + 1);
        if (note < 0 || note > 255)
            return OiError::outOfRange(which, note, 0, 255);
        if (duration < 0 || duration > 255)
            return OiError::outOfRange(which + " duration", duration, 0, 255);
        song.notes.push_back({static_cast<std::uint8_t>(note), static_cast<std::uint8_t>(duration)});
    }
    return encoder.song(static_cast<int>(slot), song);
}

EncodeResult encodeSchedule(const CommandEncoder &encoder, const CommandSpec &spec,
                            std::span<const std::string> args)
{
    if (args.size() == spec.layout.size()) {
        auto v = numbers(spec, args);
        if (!v)
            return v.error();
        return encoder.schedule(v->front(), std::span<const int>(*v).subspan(1));
    }
    auto schedule = parseSchedule(joined(args));
    if (!schedule)
        return schedule.error();
    return encoder.schedule(*schedule);
}

EncodeResult encodeSetDayTime(const CommandEncoder &encoder, const CommandSpec &spec,
                              std::span<const std::string> args)
{
    if (args.size() == 2) {
        const auto day = parseWeekday(args[0]);
        if (!day)
            return OiError::invalid("day", "'" + args[0] + "' is not a day of the week");
        auto time = parseClockTime(args[1]);
        if (!time)
            return time.error();
        return encoder.setDayTime(static_cast<int>(*day), time->hour, time->minute);
    }
    if (args.size() == 3) {
        std::vector<std::string> copy(args.begin(), args.end());
        if (const auto day = parseWeekday(copy[0]))
            copy[0] = std::to_string(static_cast<int>(*day));
        auto v = fixedNumbers(spec, copy);
        if (!v)
            return v.error();
        return encoder.setDayTime((*v)[0], (*v)[1], (*v)[2]);
    }
    return wrongCount(spec, args.size());
}

EncodeResult encodeScript(const CommandEncoder &encoder, const CommandSpec &spec,
                          std::span<const std::string> args)
{
    if (args.empty())
        return wrongCount(spec, 0);
    auto v = numbers(spec, args);
    if (!v) {
        auto body = assembleScript(encoder.robotProfile(), joined(args));
        if (!body)
            return body.error();
        return encoder.script(*body);
    }
    // LENGTH BYTE ..., with the length counting bytes (ERRATA 11).
    const int length = v->front();
    if (length < 0 || static_cast<std::size_t>(length) != v->size() - 1) {
        OiError e = OiError::invalid("script length", std::to_string(length)
                                                          + " does not match the "
                                                          + std::to_string(v->size() - 1)
                                                          + " bytes that follow");
        e.value = length;
        return e;
    }
    Bytes body;
    for (std::size_t i = 1; i < v->size(); ++i) {
        if ((*v)[i] < 0 || (*v)[i] > 255)
            return OiError::outOfRange("script byte " + std::to_string(i), (*v)[i], 0, 255);
        body.push_back(static_cast<std::uint8_t>((*v)[i]));
    }
    // Bytes given as numbers must still be whole commands of the robot.
    if (const auto text = disassembleScript(encoder.robotProfile(), body); !text)
        return text.error();
    return encoder.script(body);
}

} // namespace

bool parseInteger(std::string_view text, long long &out)
{
    bool negative = false;
    if (!text.empty() && (text.front() == '-' || text.front() == '+')) {
        negative = text.front() == '-';
        text.remove_prefix(1);
    }
    int base = 10;
    if (text.size() > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
        base = 16;
        text.remove_prefix(2);
    }
    if (text.empty() || text.front() == '-' || text.front() == '+')
        return false;
    unsigned long long magnitude = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), magnitude, base);
    if (ec != std::errc() || end != text.data() + text.size() || magnitude > LLONG_MAX)
        return false;
    out = negative ? -static_cast<long long>(magnitude) : static_cast<long long>(magnitude);
    return true;
}

std::span<const CommandSpec> allCommandSpecs() { return kSpecs; }

const CommandSpec &commandSpec(Command command) { return kSpecs[static_cast<int>(command)]; }

const CommandSpec *commandSpecByName(std::string_view name)
{
    for (const CommandSpec &spec : kSpecs)
        if (spec.name == name)
            return &spec;
    return nullptr;
}

const CommandSpec *commandSpecForOpcode(const RobotProfile &profile, std::uint8_t opcode)
{
    for (const CommandSpec &spec : kSpecs)
        if (spec.opcode == opcode && profile.has(spec.command))
            return &spec;
    return nullptr;
}

EncodeResult encodeCommand(const CommandEncoder &e, std::string_view name,
                           std::span<const std::string> args)
{
    const CommandSpec *found = commandSpecByName(name);
    if (!found)
        return OiError::invalid("command", "'" + std::string(name) + "' is not a command");
    const CommandSpec &spec = *found;
    if (auto refused = e.refuse(spec.command))
        return *refused;

    // Friendly forms first; each falls back to the document's numbers.
    std::vector<std::string> a(args.begin(), args.end());
    switch (spec.command) {
    case C::Song:
        return encodeSong(e, spec, a);
    case C::Schedule:
        return encodeSchedule(e, spec, a);
    case C::SetDayTime:
        return encodeSetDayTime(e, spec, a);
    case C::Script:
        return encodeScript(e, spec, a);
    case C::Stream:
    case C::QueryList: {
        auto ids = countedIds(spec, a);
        if (!ids)
            return ids.error();
        return spec.command == C::Stream ? e.stream(*ids) : e.queryList(*ids);
    }
    case C::DigitLedsAscii:
        if (a.size() == 1) {
            const auto codes = digitAsciiCodes(a[0]);
            if (a[0].size() > 4)
                return OiError::invalid("text", "'" + a[0] + "' is longer than the 4 digits");
            return e.digitLedsAscii(codes[0], codes[1], codes[2], codes[3]);
        }
        break;
    case C::WaitEvent:
        if (a.size() == 1) {
            if (const auto event = parseWaitEvent(a[0]))
                a[0] = std::to_string(*event);
            else if (long long n = 0; !parseInteger(a[0], n))
                return OiError::invalid("event", "'" + a[0] + "' is not a wait event");
        }
        break;
    case C::Drive:
        if (a.size() == 2) {
            if (a[1] == "straight")
                a[1] = std::to_string(kRadiusStraight);
            else if (a[1] == "cw")
                a[1] = std::to_string(kRadiusTurnInPlaceClockwise);
            else if (a[1] == "ccw")
                a[1] = std::to_string(kRadiusTurnInPlaceCounterClockwise);
        }
        break;
    case C::Baud:
        if (long long rate = 0; a.size() == 1 && parseInteger(a[0], rate) && rate > 11) {
            const int code = baudCodeFor(static_cast<int>(rate));
            if (code < 0)
                return OiError::invalid("baud", a[0] + " is not a rate the robot offers "
                                                       "(300 .. 115200, or a code 0..11)");
            a[0] = std::to_string(code);
        }
        break;
    default:
        break;
    }

    auto r = fixedNumbers(spec, a);
    if (!r)
        return r.error();
    return encodeCommand(e, OiCommand{spec.command, *r, {}});
}

} // namespace oi
