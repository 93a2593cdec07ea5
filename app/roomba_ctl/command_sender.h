// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "profile_probe.h"
#include "result.h"
#include "stream_parser.h"

#include <QList>
#include <QObject>
#include <QString>
#include <QTimer>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace oilink {
class Transport;
}

// roomba-ctl send: one command to a robot on an open transport, sent so that
// the robot carries it out.
//
//  1. Without a profile, the robot is asked what it is (ProfileProbe, with
//     Start only if the robot is silent).
//  2. The stream an earlier client left running is paused, and the robot is
//     asked for its mode and what would make Safe mode refuse to drive
//     (wheel drops, cliffs, the dock) and whether a song is playing.
//     Silence means Off mode: Start, and ask again. A robot in Safe or Full
//     therefore stays there.
//  3. A command the documents allow only in Safe or Full finds the robot in
//     Safe (entered from Passive), or, without mode changes, is refused.
//     A command the robot will ignore as things are gets a warning.
//  4. The command; the answer to Sensors or Query List is read.
class CommandSender : public QObject {
    Q_OBJECT
public:
    struct Order {
        std::string name;
        std::vector<std::string> args;
        std::optional<oi::ProfileId> profile; // nullopt: ask the robot
        QList<int> bauds;                     // tried when asking, where the transport has a baud
        bool changeMode = true;               // false: never send Start or Safe
    };

    CommandSender(oilink::Transport &transport, Order order, QObject *parent = nullptr);
    ~CommandSender() override;

    // Opens the transport (from the event loop) and goes through the steps.
    void start();

signals:
    void replied(const oi::SensorSnapshot &snapshot, oi::FrameKind kind);
    void warning(const QString &text);
    void note(const QString &text);
    // status 0: sent (and answered); otherwise `error` says why not.
    void finished(int status, const QString &error);

private:
    enum class Phase { Idle, Probing, Draining, AskingState, AwaitingReply, Done };

    void onOpened();
    void onBytes(const QByteArray &bytes);
    void onTimeout();
    void useProfile(oi::ProfileId id);
    void askState();
    void decide(const oi::SensorSnapshot &state);
    void sendCommand();
    void write(const oi::Bytes &bytes);
    void finish(int status, const QString &error = {});

    oilink::Transport &m_transport;
    Order m_order;
    const oi::RobotProfile *m_profile = nullptr;
    oi::Bytes m_command;
    std::unique_ptr<oilink::ProfileProbe> m_probe;
    oi::StreamParser m_parser;
    QTimer m_timer;
    Phase m_phase = Phase::Idle;
    bool m_startSent = false;
};
