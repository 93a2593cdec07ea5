// SPDX-License-Identifier: GPL-3.0-or-later
// What the machine charges a thread for waking up, the floor under every
// dashboard figure: with one robot the virtual robots' thread wakes for each
// stream frame (every 15 ms) and the window's for each display tick (every
// 33 ms), whatever work they then do. Two threads, each woken every 15 ms
// for --seconds (default 20) and doing nothing else:
//  - bare: clock_nanosleep to the next 15 ms, as a thread can at the least;
//  - Qt: a QThread's event loop with a precise QTimer, as the robots' is.
// Prints each one's CPU per wake-up and the share of a core at 66.7 wakes a
// second. On a virtual machine this is most of the cost of one robot.
//
//   bench_wake_cost [--seconds S]

#include <QCoreApplication>
#include <QThread>
#include <QTimer>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

#include <sys/resource.h>

namespace {

constexpr long kPeriodNs = 15'000'000;

double threadCpuSeconds()
{
    rusage usage{};
    getrusage(RUSAGE_THREAD, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec)
           + double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
}

struct Cost {
    double cpuSeconds = 0;
    long wakes = 0;
    double usPerWake() const { return wakes ? cpuSeconds * 1e6 / double(wakes) : 0; }
};

long wakesIn(double seconds) { return long(seconds * 1e9 / double(kPeriodNs)); }

Cost bareWakes(double seconds)
{
    const long wakes = wakesIn(seconds);
    const double before = threadCpuSeconds();
    timespec next{};
    clock_gettime(CLOCK_MONOTONIC, &next);
    for (long i = 0; i < wakes; ++i) {
        next.tv_nsec += kPeriodNs;
        if (next.tv_nsec >= 1'000'000'000) {
            next.tv_nsec -= 1'000'000'000;
            ++next.tv_sec;
        }
        clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, nullptr);
    }
    return {threadCpuSeconds() - before, wakes};
}

Cost qtWakes(double seconds)
{
    Cost cost;
    QThread thread;
    QObject home;
    home.moveToThread(&thread);
    thread.start();
    // The timer and its count live on the thread; the main thread waits.
    QMetaObject::invokeMethod(
        &home,
        [&] {
            auto *timer = new QTimer(&home);
            timer->setTimerType(Qt::PreciseTimer);
            const long wakes = wakesIn(seconds);
            const double before = threadCpuSeconds();
            QObject::connect(timer, &QTimer::timeout, &home, [&cost, timer, wakes, before] {
                if (++cost.wakes < wakes)
                    return;
                timer->stop();
                cost.cpuSeconds = threadCpuSeconds() - before;
                QThread::currentThread()->quit();
            });
            timer->start(int(kPeriodNs / 1'000'000));
        },
        Qt::BlockingQueuedConnection);
    thread.wait();
    return cost;
}

void print(const char *name, const Cost &cost)
{
    const double percent = cost.usPerWake() / (double(kPeriodNs) / 1e3) * 100;
    std::printf("%-6s %ld wake-ups, %.1f us of CPU each: %.2f %% of a core at one every 15 ms\n", name, cost.wakes,
                cost.usPerWake(), percent);
}

} // namespace

int main(int argc, char **argv)
{
    double seconds = 20;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--seconds") == 0 && i + 1 < argc) {
            char *end = nullptr;
            seconds = std::strtod(argv[++i], &end);
            if (*end != '\0' || !(seconds > 0)) {
                std::fprintf(stderr, "--seconds: '%s' is not a number of seconds more than 0\n", argv[i]);
                return 2;
            }
        } else {
            std::fprintf(stderr, "usage: %s [--seconds S]\n", argv[0]);
            return 2;
        }
    }
    QCoreApplication app(argc, argv);
    const Cost bare = bareWakes(seconds);
    const Cost qt = qtWakes(seconds);
    print("bare", bare);
    print("Qt", qt);
    std::printf("result: wake-up %.1f us bare, %.1f us in a Qt event loop\n", bare.usPerWake(), qt.usPerWake());
    return 0;
}
