// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// RFC 2217, the Telnet Com Port Control Option, as far as the robot needs
// it: serial data inside Telnet (0xFF doubled), SET-CONTROL for the RTS and
// DTR lines (the BRC pin), and SET-BAUDRATE for the line's rate. ser2net speaks it in telnet mode; the link
// pulses BRC through it and roomba-sim's TCP server takes it. Standard
// library only, so the link and the virtual robot share one copy.

#include <cstdint>
#include <functional>
#include <vector>

namespace rfc2217 {

using Bytes = std::vector<std::uint8_t>;

inline constexpr std::uint8_t kIac = 255, kSb = 250, kSe = 240, kWill = 251, kDo = 253;
inline constexpr std::uint8_t kComPortOption = 44;
inline constexpr std::uint8_t kSetBaudRate = 1;     // client to server
inline constexpr std::uint8_t kSetControl = 5;      // client to server
inline constexpr std::uint8_t kServerOffset = 100;  // the server's answers: 105 for SET-CONTROL
inline constexpr std::uint8_t kDtrOn = 8, kDtrOff = 9, kRtsOn = 11, kRtsOff = 12;

// What a client sends first: it will speak the Com Port Option.
inline Bytes willComPort() { return {kIac, kWill, kComPortOption}; }
inline Bytes doComPort() { return {kIac, kDo, kComPortOption}; }

// SET-CONTROL `value` (kRtsOn...); a server answers with kSetControl + kServerOffset.
inline Bytes setControl(std::uint8_t value, std::uint8_t command = kSetControl)
{
    return {kIac, kSb, kComPortOption, command, value, kIac, kSe};
}

// SET-BAUDRATE `baud` (0 asks for the current rate), four bytes in network
// order, any 0xFF among them doubled; a server answers with kSetBaudRate +
// kServerOffset and the rate it now uses.
inline Bytes setBaudRate(std::uint32_t baud, std::uint8_t command = kSetBaudRate)
{
    Bytes out{kIac, kSb, kComPortOption, command};
    for (int shift = 24; shift >= 0; shift -= 8) {
        const auto b = std::uint8_t(baud >> shift);
        out.push_back(b);
        if (b == kIac)
            out.push_back(kIac);
    }
    out.insert(out.end(), {kIac, kSe});
    return out;
}

// The rate in a SET-BAUDRATE value; 0 where the value is not four bytes.
inline std::uint32_t baudRateOf(const Bytes &value)
{
    if (value.size() != 4)
        return 0;
    return std::uint32_t(value[0]) << 24 | std::uint32_t(value[1]) << 16 | std::uint32_t(value[2]) << 8 | value[3];
}

// Serial data for the wire: every 0xFF doubled.
inline Bytes escape(const std::uint8_t *data, std::size_t size)
{
    Bytes out;
    out.reserve(size);
    for (std::size_t i = 0; i < size; ++i) {
        out.push_back(data[i]);
        if (data[i] == kIac)
            out.push_back(kIac);
    }
    return out;
}

// Telnet from the wire back to serial data, across reads: commands are taken
// out, and each Com Port Option subnegotiation is handed to `onControl` as
// (command, value bytes).
class Decoder {
public:
    using Control = std::function<void(std::uint8_t command, const Bytes &value)>;

    Bytes feed(const std::uint8_t *data, std::size_t size, const Control &onControl = {})
    {
        Bytes out;
        for (std::size_t i = 0; i < size; ++i) {
            const std::uint8_t b = data[i];
            switch (m_state) {
            case State::Data:
                if (b == kIac)
                    m_state = State::Iac;
                else
                    out.push_back(b);
                break;
            case State::Iac:
                if (b == kIac) {
                    out.push_back(kIac);
                    m_state = State::Data;
                } else if (b == kSb) {
                    m_sub.clear();
                    m_state = State::Sub;
                } else if (b >= kWill) {
                    m_state = State::Option; // WILL, WONT, DO, DONT take one byte
                } else {
                    m_state = State::Data; // NOP and the like
                }
                break;
            case State::Option:
                m_state = State::Data;
                break;
            case State::Sub:
                if (b == kIac)
                    m_state = State::SubIac;
                else
                    m_sub.push_back(b);
                break;
            case State::SubIac:
                if (b == kSe) {
                    if (m_sub.size() >= 2 && m_sub[0] == kComPortOption && onControl)
                        onControl(m_sub[1], Bytes(m_sub.begin() + 2, m_sub.end()));
                    m_state = State::Data;
                } else {
                    m_sub.push_back(b); // a doubled 0xFF inside
                    m_state = State::Sub;
                }
                break;
            }
        }
        return out;
    }

private:
    enum class State { Data, Iac, Option, Sub, SubIac };
    State m_state = State::Data;
    Bytes m_sub;
};

} // namespace rfc2217
