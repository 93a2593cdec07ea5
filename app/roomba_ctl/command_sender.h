// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "link_settings.h"
#include "oi_command.h"
#include "sensor_snapshot.h"

#include <QObject>
#include <QString>

#include <string>
#include <vector>

namespace oilink {
class RobotLink;
}

// roomba-ctl send: one command to a robot, sent so that the robot carries it
// out, through a RobotLink that only sends and asks (no stream), so the
// link's one request queue does every Sensors and Query List exchange.
//
//  1. Without a profile, the link asks the robot what it is (with Start only
//     if the robot is silent, and never without mode changes).
//  2. The robot is asked for its mode and what would make Safe mode refuse
//     to drive (wheel drops, cliffs, the dock) and whether a song is playing.
//     Silence means Off mode: Start, and ask again. A robot in Safe or Full
//     therefore stays there.
//  3. A command the documents allow only in Safe or Full finds the robot in
//     Safe (entered from Passive), or, without mode changes, is refused.
//     A command the robot will ignore as things are gets a warning.
//  4. The command; Sensors and Query List are asked through the link and
//     their answer is passed on.
class CommandSender : public QObject {
    Q_OBJECT
public:
    // For a robot found as "a Roomba 500 or a Create 2" without --profile
    // (RobotLink::profileAssumed): that Create 2 was `assumed`, and how to
    // name the right one. `where` is the robot's port or bridge.
    static QString roombaOrCreate2Note(const QString &where, bool assumed);
    // Why an answer that reads differently on the two (encoders 43/44, the
    // groups holding them) is not given.
    static QString mirroredAnswerRefusal(const QString &where, const QList<int> &ids);

    struct Order {
        std::string name;
        std::vector<std::string> args;
        oilink::LinkSettings settings; // without a profile: ask the robot
        bool changeMode = true;        // false: never send Start or Safe
    };

    CommandSender(oilink::RobotLink &link, Order order, QObject *parent = nullptr);

    // Opens the link (from the event loop) and goes through the steps.
    void start();

signals:
    void replied(const oi::SensorSnapshot &snapshot);
    void warning(const QString &text);
    void note(const QString &text);
    // status 0: sent (and answered); otherwise `error` says why not.
    void finished(int status, const QString &error);

private:
    enum class Phase { Opening, AskingState, AwaitingReply, Done };

    void useProfile(oi::ProfileId id);
    void askState();
    void onReply(const oi::SensorSnapshot &reply);
    void onQueryFailed();
    void onLinkError(const QString &message);
    void decide(const oi::SensorSnapshot &state);
    void sendCommand();
    void send(const oi::OiCommand &command);
    void finish(int status, const QString &error = {});

    oilink::RobotLink &m_link;
    Order m_order;
    const oi::RobotProfile *m_profile = nullptr;
    oi::OiCommand m_command;
    Phase m_phase = Phase::Opening;
    bool m_startSent = false;
};
