// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "broker_address.h"
#include "broker_dialog.h"
#include "saved_brokers.h"

#include <QObject>
#include <QPointer>

#include <optional>

class FleetConsole;
class FleetView;
class QAction;
class QSettings;
class QWidget;
class RobotFleet;

// The classroom broker as the window offers it: File → Connect to broker…
// and Disconnect, the fleet view in a window of its own (Ctrl+Shift+F), and
// connecting again at start to the broker the dashboard was connected to at
// quit. The fleet console behind it turns the broker's robots into tiles.
class BrokerActions : public QObject {
    Q_OBJECT
public:
    BrokerActions(RobotFleet &fleet, QWidget *dialogParent);

    QAction *connectAction() const { return m_connect; }
    QAction *disconnectAction() const { return m_disconnect; }
    QAction *fleetViewAction() const { return m_fleetViewAction; }
    FleetConsole *console() const { return m_console; }
    FleetView *fleetView() const { return m_fleetView; }

    // The dialog, with the brokers used before; keeps the one chosen and
    // connects to it. It does not block: dialog() while it is open.
    void askForBroker();
    BrokerDialog *dialog() const { return m_dialog; }
    bool connectToBroker(const mqtt::BrokerAddress &address);
    bool isConnected() const;
    void showFleetView();
    // Only where nothing needs asking: no login, or a password kept on purpose.
    // Otherwise the fleet view offers it, and the status bar says so.
    void reconnectToLastBroker(QSettings &settings);
    void saveConnectedAtQuit(QSettings &settings) const;

    void retranslate();

signals:
    // For the status bar: bad messages, a refused login, a refused command.
    void message(const QString &text);
    // A message about the broker that is no longer true (it connected).
    void messageWithdrawn(const QString &text);

private:
    void openDialog(const std::optional<SavedBroker> &preset, const QString &notice);

    QWidget *m_dialogParent;
    FleetView *m_fleetView;
    FleetConsole *m_console; // a child: robots' transports use it until the fleet is closed
    QAction *m_connect;
    QAction *m_disconnect;
    QAction *m_fleetViewAction;
    QPointer<BrokerDialog> m_dialog;
};
