// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "mcap_writer.h"
#include "recording_file.h"

#include <QString>

#include <vector>

// A recording as MCAP, for Foxglove, Lichtblick and PlotJuggler. The channels,
// schemas and encodings are listed in docs/mcap.md.
namespace oilink {

// The recording's markers go to /roomba/markers as log messages, and a
// virtual robot's true poses to /roomba/true_pose; each channel exists only
// when the recording holds such records.
struct McapExportOptions {
    mcap::Compression compression = mcap::Compression::Zstd;
};

// The topics, as docs/mcap.md lists them.
namespace mcap_topics {
inline constexpr char kTelemetry[] = "/roomba/telemetry";
inline constexpr char kPose[] = "/roomba/pose";
inline constexpr char kTruePose[] = "/roomba/true_pose"; // only from a virtual robot's recording
inline constexpr char kTransform[] = "/tf";
inline constexpr char kReceived[] = "/roomba/bytes_received";
inline constexpr char kSent[] = "/roomba/bytes_sent";
inline constexpr char kEvents[] = "/roomba/events";
inline constexpr char kMarkers[] = "/roomba/markers";
} // namespace mcap_topics

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
