// SPDX-License-Identifier: GPL-3.0-or-later
#include "broker_actions.h"

#include "broker_dialog.h"
#include "fleet_console.h"
#include "fleet_view.h"
#include "saved_brokers.h"
#include "screen_fit.h"

#include <QAction>
#include <QDialog>
#include <QSettings>

BrokerActions::BrokerActions(RobotFleet &fleet, QWidget *dialogParent)
    : QObject(dialogParent), m_dialogParent(dialogParent)
{
    // The whole classroom on a broker, in a window of its own: it can go to
    // the projector while the dashboard stays on the laptop.
    m_fleetView = new FleetView(dialogParent);
    m_fleetView->setWindowFlag(Qt::Window);
    m_fleetView->setObjectName("fleetView");
    m_fleetView->resize(1280, 800);
    m_console = new FleetConsole(fleet, *m_fleetView, this);
    connect(m_fleetView, &FleetView::connectRequested, this, &BrokerActions::askForBroker);
    connect(m_console, &FleetConsole::message, this, &BrokerActions::message);

    m_connect = new QAction(this);
    m_connect->setObjectName("connectBrokerAction");
    connect(m_connect, &QAction::triggered, this, &BrokerActions::askForBroker);
    m_disconnect = new QAction(this);
    m_disconnect->setObjectName("disconnectBrokerAction");
    m_disconnect->setEnabled(false);
    connect(m_disconnect, &QAction::triggered, this, [this] {
        m_console->disconnectFromBroker();
        m_disconnect->setEnabled(false);
    });
    m_fleetViewAction = new QAction(this);
    m_fleetViewAction->setObjectName("fleetViewAction");
    m_fleetViewAction->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_F));
    connect(m_fleetViewAction, &QAction::triggered, this, &BrokerActions::showFleetView);
}

void BrokerActions::retranslate()
{
    m_connect->setText(tr("Connect to &broker…"));
    m_disconnect->setText(tr("&Disconnect from broker"));
    m_fleetViewAction->setText(tr("&Fleet view\tCtrl+Shift+F"));
    m_fleetView->setWindowTitle(tr("Fleet view — Roomba Dashboard"));
}

void BrokerActions::askForBroker()
{
    QSettings settings;
    BrokerDialog dialog(loadSavedBrokers(settings), m_dialogParent);
    if (dialog.exec() != QDialog::Accepted)
        return;
    saveBrokers(settings, withRecentBroker(loadSavedBrokers(settings), dialog.broker()));
    connectToBroker(dialog.broker().address);
}

bool BrokerActions::connectToBroker(const mqtt::BrokerAddress &address)
{
    const bool ok = m_console->connectToBroker(address);
    m_disconnect->setEnabled(true);
    showFleetView();
    return ok;
}

bool BrokerActions::isConnected() const
{
    return m_disconnect->isEnabled();
}

void BrokerActions::showFleetView()
{
    // First shown: no larger than the screen it opens on (a 720p projector).
    if (!m_fleetView->isVisible())
        m_fleetView->resize(screenfit::fitted(m_fleetView->size(), screenfit::available(m_fleetView).size()));
    m_fleetView->show();
    m_fleetView->raise();
    m_fleetView->activateWindow();
}

void BrokerActions::reconnectToLastBroker(QSettings &settings)
{
    const QList<SavedBroker> brokers = loadSavedBrokers(settings);
    if (!settings.value("brokers/connectedAtQuit").toBool() || brokers.isEmpty())
        return;
    const mqtt::BrokerAddress &last = brokers.first().address;
    if (last.username.isEmpty() || !last.password.isEmpty())
        connectToBroker(last);
}

void BrokerActions::saveConnectedAtQuit(QSettings &settings) const
{
    // Connected to a broker at quit: connected again at the next start.
    settings.setValue("brokers/connectedAtQuit", isConnected());
}
