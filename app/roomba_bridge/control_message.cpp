// SPDX-License-Identifier: GPL-3.0-or-later
#include "control_message.h"

#include "command_message.h"

std::optional<ControlAction> controlActionFromJson(const QByteArray &payload, QString *error, QString *program)
{
    const std::optional<QJsonObject> o = mqtt::messageObject(payload, error);
    if (!o)
        return std::nullopt;
    if (program) {
        program->clear();
        for (const QChar c : o->value(QLatin1String("program")).toString().left(64))
            if (c.isPrint())
                program->append(c);
    }
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
