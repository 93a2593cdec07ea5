// SPDX-License-Identifier: GPL-3.0-or-later
#include "recording_mcap.h"

#include "foxglove_messages.h"
#include "odometry.h"
#include "snapshot_json.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>

namespace oilink {

namespace {

using namespace foxglove;

constexpr char kBytesSchema[] = R"({"title":"roomba.Bytes","type":"object","properties":)"
                                R"({"data":{"type":"string","contentEncoding":"base64"}}})";

QMap<QString, QString> recordingMetadata(const Recording &recording)
{
    const oi::RobotProfile &profile = recording.robotProfile();
    QStringList packets;
    for (int id : recording.stream().packets)
        packets << QString::number(id);
    QMap<QString, QString> m = profileMetadata(profile);
    m.insert("baud", QString::number(recording.stream().baud));
    m.insert("packets", packets.join(','));
    for (const char *key : {"started", "program", "link"}) {
        const QJsonValue v = recording.header().value(QLatin1String(key));
        if (v.isString())
            m.insert(QLatin1String(key), v.toString());
    }
    if (recording.damage())
        m.insert("damage", recording.damage()->describe());
    return m;
}

// Everything the recording holds, channel by channel, in time order.
class Exporter {
public:
    Exporter(const Recording &recording, mcap::Writer &writer) : m_recording(recording), m_writer(writer)
    {
        const QDateTime started =
            QDateTime::fromString(recording.header().value("started").toString(), Qt::ISODateWithMs);
        m_startNs = started.isValid() ? quint64(started.toMSecsSinceEpoch()) * 1000000 : 0;
    }

    bool run()
    {
        const oi::RobotProfile &profile = m_recording.robotProfile();
        const QString title = telemetryTitle(profile);
        const QString json = QStringLiteral("json");
        const QString jsonSchema = QStringLiteral("jsonschema");
        const QMap<QString, QString> robot{{"robot", profileMetadata(profile).value("robot")}};
        m_telemetry = m_writer.addChannel(
            m_writer.addSchema(title, jsonSchema, telemetrySchema(profile, m_recording.streamedPackets(), title)),
            m_topics.telemetry, json, robot);
        const quint16 poseInFrame = m_writer.addSchema("foxglove.PoseInFrame", jsonSchema, poseInFrameSchema());
        m_pose = m_writer.addChannel(poseInFrame, m_topics.pose, json);
        const std::vector<Recording::TruePose> &truePoses = m_recording.truePoses();
        m_truePose = truePoses.empty() ? 0 : m_writer.addChannel(poseInFrame, m_topics.truePose, json);
        const quint16 frameTransform = m_writer.addSchema("foxglove.FrameTransform", jsonSchema, frameTransformSchema());
        m_transform = m_writer.addChannel(frameTransform, m_topics.transform, json);
        m_roomTransform = truePoses.empty() ? 0 : m_writer.addChannel(frameTransform, m_topics.roomTransform, json);
        const quint16 bytes = m_writer.addSchema("roomba.Bytes", jsonSchema, kBytesSchema);
        m_received = m_writer.addChannel(bytes, m_topics.bytesReceived, json);
        m_sent = m_writer.addChannel(bytes, m_topics.bytesSent, json);
        const quint16 log = m_writer.addSchema("foxglove.Log", jsonSchema, logSchema());
        m_events = m_writer.addChannel(log, m_topics.events, json);
        const QList<RecordingMarker> &marks = m_recording.markers();
        // Always there, with no message when the recording has no marker: a
        // layout's markers panel shows an empty log, not a missing topic.
        const quint16 markers = m_writer.addChannel(log, m_topics.markers, json);

        if (!m_writer.writeMetadata("recording", recordingMetadata(m_recording)))
            return false;
        const std::optional<oi::FirmwareInfo> firmware = m_recording.firmware();
        if (firmware) {
            if (!m_writer.writeMetadata("firmware", firmwareMetadata(*firmware)))
                return false;
        }

        oi::Odometry odometry;
        if (firmware)
            odometry.setCorrections(firmware->corrections);
        // The pose, its transform and the events are made once for each time
        // the recording holds, from the last frame read at it (frames read
        // together share the read's time); the pose only from frames that
        // measure motion (and the first), as a frame of a bumper alone cannot
        // move it; the events of one time as one log line. Each frame still
        // has its telemetry. Written for every frame, the pose and transform
        // took 430 bytes for a 5-byte frame, each event 180.
        struct Derived {
            qint64 timeUs = 0;
            oi::SensorSnapshot shown;
            bool moved = false;
        };
        std::optional<Derived> pending;
        std::optional<oi::SensorSnapshot> before;
        bool posed = false;
        const auto writeDerived = [&] {
            if (!pending)
                return true;
            const quint64 ns = timeNs(pending->timeUs);
            bool written = !(pending->moved || !posed) || writePose(ns, odometry.pose());
            posed = true;
            QStringList events;
            int level = Info;
            logEvents(before ? &*before : nullptr, pending->shown, [&](int eventLevel, const QString &message) {
                events << message;
                level = std::max(level, eventLevel);
            });
            if (!events.isEmpty())
                written = written && m_writer.writeMessage(m_events, ns,
                                                           logJson(ns, level, events.join(QStringLiteral("; ")), m_topics.robot));
            before = std::move(pending->shown);
            pending.reset();
            return written;
        };
        qsizetype marker = 0;
        std::size_t truePose = 0;
        bool ok = true;
        m_recording.forEachSnapshot([&](qint64 timeUs, const oi::SensorSnapshot &frame) {
            if (!ok)
                return;
            if (pending && pending->timeUs != timeUs)
                ok = writeDerived();
            ok = ok && writeBytesUpTo(timeUs);
            for (; ok && marker < marks.size() && marks[marker].timeUs <= timeUs; ++marker)
                ok = writeMarker(markers, marks[marker]);
            for (; ok && truePose < truePoses.size() && truePoses[truePose].timeUs <= timeUs; ++truePose)
                ok = writeTruePose(truePoses[truePose], odometry.pose());
            const quint64 ns = timeNs(timeUs);
            // As the CSV and the dashboard show it: corrected for the firmware.
            oi::SensorSnapshot shown = frame;
            if (firmware)
                firmware->corrections.correct(shown);
            odometry.update(frame);
            ok = ok && m_writer.writeMessage(m_telemetry, ns, snapshotToJsonText(shown));
            const bool moved = frame.hasEncoders() || frame.has(19) || frame.has(20);
            pending = Derived{timeUs, std::move(shown), moved || (pending && pending->moved)};
        });
        ok = ok && writeDerived() && writeBytesUpTo(std::numeric_limits<qint64>::max());
        for (; ok && marker < marks.size(); ++marker)
            ok = writeMarker(markers, marks[marker]);
        for (; ok && truePose < truePoses.size(); ++truePose)
            ok = writeTruePose(truePoses[truePose], odometry.pose());
        return ok;
    }

private:
    quint64 timeNs(qint64 timeUs) const { return m_startNs + quint64(std::max<qint64>(timeUs, 0)) * 1000; }

    bool writeMarker(quint16 channel, const RecordingMarker &m)
    {
        const quint64 ns = timeNs(m.timeUs);
        return m_writer.writeMessage(channel, ns, logJson(ns, Info, m.label(), "marker"));
    }

    // Each read and each write on the line as one message, in time order, up to `timeUs`.
    bool writeBytesUpTo(qint64 timeUs)
    {
        const std::vector<Recording::Chunk> &sent = m_recording.sentChunks();
        const std::vector<Recording::Chunk> &received = m_recording.chunks();
        const auto write = [&](quint16 channel, const QByteArray &bytes, const std::vector<Recording::Chunk> &chunks,
                               std::size_t &next) {
            const qsizetype from = next ? chunks[next - 1].end : 0;
            const QByteArray data = bytes.mid(from, chunks[next].end - from).toBase64();
            return m_writer.writeMessage(channel, timeNs(chunks[next++].timeUs), "{\"data\":\"" + data + "\"}");
        };
        for (;;) {
            const bool sentDue = m_nextSent < sent.size() && sent[m_nextSent].timeUs <= timeUs;
            const bool receivedDue = m_nextReceived < received.size() && received[m_nextReceived].timeUs <= timeUs;
            if (!sentDue && !receivedDue)
                return true;
            const bool ok = sentDue && (!receivedDue || sent[m_nextSent].timeUs <= received[m_nextReceived].timeUs)
                                ? write(m_sent, m_recording.sentBytes(), sent, m_nextSent)
                                : write(m_received, m_recording.receivedBytes(), received, m_nextReceived);
            if (!ok)
                return false;
        }
    }

    // Where the virtual robot truly was, in the room's frame. With the first,
    // where the odometry's frame lies in the room, from the recording's
    // start, so that a 3D view draws both.
    bool writeTruePose(const Recording::TruePose &p, const oi::Pose &odomPose)
    {
        const quint64 ns = timeNs(p.timeUs);
        if (!m_roomPlaced) {
            m_roomPlaced = true;
            const quint64 startNs = timeNs(0);
            if (!m_writer.writeMessage(m_roomTransform, startNs,
                                       frameTransformJson(startNs, kRoomFrame, m_topics.odomFrame,
                                                          odomInRoom(p.pose, odomPose))))
                return false;
        }
        return m_writer.writeMessage(m_truePose, ns, poseInFrameJson(ns, kRoomFrame, p.pose));
    }

    bool writePose(quint64 ns, const oi::Pose &pose)
    {
        return m_writer.writeMessage(m_pose, ns, poseInFrameJson(ns, m_topics.odomFrame, pose)) &&
               m_writer.writeMessage(m_transform, ns,
                                     frameTransformJson(ns, m_topics.odomFrame, m_topics.baseFrame, pose));
    }

    const Recording &m_recording;
    mcap::Writer &m_writer;
    const RobotTopics m_topics{QString::fromLatin1(kMcapRobot)};
    quint64 m_startNs = 0;
    bool m_roomPlaced = false;
    quint16 m_telemetry = 0, m_pose = 0, m_truePose = 0, m_transform = 0, m_roomTransform = 0, m_received = 0, m_sent = 0, m_events = 0;
    std::size_t m_nextReceived = 0, m_nextSent = 0;
};

} // namespace

QString exportRecordingMcap(const Recording &recording, const QString &path, const McapExportOptions &options,
                            mcap::Statistics *statistics)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return QStringLiteral("%1: %2").arg(path, file.errorString());
    mcap::Writer writer(file, {options.compression, 1024 * 1024, QString(),
                               QStringLiteral("Roomba Dashboard " ROOMBA_VERSION)});
    const bool written = writer.start() && Exporter(recording, writer).run() && writer.finish();
    if (!written) {
        file.cancelWriting();
        return QStringLiteral("%1: %2").arg(path, writer.errorString());
    }
    if (!file.commit())
        return QStringLiteral("%1: %2").arg(path, file.errorString());
    if (statistics)
        *statistics = writer.statistics();
    return QString();
}

QString exportRecordingMcap(const QString &recordingPath, const QString &path, const McapExportOptions &options,
                            std::optional<RecordingDamage> *damage, mcap::Statistics *statistics)
{
    QString error;
    const std::optional<Recording> recording = Recording::load(recordingPath, &error);
    if (!recording)
        return error;
    if (damage)
        *damage = recording->damage();
    return exportRecordingMcap(*recording, path, options, statistics);
}

} // namespace oilink
