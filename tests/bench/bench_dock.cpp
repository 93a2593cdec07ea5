// SPDX-License-Identifier: GPL-3.0-or-later
// How long, in the robot's time, from each condition on the dock to the
// words that explain it: the virtual robot and the link on a clock the
// benchmark advances (so the figures are the rules' own, not the machine's).
// Targets: 5 s for the charging checks, 2 s for the rest.
//
//   build/tests/bench/bench_dock
#include "docked_robot.h"

#include "connection_doctor.h"

#include <QCoreApplication>
#include <QSignalSpy>

#include <cstdio>
#include <string>

using namespace docked;

namespace {

struct Figure {
    const char *condition;
    qint64 ms; // -1: never explained
    qint64 targetMs; // -1: shown for information
};

// Advances in 5 ms steps until `done`, at most `limitMs`; the time it took, or -1.
template <typename Done>
qint64 timeUntil(DockedRobot &r, Done done, qint64 limitMs)
{
    const qint64 from = r.clock.nowMs();
    while (!done() && r.clock.nowMs() - from < limitMs)
        r.runFor(5);
    return done() ? r.clock.nowMs() - from : -1;
}

qint64 safeRefused()
{
    DockedRobot r(true);
    if (!r.streams())
        return -1;
    r.runFor(500);
    r.ask(oi::Command::Safe, 131);
    return timeUntil(r, [&] { return r.mode.safeRefusedOnDock(); }, 10'000);
}

enum class Drain { Warning, Current, Charge };

qint64 fullOnTheDock(Drain shown)
{
    DockedRobot r(true);
    if (!r.streams())
        return -1;
    r.runFor(500);
    const std::int32_t charge = r.latest.raw(25);
    r.ask(oi::Command::Full, 132);
    switch (shown) {
    case Drain::Warning:
        return timeUntil(r, [&] { return r.mode.cause() == RobotMode::Cause::NotCharging; }, 10'000);
    case Drain::Current:
        return timeUntil(r, [&] { return r.latest.currentMa() < 0; }, 10'000);
    case Drain::Charge: // whole mAh in packet 25, at the robot's idle draw
        return timeUntil(r, [&] { return r.latest.raw(25) < charge; }, 60'000);
    }
    return -1;
}

qint64 firstTextLine()
{
    DockedRobot r(true);
    if (!r.streams())
        return -1;
    return timeUntil(r, [&] { return !r.text.isEmpty(); }, 10'000);
}

// The doctor on a robot asleep on its dock with older firmware: to the
// step that reads its text (the baud), or to its finding, which waits for a
// slow robot to wake on each wake line first.
qint64 doctorOnTheDock(bool toFinding)
{
    ManualClock clock;
    SimLineTransport line(oi::ProfileId::Create2, {}, clock);
    line.robot().setFirmwareRelease("release-3.8.1");
    const sim::World::Dock dock = *line.robot().world().dock;
    line.robot().placeAt(oi::Pose{dock.x, dock.y, dock.headingRad + std::numbers::pi});
    const std::uint8_t startAndPower[] = {128, 133};
    line.robot().receive(startAndPower);
    line.open();
    oilink::ConnectionDoctor doctor(line, oi::ProfileId::Create2, 0, clock);
    QObject::connect(&line, &oilink::Transport::bytesReceived, &doctor, &oilink::ConnectionDoctor::feed);
    QSignalSpy done(&doctor, &oilink::ConnectionDoctor::finished);
    qint64 textAtMs = -1;
    QObject::connect(&doctor, &oilink::ConnectionDoctor::stepDone, &doctor, [&](const QString &step) {
        if (textAtMs < 0 && step.contains(QStringLiteral("prints text")))
            textAtMs = clock.nowMs();
    });
    const qint64 from = clock.nowMs();
    doctor.start();
    if (!clock.advanceUntil([&] { return !done.isEmpty(); }, 60'000))
        return -1;
    const auto report = done.first().first().value<oilink::ConnectionDoctor::Report>();
    if (report.finding != oilink::ConnectionDoctor::Finding::TextOnDock)
        return -1;
    return toFinding ? clock.nowMs() - from : textAtMs - from;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const Figure figures[] = {
        {"Safe on the dock -> 'Safe mode is refused on the charger'", safeRefused(), 2000},
        {"Full on the dock -> 'the battery does not charge'", fullOnTheDock(Drain::Warning), 5000},
        {"Full on the dock -> packet 23 (current) below 0", fullOnTheDock(Drain::Current), 5000},
        {"Full on the dock -> packet 25 (charge) 1 mAh lower", fullOnTheDock(Drain::Charge), -1},
        {"Passive on the dock -> first status line read by the link", firstTextLine(), 5000},
        {"asleep on the dock -> doctor step: 'the robot prints text'", doctorOnTheDock(false), 5000},
        {"asleep on the dock -> doctor finding: 'prints its charging status'", doctorOnTheDock(true), -1},
    };
    bool ok = true;
    std::printf("%-62s %10s %10s\n", "condition -> explanation", "robot ms", "target ms");
    for (const Figure &f : figures) {
        const bool met = f.ms >= 0 && (f.targetMs < 0 || f.ms <= f.targetMs);
        ok = ok && met;
        std::printf("%-62s %10lld %10s %s\n", f.condition, static_cast<long long>(f.ms),
                    f.targetMs < 0 ? "-" : std::to_string(f.targetMs).c_str(), met ? "" : "MISSED");
    }
    return ok ? 0 : 1;
}
