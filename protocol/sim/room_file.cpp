// SPDX-License-Identifier: GPL-3.0-or-later
#include "room_file.h"

#include "bounded_file.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>
#include <QSet>

#include <cmath>

namespace sim {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kVersion = 1;
const QString kFormat = QStringLiteral("roomba-room");
// World::kMaxShapes of each kind, written one to a line, take about 150 KB.
constexpr qint64 kMaxRoomBytes = 1 << 20;

// The messages' context for translators.
struct RoomFile {
    Q_DECLARE_TR_FUNCTIONS(RoomFile)
};

double toRad(double deg) { return deg * kPi / 180; }
double toDeg(double rad) { return rad * 180 / kPi; }

// Reads a room from its JSON object; the first fault ends it with a message.
class RoomReader {
public:
    std::optional<World> read(const QJsonObject &root)
    {
        if (!allowOnly(root, {"format", "version", "name", "start", "walls", "drop_offs", "rugs", "dock", "virtual_wall"}, {}))
            return std::nullopt;
        if (root.value("format").toString() != kFormat)
            return fail(RoomFile::tr("\"format\" must be \"%1\"").arg(kFormat));
        if (root.value("version").toInt(-1) != kVersion)
            return fail(RoomFile::tr("\"version\" %1 is not one this program reads (it reads %2)")
                            .arg(root.value("version").toVariant().toString())
                            .arg(kVersion));
        World w;
        w.name = root.value("name").toString().toStdString();
        if (root.contains("start")) {
            double heading = 0;
            if (!place(root.value("start"), "start", w.startX, w.startY, heading))
                return std::nullopt;
            w.startHeadingRad = toRad(heading);
        }
        for (const auto &[key, count] : {std::pair{"walls", 4}, std::pair{"drop_offs", 4}, std::pair{"rugs", 5}}) {
            const QJsonValue list = root.value(key);
            if (list.isUndefined())
                continue;
            if (!list.isArray())
                return fail(RoomFile::tr("\"%1\" must be a list").arg(key));
            const QJsonArray items = list.toArray();
            if (std::size_t(items.size()) > World::kMaxShapes)
                return fail(RoomFile::tr("\"%1\" has %2 entries; a room holds at most %3")
                                .arg(key)
                                .arg(items.size())
                                .arg(World::kMaxShapes));
            for (qsizetype i = 0; i < items.size(); ++i) {
                const QString where = QStringLiteral("%1[%2]").arg(key).arg(i);
                double v[5];
                if (!numbers(items[i], where, v, count))
                    return std::nullopt;
                if (QLatin1String(key) == QLatin1String("walls")) {
                    if (v[0] == v[2] && v[1] == v[3])
                        return fail(RoomFile::tr("%1: a wall must have some length").arg(where));
                    w.walls.push_back({v[0], v[1], v[2], v[3]});
                    continue;
                }
                if (!(v[0] < v[2] && v[1] < v[3]))
                    return fail(RoomFile::tr("%1: x_min must be below x_max and y_min below y_max").arg(where));
                if (QLatin1String(key) == QLatin1String("drop_offs")) {
                    w.dropOffs.push_back({v[0], v[1], v[2], v[3]});
                    continue;
                }
                if (!(v[4] >= 0 && v[4] <= 1))
                    return fail(RoomFile::tr("%1: the shade (the fifth number) must be from 0 (the floor as it is) "
                                             "to 1 (black), not %2")
                                    .arg(where, QString::number(v[4])));
                w.rugs.push_back({{v[0], v[1], v[2], v[3]}, v[4]});
            }
        }
        if (root.contains("dock")) {
            World::Dock d;
            if (!place(root.value("dock"), "dock", d.x, d.y, d.headingRad))
                return std::nullopt;
            d.headingRad = toRad(d.headingRad);
            w.dock = d;
        }
        if (root.contains("virtual_wall")) {
            World::VirtualWallBeacon b;
            if (!place(root.value("virtual_wall"), "virtual_wall", b.x, b.y, b.headingRad, &b.rangeMm))
                return std::nullopt;
            b.headingRad = toRad(b.headingRad);
            if (b.rangeMm <= 0)
                return fail(RoomFile::tr("virtual_wall: \"range_mm\" must be above 0, not %1").arg(b.rangeMm));
            w.virtualWall = b;
        }
        return w;
    }

    QString error;

private:
    std::nullopt_t fail(const QString &message)
    {
        error = message;
        return std::nullopt;
    }

    bool allowOnly(const QJsonObject &o, const QStringList &allowed, const QString &where)
    {
        for (const QString &key : o.keys())
            if (!allowed.contains(key)) {
                fail(where.isEmpty() ? RoomFile::tr("unknown key \"%1\"").arg(key)
                                     : RoomFile::tr("%1: unknown key \"%2\"").arg(where, key));
                return false;
            }
        return true;
    }

    bool number(const QJsonValue &v, const QString &where, double &out)
    {
        if (!v.isDouble() || !std::isfinite(v.toDouble())) {
            fail(RoomFile::tr("%1 must be a number").arg(where));
            return false;
        }
        out = v.toDouble();
        return true;
    }

    bool numbers(const QJsonValue &v, const QString &where, double *out, int count)
    {
        const QJsonArray a = v.toArray();
        if (!v.isArray() || a.size() != count) {
            fail(RoomFile::tr("%1 must be a list of %2 numbers").arg(where).arg(count));
            return false;
        }
        for (int i = 0; i < count; ++i)
            if (!number(a[i], QStringLiteral("%1[%2]").arg(where).arg(i), out[i]))
                return false;
        return true;
    }

    // {"x_mm", "y_mm", "heading_deg"} and, for a beam, "range_mm".
    bool place(const QJsonValue &v, const QString &where, double &x, double &y, double &headingDeg,
               double *rangeMm = nullptr)
    {
        if (!v.isObject()) {
            fail(RoomFile::tr("\"%1\" must be an object with x_mm, y_mm and heading_deg").arg(where));
            return false;
        }
        const QJsonObject o = v.toObject();
        QStringList keys{"x_mm", "y_mm", "heading_deg"};
        if (rangeMm)
            keys << "range_mm";
        if (!allowOnly(o, keys, where))
            return false;
        double *targets[] = {&x, &y, &headingDeg, rangeMm};
        for (qsizetype i = 0; i < keys.size(); ++i) {
            if (!o.contains(keys[i])) {
                fail(RoomFile::tr("%1: \"%2\" is missing").arg(where, keys[i]));
                return false;
            }
            if (!number(o.value(keys[i]), QStringLiteral("%1.%2").arg(where, keys[i]), *targets[i]))
                return false;
        }
        return true;
    }
};

QString lineAndColumn(const QByteArray &text, int offset)
{
    const QByteArray before = text.left(offset);
    const qsizetype line = before.count('\n') + 1;
    const qsizetype column = offset - (before.lastIndexOf('\n') + 1) + 1;
    return RoomFile::tr("line %1, column %2").arg(line).arg(column);
}

QString number(double v) { return QString::number(v, 'g', QLocale::FloatingPointShortest); }

void setError(QString *error, const QString &message)
{
    if (error)
        *error = message;
}

} // namespace

std::optional<World> roomFromJson(const QByteArray &json, QString *error)
{
    QJsonParseError parse{};
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parse);
    if (parse.error != QJsonParseError::NoError) {
        setError(error, RoomFile::tr("not JSON at %1: %2").arg(lineAndColumn(json, parse.offset), parse.errorString()));
        return std::nullopt;
    }
    if (!doc.isObject()) {
        setError(error, RoomFile::tr("a room file holds one JSON object"));
        return std::nullopt;
    }
    RoomReader reader;
    std::optional<World> world = reader.read(doc.object());
    if (!world)
        setError(error, reader.error);
    return world;
}

std::optional<World> loadRoomFile(const QString &path, QString *error)
{
    QString why;
    const std::optional<QByteArray> bytes = files::readBounded(path, kMaxRoomBytes, &why);
    if (!bytes) {
        setError(error, RoomFile::tr("%1: cannot read: %2").arg(path, why));
        return std::nullopt;
    }
    std::optional<World> world = roomFromJson(*bytes, &why);
    if (!world)
        setError(error, RoomFile::tr("%1: %2").arg(QFileInfo(path).fileName(), why));
    return world;
}

QByteArray roomToJson(const World &w)
{
    // By hand, so each wall stays on one line.
    const auto place = [](double x, double y, double rad) {
        return QStringLiteral("{\"x_mm\": %1, \"y_mm\": %2, \"heading_deg\": %3")
            .arg(number(x), number(y), number(toDeg(rad)));
    };
    const auto quads = [](const QList<QList<double>> &items) {
        QStringList lines;
        for (const auto &v : items) {
            QStringList numbers;
            for (double d : v)
                numbers << number(d);
            lines << QStringLiteral("    [%1]").arg(numbers.join(QStringLiteral(", ")));
        }
        return lines.isEmpty() ? QStringLiteral("[]") : QStringLiteral("[\n%1\n  ]").arg(lines.join(",\n"));
    };
    QList<QList<double>> walls, drops, rugs;
    for (const Segment &s : w.walls)
        walls.append({s.x1, s.y1, s.x2, s.y2});
    for (const Area &a : w.dropOffs)
        drops.append({a.xMin, a.yMin, a.xMax, a.yMax});
    for (const Rug &r : w.rugs)
        rugs.append({r.area.xMin, r.area.yMin, r.area.xMax, r.area.yMax, r.shade});

    QStringList fields;
    fields << QStringLiteral("\"format\": \"%1\"").arg(kFormat) << QStringLiteral("\"version\": %1").arg(kVersion);
    const QByteArray name = QJsonDocument(QJsonArray{QString::fromStdString(w.name)}).toJson(QJsonDocument::Compact);
    fields << QStringLiteral("\"name\": %1").arg(QString::fromUtf8(name.mid(1, name.size() - 2)));
    fields << QStringLiteral("\"start\": %1}").arg(place(w.startX, w.startY, w.startHeadingRad));
    fields << QStringLiteral("\"walls\": %1").arg(quads(walls));
    fields << QStringLiteral("\"drop_offs\": %1").arg(quads(drops));
    if (!w.rugs.empty())
        fields << QStringLiteral("\"rugs\": %1").arg(quads(rugs));
    if (w.dock)
        fields << QStringLiteral("\"dock\": %1}").arg(place(w.dock->x, w.dock->y, w.dock->headingRad));
    if (w.virtualWall)
        fields << QStringLiteral("\"virtual_wall\": %1, \"range_mm\": %2}")
                      .arg(place(w.virtualWall->x, w.virtualWall->y, w.virtualWall->headingRad),
                           number(w.virtualWall->rangeMm));
    return QStringLiteral("{\n  %1\n}\n").arg(fields.join(",\n  ")).toUtf8();
}

bool saveRoomFile(const QString &path, const World &world, QString *error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) {
        setError(error, RoomFile::tr("%1: cannot write: %2").arg(path, file.errorString()));
        return false;
    }
    file.write(roomToJson(world));
    if (!file.commit()) {
        setError(error, RoomFile::tr("%1: cannot write: %2").arg(path, file.errorString()));
        return false;
    }
    return true;
}

} // namespace sim
