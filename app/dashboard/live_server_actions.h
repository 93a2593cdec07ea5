// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "foxglove_server.h"

#include <QObject>
#include <QPointer>
#include <QString>

class LiveRobots;
class QAction;
class QCheckBox;
class QDialog;
class QLabel;
class QLineEdit;
class QSpinBox;
class QWidget;
class RobotFleet;
class RoomRobots;

// View → Live data server…: the window's robots served over the Foxglove
// WebSocket protocol (docs/foxglove.md), for Foxglove, Lichtblick and
// PlotJuggler. On this machine only unless the user gives another address,
// which the dialog and the log then say.
class LiveServerActions : public QObject {
    Q_OBJECT
public:
    LiveServerActions(RobotFleet &fleet, RoomRobots &room, QWidget *dialogParent);
    ~LiveServerActions() override;

    QAction *action() const { return m_action; }
    foxglove::Server &server() { return m_server; }
    // Serves on `address`; false with the reason said as message().
    bool start(const foxglove::ServerAddress &address);
    void stop();
    // The dialog, built on first use (tests look into it).
    QDialog *dialog();
    void retranslate();

signals:
    // One line for the status bar: started, stopped, refused, a client dropped.
    void message(const QString &text);

private:
    void showState();
    void applyFromDialog();

    RobotFleet &m_fleet;
    foxglove::Server m_server;
    LiveRobots *m_robots = nullptr;
    QWidget *m_dialogParent;
    QAction *m_action = nullptr;
    QString m_error; // why the last start failed
    QString m_asked; // the address of the last start, as the dialog shows it
    QPointer<QDialog> m_dialog;
    QCheckBox *m_serve = nullptr;
    QLineEdit *m_address = nullptr;
    QSpinBox *m_rate = nullptr;
    QLabel *m_url = nullptr;
    QLabel *m_clients = nullptr;
    QLabel *m_reach = nullptr;
    QLabel *m_intro = nullptr;
    QLabel *m_addressLabel = nullptr;
    QLabel *m_rateLabel = nullptr;
};
