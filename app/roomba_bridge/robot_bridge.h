// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "bridge_inbox.h"
#include "control_message.h"
#include "control_lease.h"
#include "goal_drive.h"
#include "link_status.h"
#include "mqtt_client.h"
#include "network_command_rules.h"
#include "oi_command.h"
#include "sensor_snapshot.h"
#include "telemetry_changes.h"

#include <QJsonObject>
#include <QLoggingCategory>
#include <QObject>
#include <QTimer>

#include <optional>

class RobotSession;
namespace mqtt {
struct CommandMessage;
}

Q_DECLARE_LOGGING_CATEGORY(lcBridge)

// One robot on the broker (docs/mqtt.md): publishes its state (retained),
// telemetry and link statistics, takes commands and control messages from
// clients, and answers each on the client's reply topic. The session owns
// the link and the robot's safety rules; this adds the network's: one
// controller at a time with a heartbeat, stop all, and the robot stopped
// while the broker is gone.
class RobotBridge : public QObject {
    Q_OBJECT
public:
    struct Options {
        QString name;               // the robot's name in the topics
        double telemetryRateHz = 0; // 0: every frame
        // Every packet in every message, as before the changes-only
        // telemetry (docs/mqtt.md): about five times the bytes.
        bool fullTelemetry = false;
        // Full mode over the network, where the robot itself ignores cliffs
        // and wheel drops: off unless the teacher allows it.
        bool allowFull = false;
        // Schedule and Set Day/Time over the network: the robot would start
        // cleaning later by itself, with nobody in control.
        bool allowSchedule = false;
    };

    // The longest command or control message the bridge reads; a longer
    // one is dropped unread and answered with an error.
    static constexpr qsizetype kMaxPayloadBytes = 4096;
    // The nice value of the thread that reads the students' connection.
    static constexpr int kStudentsNice = 10;
    // What that thread reads at most: a class of 30 driving one robot in
    // turn sends far fewer (heartbeats 10 a second, a drive pad's 20 to 50).
    static constexpr int kMaxStudentMessagesPerSecond = 2000;

    RobotBridge(RobotSession &robot, mqtt::MqttClient &broker, oilink::Clock &clock, Options options,
                QObject *parent = nullptr);
    ~RobotBridge() override;

    // The state the broker publishes when the bridge dies: set it on the
    // client before it connects.
    static mqtt::LastWill lastWill(const QString &name);

    // A second connection that hears only the teacher's topics (stop all,
    // takeovers), under an account of its own: a flood on a command topic
    // fills the broker's queue for the first connection, and mosquitto
    // then drops what comes next for it, stops included. Set before start().
    void setStopLine(mqtt::MqttClient &stopLine);

    // Subscribes and starts publishing; connect the client afterwards.
    void start();
    // Stops the robot and leaves it in Passive, frees control and
    // publishes the offline state; the client may disconnect afterwards.
    void shutDown();

    QString controller() const { return m_lease.holder(); }
    QJsonObject state() const;
    // Messages that arrived but wait to be read.
    qsizetype waitingMessages() const { return m_inbox.waiting(); }

private:
    void onMessage(const BridgeInbox::Message &message);
    void onPayloadTooLarge(const QString &topic, qsizetype bytes);
    void onBrokerConnected();
    void onBrokerLost(const QString &reason);
    void onLinkState(oilink::LinkState state);
    void onStopLineLost(const QString &reason);
    // Returns who had control.
    QString freeControlAndStop();
    void onFrame(const oi::SensorSnapshot &frame);
    void handleCommand(const BridgeInbox::Message &message);
    void handleControl(const QString &client, const QByteArray &payload, bool takeover, qint64 arrivedMs);
    // A move with a goal (goal_command.h): answered when it ends.
    void handleGoal(const QString &client, const QString &id, const mqtt::CommandMessage &request);
    // Ends a running goal because the bridge stops the robot (it stops it
    // next) and tells the client that asked for it: `stop` is the reason as
    // a word a program reads, `error` the same in words, `by` who stopped it.
    void endGoal(classroom::StopReason stop, const QString &error, const QString &by = {});
    void replyGoal(const GoalDrive::Result &result, classroom::StopReason stop, const QString &error, const QString &by = {},
                   const QStringList &cause = {});
    void onGoalEnded(const GoalDrive::Result &result);
    // Why a client may not drive now (it does not hold control), or empty;
    // `holder` is set to who does.
    QString controlRefusal(const QString &client) const;
    void stopAll();
    // The command's bytes are validated; motion goes through the teleop
    // rules, the rest straight to the robot. Returns the error, or empty.
    QString sendValidated(const oi::OiCommand &command);
    // Drive 0,0 and motors off, sent whatever the bridge believes the robot
    // is doing; Safe first if the robot may be carrying out a command of its
    // own in Passive.
    void stopRobot();
    // A stop from a client that does not hold control: the controller is
    // told, since the robot no longer does what it last asked.
    void tellControllerOfStop(const QString &by);
    // In Full mode the robot drives off an edge: the bridge stops it.
    void stopAtEdges(const oi::SensorSnapshot &frame);
    void reply(const QString &client, QJsonObject answer);
    // One log line per refusal at most every second, with the message's
    // size and not its content: a flood of bad messages fills no disk.
    void logRefusal(const QString &client, qsizetype bytes, const QString &error);
    void replyControl(const QString &client, bool ok, const QString &error = {});
    void publishState(bool always = false);
    void logModeReason();
    // The battery as the state says it, to a tenth of a percent.
    std::optional<double> batteryShown() const;
    // `whole`: every packet; otherwise what changed (TelemetryChanges).
    void publishTelemetry(const oi::SensorSnapshot &frame, bool whole);
    void publishTelemetryText(const oi::SensorSnapshot &packets, bool keyFrame);
    void publishStats();

    RobotSession &m_robot;
    mqtt::MqttClient &m_broker;
    mqtt::MqttClient *m_stopLine = nullptr;
    oilink::Clock &m_clock;
    ControlLease m_lease;
    Options m_options;
    NetworkCommandRules m_rules;
    BridgeInbox m_inbox;
    GoalDrive m_goal;
    QString m_goalClient, m_goalId; // who asked for the running goal, and the id of its message
    QString m_program; // the program its controller said it runs, for the fleet view; empty if none
    // The link streamed, then stopped: a stop sent meanwhile may be lost.
    bool m_linkWasLive = false;
    bool m_linkInterrupted = false;
    qint64 m_refusalLoggedMs = -1;
    int m_refusalsUnlogged = 0;
    bool m_atEdge = false;
    QTimer m_telemetryTimer;
    oilink::TelemetryChanges m_telemetryChanges;
    QTimer m_statsTimer;
    bool m_frameWaiting = false;
    bool m_shutDown = false;
    QJsonObject m_publishedState;
    QString m_loggedModeReason;
    std::optional<double> m_publishedBattery;
    // The pack's health goes out when its verdict changes, else its figures every kHealthEveryMs at most.
    static constexpr qint64 kHealthEveryMs = 10'000;
    QString m_publishedHealth; // the condition's key
    qint64 m_healthPublishedMs = -kHealthEveryMs;
    bool m_stateUnsent = false; // the broker refused the last one: try again
};
