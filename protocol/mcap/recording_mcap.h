// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "mcap_writer.h"
#include "recording_file.h"

#include <QString>

#include <vector>

// A recording as MCAP, for Foxglove, Lichtblick and PlotJuggler. The channels,
// schemas and encodings are listed in docs/mcap.md.
namespace oilink {

// The recording is robot r1, as the live data server's first robot: its
// channels are /r1/telemetry, /r1/pose, ... (foxglove::RobotTopics). Its
// markers go to /r1/markers as log messages, and a virtual robot's true poses
// to /r1/true_pose; each channel exists only when the recording holds such records.
struct McapExportOptions {
    mcap::Compression compression = mcap::Compression::Zstd;
};

// The robot a recording is, in the topics.
inline constexpr char kMcapRobot[] = "r1";

// Writes `recording` to `path` through a QSaveFile: on failure nothing is
// left under that name. Returns "" or the error, naming the file. A damaged
// recording is written up to its damage (the caller says where, from
// recording.damage()). `statistics`, when given, receives what was written.
QString exportRecordingMcap(const Recording &recording, const QString &path, const McapExportOptions &options,
                            mcap::Statistics *statistics = nullptr);

// The same, reading the recording from `recordingPath`; `damage` receives
// where a damaged recording stopped being readable.
QString exportRecordingMcap(const QString &recordingPath, const QString &path, const McapExportOptions &options,
                            std::optional<RecordingDamage> *damage = nullptr, mcap::Statistics *statistics = nullptr);

} // namespace oilink
