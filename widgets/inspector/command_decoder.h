// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "oi_command.h"
#include "robot_profile.h"

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

// Reads the bytes sent to a robot back as commands, for the byte inspector:
// "137 255 56 1 244" is "Drive velocity -200 radius 500". Also checks the
// raw bytes a person types before they are sent.
class CommandDecoder {
public:
    enum class Status : std::uint8_t {
        Complete,   // a whole command of the profile
        Incomplete, // the bytes end before the command does
        Unknown,    // the first byte is no opcode of the profile
    };
    struct Decoded {
        Status status = Status::Unknown;
        std::size_t length = 0; // bytes this piece covers, at least 1
        std::optional<oi::OiCommand> command; // when Complete
        QString meaning;
    };

    explicit CommandDecoder(const oi::RobotProfile &profile = oi::profile(oi::ProfileId::Create2))
        : m_profile(&profile) {}
    void setProfile(const oi::RobotProfile &profile) { m_profile = &profile; }
    const oi::RobotProfile &robotProfile() const { return *m_profile; }

    // Splits `bytes` into commands. An unknown opcode takes the rest of the
    // bytes with it: without knowing the command there is no telling where
    // the next one starts.
    std::vector<Decoded> decode(std::span<const std::uint8_t> bytes) const;
    // The one command at the start of `bytes` (which must not be empty).
    Decoded decodeOne(std::span<const std::uint8_t> bytes) const;

    // Parses typed bytes ("128 131", "0x80 0x83", commas allowed) and checks
    // them: every number 0..255, each command an opcode of the profile with
    // all its data bytes, and the values within what the command encoder
    // accepts. Returns the bytes, or nullopt with a sentence in `error`.
    std::optional<QByteArray> parseRaw(const QString &text, QString *error) const;

    // Packet or group names for messages: "Voltage (22)", "group 100 (packets 7..58)".
    QString packetLabel(int packetOrGroupId) const;

private:
    QString describe(const oi::OiCommand &command) const;

    const oi::RobotProfile *m_profile;
};
