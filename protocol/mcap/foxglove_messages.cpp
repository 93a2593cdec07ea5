// SPDX-License-Identifier: GPL-3.0-or-later
#include "foxglove_messages.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QStringList>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

namespace oilink::foxglove {

namespace {

QString fromStd(std::string_view text)
{
    return QString::fromUtf8(text.data(), qsizetype(text.size()));
}

constexpr char kTimeSchema[] = R"({"type":"object","properties":{"sec":{"type":"integer","minimum":0},)"
                               R"("nsec":{"type":"integer","minimum":0,"maximum":999999999}}})";
constexpr char kVector3Schema[] = R"({"type":"object","properties":{"x":{"type":"number"},"y":{"type":"number"},)"
                                  R"("z":{"type":"number"}}})";
constexpr char kQuaternionSchema[] = R"({"type":"object","properties":{"x":{"type":"number"},)"
                                     R"("y":{"type":"number"},"z":{"type":"number"},"w":{"type":"number"}}})";

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

QByteArray positionJson(const oi::Pose &pose)
{
    return "{\"x\":" + number(pose.xMm / 1000) + ",\"y\":" + number(pose.yMm / 1000) + ",\"z\":0}";
}

QByteArray orientationJson(const oi::Pose &pose)
{
    return "{\"x\":0,\"y\":0,\"z\":" + number(std::sin(pose.thetaRad / 2)) +
           ",\"w\":" + number(std::cos(pose.thetaRad / 2)) + '}';
}

QString modeName(int mode)
{
    static const char *const names[] = {"Off", "Passive", "Safe", "Full"};
    return mode >= 0 && mode < 4 ? QLatin1String(names[mode]) : QString::number(mode);
}

// "create2" → "Create2": a ROS 2 message name is PascalCase.
QString pascalCase(const QString &key)
{
    QString name;
    bool upper = true;
    for (const QChar c : key) {
        if (!c.isLetterOrNumber()) {
            upper = true;
            continue;
        }
        name += upper ? c.toUpper() : c;
        upper = false;
    }
    return name;
}

} // namespace

RobotTopics::RobotTopics(const QString &name)
    : robot(name), telemetry('/' + name + "/telemetry"), telemetryRos2('/' + name + "/telemetry_ros2"),
      pose('/' + name + "/pose"), truePose('/' + name + "/true_pose"), transform('/' + name + "/tf"),
      roomTransform('/' + name + "/room_tf"),
      bytesReceived('/' + name + "/bytes_received"), bytesSent('/' + name + "/bytes_sent"),
      events('/' + name + "/events"), markers('/' + name + "/markers"), odomFrame(name + "/odom"),
      baseFrame(name + "/base_link")
{
}

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

QByteArray telemetrySchema(const oi::RobotProfile &profile, const std::vector<const oi::PacketInfo *> &packets,
                           const QString &title)
{
    QJsonObject properties;
    for (const oi::PacketInfo *p : packets) {
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

QString telemetryTitle(const oi::RobotProfile &profile)
{
    return QStringLiteral("roomba.Telemetry.%1").arg(fromStd(profile.key));
}

std::vector<const oi::PacketInfo *> profilePackets(const oi::RobotProfile &profile)
{
    std::vector<const oi::PacketInfo *> packets;
    for (const oi::PacketInfo &p : profile.packets())
        if (!p.isUnused())
            packets.push_back(&p);
    return packets;
}

QByteArray poseInFrameJson(quint64 ns, const QString &frame, const oi::Pose &pose)
{
    return "{\"timestamp\":" + timeJson(ns) + ",\"frame_id\":\"" + frame.toUtf8() + "\",\"pose\":{\"position\":" +
           positionJson(pose) + ",\"orientation\":" + orientationJson(pose) + "}}";
}

oi::Pose odomInRoom(const oi::Pose &truePose, const oi::Pose &odomPose)
{
    // T with T ∘ odom = true: its turn is the difference, its origin the
    // true position less the odometry's position turned by it.
    oi::Pose t;
    t.thetaRad = std::remainder(truePose.thetaRad - odomPose.thetaRad, 2 * M_PI);
    const double c = std::cos(t.thetaRad), s = std::sin(t.thetaRad);
    t.xMm = truePose.xMm - (c * odomPose.xMm - s * odomPose.yMm);
    t.yMm = truePose.yMm - (s * odomPose.xMm + c * odomPose.yMm);
    return t;
}

QByteArray frameTransformJson(quint64 ns, const QString &parent, const QString &child, const oi::Pose &pose)
{
    return "{\"timestamp\":" + timeJson(ns) + ",\"parent_frame_id\":\"" + parent.toUtf8() +
           "\",\"child_frame_id\":\"" + child.toUtf8() + "\",\"translation\":" + positionJson(pose) +
           ",\"rotation\":" + orientationJson(pose) + '}';
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

QByteArray telemetryRos2Schema(const std::vector<const oi::PacketInfo *> &packets)
{
    QByteArray text;
    for (const oi::PacketInfo *p : packets)
        text += "float64 " + QByteArray(p->key.data(), qsizetype(p->key.size())) + '\n';
    return text;
}

QByteArray telemetryCdr(const oi::SensorSnapshot &frame, const std::vector<const oi::PacketInfo *> &packets)
{
    // The encapsulation header (CDR, little-endian), then the doubles, each
    // 8-aligned from the end of the header, which they are back to back.
    QByteArray cdr(4 + 8 * qsizetype(packets.size()), Qt::Uninitialized);
    char *out = cdr.data();
    const char header[4] = {0x00, 0x01, 0x00, 0x00};
    std::memcpy(out, header, 4);
    out += 4;
    for (const oi::PacketInfo *p : packets) {
        const double value = frame.has(p->id) ? double(frame.raw(p->id)) : std::numeric_limits<double>::quiet_NaN();
        static_assert(Q_BYTE_ORDER == Q_LITTLE_ENDIAN, "CDR written little-endian as the machine holds it");
        std::memcpy(out, &value, 8);
        out += 8;
    }
    return cdr;
}

QString telemetryRos2Name(const oi::RobotProfile &profile)
{
    return QStringLiteral("roomba_msgs/msg/Telemetry%1").arg(pascalCase(fromStd(profile.key)));
}

QMap<QString, QString> profileMetadata(const oi::RobotProfile &profile)
{
    return {{"profile", fromStd(profile.key)}, {"robot", fromStd(profile.name)}};
}

QMap<QString, QString> firmwareMetadata(const oi::FirmwareInfo &firmware)
{
    return {{"release", fromStd(firmware.release)},
            {"version", fromStd(firmware.version.toString())},
            {"angle_corrected", firmware.corrections.angleDivisor ? "yes" : "no"}};
}

} // namespace oilink::foxglove
