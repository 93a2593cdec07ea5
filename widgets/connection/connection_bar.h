// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "brc_line.h"
#include "robot_profile.h"

#include <QString>
#include <QWidget>

#include <optional>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QToolButton;

// Where and how to reach the robot, as the user chose it.
struct ConnectionRequest {
    // Current: the robot as it is connected, which the bar cannot choose
    // itself (a robot on a broker, a recording); connecting reconnects it.
    enum class Transport { Virtual, Serial, Tcp, Current };
    Transport transport = Transport::Virtual;
    QString portPath;                     // serial: a listed port or a typed path (ptys are not listed)
    QString host;                         // TCP
    quint16 tcpPort = 0;                  // TCP
    std::optional<oi::ProfileId> profile; // nullopt: detect automatically
    int baud = 0;                         // 0: the profile's default
    oi::BrcLine brcLine = oi::BrcLine::Rts; // the wake line: the adapter's line wired to BRC
    friend bool operator==(const ConnectionRequest &, const ConnectionRequest &) = default;
};

// The connection bar: transport, port, profile, baud, wake line, Connect/Disconnect, and
// one inline error line. It validates what was typed before asking to connect.
class ConnectionBar : public QWidget {
    Q_OBJECT
public:
    explicit ConnectionBar(QWidget *parent = nullptr);

    ConnectionRequest request() const;
    // The choice to offer, e.g. the last connection.
    void setRequest(const ConnectionRequest &request);
    void setConnected(bool connected);
    // What the link was actually opened with (a command line may differ
    // from the last choice): the fields show it, locked while connected.
    void showConnected(const ConnectionRequest &request);
    // A robot the bar cannot choose, named by `description` ("r1 on the
    // broker"): offered as the transport, with no port, profile or baud.
    void showCurrent(const QString &description, bool connected);
    // Shows `message` inline until the next connect attempt or clearError();
    // the same message twice is shown once.
    void showError(const QString &message);
    // Takes the error away, as when the link streams again after a fault.
    void clearError() { showError(QString()); }
    QString errorText() const;
    void refreshPorts();
    // A Wake button beside the error while the robot is switched off at its
    // power button (LinkStats::switchedOff).
    void offerWake(bool offered);
    bool wakeOffered() const;

signals:
    void connectRequested(const ConnectionRequest &request);
    void disconnectRequested();
    void wakeRequested(); // the Wake button

protected:
    void changeEvent(QEvent *e) override;

private:
    // Errors this bar finds itself; it can say them again in a new language.
    enum class OwnError { None, NoPort, BadBridge };
    void retranslateUi();
    void showOwnError(OwnError error);
    void tryConnect();
    void updateTransportFields();

    QComboBox *m_transport = nullptr;
    QComboBox *m_port = nullptr;
    QToolButton *m_refresh = nullptr;
    QLineEdit *m_tcp = nullptr;
    QComboBox *m_profile = nullptr;
    QComboBox *m_baud = nullptr;
    QComboBox *m_brcLine = nullptr;
    QPushButton *m_connect = nullptr;
    QPushButton *m_disconnect = nullptr;
    QLabel *m_lockedHint = nullptr;
    bool m_connected = false;
    bool m_portsListed = false; // refreshPorts() has run
    QLabel *m_error = nullptr;
    QPushButton *m_wake = nullptr;
    OwnError m_ownError = OwnError::None;
    QString m_badBridge; // the bridge address that BadBridge is about
};

Q_DECLARE_METATYPE(ConnectionRequest)
