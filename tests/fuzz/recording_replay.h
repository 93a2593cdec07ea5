// SPDX-License-Identifier: GPL-3.0-or-later
// The check fuzz_recording runs on each input, shared with
// tests/link/tst_file_fuzz_regressions.cpp so a saved input replays exactly.
#pragma once

#include "recording_file.h"

#include <QByteArray>
#include <QString>
#include <QTextStream>

#include <string>

namespace fuzz {

// Input: the bytes of a .oirec file.
//
// Invariants, for a file that opens:
// - the frame index runs forward: each frame ends after the one before it,
//   within the received bytes, at a time that never decreases and is not
//   after the recording's end;
// - replaying to the end decodes every indexed frame exactly once, at its
//   indexed time;
// - the CSV has a header row and one row per frame, and is at most 8 times
//   the file's size and a header: a frame is the stream's, at least 5 bytes,
//   and its row at most 4 times that (a 20-digit time, a 6-digit value for a
//   packet of an id and 2 bytes), whatever the file says its stream is;
// - it holds at most oilink::kMaxMarkers markers.
// Returns an empty string when they hold, else what broke.
inline std::string checkRecordingInput(const QByteArray &input)
{
    QString error;
    const std::optional<oilink::Recording> recording =
        oilink::Recording::fromBytes(input, QStringLiteral("fuzz.oirec"), &error);
    if (!recording)
        return error.isEmpty() ? "refused without a reason" : std::string();

    const auto &frames = recording->frames();
    qsizetype lastEnd = 0;
    qint64 lastTime = 0;
    for (const oilink::Recording::Frame &f : frames) {
        if (f.end <= lastEnd || f.end > recording->receivedBytes().size())
            return "a frame ends at " + std::to_string(f.end) + " after " + std::to_string(lastEnd);
        if (f.timeUs < lastTime || f.timeUs > recording->durationUs())
            return "a frame's time " + std::to_string(f.timeUs) + " is out of order";
        lastEnd = f.end;
        lastTime = f.timeUs;
    }

    std::size_t replayed = 0;
    bool inStep = true;
    recording->forEachSnapshot([&](qint64 timeUs, const oi::SensorSnapshot &) {
        if (replayed >= frames.size() || frames[replayed].timeUs != timeUs)
            inStep = false;
        ++replayed;
    });
    if (!inStep || replayed != frames.size())
        return "replay decoded " + std::to_string(replayed) + " frames of " + std::to_string(frames.size());

    QString csv;
    QTextStream out(&csv);
    recording->writeCsv(out);
    out.flush();
    if (static_cast<std::size_t>(csv.count(QLatin1Char('\n'))) != frames.size() + 1)
        return "the CSV has " + std::to_string(csv.count(QLatin1Char('\n'))) + " lines for "
               + std::to_string(frames.size()) + " frames";
    if (csv.size() > 8 * input.size() + 4096)
        return "the CSV is " + std::to_string(csv.size()) + " characters from " + std::to_string(input.size())
               + " bytes";
    if (recording->markers().size() > oilink::kMaxMarkers)
        return std::to_string(recording->markers().size()) + " markers read";
    return {};
}

} // namespace fuzz
