// SPDX-License-Identifier: GPL-3.0-or-later
// A soak with faults: RobotLink against the virtual robot on a
// pseudo-terminal for a long time, reached through a symlink as a USB
// adapter would be through /dev/serial/by-id. The robot adds stray 19s,
// corrupted and dropped bytes; every few minutes the port is pulled away
// (the pty closes and the symlink goes) and comes back as a new pty behind
// the same symlink; a recording runs all along. Not a test: run it by hand.
//
//   bench_soak [--minutes M] [--unplug-every-minutes U] [--unplugged-seconds S]
//              [--fault-rate P] [--recording FILE]
//
// Prints every minute, then: intact frames the robot sent while a client
// listened and the frames the link delivered, session by session (none may
// be lost outside the unplugged spans), reconnects, the resident memory at
// the start, middle and end, and the recording replayed in full against
// the live count.
#include "pty_robot_server.h"
#include "recording_file.h"
#include "local_robot_port.h"
#include "stream_parser.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTimer>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace {

constexpr std::uint8_t kStreamGroup = 100; // what the link streams from a Create 2 at 115200
constexpr int kDrainMs = 300;             // between silencing the robot and pulling the port

struct Options {
    double minutes = 30;
    double unplugEveryMinutes = 3;
    double unpluggedSeconds = 5;
    double faultRate = 0.0005; // per byte, for each of the three faults
    QString recording;
};

bool parseOptions(const QStringList &args, Options &o)
{
    for (qsizetype i = 1; i < args.size(); i += 2) {
        if (i + 1 >= args.size())
            return false;
        const QString &a = args[i];
        if (a == QLatin1String("--recording")) {
            o.recording = args[i + 1];
            continue;
        }
        bool ok = false;
        const double value = args[i + 1].toDouble(&ok);
        if (!ok || value < 0)
            return false;
        if (a == QLatin1String("--minutes"))
            o.minutes = value;
        else if (a == QLatin1String("--unplug-every-minutes"))
            o.unplugEveryMinutes = value;
        else if (a == QLatin1String("--unplugged-seconds"))
            o.unpluggedSeconds = value;
        else if (a == QLatin1String("--fault-rate"))
            o.faultRate = value;
        else
            return false;
    }
    return o.minutes > 0 && o.unplugEveryMinutes > 0;
}

long residentKiB()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : status.readAll().split('\n'))
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').value(0).toLong();
    return -1;
}

// Frames counted on both sides while one pty was plugged in.
struct Session {
    quint64 sent = 0;     // intact frames the robot wrote while the link had the port open
    quint64 received = 0; // snapshots the link delivered
};

class Soak : public QObject {
public:
    explicit Soak(const Options &options, const QString &dir)
        : m_options(options), m_symlink(QDir(dir).filePath(QStringLiteral("robot"))),
          m_robotSide(oi::profile(oi::ProfileId::Create2))
    {
        const std::uint8_t group[] = {kStreamGroup};
        m_robotSide.setExpectedStream(group);
        m_robotSide.setSnapshotHandler([this](const oi::SensorSnapshot &, oi::FrameKind kind) {
            if (kind == oi::FrameKind::Stream)
                ++m_sessions.back().sent;
        });
        m_recording = options.recording.isEmpty() ? QDir(dir).filePath(QStringLiteral("soak.oirec"))
                                                  : options.recording;
        oilink::connectEvent<oilink::event::Frame>(&m_link, this, [this] {
            ++m_live;
            if (m_plugged)
                ++m_sessions.back().received;
            else
                ++m_receivedUnplugged;
        });
        oilink::connectEvent<oilink::event::Error>(&m_link, this, [this] { ++m_errors; });
        oilink::connectEvent<oilink::event::StreamStarted>(&m_link, this,
                [this](oi::ProfileId, int, const QList<int> &packets) {
                    if (packets != QList<int>{kStreamGroup})
                        std::printf("warning: the link streams other packets than group %d\n", kStreamGroup);
                });
    }

    bool start()
    {
        if (!plugIn())
            return false;
        m_clock.start();
        m_link.post(oilink::request::Open{oilink::LinkSettings::serial(m_symlink, oi::ProfileId::Create2)});
        m_link.post(oilink::request::StartRecording{m_recording});
        const int totalMs = int(m_options.minutes * 60000);
        QTimer::singleShot(2000, this, [this] { m_rssStart = residentKiB(); });
        QTimer::singleShot(totalMs / 2, this, [this] { m_rssMiddle = residentKiB(); });
        QTimer::singleShot(totalMs, this, [this] { finish(); });
        m_unplugTimer.setInterval(int(m_options.unplugEveryMinutes * 60000));
        connect(&m_unplugTimer, &QTimer::timeout, this, &Soak::pullOut);
        m_unplugTimer.start();
        m_progress.setInterval(60000);
        connect(&m_progress, &QTimer::timeout, this, &Soak::printProgress);
        m_progress.start();
        return true;
    }

private:
    bool plugIn()
    {
        m_server = std::make_unique<sim::PtyRobotServer>(oi::profile(oi::ProfileId::Create2), ++m_seed);
        QString error;
        if (!m_server->open(&error)) {
            std::fprintf(stderr, "bench_soak: %s\n", qPrintable(error));
            return false;
        }
        const double p = m_options.faultRate;
        m_server->robot().robot().setFaultRates({p, p, p});
        QFile::remove(m_symlink);
        if (!QFile::link(m_server->slavePath(), m_symlink)) {
            std::fprintf(stderr, "bench_soak: cannot link %s\n", qPrintable(m_symlink));
            return false;
        }
        // What the robot says while nobody has the port open is lost, as on a cable.
        connect(&m_server->robot(), &sim::RealTimeRobot::bytesOut, this, [this](const QByteArray &bytes) {
            if (m_server->clientConnected())
                m_robotSide.feed({reinterpret_cast<const std::uint8_t *>(bytes.constData()), std::size_t(bytes.size())});
        });
        m_robotSide.reset();
        const std::uint8_t group[] = {kStreamGroup};
        m_robotSide.setExpectedStream(group);
        m_sessions.push_back({});
        m_plugged = true;
        return true;
    }

    // Silences the robot, lets the link read what is on the line, then
    // closes the pty and takes the symlink away.
    void pullOut()
    {
        m_server->robot().robot().disconnect();
        QTimer::singleShot(kDrainMs, this, [this] {
            m_plugged = false;
            ++m_unplugs;
            m_server.reset();
            QFile::remove(m_symlink);
            QTimer::singleShot(int(m_options.unpluggedSeconds * 1000), this, [this] {
                if (!plugIn())
                    QCoreApplication::exit(1);
            });
        });
    }

    void printProgress()
    {
        const oilink::LinkStats s = m_link.lastStatistics();
        std::printf("%5.1f min: %llu frames, %.1f/s, %llu checksum failures, %llu resyncs, %u reconnects, "
                    "%ld KiB resident\n",
                    m_clock.elapsed() / 60000.0, static_cast<unsigned long long>(m_live), s.framesPerSecond,
                    static_cast<unsigned long long>(s.checksumFailures),
                    static_cast<unsigned long long>(s.resyncs), s.reconnects, residentKiB());
        std::fflush(stdout);
    }

    void finish()
    {
        m_unplugTimer.stop();
        m_progress.stop();
        m_server->robot().robot().disconnect();
        QTimer::singleShot(kDrainMs, this, [this] {
            m_plugged = false;
            m_link.closeAndWait();
            m_rssEnd = residentKiB();
            report();
            QCoreApplication::exit(0);
        });
    }

    void report()
    {
        const oilink::LinkStats s = m_link.lastStatistics();
        quint64 sent = 0, received = 0, worst = 0;
        for (std::size_t i = 0; i < m_sessions.size(); ++i) {
            const Session &session = m_sessions[i];
            sent += session.sent;
            received += session.received;
            const quint64 lost = session.sent > session.received ? session.sent - session.received : 0;
            worst = std::max(worst, lost);
            std::printf("session %zu: %llu intact frames sent, %llu received, %lld lost\n", i + 1,
                        static_cast<unsigned long long>(session.sent),
                        static_cast<unsigned long long>(session.received),
                        static_cast<long long>(session.sent) - static_cast<long long>(session.received));
        }
        std::printf("\nminutes:            %.1f\n", m_clock.elapsed() / 60000.0);
        std::printf("intact frames:      %llu sent, %llu received while plugged in, %llu while unplugged; "
                    "at most %llu lost in one session\n",
                    static_cast<unsigned long long>(sent), static_cast<unsigned long long>(received),
                    static_cast<unsigned long long>(m_receivedUnplugged), static_cast<unsigned long long>(worst));
        std::printf("line:               %llu checksum failures, %llu resyncs, %llu bytes discarded\n",
                    static_cast<unsigned long long>(s.checksumFailures), static_cast<unsigned long long>(s.resyncs),
                    static_cast<unsigned long long>(s.bytesDiscarded));
        std::printf("unplugged:          %d times; reconnects succeeded %u, failed attempts %d\n", m_unplugs,
                    s.reconnects, m_errors);
        std::printf("resident memory:    %ld KiB at start, %ld KiB in the middle, %ld KiB at the end\n",
                    m_rssStart, m_rssMiddle, m_rssEnd);

        QString error;
        const std::optional<oilink::Recording> recording = oilink::Recording::load(m_recording, &error);
        if (!recording) {
            std::printf("recording:          does not open: %s\n", qPrintable(error));
            return;
        }
        quint64 replayed = 0;
        recording->forEachSnapshot([&](qint64, const oi::SensorSnapshot &) { ++replayed; });
        std::printf("recording:          %s, %.1f MB, %.1f min, %s; %llu frames replayed, %llu live\n",
                    qPrintable(m_recording), QFile(m_recording).size() / 1e6, recording->durationUs() / 6e7,
                    recording->damage() ? qPrintable(recording->damage()->describe()) : "intact",
                    static_cast<unsigned long long>(replayed), static_cast<unsigned long long>(m_live));
    }

    Options m_options;
    QString m_symlink;
    QString m_recording;
    std::unique_ptr<sim::PtyRobotServer> m_server;
    oi::StreamParser m_robotSide; // the robot's own output, read as the link should read it
    oilink::LocalRobotPort m_link;
    std::vector<Session> m_sessions;
    bool m_plugged = false;
    quint64 m_live = 0;
    quint64 m_receivedUnplugged = 0;
    int m_unplugs = 0;
    int m_errors = 0;
    std::uint32_t m_seed = 0;
    long m_rssStart = -1, m_rssMiddle = -1, m_rssEnd = -1;
    QElapsedTimer m_clock;
    QTimer m_unplugTimer;
    QTimer m_progress;
};

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    oilink::registerLinkMetaTypes();
    Options options;
    if (!parseOptions(app.arguments(), options)) {
        std::fprintf(stderr, "usage: bench_soak [--minutes M] [--unplug-every-minutes U] "
                             "[--unplugged-seconds S] [--fault-rate P] [--recording FILE]\n");
        return 2;
    }
    QTemporaryDir dir;
    if (!dir.isValid())
        return 1;
    std::printf("soak: %.1f minutes, port pulled every %.1f minutes for %.1f s, faults %.4f per byte each\n",
                options.minutes, options.unplugEveryMinutes, options.unpluggedSeconds, options.faultRate);
    std::fflush(stdout);
    Soak soak(options, dir.path());
    if (!soak.start())
        return 1;
    return QCoreApplication::exec();
}
