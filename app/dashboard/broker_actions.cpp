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
    connect(m_console, &FleetConsole::messageWithdrawn, this, &BrokerActions::messageWithdrawn);
    connect(m_console, &FleetConsole::loginRefused, this,
            [this](const mqtt::BrokerAddress &address, const QString &why) {
                // Asked again, the account named, rather than refused every second.
                SavedBroker refused{address, false};
                refused.address.password.clear();
                QSettings settings;
                for (const SavedBroker &b : loadSavedBrokers(settings))
                    if (b.address.host == address.host && b.address.port == address.port)
                        refused.rememberPassword = b.rememberPassword;
                showFleetView();
                openDialog(refused, tr("%1. Type the password again, or another user name.").arg(why));
            });

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
    openDialog(std::nullopt, {});
}

void BrokerActions::openDialog(const std::optional<SavedBroker> &preset, const QString &notice)
{
    if (m_dialog)
        m_dialog->close();
    QSettings settings;
    // Over the fleet view when that is where the class looks.
    QWidget *parent = m_fleetView->isVisible() ? static_cast<QWidget *>(m_fleetView) : m_dialogParent;
    m_dialog = new BrokerDialog(loadSavedBrokers(settings), parent);
    m_dialog->setAttribute(Qt::WA_DeleteOnClose);
    if (preset)
        m_dialog->setBroker(*preset);
    m_dialog->setNotice(notice);
    connect(m_dialog, &QDialog::accepted, this, [this, dialog = m_dialog] {
        QSettings settings;
        saveBrokers(settings, withRecentBroker(loadSavedBrokers(settings), dialog->broker()));
        connectToBroker(dialog->broker().address);
    });
    m_dialog->open();
}

bool BrokerActions::connectToBroker(const mqtt::BrokerAddress &address)
{
    m_fleetView->setReconnectOffer({});
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
    if (last.username.isEmpty() || !last.password.isEmpty()) {
        connectToBroker(last);
        emit message(tr("Connecting again to %1, the class of the last session.").arg(last.displayUrl()));
        return;
    }
    // Not forgotten: offered, one click away, the password asked for.
    const QString offer = tr("Last session: the class on %1 as \"%2\". Reconnect… asks for the password.")
                              .arg(last.displayUrl(), last.username);
    m_fleetView->setReconnectOffer(offer);
    emit message(offer);
    showFleetView();
}

void BrokerActions::saveConnectedAtQuit(QSettings &settings) const
{
    // Connected to a broker at quit: connected again at the next start.
    settings.setValue("brokers/connectedAtQuit", isConnected());
}

#include "moc_broker_actions.cpp"
