// SPDX-License-Identifier: GPL-3.0-or-later
#include "saved_brokers.h"

#include "bounded_file.h"

#include <QSettings>

QList<SavedBroker> loadSavedBrokers(QSettings &settings)
{
    QList<SavedBroker> list;
    const int n = files::beginReadBoundedArray(settings, "brokers", kMaxSavedBrokers);
    for (int i = 0; i < n; ++i) {
        settings.setArrayIndex(i);
        SavedBroker b;
        b.address.host = settings.value("host").toString();
        b.address.port = settings.value("port", 1883).toInt();
        b.address.username = settings.value("user").toString();
        b.rememberPassword = settings.value("rememberPassword", false).toBool();
        if (b.rememberPassword)
            b.address.password = settings.value("password").toString();
        b.address.tls = settings.value("tls", false).toBool();
        b.address.caFile = settings.value("caFile").toString();
        if (!b.address.host.isEmpty() && b.address.port >= 1 && b.address.port <= 65535)
            list << b;
    }
    settings.endArray();
    return list;
}

void saveBrokers(QSettings &settings, const QList<SavedBroker> &brokers)
{
    settings.remove("brokers");
    settings.beginWriteArray("brokers", int(brokers.size()));
    for (int i = 0; i < brokers.size(); ++i) {
        const SavedBroker &b = brokers[i];
        settings.setArrayIndex(i);
        settings.setValue("host", b.address.host);
        settings.setValue("port", b.address.port);
        settings.setValue("user", b.address.username);
        settings.setValue("rememberPassword", b.rememberPassword);
        if (b.rememberPassword)
            settings.setValue("password", b.address.password);
        settings.setValue("tls", b.address.tls);
        settings.setValue("caFile", b.address.caFile);
    }
    settings.endArray();
}

QList<SavedBroker> withRecentBroker(QList<SavedBroker> brokers, const SavedBroker &broker)
{
    brokers.removeIf([&](const SavedBroker &b) {
        return b.address.host == broker.address.host && b.address.port == broker.address.port;
    });
    brokers.prepend(broker);
    if (brokers.size() > kMaxSavedBrokers)
        brokers.resize(kMaxSavedBrokers);
    return brokers;
}
