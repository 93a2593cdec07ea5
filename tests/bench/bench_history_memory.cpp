// SPDX-License-Identifier: GPL-3.0-or-later
// What the sensor history costs: an hour of group 100 frames from a Create 2
// at the 15 ms stream period, for one robot at the full rate and for a
// classroom of robots of which one is selected (full rate) and the rest are
// kept at the reduced rate. Prints the bytes each history holds, the
// process's resident memory, and the CPU time an append takes.
//
//   bench_history_memory [--minutes M] [--robots N]
//
// The frames are synthesized like a driving robot's: batteries that drain,
// currents that follow driving and standing, encoders that count and roll
// over, cliff and light-bump signals with noise, bumps now and then.
#include "sensor_history.h"

#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace {

constexpr double kFramePeriod = 0.015;

// VmRSS from /proc/self/status, in MiB.
double residentMiB()
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmRSS:", 0) == 0)
            return std::atof(line.c_str() + 6) / 1024.0;
    return -1;
}

// Process CPU time in seconds: the machine may be busy with other work.
double cpuNow() { return double(std::clock()) / CLOCKS_PER_SEC; }

double mib(std::size_t bytes) { return bytes / 1048576.0; }

// Frame k of robot r: every packet of group 100, in range, varying as it
// would while the robot drives around a room.
class DrivingRobot {
public:
    explicit DrivingRobot(int robot) : m_robot(robot), m_seed(0x9e3779b9u * unsigned(robot + 1)) {}

    oi::SensorSnapshot frame(long k)
    {
        const oi::RobotProfile &profile = oi::profile(oi::ProfileId::Create2);
        oi::SensorSnapshot s(profile);
        const double t = k * kFramePeriod + m_robot * 3.7;
        // Drives for 30 s, stands for 10 s, now and then a bump and a turn.
        const bool driving = std::fmod(t, 40.0) < 30.0;
        const bool bump = driving && std::fmod(t, 13.0) < 0.2;
        const int speed = driving ? (bump ? -100 : 200) : 0;
        const int left = speed + (bump ? 0 : int(30 * std::sin(t / 5.0)));
        const int right = speed - (bump ? 0 : int(30 * std::sin(t / 5.0)));
        m_leftCounts += left * kFramePeriod * 508.8 / (3.14159265 * 72.0);
        m_rightCounts += right * kFramePeriod * 508.8 / (3.14159265 * 72.0);
        const double wall = std::max(0.0, std::sin(t / 9.0));

        s.set(7, bump ? 1 : 0);
        s.set(8, wall > 0.9);
        for (int id = 9; id <= 12; ++id)
            s.set(id, 0);
        s.set(13, 0);
        s.set(14, 0);
        s.set(15, 0);
        s.set(16, 0);
        s.set(17, std::fmod(t, 120.0) < 5.0 ? 161 : 0);
        s.set(18, 0);
        s.set(19, int(std::lround((left + right) / 2.0 * kFramePeriod)));
        s.set(20, int(std::lround((right - left) / 235.0 * kFramePeriod * 57.3)));
        s.set(21, 0);
        s.set(22, int(16400 - t * 0.4 + 8 * noise()));
        s.set(23, int((driving ? -1100 : -350) + 60 * noise()));
        s.set(24, 27 + int(t / 1800));
        s.set(25, int(2600 - t * 0.25));
        s.set(26, 2696);
        s.set(27, int(900 * wall * wall));
        for (int id = 28; id <= 31; ++id)
            s.set(id, 2700 + int(40 * noise()) + 100 * (id - 28));
        s.set(32, 0);
        s.set(33, 0);
        s.set(34, 0);
        s.set(35, 2);
        s.set(36, 0);
        s.set(37, 0);
        s.set(38, 0);
        s.set(39, speed);
        s.set(40, bump ? -1 : 32768 - 1);
        s.set(41, right);
        s.set(42, left);
        s.set(43, wrap16(m_leftCounts));
        s.set(44, wrap16(m_rightCounts));
        int lightBumper = 0;
        for (int id = 46; id <= 51; ++id) {
            const int signal = std::clamp(int(15 + 1600 * std::pow(std::max(0.0, std::sin(t / (4.0 + id - 46) + id)), 4) + 6 * noise()), 0, 4095);
            s.set(id, signal);
            lightBumper |= signal > 1000 ? 1 << (id - 46) : 0;
        }
        s.set(45, lightBumper);
        s.set(52, 0);
        s.set(53, 0);
        s.set(54, driving ? 180 + int(40 * noise()) : 0);
        s.set(55, driving ? 170 + int(45 * noise()) : 0);
        s.set(56, 0);
        s.set(57, 0);
        s.set(58, driving ? 1 : 0);
        return s;
    }

private:
    // Uniform in -1 .. 1.
    double noise()
    {
        m_seed = m_seed * 1664525u + 1013904223u;
        return (m_seed >> 8) / double(1u << 23) - 1.0;
    }
    static int wrap16(double counts)
    {
        return int(std::int16_t(std::uint16_t(std::int64_t(std::floor(counts)) & 0xffff)));
    }

    int m_robot;
    unsigned m_seed;
    double m_leftCounts = 0, m_rightCounts = 0;
};

} // namespace

int main(int argc, char **argv)
{
    double minutes = 60;
    int robots = 30;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--minutes") && i + 1 < argc) {
            minutes = std::atof(argv[++i]);
        } else if (!std::strcmp(argv[i], "--robots") && i + 1 < argc) {
            robots = std::atoi(argv[++i]);
        } else {
            std::fprintf(stderr, "usage: bench_history_memory [--minutes M] [--robots N]\n");
            return 2;
        }
    }
    if (!(minutes > 0) || robots < 1) {
        std::fprintf(stderr, "bench_history_memory: --minutes and --robots need positive numbers\n");
        return 2;
    }
    const long frames = long(minutes * 60.0 / kFramePeriod);
    std::printf("bench_history_memory: %.0f min of Create 2 group 100 frames (%ld frames, 80 data bytes each)\n",
                minutes, frames);
    std::printf("history capacity %zu frames; reduced rate keeps %d frames of %d\n",
                SensorHistory::kDefaultCapacity, 2, SensorHistory::kReducedBlockFrames);
    const double rssStart = residentMiB();

    // The synthesis alone, to tell the append's share of the times below.
    double synthesisNs = 0;
    {
        DrivingRobot robot(0);
        const long n = std::min(frames, 24'000L);
        double sink = 0;
        const auto start = cpuNow();
        for (long k = 0; k < n; ++k)
            sink += robot.frame(k).raw(22);
        synthesisNs = (cpuNow() - start) * 1e9 / double(n);
        std::printf("synthesizing a frame: %.0f ns (checksum %.0f)\n", synthesisNs, sink);
    }

    // One robot at the full rate.
    {
        SensorHistory history;
        DrivingRobot robot(0);
        const auto start = cpuNow();
        for (long k = 0; k < frames; ++k)
            history.append(k * kFramePeriod, robot.frame(k));
        const double seconds = (cpuNow() - start);
        std::printf("one robot, full rate: %zu frames held, %.1f MiB (%.1f bytes a frame), "
                    "RSS +%.1f MiB, append %.0f ns a frame\n",
                    history.frameCount(), mib(history.memoryBytes()),
                    double(history.memoryBytes()) / double(history.frameCount()), residentMiB() - rssStart,
                    seconds * 1e9 / double(frames) - synthesisNs);
    }

    // A classroom: robot 0 selected, the others reduced, all fed frame by frame.
    {
        std::vector<std::unique_ptr<SensorHistory>> histories;
        std::vector<DrivingRobot> sources;
        for (int r = 0; r < robots; ++r) {
            histories.push_back(std::make_unique<SensorHistory>());
            histories.back()->setReducedRate(r != 0);
            sources.emplace_back(r);
        }
        const auto start = cpuNow();
        for (long k = 0; k < frames; ++k)
            for (int r = 0; r < robots; ++r)
                histories[std::size_t(r)]->append(k * kFramePeriod, sources[std::size_t(r)].frame(k));
        const double seconds = (cpuNow() - start);
        std::size_t total = 0;
        for (const auto &h : histories)
            total += h->memoryBytes();
        const SensorHistory &full = *histories.front();
        std::printf("%d robots (1 full, %d reduced): %.1f MiB in all, RSS %.1f MiB (+%.1f MiB), "
                    "append %.0f ns a frame\n",
                    robots, robots - 1, mib(total), residentMiB(), residentMiB() - rssStart,
                    seconds * 1e9 / double(frames * robots) - synthesisNs);
        std::printf("  selected robot: %.1f MiB, %zu frames\n", mib(full.memoryBytes()), full.frameCount());
        if (robots > 1) {
            const SensorHistory &reduced = *histories.back();
            std::printf("  each reduced robot: %.1f MiB, %zu frames\n", mib(reduced.memoryBytes()),
                        reduced.frameCount());
        }
        std::printf("targets: one robot for an hour <= 60 MB, 30 robots for an hour <= 1.5 GB\n");
    }
    return 0;
}
