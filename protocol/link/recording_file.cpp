// SPDX-License-Identifier: GPL-3.0-or-later
#include "recording_file.h"

#include "bounded_file.h"
#include "firmware_banner.h"
#include "sensor_csv.h"
#include "stream_packets.h"
#include "stream_parser.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QSaveFile>
#include <QtEndian>

#include <chrono>

#include <algorithm>
#include <array>
#include <cstring>
#include <span>

namespace oilink {

namespace {
constexpr int kVersionSize = 2;
constexpr int kHeaderLengthSize = 4;
constexpr int kMaxHeaderBytes = 1 << 20;
// kind (1) + time in microseconds (8) + length (2), then the payload, then CRC (2).
constexpr int kRecordHeadSize = 11;
constexpr int kCrcSize = 2;
constexpr int kTruePoseSize = 3 * 8; // x, y, heading as doubles

template <typename T>
void appendLittleEndian(QByteArray &out, T value)
{
    char bytes[sizeof(T)];
    qToLittleEndian(value, bytes);
    out.append(bytes, sizeof(T));
}

template <typename T>
T readLittleEndian(const char *at)
{
    return qFromLittleEndian<T>(at);
}

std::span<const std::uint8_t> asSpan(const QByteArray &bytes, qsizetype from, qsizetype to)
{
    return {reinterpret_cast<const std::uint8_t *>(bytes.constData()) + from, static_cast<std::size_t>(to - from)};
}

QString fromStd(std::string_view text)
{
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

// One record: kind, time, length, payload (at most kMaxPayload bytes), CRC.
QByteArray makeRecord(recording::RecordKind kind, qint64 timeUs, const QByteArray &payload)
{
    QByteArray record;
    record.reserve(kRecordHeadSize + payload.size() + kCrcSize);
    record.append(static_cast<char>(kind));
    appendLittleEndian<qint64>(record, timeUs);
    appendLittleEndian<quint16>(record, static_cast<quint16>(payload.size()));
    record += payload;
    appendLittleEndian<quint16>(record, recording::checksum(record));
    return record;
}

// Why a recorded stream is not one the robot sends, or empty: the Stream
// command refuses it (more packets than the profile streams, a frame too
// long for the baud), or it names a packet twice, alone or in a group.
// Read as it was, group 100 named 2,000 times made each CSV row 100,000
// cells: 2.6 GB from a 1.2 MB file.
QString streamProblem(const oi::RobotProfile &profile, int baud, const QList<int> &packets)
{
    const oi::EncodeResult command = streamCommand(profile, std::vector<int>(packets.begin(), packets.end()), baud);
    if (!command.ok())
        return fromStd(command.error().describe());
    std::array<bool, oi::kMaxPacketId + 1> seen{};
    for (const int id : packets) {
        const oi::PacketGroup *group = profile.group(id);
        for (int member = group ? group->first : id; member <= (group ? group->last : id); ++member) {
            if (!profile.packet(member))
                continue;
            if (seen[std::size_t(member)])
                return QCoreApplication::translate("Recording", "packet %1 is in it twice").arg(member);
            seen[std::size_t(member)] = true;
        }
    }
    return {};
}
// CRC-16 of ISO 3309 (reflected 0x1021, starts at 0xFFFF, inverted at the
// end) for each value of a byte.
constexpr std::array<quint16, 256> kCrcTable = [] {
    std::array<quint16, 256> table{};
    for (unsigned byte = 0; byte < 256; ++byte) {
        unsigned crc = byte;
        for (int bit = 0; bit < 8; ++bit)
            crc = (crc & 1) ? (crc >> 1) ^ 0x8408 : crc >> 1;
        table[byte] = static_cast<quint16>(crc);
    }
    return table;
}();
} // namespace

quint16 recording::checksum(QByteArrayView bytes)
{
    unsigned crc = 0xFFFF;
    for (const char c : bytes)
        crc = (crc >> 8) ^ kCrcTable[(crc ^ static_cast<quint8>(c)) & 0xFF];
    return static_cast<quint16>(~crc);
}

// --- Writing ---

RecordingWriter::~RecordingWriter()
{
    close();
}

bool RecordingWriter::fail(const QString &what)
{
    m_error = QStringLiteral("%1: %2: %3").arg(m_file.fileName(), what, m_file.errorString());
    m_file.close();
    return false;
}

bool RecordingWriter::open(const QString &path, QJsonObject header)
{
    close();
    m_error.clear();
    m_written = 0;
    m_file.setFileName(path);
    if (!m_file.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return fail(QCoreApplication::translate("Recording", "cannot create the recording"));
    header.insert(QStringLiteral("format"), QStringLiteral("Roomba Dashboard recording"));
    header.insert(QStringLiteral("version"), recording::kVersion);
    // The header keeps whole milliseconds; record times count from that
    // written instant, so `started` plus a record's time is exact to the
    // microsecond (a stop 0.5 ms after an event is not read as before it).
    const qint64 nowUs = std::chrono::duration_cast<std::chrono::microseconds>(
                             std::chrono::system_clock::now().time_since_epoch())
                             .count();
    m_clock.start();
    m_startedUs = nowUs % 1000;
    header.insert(QStringLiteral("started"),
                  QDateTime::fromMSecsSinceEpoch(nowUs / 1000, Qt::UTC).toString(Qt::ISODateWithMs));
    const QByteArray json = QJsonDocument(header).toJson(QJsonDocument::Compact);
    QByteArray head(recording::kMagic, recording::kMagicSize);
    appendLittleEndian<quint16>(head, recording::kVersion);
    appendLittleEndian<quint32>(head, static_cast<quint32>(json.size()));
    head += json;
    if (m_file.write(head) != head.size())
        return fail(QCoreApplication::translate("Recording", "cannot write"));
    m_written = head.size();
    m_lastFlushMs = 0;
    return flush();
}

bool RecordingWriter::append(recording::RecordKind kind, const QByteArray &bytes)
{
    if (!m_file.isOpen())
        return false;
    const qint64 timeUs = m_startedUs + m_clock.nsecsElapsed() / 1000;
    for (qsizetype from = 0; from < bytes.size() || (from == 0 && bytes.isEmpty()); from += recording::kMaxPayload) {
        const QByteArray record = makeRecord(kind, timeUs, bytes.mid(from, recording::kMaxPayload));
        if (m_file.write(record) != record.size())
            return fail(QCoreApplication::translate("Recording", "cannot write"));
        m_written += record.size();
        if (bytes.isEmpty())
            break;
    }
    // The caller's timer flushes a quiet line; a busy one flushes here.
    if (m_clock.elapsed() - m_lastFlushMs >= recording::kFlushIntervalMs)
        return flush();
    return true;
}

bool RecordingWriter::appendStreamStarted(oi::ProfileId profile, int baud, const QList<int> &packets)
{
    QJsonArray ids;
    for (int id : packets)
        ids.append(id);
    const QJsonObject info{{QStringLiteral("profile"), fromStd(oi::profile(profile).key)},
                           {QStringLiteral("baud"), baud},
                           {QStringLiteral("packets"), ids}};
    return append(recording::RecordKind::StreamStarted, QJsonDocument(info).toJson(QJsonDocument::Compact));
}

bool RecordingWriter::appendMarkerEdit(const MarkerEdit &edit)
{
    return append(recording::RecordKind::Marker, edit.toJson());
}

bool RecordingWriter::appendTruePose(const oi::Pose &pose)
{
    QByteArray payload;
    payload.reserve(kTruePoseSize);
    appendLittleEndian<double>(payload, pose.xMm);
    appendLittleEndian<double>(payload, pose.yMm);
    appendLittleEndian<double>(payload, pose.thetaRad);
    return append(recording::RecordKind::TruePose, payload);
}

bool RecordingWriter::flush()
{
    if (!m_file.isOpen())
        return false;
    m_lastFlushMs = m_clock.elapsed();
    if (!m_file.flush())
        return fail(QCoreApplication::translate("Recording", "cannot write"));
    return true;
}

void RecordingWriter::close()
{
    if (m_file.isOpen()) {
        m_file.flush();
        m_file.close();
    }
}

// --- Reading ---

QString RecordingDamage::describe() const
{
    return QCoreApplication::translate("Recording", "%1 at byte %2 (record %3, after %4 s)")
        .arg(reason)
        .arg(byteOffset)
        .arg(recordIndex)
        .arg(static_cast<double>(timeUs) / 1e6, 0, 'f', 3);
}

std::optional<Recording> Recording::load(const QString &path, QString *error)
{
    QString why;
    const std::optional<QByteArray> data = files::readBounded(path, recording::kMaxFileBytes, &why);
    if (!data) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, why);
        return std::nullopt;
    }
    return fromBytes(*data, path, error);
}

std::optional<Recording::StreamInfo> Recording::readStream(const QString &path, QString *error)
{
    QFile file;
    QString why;
    if (!files::openBounded(file, path, recording::kMaxFileBytes, &why)) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, why);
        return std::nullopt;
    }
    // The description is the first record or nearly: a small start of the
    // file holds it; the whole file only when it does not.
    constexpr qint64 kStart = 64 * 1024;
    QByteArray data = file.read(kStart);
    std::optional<Recording> r = parse(data, path, error, Depth::Stream);
    if (!r && !file.atEnd()) {
        data += file.read(recording::kMaxFileBytes - data.size());
        r = parse(data, path, error, Depth::Stream);
    }
    if (!r)
        return std::nullopt;
    return r->m_stream;
}

std::optional<Recording> Recording::fromBytes(const QByteArray &data, const QString &path, QString *error)
{
    return parse(data, path, error, Depth::Frames);
}

std::optional<Recording> Recording::parse(const QByteArray &data, const QString &path, QString *error, Depth depth)
{
    auto refuse = [&](const QString &why) -> std::optional<Recording> {
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, why);
        return std::nullopt;
    };
    const qsizetype prefix = recording::kMagicSize + kVersionSize + kHeaderLengthSize;
    if (data.size() < prefix || !data.startsWith(QByteArray(recording::kMagic, recording::kMagicSize)))
        return refuse(QCoreApplication::translate("Recording", "not a Roomba Dashboard recording"));
    const auto version = readLittleEndian<quint16>(data.constData() + recording::kMagicSize);
    if (version < recording::kOldestVersion || version > recording::kVersion)
        return refuse(QCoreApplication::translate("Recording", "recording format version %1; this program reads versions %2 to %3")
                          .arg(version)
                          .arg(recording::kOldestVersion)
                          .arg(recording::kVersion));
    const auto headerBytes = readLittleEndian<quint32>(data.constData() + recording::kMagicSize + kVersionSize);
    if (headerBytes > kMaxHeaderBytes || prefix + static_cast<qsizetype>(headerBytes) > data.size())
        return refuse(QCoreApplication::translate("Recording", "the header is truncated"));
    QJsonParseError jsonError;
    const QJsonDocument header = QJsonDocument::fromJson(data.mid(prefix, headerBytes), &jsonError);
    if (!header.isObject())
        return refuse(QCoreApplication::translate("Recording", "the header is not valid JSON: %1").arg(jsonError.errorString()));

    Recording r;
    r.m_header = header.object();
    qsizetype at = prefix + headerBytes;
    qint64 lastTimeUs = 0;
    auto damaged = [&](const QString &reason) {
        r.m_damage = RecordingDamage{at, r.m_records, lastTimeUs, reason};
    };
    while (at < data.size()) {
        if (data.size() - at < kRecordHeadSize + kCrcSize) {
            damaged(QCoreApplication::translate("Recording", "truncated record"));
            break;
        }
        const char *head = data.constData() + at;
        const auto kind = static_cast<recording::RecordKind>(static_cast<quint8>(head[0]));
        const auto timeUs = readLittleEndian<qint64>(head + 1);
        const auto length = readLittleEndian<quint16>(head + 9);
        if (data.size() - at < kRecordHeadSize + length + kCrcSize) {
            damaged(QCoreApplication::translate("Recording", "truncated record"));
            break;
        }
        const QByteArrayView covered(head, kRecordHeadSize + length);
        if (readLittleEndian<quint16>(head + kRecordHeadSize + length) != recording::checksum(covered)) {
            damaged(QCoreApplication::translate("Recording", "checksum mismatch"));
            break;
        }
        if (timeUs < lastTimeUs) {
            damaged(QCoreApplication::translate("Recording", "time runs backwards"));
            break;
        }
        const char *payload = head + kRecordHeadSize;
        switch (kind) {
        case recording::RecordKind::Received:
            if (r.m_received.isEmpty())
                r.m_received.reserve(data.size() - at); // the bytes cannot outgrow the file
            r.m_received.append(payload, length);
            r.m_chunks.push_back({timeUs, r.m_received.size()});
            break;
        case recording::RecordKind::Sent:
            r.m_sent.append(payload, length);
            r.m_sentChunks.push_back({timeUs, r.m_sent.size()});
            break;
        case recording::RecordKind::StreamStarted: {
            if (r.m_stream.profile)
                break; // the first stream decides how the whole file is read
            const QJsonObject info = QJsonDocument::fromJson(QByteArray(payload, length)).object();
            const std::string key = info.value(QStringLiteral("profile")).toString().toStdString();
            r.m_stream.profile = oi::profileByKey(key);
            r.m_stream.baud = info.value(QStringLiteral("baud")).toInt();
            bool packetsKnown = r.m_stream.profile != nullptr;
            for (const QJsonValue id : info.value(QStringLiteral("packets")).toArray()) {
                // Ids go to the parser as bytes: 300 must not be read as 44.
                const int packet = id.toInt(-1);
                r.m_stream.packets << packet;
                packetsKnown = packetsKnown && r.m_stream.profile->isValidSensorId(packet);
            }
            const QString problem = packetsKnown && !r.m_stream.packets.isEmpty()
                                        ? streamProblem(*r.m_stream.profile, r.m_stream.baud, r.m_stream.packets)
                                        : QString();
            if (!packetsKnown || r.m_stream.packets.isEmpty())
                damaged(QCoreApplication::translate("Recording", "unreadable stream description"));
            else if (!problem.isEmpty())
                damaged(QCoreApplication::translate("Recording", "a stream no robot sends (%1)").arg(problem));
            if (r.m_damage)
                r.m_stream = {};
            break;
        }
        case recording::RecordKind::Marker: {
            const std::optional<MarkerEdit> edit = MarkerEdit::fromJson(QByteArray(payload, length));
            if (!edit) {
                damaged(QCoreApplication::translate("Recording", "unreadable marker"));
                break;
            }
            if (edit->kind == MarkerEdit::Kind::Add && r.m_markers.size() >= kMaxMarkers)
                ++r.m_markersLeftOut;
            applyMarkerEdit(r.m_markers, *edit); // an edit of a marker that is gone changes nothing
            break;
        }
        case recording::RecordKind::TruePose:
            if (length != kTruePoseSize) {
                damaged(QCoreApplication::translate("Recording", "unreadable true pose"));
                break;
            }
            r.m_truePoses.push_back({timeUs,
                                     {readLittleEndian<double>(payload), readLittleEndian<double>(payload + 8),
                                      readLittleEndian<double>(payload + 16)}});
            break;
        default:
            damaged(QCoreApplication::translate("Recording", "unknown record type 0x%1").arg(static_cast<quint8>(head[0]), 2, 16, QLatin1Char('0')));
            break;
        }
        if (r.m_damage || (depth == Depth::Stream && r.m_stream.profile))
            break;
        lastTimeUs = timeUs;
        at += kRecordHeadSize + length + kCrcSize;
        ++r.m_records;
    }
    r.m_durationUs = lastTimeUs;
    r.m_readableEnd = at;
    if (!r.m_stream.profile) {
        if (r.m_damage)
            return refuse(QCoreApplication::translate("Recording", "damaged before the stream started: %1").arg(r.m_damage->describe()));
        return refuse(QCoreApplication::translate("Recording", "the recording holds no sensor stream"));
    }
    if (depth == Depth::Frames)
        r.indexFrames();
    return r;
}

bool Recording::saveMarkerEdits(const QString &path, const QList<MarkerEdit> &edits, QString *error)
{
    QFile file;
    QString why;
    if (!files::openBounded(file, path, recording::kMaxFileBytes, &why, QIODevice::ReadWrite)) {
        if (error)
            *error = QStringLiteral("%1: %2").arg(path, why);
        return false;
    }
    // Mapped, not copied: the records are checked where they lie.
    const qint64 size = file.size();
    const uchar *mapped = size > 0 ? file.map(0, size) : nullptr;
    const QByteArray data = mapped ? QByteArray::fromRawData(reinterpret_cast<const char *>(mapped), size)
                                   : file.readAll();
    const std::optional<Recording> r = parse(data, path, error, Depth::Records);
    if (!r)
        return false;
    // At the last readable time, so that times never go back.
    QByteArray records;
    for (const MarkerEdit &edit : edits)
        records += makeRecord(recording::RecordKind::Marker, r->m_durationUs, edit.toJson());
    // An intact file of this version: the markers go on its end, and the
    // hour before them is not written again.
    if (r->m_readableEnd == data.size()
        && readLittleEndian<quint16>(data.constData() + recording::kMagicSize) == recording::kVersion) {
        const bool appended = file.seek(size) && file.write(records) == records.size() && file.flush();
        if (!appended && error)
            *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return appended;
    }
    // A damaged tail is kept after the markers, where they are read; an
    // older version says it holds markers now.
    QByteArray head = data.left(r->m_readableEnd);
    qToLittleEndian<quint16>(recording::kVersion, head.data() + recording::kMagicSize);
    QSaveFile out(path);
    const bool written = out.open(QIODevice::WriteOnly) && out.write(head) == head.size()
                         && out.write(records) == records.size()
                         && out.write(data.mid(r->m_readableEnd)) == data.size() - r->m_readableEnd && out.commit();
    if (!written && error)
        *error = QStringLiteral("%1: %2").arg(path, out.errorString());
    return written;
}

// Feeds the parser chunk by chunk; the parser says where in the bytes each
// frame ends, exactly, and seeking and stepping land on these ends.
void Recording::indexFrames()
{
    oi::StreamParser parser(*m_stream.profile);
    const std::vector<std::uint8_t> ids(m_stream.packets.begin(), m_stream.packets.end());
    parser.setExpectedStream(ids);
    parser.setFramesOnly(true); // the values are decoded where a frame is shown
    std::size_t chunk = 0;
    parser.setSnapshotHandler([&](const oi::SensorSnapshot &, oi::FrameKind kind) {
        if (kind == oi::FrameKind::Stream)
            m_frames.push_back({m_chunks[chunk].timeUs, static_cast<qsizetype>(parser.frameEndOffset())});
    });
    qsizetype from = 0;
    for (; chunk < m_chunks.size(); ++chunk) {
        parser.feed(asSpan(m_received, from, m_chunks[chunk].end));
        from = m_chunks[chunk].end;
    }
}

void Recording::forEachSnapshot(const std::function<void(qint64, const oi::SensorSnapshot &)> &visit) const
{
    oi::StreamParser parser(*m_stream.profile);
    const std::vector<std::uint8_t> ids(m_stream.packets.begin(), m_stream.packets.end());
    parser.setExpectedStream(ids);
    std::size_t frame = 0;
    parser.setSnapshotHandler([&](const oi::SensorSnapshot &snapshot, oi::FrameKind kind) {
        if (kind == oi::FrameKind::Stream && frame < m_frames.size())
            visit(m_frames[frame++].timeUs, snapshot);
    });
    // Frame by frame, so that the times line up with the index.
    qsizetype from = 0;
    for (const Frame &f : m_frames) {
        parser.feed(asSpan(m_received, from, f.end));
        from = f.end;
    }
}

std::vector<const oi::PacketInfo *> Recording::streamedPackets() const
{
    std::vector<const oi::PacketInfo *> packets;
    for (int id : m_stream.packets) {
        const oi::PacketInfo *info = m_stream.profile->packet(id);
        if (info) {
            packets.push_back(info);
            continue;
        }
        // A group: its member packets, in order.
        if (const oi::PacketGroup *g = m_stream.profile->group(id))
            for (int member = g->first; member <= g->last; ++member)
                if (const oi::PacketInfo *m = m_stream.profile->packet(member))
                    packets.push_back(m);
    }
    return packets;
}

std::optional<oi::FirmwareInfo> Recording::firmware() const
{
    return oi::parseFirmwareBanner(std::string_view(m_received.constData(), std::size_t(m_received.size())));
}

void Recording::writeCsv(QTextStream &out) const
{
    // The markers in the last column, each on the first frame at or after it.
    QList<SensorCsv::Mark> marks;
    for (const RecordingMarker &m : m_markers)
        marks << SensorCsv::Mark{static_cast<double>(m.timeUs) / 1e6, m.label()};
    // The bytes the document reserves are always 0: no column for them.
    std::vector<const oi::PacketInfo *> columns = streamedPackets();
    std::erase_if(columns, [](const oi::PacketInfo *info) { return info->isUnused(); });
    SensorCsv csv(std::move(columns), marks);
    QByteArray buffer;
    csv.appendHeader(buffer);
    std::vector<std::optional<std::int32_t>> cells(csv.columns().size());
    // A Reset recorded with the stream names the firmware; what it reports
    // wrongly is corrected in every frame, as the dashboard shows it (ERRATA 16).
    const auto firmware = this->firmware();
    forEachSnapshot([&](qint64 timeUs, const oi::SensorSnapshot &frame) {
        oi::SensorSnapshot s = frame;
        if (firmware)
            firmware->corrections.correct(s);
        for (std::size_t i = 0; i < cells.size(); ++i)
            cells[i] = s.has(csv.columns()[i]->id) ? std::optional(s.raw(csv.columns()[i]->id)) : std::nullopt;
        csv.appendRow(buffer, static_cast<double>(timeUs) / 1e6, cells);
        // Out in pieces: an hour of frames is tens of megabytes.
        if (buffer.size() >= 64 * 1024) {
            out << QString::fromUtf8(buffer);
            buffer.clear();
        }
    });
    csv.finish(buffer);
    out << QString::fromUtf8(buffer);
}

} // namespace oilink
