// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_encoder.h"

#include "command_catalog.h"
#include "oi_command.h"

#include <algorithm>
#include <cctype>
#include <initializer_list>

namespace oi {
namespace {

std::optional<OiError> checkRange(std::string_view field, long long value, long long min,
                                  long long max)
{
    if (value < min || value > max)
        return OiError::outOfRange(std::string(field), value, min, max);
    return std::nullopt;
}

// Checks every (field, value, min, max) in order; the first failure wins.
struct RangeCheck {
    std::string_view field;
    long long value, min, max;
};
std::optional<OiError> checkAll(std::initializer_list<RangeCheck> checks)
{
    for (const RangeCheck &c : checks)
        if (auto e = checkRange(c.field, c.value, c.min, c.max))
            return e;
    return std::nullopt;
}

void put16(Bytes &out, int value)
{
    const auto u = static_cast<std::uint16_t>(value);
    out.push_back(static_cast<std::uint8_t>(u >> 8));
    out.push_back(static_cast<std::uint8_t>(u & 0xFF));
}

Bytes withOpcode(Command command, std::initializer_list<int> dataBytes = {})
{
    Bytes out{commandSpec(command).opcode};
    for (int b : dataBytes)
        out.push_back(static_cast<std::uint8_t>(b));
    return out;
}

bool isSpecialRadius(int radius)
{
    return radius == kRadiusStraight || radius == kRadiusStraightAlt || radius == -32768;
}

constexpr std::string_view kWaitEventNames[kWaitEventCount] = {
    "wheel-drop",        "front-wheel-drop",  "left-wheel-drop", "right-wheel-drop",
    "bump",              "left-bump",         "right-bump",      "virtual-wall",
    "wall",              "cliff",             "left-cliff",      "front-left-cliff",
    "front-right-cliff", "right-cliff",       "home-base",       "advance-button",
    "play-button",       "digital-input-0",   "digital-input-1", "digital-input-2",
    "digital-input-3",   "oi-mode-passive",
};

std::string sensorIdsText(const RobotProfile &profile)
{
    const int last = profile.packets().back().id;
    std::string text = "0.." + std::to_string(last);
    for (const PacketGroup &g : profile.groups())
        if (g.id > last)
            text += ", " + std::to_string(g.id);
    return text;
}

} // namespace

std::string_view waitEventName(int event)
{
    return event >= 1 && event <= kWaitEventCount ? kWaitEventNames[event - 1] : std::string_view();
}

std::optional<int> parseWaitEvent(std::string_view text)
{
    long long number = 0;
    if (parseInteger(text, number)) {
        if ((number >= 1 && number <= kWaitEventCount) || (number <= -1 && number >= -kWaitEventCount))
            return static_cast<int>(number);
        return std::nullopt;
    }
    int sign = 1;
    if (text.starts_with("not-")) {
        sign = -1;
        text.remove_prefix(4);
    } else if (text.starts_with("!")) {
        sign = -1;
        text.remove_prefix(1);
    }
    for (int i = 0; i < kWaitEventCount; ++i)
        if (kWaitEventNames[i] == text)
            return sign * (i + 1);
    return std::nullopt;
}

std::optional<OiError> CommandEncoder::refuse(Command command) const
{
    if (m_profile->has(command))
        return std::nullopt;
    const CommandSpec &spec = commandSpec(command);
    return OiError::invalid(std::string(spec.name),
                            std::string(spec.title) + " (" + std::to_string(spec.opcode)
                                + ") is not available on the " + std::string(m_profile->name));
}

EncodeResult CommandEncoder::simple(Command command) const
{
    if (auto e = refuse(command))
        return *e;
    return withOpcode(command);
}

EncodeResult CommandEncoder::reset() const { return simple(Command::Reset); }
EncodeResult CommandEncoder::start() const { return simple(Command::Start); }
EncodeResult CommandEncoder::control() const { return simple(Command::Control); }
EncodeResult CommandEncoder::safe() const { return throughControl(Command::Safe); }
EncodeResult CommandEncoder::full() const { return throughControl(Command::Full); }

// SCI: Control (130) takes Passive to Safe and is ignored in Safe or Full;
// Safe (131) is taken in Full only, Full (132) in Safe only. Control first
// reaches either mode from any of them.
EncodeResult CommandEncoder::throughControl(Command command) const
{
    if (auto e = refuse(command))
        return *e;
    if (!m_profile->caps.controlBeforeSafeOrFull)
        return withOpcode(command);
    return Bytes{commandSpec(Command::Control).opcode, commandSpec(command).opcode};
}
EncodeResult CommandEncoder::stop() const { return simple(Command::Stop); }
EncodeResult CommandEncoder::power() const { return simple(Command::Power); }
EncodeResult CommandEncoder::spot() const { return simple(Command::Spot); }
EncodeResult CommandEncoder::clean() const { return simple(Command::Clean); }
EncodeResult CommandEncoder::cover() const { return simple(Command::Cover); }
EncodeResult CommandEncoder::max() const { return simple(Command::Max); }
EncodeResult CommandEncoder::seekDock() const { return simple(Command::SeekDock); }
EncodeResult CommandEncoder::coverAndDock() const { return simple(Command::CoverAndDock); }
EncodeResult CommandEncoder::playScript() const { return simple(Command::PlayScript); }
EncodeResult CommandEncoder::showScript() const { return simple(Command::ShowScript); }

EncodeResult CommandEncoder::baud(int code) const
{
    if (auto e = refuse(Command::Baud))
        return *e;
    if (auto e = checkRange("baud code", code, 0, 11))
        return *e;
    return withOpcode(Command::Baud, {code});
}

EncodeResult CommandEncoder::demo(int demo) const
{
    if (auto e = refuse(Command::Demo))
        return *e;
    if (demo == 255)
        demo = -1;
    if (auto e = checkRange("demo", demo, -1, 9))
        return *e;
    return withOpcode(Command::Demo, {demo});
}

EncodeResult CommandEncoder::schedule(const CleaningSchedule &schedule) const
{
    const auto bytes = scheduleBytes(schedule);
    std::array<int, 14> times{};
    std::copy(bytes.begin() + 1, bytes.end(), times.begin());
    return this->schedule(bytes[0], times);
}

EncodeResult CommandEncoder::schedule(int dayBits, std::span<const int> hoursAndMinutes) const
{
    if (auto e = refuse(Command::Schedule))
        return *e;
    if (hoursAndMinutes.size() != 14)
        return OiError::invalid("schedule", "needs 14 times (hour and minute for each day), got "
                                                + std::to_string(hoursAndMinutes.size()));
    if (auto e = checkRange("days", dayBits, 0, 127))
        return *e;
    Bytes out = withOpcode(Command::Schedule, {dayBits});
    for (std::size_t i = 0; i < 14; ++i) {
        const bool hour = i % 2 == 0;
        const std::string field = std::string(weekdayName(static_cast<Weekday>(i / 2)))
                                  + (hour ? " hour" : " minute");
        if (auto e = checkRange(field, hoursAndMinutes[i], 0, hour ? 23 : 59))
            return *e;
        out.push_back(static_cast<std::uint8_t>(hoursAndMinutes[i]));
    }
    return out;
}

EncodeResult CommandEncoder::setDayTime(int day, int hour, int minute) const
{
    if (auto e = refuse(Command::SetDayTime))
        return *e;
    if (auto e = checkAll({{"day", day, 0, 6}, {"hour", hour, 0, 23}, {"minute", minute, 0, 59}}))
        return *e;
    return withOpcode(Command::SetDayTime, {day, hour, minute});
}

EncodeResult CommandEncoder::drive(int velocity, int radius) const
{
    if (auto e = refuse(Command::Drive))
        return *e;
    if (auto e = checkRange("velocity", velocity, -500, 500))
        return *e;
    if (!isSpecialRadius(radius) && (radius < -2000 || radius > 2000)) {
        OiError e = OiError::outOfRange("radius", radius, -2000, 2000);
        e.message = std::to_string(radius)
                    + " is outside -2000..2000 (32767 or 32768 drive straight, -1 and 1 turn in place)";
        return e;
    }
    Bytes out = withOpcode(Command::Drive);
    put16(out, velocity);
    put16(out, radius);
    return out;
}

EncodeResult CommandEncoder::driveDirect(int rightVelocity, int leftVelocity) const
{
    if (auto e = refuse(Command::DriveDirect))
        return *e;
    if (auto e = checkAll({{"right velocity", rightVelocity, -500, 500},
                           {"left velocity", leftVelocity, -500, 500}}))
        return *e;
    Bytes out = withOpcode(Command::DriveDirect);
    put16(out, rightVelocity);
    put16(out, leftVelocity);
    return out;
}

EncodeResult CommandEncoder::drivePwm(int rightPwm, int leftPwm) const
{
    if (auto e = refuse(Command::DrivePwm))
        return *e;
    if (auto e = checkAll({{"right PWM", rightPwm, -255, 255}, {"left PWM", leftPwm, -255, 255}}))
        return *e;
    Bytes out = withOpcode(Command::DrivePwm);
    put16(out, rightPwm);
    put16(out, leftPwm);
    return out;
}

EncodeResult CommandEncoder::motors(int motorBits) const
{
    if (auto e = refuse(Command::Motors))
        return *e;
    if (auto e = checkRange("motor bits", motorBits, 0, 31))
        return *e;
    return withOpcode(Command::Motors, {motorBits});
}

EncodeResult CommandEncoder::lowSideDrivers(int driverBits) const
{
    if (auto e = refuse(Command::LowSideDrivers))
        return *e;
    if (auto e = checkRange("driver bits", driverBits, 0, 7))
        return *e;
    return withOpcode(Command::LowSideDrivers, {driverBits});
}

EncodeResult CommandEncoder::pwmMotors(int mainBrush, int sideBrush, int vacuum) const
{
    if (auto e = refuse(Command::PwmMotors))
        return *e;
    if (auto e = checkAll({{"main brush PWM", mainBrush, -127, 127},
                           {"side brush PWM", sideBrush, -127, 127},
                           {"vacuum PWM", vacuum, 0, 127}}))
        return *e;
    return withOpcode(Command::PwmMotors, {mainBrush, sideBrush, vacuum});
}

EncodeResult CommandEncoder::pwmLowSideDrivers(int driver2, int driver1, int driver0) const
{
    if (auto e = refuse(Command::PwmLowSideDrivers))
        return *e;
    if (auto e = checkAll({{"low side driver 2 duty cycle", driver2, 0, 128},
                           {"low side driver 1 duty cycle", driver1, 0, 128},
                           {"low side driver 0 duty cycle", driver0, 0, 128}}))
        return *e;
    return withOpcode(Command::PwmLowSideDrivers, {driver2, driver1, driver0});
}

EncodeResult CommandEncoder::leds(int ledBits, int powerColor, int powerIntensity) const
{
    if (auto e = refuse(Command::Leds))
        return *e;
    if (auto e = checkRange("LED bits", ledBits, 0, 255))
        return *e;
    // ERRATA 15: the Create has only Play (bit 1) and Advance (bit 3).
    if (m_profile->caps.panel == ButtonPanel::PlayAdvance && (ledBits & ~(bit::LedPlay | bit::LedAdvance))) {
        OiError e = OiError::outOfRange("LED bits", ledBits, 0, 10);
        e.message = std::to_string(ledBits)
                    + " sets LEDs the Create lacks; only 2 (Play) and 8 (Advance) exist";
        return e;
    }
    if (auto e = checkAll({{"power LED colour", powerColor, 0, 255},
                           {"power LED intensity", powerIntensity, 0, 255}}))
        return *e;
    return withOpcode(Command::Leds, {ledBits, powerColor, powerIntensity});
}

EncodeResult CommandEncoder::schedulingLeds(int weekdayBits, int schedulingBits) const
{
    if (auto e = refuse(Command::SchedulingLeds))
        return *e;
    if (auto e = checkAll({{"weekday LED bits", weekdayBits, 0, 255},
                           {"scheduling LED bits", schedulingBits, 0, 255}}))
        return *e;
    return withOpcode(Command::SchedulingLeds, {weekdayBits, schedulingBits});
}

EncodeResult CommandEncoder::digitLedsRaw(int digit3, int digit2, int digit1, int digit0) const
{
    if (auto e = refuse(Command::DigitLedsRaw))
        return *e;
    if (auto e = checkAll({{"digit 3", digit3, 0, 255}, {"digit 2", digit2, 0, 255},
                           {"digit 1", digit1, 0, 255}, {"digit 0", digit0, 0, 255}}))
        return *e;
    EncodeResult result = withOpcode(Command::DigitLedsRaw, {digit3, digit2, digit1, digit0});
    // ERRATA 9: sent as asked, but the user should know it may do nothing,
    // on every model that has it.
    result.warning = "Digit LEDs Raw (163) does not work in current Create 2 and Roomba 500/600 firmware";
    return result;
}

EncodeResult CommandEncoder::digitLedsAscii(int digit3, int digit2, int digit1, int digit0) const
{
    if (auto e = refuse(Command::DigitLedsAscii))
        return *e;
    if (auto e = checkAll({{"digit 3", digit3, 32, 126}, {"digit 2", digit2, 32, 126},
                           {"digit 1", digit1, 32, 126}, {"digit 0", digit0, 32, 126}}))
        return *e;
    return withOpcode(Command::DigitLedsAscii, {digit3, digit2, digit1, digit0});
}

EncodeResult CommandEncoder::buttons(int buttonBits) const
{
    if (auto e = refuse(Command::Buttons))
        return *e;
    if (auto e = checkRange("button bits", buttonBits, 0, 255))
        return *e;
    return withOpcode(Command::Buttons, {buttonBits});
}

EncodeResult CommandEncoder::song(int slot, const Song &song) const
{
    if (auto e = refuse(Command::Song))
        return *e;
    if (auto e = checkRange("song number", slot, 0, m_profile->songSlots - 1))
        return *e;
    if (auto e = checkRange("song length", static_cast<long long>(song.notes.size()), 1, kMaxSongNotes))
        return *e;
    Bytes out = withOpcode(Command::Song, {slot, static_cast<int>(song.notes.size())});
    for (const SongNote &note : song.notes) {
        out.push_back(note.midi);
        out.push_back(note.duration);
    }
    EncodeResult result = std::move(out);
    if (m_profile->songSlots == 5 && slot == 4)
        result.warning = "song slot 4 may not play on some firmware (ERRATA 13)";
    return result;
}

EncodeResult CommandEncoder::play(int slot) const
{
    if (auto e = refuse(Command::Play))
        return *e;
    if (auto e = checkRange("song number", slot, 0, m_profile->songSlots - 1))
        return *e;
    EncodeResult result = withOpcode(Command::Play, {slot});
    if (m_profile->songSlots == 5 && slot == 4)
        result.warning = "song slot 4 may not play on some firmware (ERRATA 13)";
    return result;
}

EncodeResult CommandEncoder::digitalOutputs(int outputBits) const
{
    if (auto e = refuse(Command::DigitalOutputs))
        return *e;
    if (auto e = checkRange("output bits", outputBits, 0, 7))
        return *e;
    return withOpcode(Command::DigitalOutputs, {outputBits});
}

EncodeResult CommandEncoder::sendIr(int value) const
{
    if (auto e = refuse(Command::SendIr))
        return *e;
    if (auto e = checkRange("IR byte", value, 0, 255))
        return *e;
    return withOpcode(Command::SendIr, {value});
}

bool CommandEncoder::isValidSensorList(std::span<const int> ids, OiError &error) const
{
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (!m_profile->isValidSensorId(ids[i])) {
            error = OiError::invalid("packet id " + std::to_string(i + 1),
                                     std::to_string(ids[i]) + " is not a packet or group of the "
                                         + std::string(m_profile->name) + " ("
                                         + sensorIdsText(*m_profile) + ")");
            error.value = ids[i];
            return false;
        }
    }
    return true;
}

EncodeResult CommandEncoder::sensors(int packetId) const
{
    if (auto e = refuse(Command::Sensors))
        return *e;
    OiError error;
    if (!isValidSensorList({&packetId, 1}, error)) {
        error.field = "packet id";
        return error;
    }
    return withOpcode(Command::Sensors, {packetId});
}

EncodeResult CommandEncoder::stream(std::span<const int> packetIds, int baud) const
{
    if (auto e = refuse(Command::Stream))
        return *e;
    if (auto e = checkRange("number of packets", static_cast<long long>(packetIds.size()), 0,
                            m_profile->maxStreamPackets))
        return *e;
    OiError error;
    if (!isValidSensorList(packetIds, error))
        return error;
    // ERRATA 18: header, n-bytes, an id and the data per packet, checksum.
    long long frameBytes = 3;
    for (int id : packetIds)
        frameBytes += 1 + m_profile->replySize(id);
    const int rate = baud > 0 ? baud : m_profile->defaultBaud;
    const int limit = maxStreamFrameBytes(rate);
    if (frameBytes > limit) {
        OiError e = OiError::outOfRange("stream frame size", frameBytes, 0, limit);
        e.message = "a frame of " + std::to_string(frameBytes) + " bytes does not fit in 15 ms at "
                    + std::to_string(rate) + " baud (at most " + std::to_string(limit) + " bytes)";
        return e;
    }
    Bytes out = withOpcode(Command::Stream, {static_cast<int>(packetIds.size())});
    for (int id : packetIds)
        out.push_back(static_cast<std::uint8_t>(id));
    return out;
}

EncodeResult CommandEncoder::queryList(std::span<const int> packetIds) const
{
    if (auto e = refuse(Command::QueryList))
        return *e;
    if (auto e = checkRange("number of packets", static_cast<long long>(packetIds.size()), 0, 255))
        return *e;
    OiError error;
    if (!isValidSensorList(packetIds, error))
        return error;
    Bytes out = withOpcode(Command::QueryList, {static_cast<int>(packetIds.size())});
    for (int id : packetIds)
        out.push_back(static_cast<std::uint8_t>(id));
    return out;
}

EncodeResult CommandEncoder::pauseResumeStream(int state) const
{
    if (auto e = refuse(Command::PauseResumeStream))
        return *e;
    if (auto e = checkRange("stream state", state, 0, 1))
        return *e;
    return withOpcode(Command::PauseResumeStream, {state});
}

EncodeResult CommandEncoder::script(std::span<const std::uint8_t> body) const
{
    if (auto e = refuse(Command::Script))
        return *e;
    if (auto e = checkRange("script length", static_cast<long long>(body.size()), 0, 100))
        return *e;
    Bytes out = withOpcode(Command::Script, {static_cast<int>(body.size())});
    out.insert(out.end(), body.begin(), body.end());
    return out;
}

EncodeResult CommandEncoder::waitTime(int tenths) const
{
    if (auto e = refuse(Command::WaitTime))
        return *e;
    if (auto e = checkRange("time", tenths, 0, 255))
        return *e;
    return withOpcode(Command::WaitTime, {tenths});
}

EncodeResult CommandEncoder::waitDistance(int millimetres) const
{
    if (auto e = refuse(Command::WaitDistance))
        return *e;
    if (auto e = checkRange("distance", millimetres, -32768, 32767))
        return *e;
    Bytes out = withOpcode(Command::WaitDistance);
    put16(out, millimetres);
    return out;
}

EncodeResult CommandEncoder::waitAngle(int degrees) const
{
    if (auto e = refuse(Command::WaitAngle))
        return *e;
    if (auto e = checkRange("angle", degrees, -32768, 32767))
        return *e;
    Bytes out = withOpcode(Command::WaitAngle);
    put16(out, degrees);
    return out;
}

EncodeResult CommandEncoder::waitEvent(int event) const
{
    if (auto e = refuse(Command::WaitEvent))
        return *e;
    if (event == 0 || event < -kWaitEventCount || event > kWaitEventCount) {
        OiError e = OiError::outOfRange("event", event, -kWaitEventCount, kWaitEventCount);
        e.message = std::to_string(event) + " is not an event: 1..22, or -1..-22 for its inverse";
        return e;
    }
    return withOpcode(Command::WaitEvent, {event}); // two's complement for the inverse
}

// The typed sequences (oi_command.h) are the one statement of these.
Bytes CommandEncoder::stopMotion() const
{
    return *encodeCommands(*this, stopMotionCommands(*m_profile));
}

// A waiting Create reads nothing more until its wait ends (ERRATA 20), so
// whatever we send queues behind the rest of the script, which goes on in the
// mode it started in and so can end its waits. At its end a looping script's
// Play Script (153) loads the stored script behind the bytes waiting there;
// an empty Script (152 0, "Specify a length of 0 to clear the current
// script") among those bytes leaves it nothing to load. Without it the script
// would start again after our Passive, where its Drive is ignored and its
// next Wait Distance never ends: a robot deaf until its battery is pulled.
Bytes CommandEncoder::endScript() const
{
    return *encodeCommands(*this, endScriptCommands(*m_profile));
}

Bytes CommandEncoder::shutdownSequence() const
{
    return *encodeCommands(*this, shutdownCommands(*m_profile));
}

} // namespace oi
