// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_file.h"

#include "bounded_file.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtMath>

#include <cmath>

namespace {

constexpr int kVersion = 1;
const QString kFormat = QStringLiteral("roomba-lesson");
constexpr qsizetype kMaxSteps = 50;
// A lesson is a few kilobytes; anything far larger is not one.
constexpr qint64 kMaxLessonBytes = 1 << 20;
constexpr double kMaxHoldSeconds = 600;
// A room is a few metres; a hand carries a robot a short way.
constexpr double kMaxPlaceMm = 100000;
constexpr double kMaxCarryMm = 2000;

// The messages' context for translators.
struct LessonFile {
    Q_DECLARE_TR_FUNCTIONS(LessonFile)
};

QString quoted(const QJsonValue &v)
{
    if (v.isString())
        return QLatin1Char('"') + v.toString() + QLatin1Char('"');
    return QString::fromUtf8(QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact)).mid(1).chopped(1);
}

// A lesson names its robots by their exact keys, not by aliases.
bool isProfileKey(const QString &key)
{
    for (oi::ProfileId id : oi::allProfiles())
        if (key == QLatin1String(oi::profile(id).key))
            return true;
    return false;
}

// "roomba500, create2 or create1".
QString profileKeys()
{
    QStringList keys;
    for (oi::ProfileId id : oi::allProfiles())
        keys << QLatin1String(oi::profile(id).key);
    const QString last = keys.takeLast();
    return keys.isEmpty() ? last : LessonFile::tr("%1 or %2").arg(keys.join(QStringLiteral(", ")), last);
}

// What fail() returns: false, or no lesson.
struct Failed {
    operator bool() const { return false; }
    template <typename T>
    operator std::optional<T>() const { return std::nullopt; }
};

// Reads a lesson from its JSON object; the first fault ends it with a message.
class LessonReader {
public:
    std::optional<Lesson> read(const QJsonObject &root)
    {
        if (!allowOnly(root, {"format", "version", "title", "summary", "profiles", "steps"}, QString()))
            return std::nullopt;
        if (root.value("format").toString() != kFormat)
            return fail(QString(), "format", LessonFile::tr("must be \"%1\"").arg(kFormat));
        if (root.value("version").toInt(-1) != kVersion)
            return fail(QString(), "version",
                        LessonFile::tr("%1 is not a version this program reads (it reads %2)")
                            .arg(quoted(root.value("version")))
                            .arg(kVersion));
        Lesson lesson;
        if (!text(root, "title", QString(), lesson.title))
            return std::nullopt;
        if (root.contains("summary") && !text(root, "summary", QString(), lesson.summary))
            return std::nullopt;
        if (root.contains("profiles")) {
            if (!stringList(root.value("profiles"), "profiles", QString(), lesson.profiles))
                return std::nullopt;
            for (const QString &p : lesson.profiles)
                if (!isProfileKey(p))
                    return fail(QString(), "profiles",
                                LessonFile::tr("%1 is not a robot (%2)").arg(quoted(p), profileKeys()));
        }
        const QJsonValue steps = root.value("steps");
        if (!steps.isArray() || steps.toArray().isEmpty())
            return fail(QString(), "steps", LessonFile::tr("must be a list of at least one step"));
        if (steps.toArray().size() > kMaxSteps)
            return fail(QString(), "steps", LessonFile::tr("has more than %1 steps").arg(kMaxSteps));
        const QJsonArray items = steps.toArray();
        for (qsizetype i = 0; i < items.size(); ++i) {
            const QString where = LessonFile::tr("step %1").arg(i + 1);
            if (!items[i].isObject())
                return fail(where, QString(), LessonFile::tr("must be an object"));
            LessonStep step;
            if (!readStep(items[i].toObject(), where, step))
                return std::nullopt;
            lesson.steps << step;
        }
        return lesson;
    }

    QString error;

private:
    bool readStep(const QJsonObject &o, const QString &where, LessonStep &step)
    {
        if (!allowOnly(o, {"text", "highlight", "plot", "readout", "goal", "virtual_robot"}, where))
            return false;
        if (!text(o, "text", where, step.text))
            return false;
        if (o.contains("highlight")) {
            if (!stringList(o.value("highlight"), "highlight", where, step.highlight))
                return false;
            for (const QString &part : step.highlight)
                if (!lesson::diagramParts().contains(part))
                    return fail(where, "highlight",
                                LessonFile::tr("%1 is not a part of the robot diagram (%2)")
                                    .arg(quoted(part), lesson::diagramParts().join(", ")));
        }
        for (const char *field : {"plot", "readout"}) {
            if (!o.contains(field))
                continue;
            const bool isReadout = QLatin1String(field) == QLatin1String("readout");
            QStringList &keys = isReadout ? step.readout : step.plot;
            if (!stringList(o.value(field), field, where, keys))
                return false;
            const bool poseAllowed = isReadout;
            for (const QString &key : keys)
                if (!lesson::isPacketKey(key) && !(poseAllowed && lesson::poseReadouts().contains(key)))
                    return fail(where, field, LessonFile::tr("%1 is not a packet key").arg(quoted(key)));
        }
        if (o.contains("virtual_robot")) {
            if (!o.value("virtual_robot").isObject())
                return fail(where, "virtual_robot", LessonFile::tr("must be an object"));
            LessonPlacement placement;
            if (!readPlacement(o.value("virtual_robot").toObject(), where, placement))
                return false;
            step.virtualRobot = placement;
        }
        if (!o.value("goal").isObject())
            return fail(where, "goal", LessonFile::tr("is missing or not an object"));
        return readGoal(o.value("goal").toObject(), where, "goal", step.goal);
    }

    bool readPlacement(const QJsonObject &o, const QString &where, LessonPlacement &placement)
    {
        const QString field = QStringLiteral("virtual_robot");
        if (!allowOnly(o, {"label", "place", "forward_mm", "lift"}, where, field))
            return false;
        if (!text(o, "label", where, placement.label, field))
            return false;
        if (o.contains("place") && o.contains("forward_mm"))
            return fail(where, field, LessonFile::tr("needs \"place\" or \"forward_mm\", not both"));
        if (!o.contains("place") && !o.contains("forward_mm") && !o.contains("lift"))
            return fail(where, field, LessonFile::tr("needs \"place\", \"forward_mm\" or \"lift\""));
        if (o.contains("place")) {
            const QJsonArray at = o.value("place").toArray();
            const auto inRange = [](const QJsonValue &v, double limit) {
                return v.isDouble() && std::isfinite(v.toDouble()) && std::abs(v.toDouble()) <= limit;
            };
            if (!o.value("place").isArray() || at.size() != 3 || !inRange(at[0], kMaxPlaceMm)
                || !inRange(at[1], kMaxPlaceMm) || !inRange(at[2], 360))
                return fail(where, field + ".place",
                            LessonFile::tr("must be [x_mm, y_mm, heading_degrees], x and y from -%1 to %1, the "
                                           "heading from -360 to 360")
                                .arg(kMaxPlaceMm));
            placement.place = oi::Pose{at[0].toDouble(), at[1].toDouble(), qDegreesToRadians(at[2].toDouble()), 0};
        }
        if (o.contains("forward_mm")
            && !number(o, "forward_mm", where, field, -kMaxCarryMm, kMaxCarryMm, placement.forwardMm))
            return false;
        if (o.contains("lift")) {
            if (!o.value("lift").isBool())
                return fail(where, field + ".lift", LessonFile::tr("must be true or false"));
            placement.lift = o.value("lift").toBool();
        }
        return true;
    }

    bool readGoal(const QJsonObject &o, const QString &where, const QString &field, LessonGoal &goal)
    {
        if (!allowOnly(o, {"packet", "bit", "above", "below", "equals", "ir", "drive_mm", "turn_degrees",
                           "any", "all", "for_seconds"},
                       where, field))
            return false;
        const int kinds = int(o.contains("packet")) + int(o.contains("drive_mm"))
                          + int(o.contains("turn_degrees")) + int(o.contains("any")) + int(o.contains("all"));
        if (kinds != 1)
            return fail(where, field,
                        LessonFile::tr("needs exactly one of \"packet\", \"drive_mm\", \"turn_degrees\", \"any\" or \"all\""));
        if (o.contains("for_seconds")) {
            if (!number(o, "for_seconds", where, field, 0, kMaxHoldSeconds, goal.holdSeconds))
                return false;
        }
        if (o.contains("drive_mm")) {
            goal.kind = LessonGoal::Kind::Drive;
            return number(o, "drive_mm", where, field, 1, 100000, goal.distanceMm);
        }
        if (o.contains("turn_degrees")) {
            goal.kind = LessonGoal::Kind::Turn;
            return number(o, "turn_degrees", where, field, 1, 3600, goal.degrees);
        }
        for (const char *combined : {"any", "all"}) {
            if (!o.contains(combined))
                continue;
            goal.kind = QLatin1String(combined) == QLatin1String("any") ? LessonGoal::Kind::Any : LessonGoal::Kind::All;
            const QString listField = field + QLatin1Char('.') + combined;
            const QJsonArray list = o.value(combined).toArray();
            if (!o.value(combined).isArray() || list.size() < 2)
                return fail(where, listField, LessonFile::tr("must be a list of at least two goals"));
            for (qsizetype i = 0; i < list.size(); ++i) {
                const QString inner = QStringLiteral("%1[%2]").arg(listField).arg(i);
                if (!list[i].isObject())
                    return fail(where, inner, LessonFile::tr("must be an object"));
                LessonGoal g;
                if (!readGoal(list[i].toObject(), where, inner, g))
                    return false;
                goal.goals << g;
            }
            return true;
        }
        goal.kind = LessonGoal::Kind::Packet;
        if (!text(o, "packet", where, goal.packet, field))
            return false;
        if (!lesson::isPacketKey(goal.packet))
            return fail(where, field + ".packet", LessonFile::tr("%1 is not a packet key").arg(quoted(goal.packet)));
        if (!o.contains("bit") && !o.contains("above") && !o.contains("below") && !o.contains("equals")
            && !o.contains("ir"))
            return fail(where, field,
                        LessonFile::tr("needs \"bit\", \"above\", \"below\", \"equals\" or \"ir\" with \"packet\""));
        if (o.contains("bit")) {
            const QJsonValue bit = o.value("bit");
            if (bit.isString())
                goal.bits = {bit.toString()};
            else if (!stringList(bit, field + ".bit", where, goal.bits))
                return false;
            for (const QString &b : goal.bits)
                if (!isBitKey(goal.packet, b))
                    return fail(where, field + ".bit",
                                LessonFile::tr("%1 is not a bit of %2").arg(quoted(b), quoted(goal.packet)));
        }
        for (const char *key : {"above", "below", "equals"}) {
            if (!o.contains(key))
                continue;
            double v = 0;
            if (!number(o, key, where, field, -1e9, 1e9, v))
                return false;
            (QLatin1String(key) == QLatin1String("above") ? goal.above
             : QLatin1String(key) == QLatin1String("below") ? goal.below
                                                             : goal.equals) = v;
        }
        if (o.contains("ir")) {
            if (!text(o, "ir", where, goal.ir, field))
                return false;
            if (goal.ir != "dock" && goal.ir != "virtual_wall" && goal.ir != "any")
                return fail(where, field + ".ir",
                            LessonFile::tr("%1 is not an IR kind (dock, virtual_wall or any)").arg(quoted(goal.ir)));
            if (goal.packet != "ir_omni" && goal.packet != "ir_left" && goal.packet != "ir_right")
                return fail(where, field + ".ir",
                            LessonFile::tr("needs an IR packet (ir_omni, ir_left or ir_right)"));
        }
        return true;
    }

    static bool isBitKey(const QString &packet, const QString &bit)
    {
        for (oi::ProfileId id : oi::allProfiles()) {
            const oi::RobotProfile &profile = oi::profile(id);
            if (const oi::PacketInfo *p = lesson::packetByKey(profile, packet); p && lesson::bitMask(profile, p->id, bit))
                return true;
        }
        return false;
    }

    bool allowOnly(const QJsonObject &o, std::initializer_list<const char *> keys, const QString &where,
                   const QString &field = QString())
    {
        for (auto it = o.begin(); it != o.end(); ++it) {
            bool known = false;
            for (const char *k : keys)
                known = known || it.key() == QLatin1String(k);
            if (!known)
                return fail(where, field.isEmpty() ? it.key() : field + QLatin1Char('.') + it.key(),
                            LessonFile::tr("is not a field of a lesson file"));
        }
        return true;
    }

    bool text(const QJsonObject &o, const char *key, const QString &where, QString &out,
              const QString &parent = QString())
    {
        const QString field = parent.isEmpty() ? QString::fromLatin1(key) : parent + QLatin1Char('.') + key;
        const QJsonValue v = o.value(key);
        if (!v.isString() || v.toString().trimmed().isEmpty())
            return fail(where, field, LessonFile::tr("must be a text that is not empty"));
        out = v.toString().trimmed();
        return true;
    }

    bool stringList(const QJsonValue &v, const QString &field, const QString &where, QStringList &out)
    {
        if (!v.isArray())
            return fail(where, field, LessonFile::tr("must be a list of texts"));
        out.clear();
        for (const QJsonValue &item : v.toArray()) {
            if (!item.isString())
                return fail(where, field, LessonFile::tr("must be a list of texts"));
            out << item.toString();
        }
        return true;
    }

    bool number(const QJsonObject &o, const char *key, const QString &where, const QString &parent, double min,
                double max, double &out)
    {
        const QString field = parent + QLatin1Char('.') + key;
        const QJsonValue v = o.value(key);
        if (!v.isDouble() || !std::isfinite(v.toDouble()) || v.toDouble() < min || v.toDouble() > max)
            return fail(where, field, LessonFile::tr("%1 must be a number from %2 to %3").arg(quoted(v)).arg(min).arg(max));
        out = v.toDouble();
        return true;
    }

    Failed fail(const QString &where, const QString &field, const QString &why)
    {
        if (where.isEmpty())
            error = field.isEmpty() ? why : LessonFile::tr("\"%1\" %2").arg(field, why);
        else if (field.isEmpty())
            error = LessonFile::tr("%1: %2").arg(where, why);
        else
            error = LessonFile::tr("%1, \"%2\" %3").arg(where, field, why);
        return {};
    }
};

} // namespace

std::optional<Lesson> lessonFromJson(const QByteArray &json, QString *error)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (parseError.error != QJsonParseError::NoError || !doc.isObject()) {
        if (error) {
            const int line = int(json.left(parseError.offset).count('\n')) + 1;
            *error = parseError.error != QJsonParseError::NoError
                         ? LessonFile::tr("line %1: %2").arg(line).arg(parseError.errorString())
                         : LessonFile::tr("not a JSON object");
        }
        return std::nullopt;
    }
    LessonReader reader;
    std::optional<Lesson> lesson = reader.read(doc.object());
    if (!lesson && error)
        *error = reader.error;
    return lesson;
}

std::optional<Lesson> loadLessonFile(const QString &path, QString *error)
{
    const QString name = QFileInfo(path).fileName();
    QString why;
    const std::optional<QByteArray> bytes = files::readBounded(path, kMaxLessonBytes, &why);
    std::optional<Lesson> lesson = bytes ? lessonFromJson(*bytes, &why) : std::nullopt;
    if (!lesson && error)
        *error = LessonFile::tr("%1: %2").arg(name, why);
    return lesson;
}
