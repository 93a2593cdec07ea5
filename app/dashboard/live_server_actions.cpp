// SPDX-License-Identifier: GPL-3.0-or-later
#include "live_server_actions.h"

#include "live_robots.h"
#include "robot_fleet.h"
#include "robot_session.h"
#include "room_robots.h"

#include <QAction>
#include <QCheckBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

namespace {
constexpr char kAddressKey[] = "liveServer/address";
constexpr char kRateKey[] = "liveServer/messagesPerSecond";
} // namespace

LiveServerActions::LiveServerActions(RobotFleet &fleet, RoomRobots &room, QWidget *dialogParent)
    : QObject(dialogParent), m_fleet(fleet), m_server(QStringLiteral("Roomba Dashboard")),
      m_dialogParent(dialogParent)
{
    m_robots = new LiveRobots(m_server, this);
    m_robots->setTruePose([&room](const RobotSession *robot) { return room.truePose(robot); });
    for (RobotSession *robot : fleet.robots())
        m_robots->add(robot);
    connect(&fleet, &RobotFleet::robotAdded, m_robots, &LiveRobots::add);
    connect(&fleet, &RobotFleet::robotRemoved, m_robots, &LiveRobots::remove);
    foxglove::Server::Limits limits;
    limits.messagesPerSecond = QSettings().value(kRateKey, limits.messagesPerSecond).toDouble();
    m_server.setLimits(limits);
    m_action = new QAction(this);
    connect(m_action, &QAction::triggered, this, [this] {
        dialog()->show();
        dialog()->raise();
    });
    connect(&m_server, &foxglove::Server::clientCountChanged, this, &LiveServerActions::showState);
    connect(&m_server, &foxglove::Server::clientDropped, this, [this](const QString &peer, const QString &why) {
        emit message(tr("Live data server: dropped %1: %2").arg(peer, why));
    });
    connect(&m_server, &foxglove::Server::clientRefused, this, [this](const QString &peer, const QString &why) {
        emit message(tr("Live data server: refused %1, which %2; Foxglove, Lichtblick and PlotJuggler offer "
                        "the right protocol")
                         .arg(peer, why));
    });
    retranslate();
}

LiveServerActions::~LiveServerActions()
{
    delete m_robots; // before the server it publishes to
    m_robots = nullptr;
}

bool LiveServerActions::start(const foxglove::ServerAddress &address)
{
    m_asked = address.toString();
    if (!m_server.listen(address)) {
        // The live data is for watching: the robots go on without it.
        m_error = m_server.errorString();
        qWarning("live data server: %s; the dashboard goes on without it", qPrintable(m_error));
        emit message(tr("Live data server: %1. The robots go on without it; choose another port in View → Live "
                        "data server….")
                         .arg(m_error));
        showState();
        return false;
    }
    m_error.clear();
    emit message(m_server.isLoopback()
                     ? tr("Live data server on %1: connect Foxglove or Lichtblick to it.").arg(m_server.url())
                     : tr("Live data server on %1, reachable from other machines: anyone on the network can "
                          "watch the robots.")
                           .arg(m_server.url()));
    showState();
    return true;
}

void LiveServerActions::stop()
{
    m_server.close();
    emit message(tr("Live data server stopped."));
    showState();
}

QDialog *LiveServerActions::dialog()
{
    if (m_dialog)
        return m_dialog;
    m_dialog = new QDialog(m_dialogParent);
    m_dialog->setObjectName("liveServerDialog");
    auto *layout = new QVBoxLayout(m_dialog);
    m_intro = new QLabel(m_dialog);
    m_intro->setWordWrap(true);
    layout->addWidget(m_intro);
    m_serve = new QCheckBox(m_dialog);
    layout->addWidget(m_serve);
    auto *form = new QFormLayout;
    // The address last asked for (on the command line too), else the one kept.
    m_address = new QLineEdit(m_asked.isEmpty() ? QSettings()
                                                      .value(kAddressKey, QStringLiteral("127.0.0.1:%1").arg(foxglove::kDefaultPort))
                                                      .toString()
                                                : m_asked,
                              m_dialog);
    m_addressLabel = new QLabel(m_dialog);
    form->addRow(m_addressLabel, m_address);
    m_rate = new QSpinBox(m_dialog);
    m_rate->setRange(1, 200);
    m_rate->setValue(int(m_server.limits().messagesPerSecond));
    m_rateLabel = new QLabel(m_dialog);
    form->addRow(m_rateLabel, m_rate);
    layout->addLayout(form);
    m_url = new QLabel(m_dialog);
    m_url->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_url->setObjectName("liveServerUrl");
    layout->addWidget(m_url);
    m_clients = new QLabel(m_dialog);
    layout->addWidget(m_clients);
    m_reach = new QLabel(m_dialog);
    m_reach->setWordWrap(true);
    layout->addWidget(m_reach);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, m_dialog);
    connect(buttons, &QDialogButtonBox::rejected, m_dialog, &QDialog::reject);
    layout->addWidget(buttons);
    connect(m_serve, &QCheckBox::toggled, this, &LiveServerActions::applyFromDialog);
    connect(m_address, &QLineEdit::editingFinished, this, [this] {
        if (m_server.isListening())
            applyFromDialog();
    });
    connect(m_rate, &QSpinBox::valueChanged, this, [this](int rate) {
        foxglove::Server::Limits limits = m_server.limits();
        limits.messagesPerSecond = rate;
        m_server.setLimits(limits);
        QSettings().setValue(kRateKey, rate);
    });
    retranslate();
    return m_dialog;
}

void LiveServerActions::applyFromDialog()
{
    if (!m_serve->isChecked()) {
        if (m_server.isListening())
            stop();
        return;
    }
    QString error;
    const std::optional<foxglove::ServerAddress> address = foxglove::ServerAddress::parse(m_address->text(), &error);
    if (!address) {
        m_error = error;
        showState();
        return;
    }
    QSettings().setValue(kAddressKey, m_address->text().trimmed());
    start(*address);
}

void LiveServerActions::showState()
{
    if (!m_dialog)
        return;
    const bool on = m_server.isListening();
    {
        const QSignalBlocker block(m_serve);
        m_serve->setChecked(on || (!m_error.isEmpty() && m_serve->isChecked()));
    }
    m_url->setText(on ? tr("Address to paste into Foxglove or Lichtblick (Open connection → Foxglove WebSocket): %1")
                            .arg(m_server.url())
                      : m_error.isEmpty() ? tr("Not serving.")
                                          : tr("Not serving: %1").arg(m_error));
    m_clients->setText(tr("Clients connected: %1").arg(on ? m_server.clientCount() : 0));
    m_reach->setText(!on ? QString()
                     : !m_error.isEmpty()
                         ? tr("Still serving on the address before: %1").arg(m_error)
                     : m_server.isLoopback()
                         ? tr("Only programs on this computer can connect.")
                         : tr("Reachable from other computers, as asked: anyone on the network can watch the "
                              "robots. Use 127.0.0.1 to keep it on this computer."));
}

void LiveServerActions::retranslate()
{
    m_action->setText(tr("&Live data server…"));
    if (!m_dialog)
        return;
    m_dialog->setWindowTitle(tr("Live data server"));
    m_intro->setText(tr("Serves every robot's telemetry, pose, events and markers over the Foxglove WebSocket "
                        "protocol, for Foxglove, Lichtblick and PlotJuggler."));
    m_serve->setText(tr("Serve live data"));
    m_addressLabel->setText(tr("Address and port:"));
    m_rateLabel->setText(tr("Messages a second per channel:"));
    showState();
}

#include "moc_live_server_actions.cpp"
