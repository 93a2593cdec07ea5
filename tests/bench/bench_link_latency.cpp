// SPDX-License-Identifier: GPL-3.0-or-later
// Latency of the robot link: from the moment the last byte of a stream frame
// is written into a pseudo-terminal to the moment its snapshot arrives on the
// receiving (GUI-like) thread, through SerialTransport, StreamParser and the
// queued signal of LocalRobotPort. Also the link thread's CPU time per
// second of streaming. Not a test: run it by hand on a quiet machine.
//
//   bench_link_latency [--frames N] [--interval-us U] [--cpu-seconds S]
#include "local_robot_port.h"

#include <QCoreApplication>
#include <QTimer>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

constexpr std::uint8_t kGroup = 100;
constexpr int kRealFrameIntervalUs = 15000; // what a robot streams at

struct Options {
    int frames = 10000;
    int intervalUs = 2000;
    int cpuSeconds = 5;
};

bool parseOptions(int argc, char **argv, Options &o)
{
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc)
            return false;
        const int value = std::atoi(argv[++i]);
        if (value <= 0)
            return false;
        if (a == "--frames")
            o.frames = value;
        else if (a == "--interval-us")
            o.intervalUs = value;
        else if (a == "--cpu-seconds")
            o.cpuSeconds = value;
        else
            return false;
    }
    return true;
}

// Group-100 frames of a Create 2, each carrying its sequence number in the
// two encoder counts (43 low half, 44 high half).
class FrameMaker {
public:
    FrameMaker()
    {
        const oi::RobotProfile &p = oi::profile(oi::ProfileId::Create2);
        const oi::PacketGroup *g = p.group(kGroup);
        for (int id = g->first; id < 43; ++id)
            m_encoderOffset += static_cast<std::size_t>(p.replySize(id));
        m_frame.assign(3 + g->bytes + 1, 0);
        m_frame[0] = 19;
        m_frame[1] = static_cast<std::uint8_t>(1 + g->bytes);
        m_frame[2] = kGroup;
    }
    const std::vector<std::uint8_t> &make(std::uint32_t sequence)
    {
        std::uint8_t *data = m_frame.data() + 3 + m_encoderOffset;
        data[0] = static_cast<std::uint8_t>(sequence >> 8);
        data[1] = static_cast<std::uint8_t>(sequence);
        data[2] = static_cast<std::uint8_t>(sequence >> 24);
        data[3] = static_cast<std::uint8_t>(sequence >> 16);
        unsigned sum = 0;
        for (std::size_t i = 0; i + 1 < m_frame.size(); ++i)
            sum += m_frame[i];
        m_frame.back() = static_cast<std::uint8_t>(-sum & 0xFF);
        return m_frame;
    }
    static std::uint32_t sequenceOf(const oi::SensorSnapshot &s)
    {
        return (static_cast<std::uint32_t>(s.raw(44)) & 0xFFFF) << 16 | (static_cast<std::uint32_t>(s.raw(43)) & 0xFFFF);
    }
    std::size_t size() const { return m_frame.size(); }

private:
    std::size_t m_encoderOffset = 0;
    std::vector<std::uint8_t> m_frame;
};

bool writeAll(int fd, const std::vector<std::uint8_t> &bytes)
{
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0)
            return false;
        done += static_cast<std::size_t>(n);
    }
    return true;
}

// Reads what the link sent (Start and Stream) so that the bench starts
// writing only once the port is open.
bool waitForStream(int master)
{
    std::vector<std::uint8_t> got;
    const auto deadline = Clock::now() + std::chrono::seconds(10);
    while (got.size() < 4 && Clock::now() < deadline) {
        pollfd p{master, POLLIN, 0};
        if (::poll(&p, 1, 50) > 0 && (p.revents & POLLIN)) {
            std::uint8_t buf[64];
            const ssize_t n = ::read(master, buf, sizeof buf);
            if (n > 0)
                got.insert(got.end(), buf, buf + n);
        }
    }
    return got.size() >= 4 && got[0] == 128 && got[1] == 148;
}

struct Run {
    std::vector<Clock::time_point> written;
    std::vector<Clock::time_point> received;
    std::atomic<bool> writerDone{false};
    std::size_t receivedCount = 0;
};

// Writes `count` frames, one every `intervalUs`, stamping each after its last
// byte went into the master side.
void writeFrames(int master, Run &run, std::uint32_t firstSequence, int count, int intervalUs)
{
    FrameMaker maker;
    auto next = Clock::now();
    for (int i = 0; i < count; ++i) {
        std::this_thread::sleep_until(next);
        const std::uint32_t sequence = firstSequence + static_cast<std::uint32_t>(i);
        if (!writeAll(master, maker.make(sequence)))
            break;
        run.written[sequence] = Clock::now();
        next += std::chrono::microseconds(intervalUs);
    }
    run.writerDone = true;
}

// Runs the event loop until every frame came back or `grace` passed after
// the writer finished.
void collect(Run &run, std::size_t expected)
{
    QTimer poll;
    Clock::time_point writerFinished{};
    QObject::connect(&poll, &QTimer::timeout, [&] {
        if (run.receivedCount >= expected) {
            QCoreApplication::quit();
            return;
        }
        if (run.writerDone) {
            if (writerFinished == Clock::time_point{})
                writerFinished = Clock::now();
            else if (Clock::now() - writerFinished > std::chrono::seconds(2))
                QCoreApplication::quit();
        }
    });
    poll.start(20);
    QCoreApplication::exec();
}

double percentile(std::vector<double> sorted, double p)
{
    if (sorted.empty())
        return 0;
    const std::size_t at = std::min(sorted.size() - 1, static_cast<std::size_t>(p * static_cast<double>(sorted.size() - 1) + 0.5));
    return sorted[at];
}

} // namespace

int main(int argc, char **argv)
{
    Options options;
    if (!parseOptions(argc, argv, options)) {
        std::fprintf(stderr, "usage: bench_link_latency [--frames N] [--interval-us U] [--cpu-seconds S]\n");
        return 2;
    }
    QCoreApplication app(argc, argv);

    const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) {
        std::perror("bench_link_latency: pseudo-terminal");
        return 1;
    }
    const QString slave = QString::fromLocal8Bit(::ptsname(master));

    const int realFrames = options.cpuSeconds * 1000000 / kRealFrameIntervalUs;
    Run run;
    run.written.resize(static_cast<std::size_t>(options.frames + realFrames));
    run.received.resize(run.written.size());

    oilink::LocalRobotPort link;
    oilink::connectEvent<oilink::event::Frame>(&link, &app, [&run](const oi::SensorSnapshot &s) {
        const std::uint32_t sequence = FrameMaker::sequenceOf(s);
        if (sequence < run.received.size()) {
            run.received[sequence] = Clock::now();
            ++run.receivedCount;
        }
    });
    oilink::connectEvent<oilink::event::Error>(&link, &app, [](const QString &message) {
        std::fprintf(stderr, "bench_link_latency: %s\n", qPrintable(message));
    });
    link.post(oilink::request::Open{oilink::LinkSettings::serial(slave, oi::ProfileId::Create2)});
    if (!waitForStream(master)) {
        std::fprintf(stderr, "bench_link_latency: the link did not start a stream on %s\n", qPrintable(slave));
        return 1;
    }

    std::printf("bench_link_latency: %d frames of %zu bytes (Create 2, group %u) into %s, one every %d us\n",
                options.frames, FrameMaker().size(), kGroup, qPrintable(slave), options.intervalUs);

    // Phase 1: latency.
    const auto cpuBefore = link.workerCpuTime();
    const auto wallBefore = Clock::now();
    std::thread writer(writeFrames, master, std::ref(run), 0u, options.frames, options.intervalUs);
    collect(run, static_cast<std::size_t>(options.frames));
    writer.join();
    const auto cpuFast = link.workerCpuTime() - cpuBefore;
    const double wallFast = std::chrono::duration<double>(Clock::now() - wallBefore).count();

    std::vector<double> latencyUs;
    latencyUs.reserve(static_cast<std::size_t>(options.frames));
    for (int i = 0; i < options.frames; ++i) {
        const auto &r = run.received[static_cast<std::size_t>(i)];
        if (r != Clock::time_point{})
            latencyUs.push_back(std::chrono::duration<double, std::micro>(r - run.written[static_cast<std::size_t>(i)]).count());
    }
    std::sort(latencyUs.begin(), latencyUs.end());
    const double p50 = percentile(latencyUs, 0.50);
    const double p99 = percentile(latencyUs, 0.99);
    const double max = latencyUs.empty() ? 0 : latencyUs.back();
    std::printf("received %zu of %d frames\n", latencyUs.size(), options.frames);
    std::printf("latency, last byte written -> snapshot on the receiving thread: p50 %.0f us, p99 %.0f us, max %.0f us"
                " (target p99 <= 2000 us: %s)\n",
                p50, p99, max, p99 <= 2000 ? "met" : "MISSED");
    std::printf("link thread CPU at %.0f frames/s: %.2f ms per second\n", options.frames / wallFast,
                std::chrono::duration<double, std::milli>(cpuFast).count() / wallFast);

    // Phase 2: CPU time at the rate a robot streams.
    if (realFrames > 0) {
        const std::size_t before = run.receivedCount;
        const auto cpu0 = link.workerCpuTime();
        const auto wall0 = Clock::now();
        run.writerDone = false;
        std::thread realRate(writeFrames, master, std::ref(run), static_cast<std::uint32_t>(options.frames), realFrames,
                             kRealFrameIntervalUs);
        collect(run, before + static_cast<std::size_t>(realFrames));
        realRate.join();
        const auto cpu = link.workerCpuTime() - cpu0;
        const double wall = std::chrono::duration<double>(Clock::now() - wall0).count();
        const double msPerSecond = std::chrono::duration<double, std::milli>(cpu).count() / wall;
        std::printf("link thread CPU at %.1f frames/s (one every 15 ms, %d s): %.2f ms per second of streaming"
                    " (%.2f %% of one core); received %zu of %d\n",
                    1e6 / kRealFrameIntervalUs, options.cpuSeconds, msPerSecond, msPerSecond / 10.0,
                    run.receivedCount - before, realFrames);
    }

    link.stop();
    ::close(master);
    return 0;
}
