// SPDX-License-Identifier: GPL-3.0-or-later
#include "broker_address.h"

#include <QCoreApplication>
#include <QUrl>

namespace mqtt {

std::optional<BrokerAddress> BrokerAddress::fromUrl(const QString &text, QString *error)
{
    const QString trimmed = text.trimmed();
    const auto fail = [&](const QString &why) -> std::optional<BrokerAddress> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    if (trimmed.isEmpty())
        return fail(QCoreApplication::translate("mqtt::BrokerAddress", "The broker address is empty."));

    const QUrl url = QUrl(trimmed.contains(QLatin1String("://")) ? trimmed
                                                                 : QStringLiteral("mqtt://") + trimmed,
                          QUrl::StrictMode);
    const QString scheme = url.scheme().toLower();
    if (!url.isValid() || url.host().isEmpty() || (scheme != QLatin1String("mqtt") && scheme != QLatin1String("mqtts"))
        || (!url.path().isEmpty() && url.path() != QLatin1String("/")) || url.hasQuery() || url.hasFragment())
        return fail(QCoreApplication::translate("mqtt::BrokerAddress",
                                                "\"%1\" is not a broker address: give mqtt://HOST:PORT or mqtts://HOST:PORT.")
                        .arg(trimmed));

    BrokerAddress a;
    a.tls = scheme == QLatin1String("mqtts");
    a.host = url.host();
    a.port = url.port(a.tls ? 8883 : 1883);
    // QUrl reports a port outside 0..65535 as invalid; 0 is no port at all.
    if (a.port < 1 || a.port > 65535)
        return fail(QCoreApplication::translate("mqtt::BrokerAddress",
                                                "The broker's port must be from 1 to 65535, not %1.")
                        .arg(a.port));
    a.username = url.userName();
    a.password = url.password();
    return a;
}

QString BrokerAddress::displayUrl() const
{
    return QStringLiteral("%1://%2:%3").arg(tls ? QStringLiteral("mqtts") : QStringLiteral("mqtt"), host).arg(port);
}

} // namespace mqtt
