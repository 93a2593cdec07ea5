// SPDX-License-Identifier: GPL-3.0-or-later
// A recording of a Create 2 streaming group 100, frame after frame, as fast
// as the file takes them: for benchmarks that need an hour's recording.
#pragma once

#include "recording_file.h"

#include "packets_as_sent.h"

#include <functional>

// `frames` frames; `vary(i, values)` sets frame i's values (every packet
// starts at its minimum or 0); `before(i, writer)`, when given, may write
// records of its own before frame i. False with `error` set when writing fails.
inline bool writeSyntheticRecording(const QString &path, int frames,
                                    const std::function<void(int, oi::SensorSnapshot &)> &vary, QString *error,
                                    const std::function<bool(int, oilink::RecordingWriter &)> &before = {})
{
    const oi::RobotProfile &profile = oi::profile(oi::ProfileId::Create2);
    oi::SensorSnapshot values(profile);
    for (const oi::PacketInfo &p : profile.packets())
        values.set(p.id, p.min > 0 ? p.min : 0);
    oilink::RecordingWriter writer;
    if (!writer.open(path, {}) || !writer.appendStreamStarted(profile.id, 115200, {100})) {
        *error = writer.errorString();
        return false;
    }
    for (int i = 0; i < frames; ++i) {
        if (before && !before(i, writer)) {
            *error = writer.errorString();
            return false;
        }
        vary(i, values);
        oi::Bytes frame{19, 0, 100};
        oi::appendPacketData(values, 100, frame);
        frame[1] = static_cast<std::uint8_t>(frame.size() - 2);
        unsigned sum = 0;
        for (std::uint8_t b : frame)
            sum += b;
        frame.push_back(static_cast<std::uint8_t>((256 - (sum & 0xFF)) & 0xFF));
        if (!writer.append(oilink::recording::RecordKind::Received,
                           QByteArray(reinterpret_cast<const char *>(frame.data()), qsizetype(frame.size())))) {
            *error = writer.errorString();
            return false;
        }
    }
    writer.close();
    return true;
}
