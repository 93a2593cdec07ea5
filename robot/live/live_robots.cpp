// SPDX-License-Identifier: GPL-3.0-or-later
#include "live_robots.h"

#include "live_playback.h"

#include "foxglove_messages.h"
#include "robot_session.h"
#include "snapshot_json.h"

#include <QSet>

namespace fx = oilink::foxglove;

struct LiveRobots::Served {
    RobotSession *robot = nullptr;
    int number = 0;
    QString prefix; // "r1"
    std::optional<fx::RobotTopics> topics;
    const oi::RobotProfile *profile = nullptr;
    std::vector<const oi::PacketInfo *> packets;
    foxglove::Server::ChannelId telemetry = 0, telemetryRos2 = 0, pose = 0, transform = 0, truePose = 0, roomTransform = 0, events = 0,
                                markers = 0;
    std::optional<oi::SensorSnapshot> before; // for the events, while someone reads them
    std::optional<oi::Pose> odomInRoom;       // from its first true pose since the connection
    QSet<int> markersSent;
    QList<QMetaObject::Connection> connections;
};

LiveRobots::LiveRobots(foxglove::Server &server, QObject *parent)
    : QObject(parent), m_server(server), m_playback(new LivePlayback(server, this))
{
    // A client sees each frame when the link read it, whatever pace the
    // window keeps; with none, the robots' frames cost no wake-up of their own.
    connect(&m_server, &foxglove::Server::clientCountChanged, this, [this](int clients) {
        for (Served *served : std::as_const(m_robots))
            served->robot->setFramesAtReadTime(clients > 0);
    });
}

LiveRobots::~LiveRobots()
{
    for (Served *served : std::as_const(m_robots)) {
        for (const QMetaObject::Connection &c : served->connections)
            disconnect(c);
        served->robot->setFramesAtReadTime(false); // alive: a destroyed one has been forgotten
        delete served;
    }
}

QString LiveRobots::prefixOf(const RobotSession *robot) const
{
    const Served *served = m_robots.value(robot);
    return served ? served->prefix : QString();
}

void LiveRobots::add(RobotSession *robot)
{
    if (m_robots.contains(robot))
        return;
    QSet<int> taken;
    for (const Served *s : std::as_const(m_robots))
        taken.insert(s->number);
    auto *served = new Served;
    served->robot = robot;
    for (served->number = 1; taken.contains(served->number); ++served->number) {
    }
    served->prefix = QStringLiteral("r%1").arg(served->number);
    served->topics.emplace(served->prefix);
    m_robots.insert(robot, served);
    advertise(*served);
    served->connections << connect(robot, &RobotSession::frameReceived, this,
                                   [this, served](double readSeconds, const oi::SensorSnapshot &frame) {
                                       onFrame(*served, readSeconds, frame);
                                   });
    // Another robot on the line (another profile): its telemetry is another message.
    served->connections << connect(robot, &RobotSession::profileChanged, this, [this, served] {
        withdraw(*served);
        advertise(*served);
    });
    served->connections << connect(robot, &RobotSession::firmwareChanged, this, &LiveRobots::updateMetadata);
    served->connections << connect(robot, &RobotSession::identityChanged, this, &LiveRobots::updateMetadata);
    // A new connection or a jump back in a replay: time starts again. The
    // replay whose timeline the viewer drives says so in its playback state.
    served->connections << connect(robot, &RobotSession::historyReset, this, [this, served] {
        served->before.reset();
        served->odomInRoom.reset();
        served->markersSent.clear();
        if (m_playback->followed() != served->robot)
            m_server.startSession();
    });
    served->connections << connect(&robot->markers(), &RobotMarkers::changed, this,
                                   [this, served] { onMarkers(*served); });
    served->connections << connect(robot, &QObject::destroyed, this, [this, robot] { forget(robot); });
    robot->setFramesAtReadTime(m_server.clientCount() > 0);
    updateMetadata();
    m_server.startSession();
}

void LiveRobots::remove(RobotSession *robot)
{
    if (m_robots.contains(robot))
        robot->setFramesAtReadTime(false);
    forget(robot);
}

// Also for a robot being destroyed, which is not touched.
void LiveRobots::forget(const RobotSession *robot)
{
    Served *served = m_robots.take(robot);
    if (!served)
        return;
    for (const QMetaObject::Connection &c : served->connections)
        disconnect(c);
    withdraw(*served);
    if (m_clockRobot == robot) {
        m_clockRobot = nullptr;
        m_playback->follow(nullptr);
    }
    delete served;
    updateMetadata();
}

void LiveRobots::advertise(Served &served)
{
    using foxglove::Delivery;
    served.profile = &served.robot->robotProfile();
    served.packets = fx::profilePackets(*served.profile);
    const fx::RobotTopics &t = *served.topics;
    const QString json = QStringLiteral("json"), jsonSchema = QStringLiteral("jsonschema");
    const QString title = fx::telemetryTitle(*served.profile);
    auto schema = m_telemetrySchemas.constFind(served.profile);
    if (schema == m_telemetrySchemas.cend())
        schema = m_telemetrySchemas.insert(served.profile, fx::telemetrySchema(*served.profile, served.packets, title));
    served.telemetry = m_server.advertise({t.telemetry, json, title, *schema, jsonSchema}, Delivery::Latest);
    served.telemetryRos2 = m_server.advertise({t.telemetryRos2, QStringLiteral("cdr"),
                                               fx::telemetryRos2Name(*served.profile),
                                               fx::telemetryRos2Schema(served.packets), QStringLiteral("ros2msg")},
                                              Delivery::Latest);
    served.pose = m_server.advertise({t.pose, json, "foxglove.PoseInFrame", fx::poseInFrameSchema(), jsonSchema},
                                     Delivery::Latest);
    served.transform = m_server.advertise(
        {t.transform, json, "foxglove.FrameTransform", fx::frameTransformSchema(), jsonSchema}, Delivery::Latest);
    served.events = m_server.advertise({t.events, json, "foxglove.Log", fx::logSchema(), jsonSchema}, Delivery::Every);
    served.markers =
        m_server.advertise({t.markers, json, "foxglove.Log", fx::logSchema(), jsonSchema}, Delivery::Every);
    // The true pose once the robot turns out to have one (onFrame).
}

void LiveRobots::withdraw(Served &served)
{
    for (foxglove::Server::ChannelId *id : {&served.telemetry, &served.telemetryRos2, &served.pose, &served.transform,
                                            &served.truePose, &served.roomTransform, &served.events, &served.markers})
        if (*id)
            m_server.withdraw(std::exchange(*id, 0));
}

void LiveRobots::onFrame(Served &served, double readSeconds, const oi::SensorSnapshot &frame)
{
    RobotSession *robot = served.robot;
    const quint64 ns = LivePlayback::protocolTimeNs(*robot, readSeconds);
    if (!m_clockRobot || m_clockRobot == robot || (robot->isReplay() && !m_clockRobot->isReplay())) {
        m_clockRobot = robot;
        m_playback->follow(robot->isReplay() ? robot : nullptr);
        m_server.setTime(ns);
    }
    // Nobody connected: nothing to look up for each channel, thirty robots
    // times 66.7 frames a second. The true pose is advertised once first.
    if (m_server.clientCount() == 0 && (served.truePose || !m_truePose)) {
        served.before.reset();
        return;
    }
    // Nothing is copied or made for a channel nobody reads; what is held
    // back is encoded only when it is sent.
    const auto reads = [this](foxglove::Server::ChannelId id) { return id && m_server.isSubscribed(id); };
    if (reads(served.telemetry))
        m_server.publish(served.telemetry, ns, [frame] { return oilink::snapshotToJsonText(frame); });
    if (reads(served.telemetryRos2))
        m_server.publish(served.telemetryRos2, ns,
                         [frame, packets = served.packets] { return fx::telemetryCdr(frame, packets); });
    const oi::Pose pose = robot->odometry().pose();
    const fx::RobotTopics &t = *served.topics;
    if (reads(served.pose))
        m_server.publish(served.pose, ns, [ns, &t, pose] { return fx::poseInFrameJson(ns, t.odomFrame, pose); });
    if (reads(served.transform))
        m_server.publish(served.transform, ns, [ns, &t, pose] {
            return fx::frameTransformJson(ns, t.odomFrame, t.baseFrame, pose);
        });
    if (m_truePose && (!served.truePose || reads(served.truePose) || reads(served.roomTransform))) {
        if (const std::optional<oi::Pose> truePose = m_truePose(robot)) {
            const QString json = QStringLiteral("json"), jsonSchema = QStringLiteral("jsonschema");
            if (!served.truePose) {
                served.truePose = m_server.advertise(
                    {t.truePose, json, "foxglove.PoseInFrame", fx::poseInFrameSchema(), jsonSchema},
                    foxglove::Delivery::Latest);
                served.roomTransform = m_server.advertise(
                    {t.roomTransform, json, "foxglove.FrameTransform", fx::frameTransformSchema(), jsonSchema},
                    foxglove::Delivery::Latest);
            }
            if (!served.odomInRoom)
                served.odomInRoom = fx::odomInRoom(*truePose, pose);
            if (reads(served.truePose))
                m_server.publish(served.truePose, ns,
                                 [ns, p = *truePose] { return fx::poseInFrameJson(ns, fx::kRoomFrame, p); });
            // Said with each frame, for a client that subscribes later.
            if (reads(served.roomTransform))
                m_server.publish(served.roomTransform, ns, [ns, &t, room = *served.odomInRoom] {
                    return fx::frameTransformJson(ns, fx::kRoomFrame, t.odomFrame, room);
                });
        }
    }
    if (!m_server.isSubscribed(served.events)) {
        served.before.reset();
        return;
    }
    fx::logEvents(served.before ? &*served.before : nullptr, frame, [&](int level, const QString &message) {
        m_server.publish(served.events, ns, [&] { return fx::logJson(ns, level, message, served.prefix); });
    });
    served.before = frame;
}

void LiveRobots::onMarkers(Served &served)
{
    const RobotMarkers &markers = served.robot->markers();
    for (const oilink::RecordingMarker &m : markers.list()) {
        if (served.markersSent.contains(m.id))
            continue;
        served.markersSent.insert(m.id);
        const quint64 ns = LivePlayback::protocolTimeNs(*served.robot, markers.seconds(m));
        m_server.publish(served.markers, ns, [&] { return fx::logJson(ns, fx::Info, m.label(), "marker"); });
    }
}

void LiveRobots::updateMetadata()
{
    QMap<QString, QString> metadata;
    for (const Served *served : std::as_const(m_robots)) {
        const RobotSession *robot = served->robot;
        const QString key = served->prefix + QLatin1Char('.');
        metadata.insert(key + "name", robot->name());
        const QMap<QString, QString> profile = fx::profileMetadata(robot->robotProfile());
        for (auto it = profile.cbegin(); it != profile.cend(); ++it)
            metadata.insert(key + it.key(), it.value());
        if (!robot->firmwareRelease().isEmpty())
            metadata.insert(key + "firmware.release", robot->firmwareRelease());
    }
    m_server.setMetadata(metadata);
}

#include "moc_live_robots.cpp"
