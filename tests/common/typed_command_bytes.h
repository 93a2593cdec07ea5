// SPDX-License-Identifier: GPL-3.0-or-later
// The exact bytes of the typed commands a widget asks to send.
#pragma once

#include "typed_commands.h"

#include <QByteArray>
#include <QVariant>

// The commands' bytes on `profile`, one after another; a command the profile
// refuses adds "<refused>" so that no comparison passes by accident.
inline QByteArray bytesOfCommands(const oi::RobotProfile &profile, const std::vector<oi::OiCommand> &commands)
{
    QByteArray out;
    for (const oi::OiCommand &command : commands) {
        const oi::EncodeResult bytes = oi::encodeCommand(oi::CommandEncoder(profile), command);
        if (!bytes)
            return out + "<refused>";
        out.append(reinterpret_cast<const char *>(bytes->data()), qsizetype(bytes->size()));
    }
    return out;
}

// The same, for one emission a QSignalSpy caught.
inline QByteArray bytesOfCommands(const oi::RobotProfile &profile, const QVariant &commands)
{
    return bytesOfCommands(profile, commands.value<std::vector<oi::OiCommand>>());
}

// The other way: bytes as the documents write them, read as the typed
// commands they are, for tests that say what they send in bytes. Bytes that
// are no whole command fail the test that sends them (they read as nothing).
inline std::vector<oi::OiCommand> commandsOf(const QByteArray &bytes,
                                             const oi::RobotProfile &profile = oi::profile(oi::ProfileId::Create2))
{
    const auto commands = oi::decodeCommands(
        profile, {reinterpret_cast<const std::uint8_t *>(bytes.constData()), std::size_t(bytes.size())});
    return commands ? *commands : std::vector<oi::OiCommand>{};
}
