// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "broker_address.h"

#include <QList>

class QSettings;

// A broker the console connected to, as kept between runs. The password is
// kept only when the user asked for it (the settings file is plain text).
struct SavedBroker {
    mqtt::BrokerAddress address;
    bool rememberPassword = false;
    friend bool operator==(const SavedBroker &, const SavedBroker &) = default;
};

// The "brokers" array, most recent first: its first kMaxSavedBrokers entries,
// without those with no host or a port outside 1..65535.
QList<SavedBroker> loadSavedBrokers(QSettings &settings);
void saveBrokers(QSettings &settings, const QList<SavedBroker> &brokers);
// `broker` first, the same host and port dropped from further down, at most
// kMaxSavedBrokers kept.
QList<SavedBroker> withRecentBroker(QList<SavedBroker> brokers, const SavedBroker &broker);
inline constexpr int kMaxSavedBrokers = 8;
