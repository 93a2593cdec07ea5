// SPDX-License-Identifier: GPL-3.0-or-later
// Small helpers shared by the Open Interface tests.
#pragma once

#include "command_catalog.h"
#include "robot_profile.h"

#include <QList>
#include <QMetaType>
#include <QString>
#include <QStringList>

#include <string>
#include <vector>

Q_DECLARE_METATYPE(oi::ProfileId)

namespace oi_test {

inline const oi::RobotProfile &profileNamed(const QString &key)
{
    return *oi::profileByKey(key.toStdString());
}

// "137 255 56 1 244" -> bytes.
inline oi::Bytes bytesFrom(const QString &text)
{
    oi::Bytes out;
    for (const QString &t : text.split(' ', Qt::SkipEmptyParts))
        out.push_back(static_cast<std::uint8_t>(t.toInt()));
    return out;
}

inline QString textFrom(const oi::Bytes &bytes)
{
    QStringList parts;
    for (std::uint8_t b : bytes)
        parts << QString::number(b);
    return parts.join(' ');
}

// Splits command-line style arguments; text in double quotes stays one argument.
inline std::vector<std::string> argsFrom(const QString &text)
{
    std::vector<std::string> out;
    QString current;
    bool quoted = false, any = false;
    for (QChar c : text) {
        if (c == '"') {
            quoted = !quoted;
            any = true;
        } else if (c == ' ' && !quoted) {
            if (any || !current.isEmpty())
                out.push_back(current.toStdString());
            current.clear();
            any = false;
        } else {
            current += c;
        }
    }
    if (any || !current.isEmpty())
        out.push_back(current.toStdString());
    return out;
}

// Encodes "NAME ARGS..." on a profile, as roomba-ctl does.
inline oi::EncodeResult encodeLine(const QString &profileKey, const QString &line)
{
    std::vector<std::string> words = argsFrom(line);
    const std::string name = words.empty() ? std::string() : words.front();
    if (!words.empty())
        words.erase(words.begin());
    return oi::encodeCommand(oi::CommandEncoder(profileNamed(profileKey)), name, words);
}

// Builds a stream frame [19][n][ids and data][checksum] from payload bytes.
inline oi::Bytes streamFrame(const oi::Bytes &payload, bool includeHeaderInSum = true)
{
    oi::Bytes frame{19, static_cast<std::uint8_t>(payload.size())};
    frame.insert(frame.end(), payload.begin(), payload.end());
    unsigned sum = includeHeaderInSum ? 0 : 0u - 19u;
    for (std::uint8_t b : frame)
        sum += b;
    frame.push_back(static_cast<std::uint8_t>(-sum & 0xFF));
    return frame;
}

} // namespace oi_test
