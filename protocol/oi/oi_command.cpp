// SPDX-License-Identifier: GPL-3.0-or-later
#include "oi_command.h"

#include "command_catalog.h"

#include <cctype>

namespace oi {
namespace {

using C = Command;

bool isVariable(const CommandSpec &spec) { return spec.layout == "*"; }

// The layout character of fixed field `index`; Song's song number is a byte.
char fieldKind(const CommandSpec &spec, std::size_t index)
{
    return isVariable(spec) ? 'b' : spec.layout[index];
}

std::size_t fieldBytes(char kind) { return kind == 'w' ? 2 : 1; }

// Where the count byte of the variable part sits: after the song number for
// Song, right after the opcode for the others.
std::size_t countOffset(Command command) { return command == C::Song ? 2 : 1; }
std::size_t bytesPerItem(Command command) { return command == C::Song ? 2 : 1; }

int readField(const CommandSpec &spec, std::size_t index, const std::uint8_t *at)
{
    switch (fieldKind(spec, index)) {
    case 'w': {
        const auto word = static_cast<std::uint16_t>((at[0] << 8) | at[1]);
        // ERRATA 14: the document gives straight as 32768 (0x8000).
        if (spec.command == C::Drive && index == 1 && word == 0x8000)
            return kRadiusStraight;
        return static_cast<std::int16_t>(word);
    }
    case 'c':
        return static_cast<std::int8_t>(at[0]);
    default:
        return at[0];
    }
}

// "right velocity" -> "right-velocity", as the catalogue names fields.
std::string kebab(std::string_view text)
{
    std::string out;
    for (char c : text)
        out += c == ' ' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

// The offset, in one command's bytes, of the field an encoder error names;
// the first data byte where it names none of them (0 is the opcode's).
std::size_t fieldOffset(const CommandSpec &spec, const std::string &field)
{
    const std::string name = kebab(field);
    std::size_t at = 1;
    for (std::size_t i = 0; i < spec.fields.size(); ++i) {
        if (spec.fields[i] == name)
            return at;
        at += fieldBytes(fieldKind(spec, i));
    }
    if (!isVariable(spec))
        return 1;
    const std::size_t count = countOffset(spec.command);
    if (name == "song-length" || name == "number-of-packets" || name == "script-length")
        return count;
    constexpr std::string_view kPacketId = "packet-id-";
    if (name.starts_with(kPacketId)) {
        long long n = 0;
        if (parseInteger(std::string_view(name).substr(kPacketId.size()), n) && n >= 1 && n <= 255)
            return count + static_cast<std::size_t>(n);
    }
    return count;
}

CommandDecode needMore(const CommandSpec &spec, std::size_t need, std::size_t have)
{
    CommandDecode out;
    out.status = CommandDecode::Status::NeedMore;
    out.command.command = spec.command;
    out.length = need;
    const std::string title(spec.title);
    if (isVariable(spec) && have < countOffset(spec.command) + 1) {
        const bool length = spec.command == C::Song || spec.command == C::Script;
        out.error = OiError::invalid(std::string(spec.name), title + " is cut short before its "
                                                                 + (length ? "length" : "count") + " byte");
    } else {
        out.error = OiError::invalid(std::string(spec.name), title + " needs " + std::to_string(need - 1)
                                                                 + " data bytes; " + std::to_string(have - 1)
                                                                 + " remain");
    }
    return out;
}

CommandDecode failed(std::size_t at, OiError error)
{
    CommandDecode out;
    out.status = CommandDecode::Status::Error;
    out.length = at;
    out.error = std::move(error);
    return out;
}

std::vector<int> asInts(const Bytes &bytes) { return std::vector<int>(bytes.begin(), bytes.end()); }

} // namespace

std::span<const std::string_view> commandFieldNames(Command command)
{
    return commandSpec(command).fields;
}

EncodeResult encodeCommand(const CommandEncoder &e, const OiCommand &command)
{
    const CommandSpec &spec = commandSpec(command.command);
    if (auto refused = e.refuse(command.command))
        return *refused;
    if (command.fields.size() != spec.fields.size()) {
        std::string names;
        for (std::string_view name : spec.fields)
            names += (names.empty() ? "" : " ") + std::string(name);
        return OiError::invalid(std::string(spec.name),
                                "takes " + std::to_string(spec.fields.size()) + " fields ("
                                    + (names.empty() ? "none" : names) + "); got "
                                    + std::to_string(command.fields.size()));
    }
    if (!isVariable(spec) && !command.data.empty())
        return OiError::invalid(std::string(spec.name),
                                "takes no bytes after its fields; got " + std::to_string(command.data.size()));

    const std::vector<int> &v = command.fields;
    switch (command.command) {
    case C::Reset: return e.reset();
    case C::Start: return e.start();
    case C::Baud: return e.baud(v[0]);
    case C::Control: return e.control();
    case C::Safe: return e.safe();
    case C::Full: return e.full();
    case C::Power: return e.power();
    case C::Spot: return e.spot();
    case C::Clean: return e.clean();
    case C::Cover: return e.cover();
    case C::Max: return e.max();
    case C::Demo: return e.demo(v[0]);
    case C::Drive: return e.drive(v[0], v[1]);
    case C::Motors: return e.motors(v[0]);
    case C::LowSideDrivers: return e.lowSideDrivers(v[0]);
    case C::Leds: return e.leds(v[0], v[1], v[2]);
    case C::Song: {
        if (command.data.size() % 2 != 0)
            return OiError::invalid("song notes", "a note and its duration come in pairs; got "
                                                      + std::to_string(command.data.size()) + " bytes");
        Song song;
        for (std::size_t i = 0; i < command.data.size(); i += 2)
            song.notes.push_back({command.data[i], command.data[i + 1]});
        return e.song(v[0], song);
    }
    case C::Play: return e.play(v[0]);
    case C::Sensors: return e.sensors(v[0]);
    case C::SeekDock: return e.seekDock();
    case C::CoverAndDock: return e.coverAndDock();
    case C::PwmMotors: return e.pwmMotors(v[0], v[1], v[2]);
    case C::PwmLowSideDrivers: return e.pwmLowSideDrivers(v[0], v[1], v[2]);
    case C::DriveDirect: return e.driveDirect(v[0], v[1]);
    case C::DrivePwm: return e.drivePwm(v[0], v[1]);
    case C::DigitalOutputs: return e.digitalOutputs(v[0]);
    case C::Stream: return e.stream(asInts(command.data));
    case C::QueryList: return e.queryList(asInts(command.data));
    case C::PauseResumeStream: return e.pauseResumeStream(v[0]);
    case C::SendIr: return e.sendIr(v[0]);
    case C::Script: return e.script(command.data);
    case C::PlayScript: return e.playScript();
    case C::ShowScript: return e.showScript();
    case C::WaitTime: return e.waitTime(v[0]);
    case C::WaitDistance: return e.waitDistance(v[0]);
    case C::WaitAngle: return e.waitAngle(v[0]);
    case C::WaitEvent: return e.waitEvent(v[0]);
    case C::SchedulingLeds: return e.schedulingLeds(v[0], v[1]);
    case C::DigitLedsRaw: return e.digitLedsRaw(v[0], v[1], v[2], v[3]);
    case C::DigitLedsAscii: return e.digitLedsAscii(v[0], v[1], v[2], v[3]);
    case C::Buttons: return e.buttons(v[0]);
    case C::Schedule: return e.schedule(v[0], std::span(v).subspan(1));
    case C::SetDayTime: return e.setDayTime(v[0], v[1], v[2]);
    case C::Stop: return e.stop();
    }
    return OiError::invalid(std::string(spec.name), "has no encoder");
}

bool hasVariablePart(Command command) { return isVariable(commandSpec(command)); }

std::size_t commandHeaderLength(Command command)
{
    const CommandSpec &spec = commandSpec(command);
    if (isVariable(spec))
        return countOffset(command) + 1;
    std::size_t length = 1;
    for (std::size_t i = 0; i < spec.fields.size(); ++i)
        length += fieldBytes(fieldKind(spec, i));
    return length;
}

CommandDecode readCommand(const RobotProfile &profile, std::span<const std::uint8_t> bytes)
{
    if (bytes.empty()) {
        CommandDecode out;
        out.length = 1;
        out.error = OiError::invalid("command", "no bytes");
        return out;
    }
    const CommandSpec *spec = commandSpecForOpcode(profile, bytes[0]);
    if (!spec) {
        OiError e = OiError::invalid("opcode", std::to_string(bytes[0]) + " is not an opcode of the "
                                                   + std::string(profile.name));
        e.value = bytes[0];
        return failed(0, std::move(e));
    }

    // The command's size, from its layout or its count byte.
    const std::size_t header = commandHeaderLength(spec->command);
    if (bytes.size() < header)
        return needMore(*spec, header, bytes.size());
    const std::size_t size =
        isVariable(*spec) ? header + bytes[header - 1] * bytesPerItem(spec->command) : header;
    if (bytes.size() < size)
        return needMore(*spec, size, bytes.size());

    CommandDecode out;
    out.status = CommandDecode::Status::Command;
    out.command.command = spec->command;
    std::size_t at = 1;
    for (std::size_t i = 0; i < spec->fields.size(); ++i) {
        out.command.fields.push_back(readField(*spec, i, bytes.data() + at));
        at += fieldBytes(fieldKind(*spec, i));
    }
    if (isVariable(*spec))
        out.command.data.assign(bytes.begin() + std::ptrdiff_t(header), bytes.begin() + std::ptrdiff_t(size));
    out.length = size;
    return out;
}

std::vector<OiCommand> readCommands(const RobotProfile &profile, std::span<const std::uint8_t> bytes)
{
    std::vector<OiCommand> commands;
    for (std::size_t at = 0; at < bytes.size();) {
        CommandDecode d = readCommand(profile, bytes.subspan(at));
        if (d.status != CommandDecode::Status::Command)
            break;
        commands.push_back(std::move(d.command));
        at += d.length;
    }
    return commands;
}

CommandDecode decodeCommand(const RobotProfile &profile, std::span<const std::uint8_t> bytes)
{
    CommandDecode d = readCommand(profile, bytes);
    if (d.status != CommandDecode::Status::Command)
        return d;
    // The encoder's checks, so that bytes and typed calls are held to one rule.
    if (const EncodeResult checked = encodeCommand(CommandEncoder(profile), d.command); !checked) {
        CommandDecode out = failed(fieldOffset(commandSpec(d.command.command), checked.error().field), checked.error());
        out.command = std::move(d.command);
        return out;
    }
    return d;
}

std::optional<OiError> checkCommand(const CommandEncoder &encoder, const OiCommand &command)
{
    // The encoder's typed methods are where the ranges are stated; the
    // bytes they make here are dropped.
    const EncodeResult bytes = encodeCommand(encoder, command);
    if (bytes)
        return std::nullopt;
    return bytes.error();
}

EncodeResult encodeCommands(const CommandEncoder &encoder, std::span<const OiCommand> commands)
{
    Bytes out;
    for (const OiCommand &command : commands) {
        EncodeResult bytes = encodeCommand(encoder, command);
        if (!bytes)
            return bytes;
        out.insert(out.end(), bytes->begin(), bytes->end());
    }
    return out;
}

Result<OiCommand> commandFromText(const CommandEncoder &encoder, std::string_view name,
                                  std::span<const std::string> args)
{
    const EncodeResult bytes = encodeCommand(encoder, name, args);
    if (!bytes)
        return bytes.error();
    // The encoder made these bytes: they read back as the one command.
    Result<OiCommand> command = decodeCommand(encoder.robotProfile(), *bytes).command;
    command.warning = bytes.warning;
    return command;
}

Result<std::vector<OiCommand>> scriptCommands(const RobotProfile &profile, const OiCommand &script)
{
    return decodeCommands(profile, script.data);
}

std::vector<OiCommand> stopMotionCommands(const RobotProfile &profile)
{
    return {OiCommand{C::Drive, {0, 0}, {}},
            OiCommand{profile.has(C::Motors) ? C::Motors : C::LowSideDrivers, {0}, {}}};
}

std::vector<OiCommand> endScriptCommands(const RobotProfile &profile)
{
    if (!profile.has(C::Script))
        return {};
    return {OiCommand{C::Script, {}, {}}};
}

std::vector<OiCommand> shutdownCommands(const RobotProfile &profile)
{
    std::vector<OiCommand> out;
    if (profile.has(C::PauseResumeStream))
        out.push_back(OiCommand{C::PauseResumeStream, {0}, {}});
    for (const std::vector<OiCommand> &part : {endScriptCommands(profile), stopMotionCommands(profile)})
        out.insert(out.end(), part.begin(), part.end());
    out.push_back(OiCommand{C::Start, {}, {}});
    return out;
}

Result<std::vector<OiCommand>> decodeCommands(const RobotProfile &profile, std::span<const std::uint8_t> bytes)
{
    std::vector<OiCommand> commands;
    std::size_t at = 0;
    while (at < bytes.size()) {
        CommandDecode d = decodeCommand(profile, bytes.subspan(at));
        switch (d.status) {
        case CommandDecode::Status::Command:
            commands.push_back(std::move(d.command));
            at += d.length;
            break;
        case CommandDecode::Status::NeedMore: {
            const std::size_t have = bytes.size() - at;
            OiError e = std::move(d.error);
            e.field = "byte " + std::to_string(at);
            e.message += " (the bytes end at byte " + std::to_string(bytes.size()) + ", "
                         + std::to_string(d.length - have) + " short)";
            return e;
        }
        case CommandDecode::Status::Error: {
            // "byte 3: Drive Direct right velocity: 600 is outside -500..500"
            OiError e = std::move(d.error);
            const CommandSpec *spec = commandSpecForOpcode(profile, bytes[at]);
            std::string what = spec ? std::string(spec->title) + " " + e.field + ": " : std::string();
            e.message = what + OiError{{}, e.value, e.min, e.max, e.message}.describe();
            e.field = "byte " + std::to_string(at + d.length);
            return e;
        }
        }
    }
    return commands;
}

} // namespace oi
