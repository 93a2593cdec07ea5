// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_message.h"

#include "command_catalog.h"

#include <QJsonDocument>
#include <QStringList>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace mqtt {
namespace {

QString fromStd(std::string_view text) { return QString::fromUtf8(text.data(), qsizetype(text.size())); }

// Song's notes, Stream's and Query List's packet ids, Script's body.
bool hasVariablePart(const oi::CommandSpec &spec) { return spec.layout == "*"; }

// A value as it was written in the message, for errors.
QString jsonText(const QJsonValue &v)
{
    const QByteArray text = QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact);
    return QString::fromUtf8(text.mid(1, text.size() - 2)).left(40);
}

// A whole number that fits an int; ranges are the encoder's to judge.
std::optional<int> wholeNumber(const QJsonValue &v)
{
    if (!v.isDouble())
        return std::nullopt;
    const double d = v.toDouble();
    if (d != std::floor(d) || std::abs(d) > double(std::numeric_limits<int>::max()))
        return std::nullopt;
    return int(d);
}

// A version 1 argument as `roomba-ctl encode` would read it from the
// command line.
std::optional<std::string> argumentText(const QJsonValue &v)
{
    if (v.isString())
        return v.toString().toStdString();
    if (!v.isDouble())
        return std::nullopt;
    const double d = v.toDouble();
    if (d == std::floor(d) && std::abs(d) < 1e15)
        return std::to_string(static_cast<long long>(d));
    // The encoder refuses it with its own words ("1.5 is not a whole number").
    return QString::number(d).toStdString();
}

QString fieldList(std::span<const std::string_view> names)
{
    QStringList list;
    for (std::string_view n : names)
        list << fromStd(n);
    return list.join(QLatin1String(", "));
}

} // namespace

std::optional<QJsonObject> messageObject(const QByteArray &payload, QString *error)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(payload, &parseError);
    if (parseError.error != QJsonParseError::NoError) {
        *error = QStringLiteral("not JSON: %1 at byte %2").arg(parseError.errorString()).arg(parseError.offset);
        return std::nullopt;
    }
    if (!doc.isObject()) {
        *error = QStringLiteral("not a JSON object");
        return std::nullopt;
    }
    return doc.object();
}

QJsonObject commandToJson(const oi::OiCommand &command, const QString &id)
{
    const oi::CommandSpec &spec = oi::commandSpec(command.command);
    QJsonObject o{{QLatin1String("v"), kCommandVersion},
                  {QLatin1String("id"), id},
                  {QLatin1String("command"), fromStd(spec.name)}};
    const std::span<const std::string_view> names = oi::commandFieldNames(command.command);
    if (!names.empty()) {
        QJsonObject fields;
        for (std::size_t i = 0; i < names.size() && i < command.fields.size(); ++i)
            fields.insert(fromStd(names[i]), command.fields[i]);
        o.insert(QLatin1String("fields"), fields);
    }
    if (hasVariablePart(spec)) {
        QJsonArray data;
        for (std::uint8_t b : command.data)
            data.append(int(b));
        o.insert(QLatin1String("data"), data);
    }
    return o;
}

std::optional<CommandMessage> CommandMessage::fromJson(const QByteArray &payload, QString *id, QString *error)
{
    const std::optional<QJsonObject> o = messageObject(payload, error);
    if (!o)
        return std::nullopt;
    CommandMessage m;
    const QJsonValue idValue = o->value(QLatin1String("id"));
    if (idValue.isString())
        m.id = idValue.toString();
    else if (idValue.isDouble())
        m.id = QString::number(idValue.toDouble());
    *id = m.id;

    const QJsonValue version = o->value(QLatin1String("v"));
    if (version.isUndefined()) {
        m.version = 1;
    } else if (const std::optional<int> v = wholeNumber(version); v && (*v == 1 || *v == kCommandVersion)) {
        m.version = *v;
    } else {
        *error = QStringLiteral("\"v\" is %1: this bridge reads command messages of version 1 and 2 "
                                "(docs/mqtt.md, \"Commands\")")
                     .arg(jsonText(version));
        return std::nullopt;
    }

    const QJsonValue command = o->value(QLatin1String("command"));
    if (!command.isString() || command.toString().isEmpty()) {
        *error = QStringLiteral("\"command\" must be a command name such as \"drive\"");
        return std::nullopt;
    }
    m.command = command.toString();

    if (m.version == 1) {
        for (const char *key : {"fields", "data"})
            if (o->contains(QLatin1String(key))) {
                *error = QStringLiteral("\"%1\" is for version 2 messages: add \"v\": 2").arg(QLatin1String(key));
                return std::nullopt;
            }
        const QJsonValue args = o->value(QLatin1String("args"));
        if (!args.isUndefined() && !args.isNull() && !args.isArray()) {
            *error = QStringLiteral("\"args\" must be a list of numbers and words, like [200, \"straight\"]");
            return std::nullopt;
        }
        m.args = args.toArray();
        for (qsizetype i = 0; i < m.args.size(); ++i)
            if (!argumentText(m.args[i])) {
                *error = QStringLiteral("argument %1 must be a number or a word").arg(i + 1);
                return std::nullopt;
            }
        return m;
    }

    if (o->contains(QLatin1String("args"))) {
        *error = QStringLiteral("\"args\" is the text form of version 1: a version 2 message names its values "
                                "in \"fields\", like {\"velocity\": 200, \"radius\": 0}");
        return std::nullopt;
    }
    const QJsonValue fields = o->value(QLatin1String("fields"));
    if (!fields.isUndefined() && !fields.isObject()) {
        *error = QStringLiteral("\"fields\" must be an object of field names and numbers, like "
                                "{\"velocity\": 200, \"radius\": 0}");
        return std::nullopt;
    }
    m.fields = fields.toObject();
    const QJsonValue data = o->value(QLatin1String("data"));
    if (!data.isUndefined() && !data.isArray()) {
        *error = QStringLiteral("\"data\" must be a list of bytes, like [60, 32, 62, 32]");
        return std::nullopt;
    }
    m.data = data.toArray();
    return m;
}

std::optional<oi::OiCommand> CommandMessage::toCommand(const oi::RobotProfile &profile, QString *error) const
{
    if (version == 1) {
        std::vector<std::string> words;
        for (const QJsonValue &a : args)
            words.push_back(*argumentText(a));
        const oi::Result<oi::OiCommand> typed =
            oi::commandFromText(oi::CommandEncoder(profile), command.toStdString(), words);
        if (!typed) {
            *error = fromStd(typed.error().describe());
            return std::nullopt;
        }
        return *typed;
    }

    const oi::CommandSpec *spec = oi::commandSpecByName(command.toStdString());
    if (!spec) {
        *error = QStringLiteral("\"%1\" is not a command: the names are those of `roomba-ctl encode`, like "
                                "\"drive-direct\"")
                     .arg(command.left(40));
        return std::nullopt;
    }
    const std::span<const std::string_view> names = oi::commandFieldNames(spec->command);
    for (auto it = fields.begin(); it != fields.end(); ++it)
        if (std::find(names.begin(), names.end(), it.key().toStdString()) == names.end()) {
            *error = names.empty() ? QStringLiteral("%1 has no fields, so not \"%2\"").arg(command, it.key().left(40))
                                   : QStringLiteral("%1 has no field \"%2\": its fields are %3")
                                         .arg(command, it.key().left(40), fieldList(names));
            return std::nullopt;
        }
    oi::OiCommand typed{spec->command, {}, {}};
    for (std::string_view name : names) {
        const QJsonValue v = fields.value(fromStd(name));
        if (v.isUndefined()) {
            *error = QStringLiteral("%1 needs \"%2\" in \"fields\": its fields are %3")
                         .arg(command, fromStd(name), fieldList(names));
            return std::nullopt;
        }
        const std::optional<int> value = wholeNumber(v);
        if (!value) {
            *error = QStringLiteral("\"%1\" must be a whole number, not %2").arg(fromStd(name), jsonText(v));
            return std::nullopt;
        }
        typed.fields.push_back(*value);
    }
    if (!hasVariablePart(*spec) && !data.isEmpty()) {
        *error = QStringLiteral("%1 has no \"data\": only song, stream, query-list and script do").arg(command);
        return std::nullopt;
    }
    for (qsizetype i = 0; i < data.size(); ++i) {
        const std::optional<int> b = wholeNumber(data[i]);
        if (!b || *b < 0 || *b > 255) {
            *error = QStringLiteral("\"data\" item %1 must be a byte from 0 to 255, not %2").arg(i + 1).arg(jsonText(data[i]));
            return std::nullopt;
        }
        typed.data.push_back(std::uint8_t(*b));
    }
    return typed;
}

} // namespace mqtt
