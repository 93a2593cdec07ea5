// SPDX-License-Identifier: GPL-3.0-or-later
#include "recording_mcap.h"

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

QString fromStd(std::string_view text)
{
    return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

// foxglove.Log levels.
enum LogLevel { Info = 2, Warning = 3 };

// Foxglove's well-known schemas (https://docs.foxglove.dev/docs/sdk/schemas),
// as JSON Schemas with the fields we fill.
constexpr char kTimeSchema[] = R"({"type":"object","properties":{"sec":{"type":"integer","minimum":0},)"
                               R"("nsec":{"type":"integer","minimum":0,"maximum":999999999}}})";
constexpr char kVector3Schema[] = R"({"type":"object","properties":{"x":{"type":"number"},"y":{"type":"number"},)"
                                  R"("z":{"type":"number"}}})";
constexpr char kQuaternionSchema[] = R"({"type":"object","properties":{"x":{"type":"number"},)"
                                     R"("y":{"type":"number"},"z":{"type":"number"},"w":{"type":"number"}}})";

QByteArray poseInFrameSchema()
{
    return QByteArray(R"({"title":"foxglove.PoseInFrame","type":"object","properties":{"timestamp":)") + kTimeSchema +
           R"(,"frame_id":{"type":"string"},"pose":{"type":"object","properties":{"position":)" + kVector3Schema +
           R"(,"orientation":)" + kQuaternionSchema + "}}}}";
}

QByteArray frameTransformSchema()
{
    return QByteArray(R"({"title":"foxglove.FrameTransform","type":"object","properties":{"timestamp":)") +
           kTimeSchema + R"(,"parent_frame_id":{"type":"string"},"child_frame_id":{"type":"string"},"translation":)" +
           kVector3Schema + R"(,"rotation":)" + kQuaternionSchema + "}}";
}

QByteArray logSchema()
{
    return QByteArray(R"({"title":"foxglove.Log","type":"object","properties":{"timestamp":)") + kTimeSchema +
           R"(,"level":{"type":"integer","enum":[0,1,2,3,4,5]},"message":{"type":"string"},)"
           R"("name":{"type":"string"},"file":{"type":"string"},"line":{"type":"integer","minimum":0}}})";
}

constexpr char kBytesSchema[] = R"({"title":"roomba.Bytes","type":"object","properties":)"
                                R"({"data":{"type":"string","contentEncoding":"base64"}}})";

// One property per packet the stream carries, with its name, unit, range
// and bit meanings, so that a plot panel lists every field.
QByteArray telemetrySchema(const Recording &recording, const QString &title)
{
    const oi::RobotProfile &profile = recording.robotProfile();
    QJsonObject properties;
    for (const oi::PacketInfo *p : recording.streamedPackets()) {
        QString description = QStringLiteral("Packet %1").arg(p->id);
        if (!p->unit.empty())
            description += QStringLiteral(", in %1").arg(fromStd(p->unit));
        QStringList bits;
        for (const oi::BitMeaning &b : profile.bits(p->id))
            bits << QStringLiteral("0x%1 %2").arg(b.mask, 2, 16, QLatin1Char('0')).arg(fromStd(b.name));
        if (!bits.isEmpty())
            description += QStringLiteral("; bits: ") + bits.join(QStringLiteral(", "));
        properties.insert(fromStd(p->key), QJsonObject{{"type", "integer"},
                                                       {"title", fromStd(p->name)},
                                                       {"description", description},
                                                       {"minimum", p->min},
                                                       {"maximum", p->max}});
    }
    return QJsonDocument(QJsonObject{{"title", title}, {"type", "object"}, {"properties", properties}})
        .toJson(QJsonDocument::Compact);
}

QByteArray timeJson(quint64 ns)
{
    return "{\"sec\":" + QByteArray::number(ns / 1000000000) + ",\"nsec\":" + QByteArray::number(ns % 1000000000) +
           '}';
}

QByteArray number(double value)
{
    char text[32];
    const int n = std::snprintf(text, sizeof text, "%.6g", value);
    return QByteArray(text, n);
}

// The pose in metres, turned about z.
QByteArray positionJson(const oi::Pose &pose)
{
    return "{\"x\":" + number(pose.xMm / 1000) + ",\"y\":" + number(pose.yMm / 1000) + ",\"z\":0}";
}

QByteArray orientationJson(const oi::Pose &pose)
{
    return "{\"x\":0,\"y\":0,\"z\":" + number(std::sin(pose.thetaRad / 2)) +
           ",\"w\":" + number(std::cos(pose.thetaRad / 2)) + '}';
}

QByteArray logJson(quint64 ns, int level, const QString &message, const QString &name)
{
    return QJsonDocument(QJsonObject{{"timestamp", QJsonObject{{"sec", qint64(ns / 1000000000)},
                                                               {"nsec", qint64(ns % 1000000000)}}},
                                     {"level", level},
                                     {"message", message},
                                     {"name", name},
                                     {"file", ""},
                                     {"line", 0}})
        .toJson(QJsonDocument::Compact);
}

QString modeName(int mode)
{
    static const char *const names[] = {"Off", "Passive", "Safe", "Full"};
    return mode >= 0 && mode < 4 ? QLatin1String(names[mode]) : QString::number(mode);
}

// What changed between two frames that a reader of the run wants to find:
// bumps, wheel drops, cliffs and the mode. `before` is null for the first frame,
// which logs what is already set.
void logEvents(const oi::SensorSnapshot *before, const oi::SensorSnapshot &now,
               const std::function<void(int level, const QString &)> &log)
{
    const oi::RobotProfile &profile = now.robotProfile();
    const auto was = [&](int id) { return before && before->has(id) ? before->raw(id) : 0; };
    if (now.has(7))
        for (const oi::BitMeaning &b : profile.bits(7))
            if ((now.raw(7) & b.mask) != (was(7) & b.mask))
                log(now.raw(7) & b.mask ? Warning : Info,
                    fromStd(b.name) + (now.raw(7) & b.mask ? QString() : QStringLiteral(" cleared")));
    for (int id = 9; id <= 12; ++id)
        if (now.has(id) && (now.raw(id) != 0) != (was(id) != 0))
            log(now.raw(id) ? Warning : Info,
                fromStd(profile.packet(id)->name) + (now.raw(id) ? QString() : QStringLiteral(" cleared")));
    if (now.has(35) && (!before || !before->has(35)))
        log(Info, QStringLiteral("Mode %1").arg(modeName(now.raw(35))));
    else if (now.has(35) && now.raw(35) != before->raw(35))
        log(Info, QStringLiteral("Mode %1 → %2").arg(modeName(before->raw(35)), modeName(now.raw(35))));
}

QMap<QString, QString> recordingMetadata(const Recording &recording)
{
    const oi::RobotProfile &profile = recording.robotProfile();
    QStringList packets;
    for (int id : recording.stream().packets)
        packets << QString::number(id);
    QMap<QString, QString> m{{"profile", fromStd(profile.key)},
                             {"robot", fromStd(profile.name)},
                             {"baud", QString::number(recording.stream().baud)},
                             {"packets", packets.join(',')}};
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
        const QString telemetryTitle = QStringLiteral("roomba.Telemetry.%1").arg(fromStd(profile.key));
        const QString json = QStringLiteral("json");
        const QString jsonSchema = QStringLiteral("jsonschema");
        const QMap<QString, QString> robot{{"robot", fromStd(profile.name)}};
        m_telemetry = m_writer.addChannel(
            m_writer.addSchema(telemetryTitle, jsonSchema, telemetrySchema(m_recording, telemetryTitle)),
            mcap_topics::kTelemetry, json, robot);
        const quint16 poseInFrame = m_writer.addSchema("foxglove.PoseInFrame", jsonSchema, poseInFrameSchema());
        m_pose = m_writer.addChannel(poseInFrame, mcap_topics::kPose, json);
        const std::vector<Recording::TruePose> &truePoses = m_recording.truePoses();
        m_truePose = truePoses.empty() ? 0 : m_writer.addChannel(poseInFrame, mcap_topics::kTruePose, json);
        m_transform = m_writer.addChannel(
            m_writer.addSchema("foxglove.FrameTransform", jsonSchema, frameTransformSchema()),
            mcap_topics::kTransform, json);
        const quint16 bytes = m_writer.addSchema("roomba.Bytes", jsonSchema, kBytesSchema);
        m_received = m_writer.addChannel(bytes, mcap_topics::kReceived, json);
        m_sent = m_writer.addChannel(bytes, mcap_topics::kSent, json);
        const quint16 log = m_writer.addSchema("foxglove.Log", jsonSchema, logSchema());
        m_events = m_writer.addChannel(log, mcap_topics::kEvents, json);
        const QList<RecordingMarker> &marks = m_recording.markers();
        const quint16 markers = marks.isEmpty() ? 0 : m_writer.addChannel(log, mcap_topics::kMarkers, json);

        if (!m_writer.writeMetadata("recording", recordingMetadata(m_recording)))
            return false;
        const std::optional<oi::FirmwareInfo> firmware = m_recording.firmware();
        if (firmware) {
            const QMap<QString, QString> m{{"release", fromStd(firmware->release)},
                                           {"version", fromStd(firmware->version.toString())},
                                           {"angle_corrected", firmware->corrections.angleDivisor ? "yes" : "no"}};
            if (!m_writer.writeMetadata("firmware", m))
                return false;
        }

        oi::Odometry odometry;
        if (firmware)
            odometry.setCorrections(firmware->corrections);
        std::optional<oi::SensorSnapshot> before;
        qsizetype marker = 0;
        std::size_t truePose = 0;
        bool ok = true;
        m_recording.forEachSnapshot([&](qint64 timeUs, const oi::SensorSnapshot &frame) {
            if (!ok)
                return;
            ok = writeBytesUpTo(timeUs);
            for (; ok && marker < marks.size() && marks[marker].timeUs <= timeUs; ++marker)
                ok = writeMarker(markers, marks[marker]);
            for (; ok && truePose < truePoses.size() && truePoses[truePose].timeUs <= timeUs; ++truePose)
                ok = writeTruePose(truePoses[truePose]);
            const quint64 ns = timeNs(timeUs);
            // As the CSV and the dashboard show it: corrected for the firmware.
            oi::SensorSnapshot shown = frame;
            if (firmware)
                firmware->corrections.correct(shown);
            odometry.update(frame);
            ok = ok && m_writer.writeMessage(m_telemetry, ns, snapshotToJsonText(shown)) && writePose(ns, odometry.pose());
            logEvents(before ? &*before : nullptr, shown, [&](int level, const QString &message) {
                ok = ok && m_writer.writeMessage(m_events, ns, logJson(ns, level, message, "roomba"));
            });
            before = std::move(shown);
        });
        ok = ok && writeBytesUpTo(std::numeric_limits<qint64>::max());
        for (; ok && marker < marks.size(); ++marker)
            ok = writeMarker(markers, marks[marker]);
        for (; ok && truePose < truePoses.size(); ++truePose)
            ok = writeTruePose(truePoses[truePose]);
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

    static QByteArray poseInFrameJson(quint64 ns, const char *frame, const oi::Pose &pose)
    {
        return "{\"timestamp\":" + timeJson(ns) + ",\"frame_id\":\"" + frame + "\",\"pose\":{\"position\":" +
               positionJson(pose) + ",\"orientation\":" + orientationJson(pose) + "}}";
    }

    // Where the virtual robot truly was, in the room's frame.
    bool writeTruePose(const Recording::TruePose &p)
    {
        const quint64 ns = timeNs(p.timeUs);
        return m_writer.writeMessage(m_truePose, ns, poseInFrameJson(ns, "room", p.pose));
    }

    bool writePose(quint64 ns, const oi::Pose &pose)
    {
        const QByteArray stamp = timeJson(ns);
        const QByteArray position = positionJson(pose);
        const QByteArray orientation = orientationJson(pose);
        return m_writer.writeMessage(m_pose, ns, poseInFrameJson(ns, "odom", pose)) &&
               m_writer.writeMessage(m_transform, ns,
                                     "{\"timestamp\":" + stamp +
                                         ",\"parent_frame_id\":\"odom\",\"child_frame_id\":\"base_link\","
                                         "\"translation\":" +
                                         position + ",\"rotation\":" + orientation + '}');
    }

    const Recording &m_recording;
    mcap::Writer &m_writer;
    quint64 m_startNs = 0;
    quint16 m_telemetry = 0, m_pose = 0, m_truePose = 0, m_transform = 0, m_received = 0, m_sent = 0, m_events = 0;
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
