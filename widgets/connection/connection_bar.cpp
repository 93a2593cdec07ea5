// SPDX-License-Identifier: GPL-3.0-or-later
#include "connection_bar.h"

#include "robot_address.h"

#include "display_palette.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QToolButton>
#include <QVBoxLayout>

ConnectionBar::ConnectionBar(QWidget *parent) : QWidget(parent)
{
    m_transport = new QComboBox(this);
    m_transport->setObjectName("transport");
    for (auto t : {ConnectionRequest::Transport::Virtual, ConnectionRequest::Transport::Serial,
                   ConnectionRequest::Transport::Tcp})
        m_transport->addItem(QString(), int(t));

    m_port = new QComboBox(this);
    m_port->setObjectName("port");
    m_port->setEditable(true);
    m_port->setMinimumContentsLength(14);
    m_refresh = new QToolButton(this);
    m_refresh->setObjectName("refresh");
    m_tcp = new QLineEdit(this);
    m_tcp->setObjectName("tcp");

    m_profile = new QComboBox(this);
    m_profile->setObjectName("profile");
    m_profile->addItem(QString(), -1);
    for (oi::ProfileId id : oi::allProfiles()) {
        const std::string_view name = oi::profile(id).name;
        m_profile->addItem(QString::fromUtf8(name.data(), qsizetype(name.size())), int(id));
    }
    m_baud = new QComboBox(this);
    m_baud->setObjectName("baud");
    m_baud->addItem(QString(), 0);
    for (int baud : {115200, 57600, 38400, 19200, 9600})
        m_baud->addItem(QString::number(baud), baud);

    m_brcLine = new QComboBox(this);
    m_brcLine->setObjectName("brcLine");
    for (oi::BrcLine line : oi::kBrcLines)
        m_brcLine->addItem(QString(), int(line));

    m_connect = new QPushButton(this);
    m_connect->setObjectName("connect");
    m_disconnect = new QPushButton(this);
    m_disconnect->setObjectName("disconnect");
    m_lockedHint = new QLabel(this);
    m_lockedHint->setObjectName("lockedHint");
    m_lockedHint->setEnabled(false); // greyed as the fields it speaks of
    m_error = new QLabel(this);
    m_error->setObjectName("error");
    m_error->setWordWrap(true);
    m_error->setHidden(true);
    const QColor alert = display::stateColor(display::State::Alert, palette());
    m_error->setStyleSheet(QString("QLabel { color: %1; font-weight: bold; }").arg(alert.name()));

    m_wake = new QPushButton(this);
    m_wake->setObjectName("wake");
    m_wake->setHidden(true);

    auto *row = new QHBoxLayout;
    row->addWidget(m_transport);
    row->addWidget(m_port, 1);
    row->addWidget(m_refresh);
    row->addWidget(m_tcp, 1);
    row->addWidget(m_profile);
    row->addWidget(m_baud);
    row->addWidget(m_brcLine);
    row->addStretch(); // takes the room when no port or bridge field shows
    row->addWidget(m_lockedHint);
    row->addWidget(m_connect);
    row->addWidget(m_disconnect);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(row);
    auto *errorRow = new QHBoxLayout;
    errorRow->addWidget(m_error, 1);
    errorRow->addWidget(m_wake);
    layout->addLayout(errorRow);

    // Item texts change with the language; the combos follow their width.
    for (QComboBox *combo : {m_transport, m_profile, m_baud, m_brcLine})
        combo->setSizeAdjustPolicy(QComboBox::AdjustToContents);

    connect(m_transport, &QComboBox::currentIndexChanged, this, &ConnectionBar::updateTransportFields);
    connect(m_refresh, &QToolButton::clicked, this, &ConnectionBar::refreshPorts);
    connect(m_connect, &QPushButton::clicked, this, &ConnectionBar::tryConnect);
    connect(m_tcp, &QLineEdit::returnPressed, this, &ConnectionBar::tryConnect);
    connect(m_disconnect, &QPushButton::clicked, this, &ConnectionBar::disconnectRequested);
    connect(m_wake, &QPushButton::clicked, this, &ConnectionBar::wakeRequested);

    // The ports are listed when the serial port is first chosen: asking the
    // system for them is the dearest part of building the bar, and a window
    // that starts with virtual or saved robots does not need them.
    updateTransportFields();
    setConnected(false);
    retranslateUi();
}

void ConnectionBar::retranslateUi()
{
    // Item texts change in place, so the current choice and its data stay.
    m_transport->setItemText(0, tr("Virtual robot"));
    m_transport->setItemText(1, tr("Serial port"));
    m_transport->setItemText(2, tr("TCP (ser2net)"));
    m_transport->setAccessibleName(tr("Transport"));
    m_port->lineEdit()->setPlaceholderText(tr("/dev/ttyUSB0 or a typed path"));
    m_port->setAccessibleName(tr("Serial port"));
    m_refresh->setText(tr("Refresh"));
    m_tcp->setPlaceholderText(tr("host:port, e.g. raspberrypi:3333"));
    m_tcp->setAccessibleName(tr("TCP bridge"));
    m_profile->setItemText(0, tr("Auto"));
    m_profile->setAccessibleName(tr("Robot profile"));
    m_baud->setItemText(0, tr("Default baud"));
    m_baud->setAccessibleName(tr("Baud rate"));
    // The line of the serial adapter (or RFC 2217 bridge) wired to the robot's BRC pin.
    m_brcLine->setItemText(m_brcLine->findData(int(oi::BrcLine::Rts)), tr("Wake: RTS"));
    m_brcLine->setItemText(m_brcLine->findData(int(oi::BrcLine::Dtr)), tr("Wake: DTR"));
    m_brcLine->setItemText(m_brcLine->findData(int(oi::BrcLine::Both)), tr("Wake: both"));
    m_brcLine->setItemText(m_brcLine->findData(int(oi::BrcLine::None)), tr("Wake: none"));
    m_brcLine->setAccessibleName(tr("Wake line"));
    m_connect->setText(tr("Connect"));
    m_disconnect->setText(tr("Disconnect"));
    m_wake->setText(tr("Wake"));
    m_wake->setToolTip(tr("Pulse the robot's BRC pin: switches on a robot switched off at its power button"));
    // Said beside the greyed fields, and on each of them.
    m_lockedHint->setText(tr("Disconnect to change the port"));
    for (QWidget *w : std::initializer_list<QWidget *>{m_transport, m_port, m_refresh, m_tcp, m_profile, m_baud, m_connect})
        w->setToolTip(m_connected ? m_lockedHint->text() : QString());
    m_brcLine->setToolTip(m_connected ? m_lockedHint->text()
                                      : tr("The adapter's line wired to the robot's BRC pin, pulsed to wake it and "
                                           "keep it awake. Many cables use RTS, some DTR; both pulses the two; none: the cable has no BRC wire."));
    m_refresh->setToolTip(m_connected ? m_lockedHint->text() : tr("List the serial ports again"));
    if (m_ownError != OwnError::None)
        showOwnError(m_ownError);
}

void ConnectionBar::changeEvent(QEvent *e)
{
    if (e->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(e);
}

void ConnectionBar::showOwnError(OwnError error)
{
    QString host;
    quint16 port = 0;
    // The bridge's address is read as on every command line, with the same words.
    showError(error == OwnError::NoPort ? tr("Choose a serial port or type its path.")
                                        : oilink::RobotAddress::readHostPort(m_badBridge, &host, &port));
    m_ownError = error;
}

void ConnectionBar::refreshPorts()
{
    m_portsListed = true;
    const QString typed = m_port->currentText();
    m_port->clear();
    for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts())
        m_port->addItem(info.systemLocation());
    m_port->setEditText(typed);
}

void ConnectionBar::updateTransportFields()
{
    const auto t = ConnectionRequest::Transport(m_transport->currentData().toInt());
    if (t == ConnectionRequest::Transport::Serial && !m_portsListed)
        refreshPorts();
    m_port->setVisible(t == ConnectionRequest::Transport::Serial);
    m_refresh->setVisible(t == ConnectionRequest::Transport::Serial);
    m_tcp->setVisible(t == ConnectionRequest::Transport::Tcp);
    m_profile->setVisible(t != ConnectionRequest::Transport::Current);
    m_baud->setVisible(t != ConnectionRequest::Transport::Current);
    m_baud->setEnabled(t != ConnectionRequest::Transport::Virtual);
    m_brcLine->setVisible(t == ConnectionRequest::Transport::Serial || t == ConnectionRequest::Transport::Tcp);
}

void ConnectionBar::showCurrent(const QString &description, bool connected)
{
    int at = m_transport->findData(int(ConnectionRequest::Transport::Current));
    if (at < 0) {
        m_transport->addItem(QString(), int(ConnectionRequest::Transport::Current));
        at = m_transport->count() - 1;
    }
    m_transport->setItemText(at, description);
    m_transport->setCurrentIndex(at);
    updateTransportFields();
    setConnected(connected);
}

ConnectionRequest ConnectionBar::request() const
{
    ConnectionRequest r;
    r.transport = ConnectionRequest::Transport(m_transport->currentData().toInt());
    r.portPath = m_port->currentText().trimmed();
    const QString tcp = m_tcp->text().trimmed();
    const qsizetype colon = tcp.lastIndexOf(':');
    r.host = colon > 0 ? tcp.left(colon) : tcp;
    r.tcpPort = colon > 0 ? tcp.mid(colon + 1).toUShort() : 0;
    const int profile = m_profile->currentData().toInt();
    if (profile >= 0)
        r.profile = oi::ProfileId(profile);
    r.baud = m_baud->currentData().toInt();
    r.brcLine = oi::BrcLine(m_brcLine->currentData().toInt());
    return r;
}

void ConnectionBar::setRequest(const ConnectionRequest &r)
{
    // The current robot's own entry goes once another kind is chosen for it.
    if (const int current = m_transport->findData(int(ConnectionRequest::Transport::Current));
        current >= 0 && r.transport != ConnectionRequest::Transport::Current)
        m_transport->removeItem(current);
    m_transport->setCurrentIndex(m_transport->findData(int(r.transport)));
    m_port->setEditText(r.portPath);
    m_tcp->setText(r.host.isEmpty() ? QString() : QString("%1:%2").arg(r.host).arg(r.tcpPort));
    m_profile->setCurrentIndex(m_profile->findData(r.profile ? int(*r.profile) : -1));
    const int baud = m_baud->findData(r.baud);
    m_baud->setCurrentIndex(baud >= 0 ? baud : 0);
    m_brcLine->setCurrentIndex(m_brcLine->findData(int(r.brcLine)));
    updateTransportFields();
}

void ConnectionBar::showConnected(const ConnectionRequest &request)
{
    setRequest(request);
    setConnected(true);
}

void ConnectionBar::tryConnect()
{
    const ConnectionRequest r = request();
    showError(QString());
    if (r.transport == ConnectionRequest::Transport::Serial && r.portPath.isEmpty()) {
        showOwnError(OwnError::NoPort);
        return;
    }
    QString host;
    quint16 port = 0;
    if (r.transport == ConnectionRequest::Transport::Tcp
        && !oilink::RobotAddress::readHostPort(m_tcp->text().trimmed(), &host, &port).isEmpty()) {
        m_badBridge = m_tcp->text().trimmed();
        showOwnError(OwnError::BadBridge);
        return;
    }
    emit connectRequested(r);
}

void ConnectionBar::setConnected(bool connected)
{
    m_connected = connected;
    m_lockedHint->setVisible(connected);
    m_connect->setEnabled(!connected);
    m_disconnect->setEnabled(connected);
    for (QWidget *w : std::initializer_list<QWidget *>{m_transport, m_port, m_refresh, m_tcp, m_profile, m_brcLine})
        w->setEnabled(!connected);
    m_baud->setEnabled(!connected && request().transport != ConnectionRequest::Transport::Virtual);
    retranslateUi();
}

void ConnectionBar::showError(const QString &message)
{
    m_ownError = OwnError::None; // messages from elsewhere come translated already
    m_error->setText(message);
    m_error->setHidden(message.isEmpty());
}

void ConnectionBar::offerWake(bool offered) { m_wake->setHidden(!offered); }

bool ConnectionBar::wakeOffered() const { return !m_wake->isHidden(); }

QString ConnectionBar::errorText() const { return m_error->isHidden() ? QString() : m_error->text(); }

#include "moc_connection_bar.cpp"
