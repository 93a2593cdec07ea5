// SPDX-License-Identifier: GPL-3.0-or-later
#include "replay_transport.h"

#include <QFileInfo>

#include <algorithm>

namespace oilink {

ReplayTransport::ReplayTransport(const QString &path, QObject *parent)
    : Transport(parent), m_path(path), m_tick(this)
{
    m_tick.setInterval(kTickMs);
    m_tick.setTimerType(Qt::PreciseTimer);
    connect(&m_tick, &QTimer::timeout, this, &ReplayTransport::tick);
}

ReplayTransport::~ReplayTransport() = default;

QString ReplayTransport::describe() const
{
    return tr("replay of %1").arg(QFileInfo(m_path).fileName());
}

void ReplayTransport::open()
{
    if (!m_recording) {
        QString error;
        m_recording = Recording::load(m_path, &error);
        if (!m_recording) {
            emit errorOccurred(error);
            return;
        }
    }
    m_open = true;
    emit opened();
    seek(0);
    play();
}

void ReplayTransport::close()
{
    m_open = false;
    m_playing = false;
    m_tick.stop();
}

bool ReplayTransport::write(const QByteArray &)
{
    return m_open;
}

void ReplayTransport::controlReplay(const ReplayCommand &command)
{
    if (!m_open)
        return;
    switch (command.kind) {
    case ReplayCommand::Kind::Play:
        play();
        break;
    case ReplayCommand::Kind::Pause:
        pause();
        break;
    case ReplayCommand::Kind::SetSpeed:
        if (command.speed >= kMinReplaySpeed && command.speed <= kMaxReplaySpeed)
            m_speed = command.speed;
        break;
    case ReplayCommand::Kind::Seek:
    {
        qint64 timeUs = std::clamp<qint64>(command.timeUs, 0, m_recording->durationUs());
        const auto &frames = m_recording->frames();
        const auto next = std::lower_bound(frames.begin(), frames.end(), timeUs,
                                           [](const Recording::Frame &f, qint64 t) { return f.timeUs < t; });
        if (command.atOrAfter && next != frames.end())
            timeUs = next->timeUs;
        seek(timeUs);
        break;
    }
    case ReplayCommand::Kind::Step: {
        pause();
        const int count = static_cast<int>(m_recording->frames().size());
        if (count > 0)
            showFrame(std::clamp(m_nextFrame - 1 + command.frames, 0, count - 1));
        break;
    }
    }
    emitStatus();
}

void ReplayTransport::play()
{
    if (m_finished)
        seek(0);
    m_playing = true;
    m_sinceTick.start();
    m_tick.start();
}

void ReplayTransport::pause()
{
    m_playing = false;
    m_tick.stop();
}

void ReplayTransport::seek(qint64 timeUs)
{
    const auto &frames = m_recording->frames();
    const auto after = std::upper_bound(frames.begin(), frames.end(), timeUs,
                                        [](qint64 t, const Recording::Frame &f) { return t < f.timeUs; });
    const int last = static_cast<int>(after - frames.begin()) - 1;
    if (last >= 0) {
        showFrame(last);
    } else {
        m_delivered = 0;
        m_nextFrame = 0;
        m_finished = false;
    }
    m_positionUs = timeUs;
}

// Hands the link frame `frame` alone: from the end of the one before it.
// The new position is announced first, so that the frame's snapshot arrives
// after it and is placed at the frame's time.
void ReplayTransport::showFrame(int frame)
{
    const auto &frames = m_recording->frames();
    m_delivered = frame > 0 ? frames[frame - 1].end : 0;
    m_nextFrame = frame + 1;
    m_positionUs = frames[frame].timeUs;
    m_finished = false;
    emitStatus();
    deliverThrough(frames[frame].end);
}

// Frame by frame, each at its recorded time, so that the link stamps every
// snapshot with the time the robot sent it, at any speed.
void ReplayTransport::deliverThrough(qsizetype end)
{
    // The link may close this transport from a slot of any delivery.
    const auto &frames = m_recording->frames();
    auto first = std::upper_bound(frames.begin(), frames.end(), m_delivered,
                                  [](qsizetype at, const Recording::Frame &f) { return at < f.end; });
    for (auto i = first - frames.begin(); m_recording && i < qsizetype(m_recording->frames().size())
                                          && m_recording->frames()[i].end <= end; ++i)
        deliver(m_recording->frames()[i].end, m_recording->frames()[i].timeUs);
    if (m_recording)
        deliver(end, m_positionUs);
}

void ReplayTransport::deliver(qsizetype end, qint64 timeUs)
{
    if (end <= m_delivered)
        return;
    const QByteArray bytes = m_recording->receivedBytes().mid(m_delivered, end - m_delivered);
    m_delivered = end;
    m_readTimeUs = timeUs;
    emit bytesReceived(bytes);
}

void ReplayTransport::tick()
{
    if (!m_playing)
        return;
    // Never past the end: a report beyond it would make the end look like a jump back.
    m_positionUs = std::min(m_recording->durationUs(),
                            m_positionUs + static_cast<qint64>(m_sinceTick.nsecsElapsed() / 1000.0 * m_speed));
    m_sinceTick.start();
    const auto &frames = m_recording->frames();
    int last = m_nextFrame - 1;
    while (last + 1 < static_cast<int>(frames.size()) && frames[last + 1].timeUs <= m_positionUs)
        ++last;
    const bool newFrames = last >= m_nextFrame;
    m_nextFrame = last + 1;
    if (!m_sinceStatus.isValid() || m_sinceStatus.elapsed() >= kStatusEveryMs)
        emitStatus(); // before the frames it counts
    if (newFrames)
        deliverThrough(frames[last].end);
    if (m_positionUs >= m_recording->durationUs()) {
        // Whatever followed the last frame (a reply, a banner) comes too.
        deliverThrough(m_recording->receivedBytes().size());
        m_finished = true;
        pause();
        emitStatus();
    }
}

ReplayStatus ReplayTransport::status() const
{
    ReplayStatus s;
    s.path = m_path;
    s.playing = m_playing;
    s.finished = m_finished;
    s.speed = m_speed;
    s.positionUs = m_positionUs;
    s.frame = m_nextFrame - 1;
    if (m_recording) {
        s.durationUs = m_recording->durationUs();
        s.frameCount = static_cast<int>(m_recording->frames().size());
        s.markers = m_recording->markers();
        s.markersLeftOut = m_recording->markersLeftOut();
        if (m_recording->damage())
            s.damage = m_recording->damage()->describe();
    }
    return s;
}

void ReplayTransport::emitStatus()
{
    m_sinceStatus.start();
    emit replayStatus(status());
}

} // namespace oilink

#include "moc_replay_transport.cpp"
