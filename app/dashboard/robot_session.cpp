// SPDX-License-Identifier: GPL-3.0-or-later
#include "robot_session.h"

#include "command_catalog.h"

#include <algorithm>

namespace {
constexpr qsizetype kMaxBannerBytes = 8192;
}

RobotSession::RobotSession(QObject *parent) : QObject(parent)
{
    oilink::registerLinkMetaTypes();
    m_clock.start();
    connect(&m_link, &oilink::RobotLinkThread::snapshot, this, &RobotSession::onSnapshot);
    connect(&m_link, &oilink::RobotLinkThread::streamStarted, this,
            [this](oi::ProfileId profile, int, const QList<int> &) { onStreamStarted(profile); });
    connect(&m_link, &oilink::RobotLinkThread::stateChanged, this, [this](oilink::LinkState state) {
        m_state = state;
        emit stateChanged(state);
    });
    connect(&m_link, &oilink::RobotLinkThread::statistics, this, [this](const oilink::LinkStats &stats) {
        m_stats = stats;
        emit statisticsChanged(stats);
    });
    connect(&m_link, &oilink::RobotLinkThread::errorOccurred, this, &RobotSession::errorOccurred);
    connect(&m_link, &oilink::RobotLinkThread::rawBytesSent, this, &RobotSession::onBytesSent);
    connect(&m_link, &oilink::RobotLinkThread::rawBytesReceived, this, &RobotSession::onBytesReceived);
    connect(&m_link, &oilink::RobotLinkThread::recordingStatus, this, [this](const oilink::RecordingStatus &s) {
        m_recording = s;
        emit recordingStatus(s);
    });
    connect(&m_link, &oilink::RobotLinkThread::replayStatus, this, [this](const oilink::ReplayStatus &s) {
        m_replay = s;
        m_sinceReplayStatus.start();
        emit replayStatus(s);
    });
}

RobotSession::~RobotSession() { closeAndWait(); }

void RobotSession::setTransportFactory(oilink::RobotLink::TransportFactory factory)
{
    m_link.setTransportFactory(std::move(factory));
}

void RobotSession::setSnapshotObserver(std::function<void(double, const oi::SensorSnapshot &)> observer)
{
    m_observer = std::move(observer);
}

void RobotSession::connectTo(const oilink::LinkSettings &settings)
{
    if (m_connected)
        m_link.close();
    m_settings = settings;
    m_connected = true;
    m_replay = {};
    m_sinceReplayStatus.invalidate();
    m_latest = oi::SensorSnapshot(*m_profile);
    m_snapshotCount = 0;
    m_clock.restart();
    m_link.open(settings);
}

void RobotSession::disconnectFromRobot()
{
    if (!m_connected)
        return;
    m_connected = false;
    m_link.close();
}

void RobotSession::closeAndWait()
{
    if (m_link.isRunning())
        m_link.closeAndWait();
    m_connected = false;
}

bool RobotSession::send(const QByteArray &bytes)
{
    if (!m_connected || bytes.isEmpty())
        return false;
    m_link.send(bytes);
    return true;
}

double RobotSession::secondsSinceConnect() const
{
    if (!isReplay() || !m_sinceReplayStatus.isValid())
        return m_clock.nsecsElapsed() / 1e9;
    // Between the replay's reports its clock runs on at its speed.
    const double sinceReport = m_replay.playing ? m_sinceReplayStatus.nsecsElapsed() / 1e9 * m_replay.speed : 0.0;
    return std::min(m_replay.positionUs / 1e6 + sinceReport, m_replay.durationUs / 1e6);
}

void RobotSession::onStreamStarted(oi::ProfileId profile)
{
    if (m_profile->id == profile && m_latest.robotProfile().id == profile)
        return;
    m_profile = &oi::profile(profile);
    m_latest = oi::SensorSnapshot(*m_profile);
    emit profileChanged(profile);
}

void RobotSession::onSnapshot(const oi::SensorSnapshot &snapshot)
{
    if (snapshot.robotProfile().id != m_profile->id)
        onStreamStarted(snapshot.robotProfile().id);
    m_latest.merge(snapshot);
    ++m_snapshotCount;
    if (m_observer)
        m_observer(secondsSinceConnect(), snapshot);
}

void RobotSession::onBytesSent(const QByteArray &bytes)
{
    // A Reset makes the robot print its banner with the firmware version.
    if (bytes.size() == 1 && static_cast<std::uint8_t>(bytes[0]) == oi::commandSpec(oi::Command::Reset).opcode) {
        m_awaitingBanner = true;
        m_bannerText.clear();
    }
    emit bytesSent(bytes, QDateTime::currentMSecsSinceEpoch());
}

void RobotSession::onBytesReceived(const QByteArray &bytes)
{
    if (m_awaitingBanner) {
        m_bannerText += bytes;
        if (m_bannerText.size() > kMaxBannerBytes)
            m_bannerText = m_bannerText.right(kMaxBannerBytes);
        if (const auto info = oi::parseFirmwareBanner(std::string_view(m_bannerText.constData(), m_bannerText.size()))) {
            m_awaitingBanner = false;
            m_firmware = QString::fromStdString(info->release);
            m_corrections = info->corrections;
            emit firmwareChanged(m_firmware);
        }
    }
    emit bytesReceived(bytes, QDateTime::currentMSecsSinceEpoch());
}
