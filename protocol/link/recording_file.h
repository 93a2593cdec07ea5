// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "firmware_banner.h"
#include "odometry.h"
#include "recording_markers.h"
#include "robot_profile.h"
#include "sensor_snapshot.h"

#include <QByteArray>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonObject>
#include <QList>
#include <QString>
#include <QTextStream>

#include <functional>
#include <optional>
#include <vector>

namespace oilink {

// A recording of every byte on a robot link, with timestamps. The format is
// described in recording_format.md; in short: a magic, a version, a JSON
// header, then records of (kind, microseconds, length, bytes, CRC-16).
namespace recording {
inline constexpr char kMagic[] = "OIRECORD"; // 8 bytes, no terminator in the file
inline constexpr int kMagicSize = 8;
inline constexpr quint16 kVersion = 3;       // written; 2 added markers, 3 the true pose
inline constexpr quint16 kOldestVersion = 1; // still read
inline constexpr int kMaxPayload = 0xFFFF;
inline constexpr int kFlushIntervalMs = 1000;
inline constexpr char kFileSuffix[] = "oirec";
// A recording is read whole: an hour at 115200 baud is about 23 MB, so this
// is some 40 hours; a larger file is refused unread.
inline constexpr qint64 kMaxFileBytes = qint64(1) << 30;

enum class RecordKind : quint8 {
    Received = 'R',      // bytes from the robot
    Sent = 'T',          // bytes to the robot
    StreamStarted = 'S', // JSON: {"profile": "create2", "baud": 115200, "packets": [..]}
    Marker = 'M',        // JSON: one MarkerEdit (version 2)
    TruePose = 'P',      // x and y in mm, heading in rad: three little-endian doubles (version 3)
};

// A record's CRC: qChecksum's (CRC-16 of ISO 3309), a byte at a time
// rather than Qt's half-byte steps, as an hour's recording is checked
// whole when it is opened.
quint16 checksum(QByteArrayView bytes);
} // namespace recording

// Appends records to a recording file as they happen. Not QSaveFile: a
// recording must survive a crash, so the file is written in place and
// flushed at least once a second (by the caller's timer or by append()).
class RecordingWriter {
public:
    RecordingWriter() = default;
    ~RecordingWriter();
    RecordingWriter(const RecordingWriter &) = delete;
    RecordingWriter &operator=(const RecordingWriter &) = delete;

    // Creates (or replaces) the file and writes the header. `header` gains
    // "format", "version" and "started". False with errorString() on failure.
    bool open(const QString &path, QJsonObject header);
    bool isOpen() const { return m_file.isOpen(); }
    // Time runs from open(). Payloads longer than 64 KiB are split.
    bool append(recording::RecordKind kind, const QByteArray &bytes);
    bool appendStreamStarted(oi::ProfileId profile, int baud, const QList<int> &packets);
    bool appendMarkerEdit(const MarkerEdit &edit);
    // Where a virtual robot truly is now, in its room (the map's coordinates).
    bool appendTruePose(const oi::Pose &pose);
    // Pushes what is buffered to the operating system.
    bool flush();
    void close();
    QString errorString() const { return m_error; }
    QString path() const { return m_file.fileName(); }
    qint64 bytesWritten() const { return m_written; }

private:
    bool fail(const QString &what);

    QFile m_file;
    QElapsedTimer m_clock;
    qint64 m_startedUs = 0; // the microseconds `started` leaves out
    qint64 m_lastFlushMs = 0;
    qint64 m_written = 0;
    QString m_error;
};

// Where a damaged recording stops being readable.
struct RecordingDamage {
    qint64 byteOffset = 0; // in the file
    int recordIndex = 0;   // the first unreadable record, counting from 0
    qint64 timeUs = 0;     // time of the last good record
    QString reason;        // "checksum mismatch", "truncated record", ...
    QString describe() const;
};

// A recording read into memory, with an index of its stream frames. A damaged
// file loads up to the damage, which damage() reports.
class Recording {
public:
    struct Chunk {
        qint64 timeUs = 0;
        qsizetype end = 0; // received bytes [previous end, end)
    };
    struct Frame {
        qint64 timeUs = 0; // of the chunk holding the frame's last byte
        qsizetype end = 0; // offset in receivedBytes() just after the frame
    };
    // Where a virtual robot truly was (a `P` record); travelledMm is unused.
    struct TruePose {
        qint64 timeUs = 0;
        oi::Pose pose;
    };
    struct StreamInfo {
        const oi::RobotProfile *profile = nullptr;
        int baud = 0;
        QList<int> packets;
    };

    // nullopt with `error` set when the file cannot be used at all: missing,
    // not a recording, a newer version, or no stream in it.
    static std::optional<Recording> load(const QString &path, QString *error);
    // The same from the file's bytes; `path` only names the file in `error`.
    static std::optional<Recording> fromBytes(const QByteArray &data, const QString &path, QString *error);
    // What the stream is, read from the file's start alone (a replay is
    // set up with it; the replay then loads the whole file once). The same
    // errors as load() up to the stream's description.
    static std::optional<StreamInfo> readStream(const QString &path, QString *error);

    const QJsonObject &header() const { return m_header; }
    const StreamInfo &stream() const { return m_stream; }
    const oi::RobotProfile &robotProfile() const { return *m_stream.profile; }
    const QByteArray &receivedBytes() const { return m_received; }
    const std::vector<Chunk> &chunks() const { return m_chunks; }
    const std::vector<Frame> &frames() const { return m_frames; }
    // The bytes sent to the robot, and where each write ended, as chunks() does.
    const QByteArray &sentBytes() const { return m_sent; }
    const std::vector<Chunk> &sentChunks() const { return m_sentChunks; }
    qint64 durationUs() const { return m_durationUs; }
    qint64 bytesSent() const { return m_sent.size(); }
    int recordCount() const { return m_records; }
    const std::optional<RecordingDamage> &damage() const { return m_damage; }
    // The markers after every edit the file holds, in time order: the first
    // kMaxMarkers added; markersLeftOut() counts those added beyond them.
    const QList<RecordingMarker> &markers() const { return m_markers; }
    int markersLeftOut() const { return m_markersLeftOut; }
    // The virtual robot's true poses, in file order; empty for a real robot.
    const std::vector<TruePose> &truePoses() const { return m_truePoses; }

    // Adds `edits` to the recording at `path` (a replay's markers changing):
    // the whole file is written again through a QSaveFile, with the edits
    // as `M` records where reading stops (the end, or before a damaged
    // tail, which is kept). An older version becomes the current one. False with
    // `error` set when the file cannot be read or written; it is unchanged then.
    static bool saveMarkerEdits(const QString &path, const QList<MarkerEdit> &edits, QString *error);

    // Decodes every stream frame in order, as the link would.
    void forEachSnapshot(const std::function<void(qint64 timeUs, const oi::SensorSnapshot &)> &visit) const;
    // The single packets the stream carries, its groups opened up, in order.
    std::vector<const oi::PacketInfo *> streamedPackets() const;
    // The firmware, when a Reset recorded with the stream printed its banner.
    std::optional<oi::FirmwareInfo> firmware() const;
    // One row per frame, in the form every sensor CSV has (SensorCsv): time_s,
    // then one column per packet of the stream, and with markers `marker`.
    // Bit fields and signed values are written as the decoded numbers; the
    // angle corrected when the recording holds the firmware's banner.
    void writeCsv(QTextStream &out) const;

private:
    // How far parse() reads: to the stream's description, every record, or
    // every record and the frames' index.
    enum class Depth { Stream, Records, Frames };
    static std::optional<Recording> parse(const QByteArray &data, const QString &path, QString *error, Depth depth);
    void indexFrames();

    QJsonObject m_header;
    StreamInfo m_stream;
    QByteArray m_received;
    std::vector<Chunk> m_chunks;
    std::vector<Frame> m_frames;
    QByteArray m_sent;
    std::vector<Chunk> m_sentChunks;
    qint64 m_durationUs = 0;
    int m_records = 0;
    std::optional<RecordingDamage> m_damage;
    qsizetype m_readableEnd = 0; // in the file: where reading stopped
    QList<RecordingMarker> m_markers;
    int m_markersLeftOut = 0;
    std::vector<TruePose> m_truePoses;
};

} // namespace oilink
