// SPDX-License-Identifier: GPL-3.0-or-later
// What the pack's health costs per frame: BatteryHealth::observe() on a
// million frames of a discharge with a current step every few seconds (as
// the robot's model calls it, once a frame), and report(), which the
// session asks for once a second. Prints ns per frame and µs per report.
// Run by hand, or by tests/bench/perf_table.sh: build/tests/bench/bench_battery_health
#include "battery_health.h"

#include <QElapsedTimer>

#include <cstdio>

int main()
{
    constexpr int kFrames = 1'000'000;
    std::vector<oi::SensorSnapshot> frames;
    frames.reserve(4000);
    // 60 s of frames, every 15 ms: driving 15 s, resting 5 s, in turn.
    for (int i = 0; i < 4000; ++i) {
        oi::SensorSnapshot s(oi::profile(oi::ProfileId::Create2));
        const bool driving = (i * 15 / 1000) % 20 < 15;
        const int ma = driving ? -1900 : -950;
        s.set(21, 0);
        s.set(22, 15000 - i / 10 + ma / 2);
        s.set(23, ma);
        s.set(25, 2400 - i / 100);
        s.set(26, 3000);
        frames.push_back(s);
    }
    BatteryHealth health;
    QElapsedTimer timer;
    timer.start();
    for (int i = 0; i < kFrames; ++i)
        health.observe(frames[std::size_t(i) % frames.size()], i * 0.015);
    const double nsPerFrame = double(timer.nsecsElapsed()) / kFrames;

    constexpr int kReports = 10'000;
    double confidence = 0;
    timer.restart();
    for (int i = 0; i < kReports; ++i)
        confidence += health.report().confidence;
    const double usPerReport = double(timer.nsecsElapsed()) / kReports / 1000;
    std::printf("result: battery health %.1f ns per frame, %.2f us per report (%d resistance samples, check %.0f)\n",
                nsPerFrame, usPerReport, health.measurement().resistanceSamples, confidence);
    return 0;
}
