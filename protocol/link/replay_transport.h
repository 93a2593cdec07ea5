// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "recording_file.h"
#include "replay_control.h"
#include "transport.h"

#include <QElapsedTimer>
#include <QMetaType>
#include <QTimer>

#include <optional>

namespace oilink {

// A recording played back as if it were the robot: received bytes come out
// at their recorded times (scaled by the speed), always ending on a frame
// boundary so that pausing, seeking and stepping never split a frame. What
// the link writes is accepted and dropped: there is no robot to answer.
class ReplayTransport : public Transport {
    Q_OBJECT
public:
    static constexpr int kTickMs = 10;
    static constexpr int kStatusEveryMs = 100;

    explicit ReplayTransport(const QString &path, QObject *parent = nullptr);
    ~ReplayTransport() override;

    void open() override; // loads the file and starts playing
    void close() override;
    bool isOpen() const override { return m_open; }
    bool write(const QByteArray &bytes) override;
    void flush(int) override {}
    QString describe() const override;
    // The recorded time of the frame being delivered.
    qint64 readTimeUs() const override { return m_readTimeUs; }

    void controlReplay(const ReplayCommand &command) override;
    ReplayStatus status() const;

private:
    void tick();
    void play();
    void pause();
    void seek(qint64 timeUs);
    void showFrame(int frame);
    void deliverThrough(qsizetype end);
    void deliver(qsizetype end, qint64 timeUs);
    void emitStatus();

    QString m_path;
    std::optional<Recording> m_recording;
    bool m_open = false;
    bool m_playing = false;
    bool m_finished = false;
    double m_speed = 1.0;
    qint64 m_positionUs = 0;
    qint64 m_readTimeUs = 0; // of the bytes being delivered
    qsizetype m_delivered = 0; // received bytes handed to the link so far
    int m_nextFrame = 0;
    QTimer m_tick;
    QElapsedTimer m_sinceTick;
    QElapsedTimer m_sinceStatus;
};

} // namespace oilink
