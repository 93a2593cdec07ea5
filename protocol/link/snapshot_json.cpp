// SPDX-License-Identifier: GPL-3.0-or-later
#include "snapshot_json.h"

#include <QCoreApplication>
#include <QJsonValue>

#include <cmath>

namespace oilink {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("oilink::SnapshotJson", text);
}

QString keyOf(const oi::PacketInfo &p)
{
    return QString::fromLatin1(p.key.data(), qsizetype(p.key.size()));
}

// What the packet's bytes can carry on the wire.
std::pair<qint64, qint64> wireRange(const oi::PacketInfo &p)
{
    const qint64 span = qint64(1) << (8 * p.bytes);
    return p.isSigned ? std::pair{-span / 2, span / 2 - 1} : std::pair{qint64(0), span - 1};
}

struct StatKey {
    const char *key;
    quint64 LinkStats::*field;
};
constexpr StatKey kCounters[] = {
    {"frames", &LinkStats::frames},
    {"replies", &LinkStats::replies},
    {"checksum_failures", &LinkStats::checksumFailures},
    {"resyncs", &LinkStats::resyncs},
    {"bytes_discarded", &LinkStats::bytesDiscarded},
    {"bytes_received", &LinkStats::bytesReceived},
    {"bytes_sent", &LinkStats::bytesSent},
};

} // namespace

QJsonObject snapshotToJson(const oi::SensorSnapshot &snapshot)
{
    QJsonObject o;
    for (const oi::PacketInfo &p : snapshot.robotProfile().packets())
        if (snapshot.has(p.id))
            o.insert(keyOf(p), snapshot.raw(p.id));
    return o;
}

QByteArray snapshotToJsonText(const oi::SensorSnapshot &snapshot)
{
    QByteArray text;
    text.reserve(1024);
    text += '{';
    for (const oi::PacketInfo &p : snapshot.robotProfile().packets()) {
        if (!snapshot.has(p.id))
            continue;
        if (text.size() > 1)
            text += ',';
        // Packet keys are snake_case ASCII: nothing to escape.
        text += '"';
        text.append(p.key.data(), qsizetype(p.key.size()));
        text += "\":";
        text += QByteArray::number(snapshot.raw(p.id));
    }
    text += '}';
    return text;
}

std::optional<oi::SensorSnapshot> snapshotFromJson(const QJsonObject &object, const oi::RobotProfile &profile,
                                                   QString *error)
{
    oi::SensorSnapshot s(profile);
    for (const oi::PacketInfo &p : profile.packets()) {
        const QJsonValue v = object.value(keyOf(p));
        if (v.isUndefined())
            continue;
        const double d = v.toDouble(std::nan(""));
        const auto [lo, hi] = wireRange(p);
        if (!v.isDouble() || d != std::floor(d) || d < double(lo) || d > double(hi)) {
            if (error)
                *error = tr("%1 must be a whole number from %2 to %3, not %4.")
                             .arg(keyOf(p))
                             .arg(lo)
                             .arg(hi)
                             .arg(v.isDouble() ? QString::number(d) : v.toVariant().toString().left(40));
            return std::nullopt;
        }
        s.set(p.id, std::int32_t(d));
    }
    return s;
}

QJsonObject statisticsToJson(const LinkStats &stats)
{
    QJsonObject o;
    for (const StatKey &k : kCounters)
        o.insert(QLatin1String(k.key), double(stats.*k.field));
    o.insert(QLatin1String("frames_per_second"), std::round(stats.framesPerSecond * 10) / 10);
    o.insert(QLatin1String("reconnects"), double(stats.reconnects));
    if (stats.bunchedEveryMs > 0)
        o.insert(QLatin1String("bunched_every_ms"), stats.bunchedEveryMs);
    o.insert(QLatin1String("last_frame"), stats.lastFrameTime.isValid()
                                              ? QJsonValue(stats.lastFrameTime.toString(Qt::ISODateWithMs))
                                              : QJsonValue(QJsonValue::Null));
    return o;
}

std::optional<LinkStats> statisticsFromJson(const QJsonObject &object, QString *error)
{
    LinkStats st;
    const auto count = [&](const char *key, auto &field) {
        const QJsonValue v = object.value(QLatin1String(key));
        if (v.isUndefined())
            return true;
        if (!v.isDouble() || v.toDouble() < 0) {
            if (error)
                *error = tr("%1 must be a number of at least 0.").arg(QLatin1String(key));
            return false;
        }
        field = static_cast<std::remove_reference_t<decltype(field)>>(v.toDouble());
        return true;
    };
    for (const StatKey &k : kCounters)
        if (!count(k.key, st.*k.field))
            return std::nullopt;
    if (!count("frames_per_second", st.framesPerSecond) || !count("reconnects", st.reconnects)
        || !count("bunched_every_ms", st.bunchedEveryMs))
        return std::nullopt;
    const QJsonValue last = object.value(QLatin1String("last_frame"));
    if (last.isString())
        st.lastFrameTime = QDateTime::fromString(last.toString(), Qt::ISODateWithMs);
    return st;
}

} // namespace oilink
