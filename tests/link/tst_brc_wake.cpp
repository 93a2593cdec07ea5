// SPDX-License-Identifier: GPL-3.0-or-later
// The link and the robot's BRC pin: a sleeping Create 2 woken by the link
// and kept awake, through the in-process virtual robot and over a
// pseudo-terminal (roomba-sim's control socket standing in for RTS).
#include "sim_process.h"

#include "brc_pulser.h"
#include "real_time_robot.h"
#include "robot_link.h"
#include "tcp_transport.h"
#include "virtual_transport.h"

#include <QSignalSpy>
#include <QTest>

using namespace std::chrono_literals;

namespace {
constexpr int kTimeoutMs = 20000;
// Ten minutes of 15 ms stream frames.
constexpr int kTenMinutesOfFrames = 10 * 60 * 1000 / 15;
} // namespace

class TestBrcWake : public QObject {
    Q_OBJECT
private slots:
    void pulsesReachTheVirtualRobot()
    {
        oilink::VirtualTransport transport(oi::ProfileId::Create2, 1);
        transport.open();
        sim::VirtualRobot &robot = transport.robot()->robot();
        const std::uint8_t startAndPower[] = {128, 133};
        robot.receive(startAndPower);
        QVERIFY(robot.asleep());
        oilink::BrcPulser pulser;
        pulser.setTransport(&transport);
        QVERIFY(pulser.canPulse());
        QSignalSpy pulsed(&pulser, &oilink::BrcPulser::pulsed);
        QVERIFY(pulser.wake());
        QVERIFY(!robot.asleep()); // woken as the pin fell
        QTRY_COMPARE_WITH_TIMEOUT(pulsed.size(), 1, kTimeoutMs);

        // Three pulses of 100 ms: 19200 baud.
        QCOMPARE(robot.baud(), 115200);
        QVERIFY(pulser.pulseForBaud19200());
        QTRY_COMPARE_WITH_TIMEOUT(pulsed.size(), 4, kTimeoutMs);
        QCOMPARE(robot.baud(), 19200);
    }

    void rawTcpSaysItCannot()
    {
        oilink::TcpTransport transport(QStringLiteral("127.0.0.1"), 1);
        oilink::BrcPulser pulser;
        pulser.setTransport(&transport);
        QVERIFY(!pulser.canPulse());
        QVERIFY(!pulser.wake());
        QVERIFY(transport.brcUnavailable().contains(QStringLiteral("raw TCP carries no modem lines")));
    }

    // roomba-sim's robot asleep, its clock 100 times as fast: the link wakes
    // it, and pulses every real second (100 robot seconds) keep it awake
    // through ten of its minutes.
    void theLinkWakesARobotOnAPtyAndKeepsItAwake()
    {
        SimProcess sim;
        QVERIFY(sim.start({QStringLiteral("--asleep"), QStringLiteral("--speed"), QStringLiteral("100")}));
        oilink::RobotLink link;
        QSignalSpy errors(&link, &oilink::RobotLink::errorOccurred);
        int frames = 0, notPassive = 0;
        connect(&link, &oilink::RobotLink::snapshot, this, [&](const oi::SensorSnapshot &s) {
            ++frames;
            notPassive += s.oiMode() != oi::OiMode::Passive;
        });
        oilink::LinkSettings settings = oilink::LinkSettings::serial(sim.where(), oi::ProfileId::Create2);
        settings.streamPackets = {35};
        settings.keepAwakeMs = 1000;
        link.open(settings);
        QTRY_VERIFY_WITH_TIMEOUT(frames > 0, kTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(frames >= kTenMinutesOfFrames, 60000);
        QCOMPARE(notPassive, 0);
        QCOMPARE(link.state(), oilink::LinkState::Streaming);
        link.close();
    }

    // The same robot without the keep-awake pulses falls asleep: the
    // stream stops and the link says there is no data.
    void withoutKeepAwakeItSleeps()
    {
        SimProcess sim;
        QVERIFY(sim.start({QStringLiteral("--asleep"), QStringLiteral("--speed"), QStringLiteral("100")}));
        oilink::RobotLink link;
        QSignalSpy states(&link, &oilink::RobotLink::stateChanged);
        int frames = 0;
        connect(&link, &oilink::RobotLink::snapshot, this, [&](const oi::SensorSnapshot &) { ++frames; });
        oilink::LinkSettings settings = oilink::LinkSettings::serial(sim.where(), oi::ProfileId::Create2);
        settings.streamPackets = {35};
        settings.keepAwakeMs = 0;
        link.open(settings);
        QTRY_VERIFY_WITH_TIMEOUT(frames > 0, kTimeoutMs);
        QTRY_COMPARE_WITH_TIMEOUT(link.state(), oilink::LinkState::Stale, kTimeoutMs);
        link.close();
    }
};

QTEST_GUILESS_MAIN(TestBrcWake)
#include "tst_brc_wake.moc"
