// SPDX-License-Identifier: GPL-3.0-or-later
#include "control_message.h"

#include "command_message.h"

#include <cmath>

std::optional<ControlAction> controlActionFromJson(const QByteArray &payload, QString *error, QString *program,
                                                   std::optional<qint64> *sentMs)
{
    const std::optional<QJsonObject> o = mqtt::messageObject(payload, error);
    if (!o)
        return std::nullopt;
    if (sentMs) {
        sentMs->reset();
        const QJsonValue sent = o->value(QLatin1String("sent_ms"));
        if (!sent.isUndefined()) {
            const double ms = sent.toDouble(-1);
            if (!sent.isDouble() || ms < 0 || ms > 9007199254740992.0 || ms != std::floor(ms)) {
                *error = QStringLiteral("\"sent_ms\" must be a whole number of milliseconds from 0 to 2^53");
                return std::nullopt;
            }
            *sentMs = qint64(ms);
        }
    }
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
