// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_request.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace {

std::optional<QJsonObject> objectOf(const QByteArray &payload, QString *error)
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

// An argument as `roomba-ctl encode` would read it from the command line.
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

} // namespace

std::optional<CommandRequest> CommandRequest::fromJson(const QByteArray &payload, QString *id, QString *error)
{
    const std::optional<QJsonObject> o = objectOf(payload, error);
    if (!o)
        return std::nullopt;
    CommandRequest r;
    const QJsonValue idValue = o->value(QLatin1String("id"));
    if (idValue.isString())
        r.id = idValue.toString();
    else if (idValue.isDouble())
        r.id = QString::number(idValue.toDouble());
    *id = r.id;
    const QJsonValue command = o->value(QLatin1String("command"));
    if (!command.isString() || command.toString().isEmpty()) {
        *error = QStringLiteral("\"command\" must be a command name such as \"drive\"");
        return std::nullopt;
    }
    r.command = command.toString();
    const QJsonValue args = o->value(QLatin1String("args"));
    if (!args.isUndefined() && !args.isNull() && !args.isArray()) {
        *error = QStringLiteral("\"args\" must be a list of numbers and words, like [200, \"straight\"]");
        return std::nullopt;
    }
    const QJsonArray list = args.toArray();
    for (qsizetype i = 0; i < list.size(); ++i) {
        const std::optional<std::string> text = argumentText(list[i]);
        if (!text) {
            *error = QStringLiteral("argument %1 must be a number or a word").arg(i + 1);
            return std::nullopt;
        }
        r.args.push_back(*text);
    }
    return r;
}

std::optional<ControlAction> controlActionFromJson(const QByteArray &payload, QString *error)
{
    const std::optional<QJsonObject> o = objectOf(payload, error);
    if (!o)
        return std::nullopt;
    const QString action = o->value(QLatin1String("action")).toString();
    if (action == QLatin1String("take"))
        return ControlAction::Take;
    if (action == QLatin1String("keep"))
        return ControlAction::Keep;
    if (action == QLatin1String("release"))
        return ControlAction::Release;
    *error = QStringLiteral("\"action\" must be \"take\", \"keep\" or \"release\"");
    return std::nullopt;
}
