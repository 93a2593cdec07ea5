// SPDX-License-Identifier: GPL-3.0-or-later
// The link and the robot's BRC pin: a sleeping Create 2 woken by the link
// and kept awake, through the in-process virtual robot and over a
// pseudo-terminal (roomba-sim's control socket standing in for RTS). In
// process, the robot and the link's timed rules run on a clock the test
// advances.
#include "sim_line_transport.h"
#include "sim_process.h"

#include "brc_pulser.h"
#include "real_time_robot.h"
#include "rfc2217.h"
#include "robot_link.h"
#include "tcp_robot_server.h"
#include "tcp_transport.h"
#include "virtual_transport.h"

#include <QSignalSpy>
#include <QTest>

namespace {
constexpr int kTimeoutMs = 20000;
// Ten minutes of 15 ms stream frames.
constexpr int kTenMinutesOfFrames = 10 * 60 * 1000 / 15;
const std::uint8_t kStartAndPower[] = {128, 133};

oilink::LinkSettings testLine(std::optional<oi::ProfileId> profile)
{
    oilink::LinkSettings settings = oilink::LinkSettings::serial(QStringLiteral("test line"), profile);
    settings.streamPackets = {35};
    return settings;
}
} // namespace

class TestBrcWake : public QObject {
    Q_OBJECT

    // A link to a sleeping robot whose clock runs 100 times as fast: woken,
    // and with a pulse every real second (100 robot seconds) kept awake and
    // in Passive through ten of its minutes of frames.
    void staysAwakeForTenMinutes(oilink::LinkSettings settings)
    {
        oilink::RobotLink link;
        int frames = 0, notPassive = 0;
        connect(&link, &oilink::RobotLink::snapshot, this, [&](const oi::SensorSnapshot &s) {
            ++frames;
            notPassive += s.oiMode() != oi::OiMode::Passive;
        });
        settings.streamPackets = {35};
        settings.keepAwakeMs = 1000;
        link.open(settings);
        QTRY_VERIFY_WITH_TIMEOUT(frames > 0, kTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(frames >= kTenMinutesOfFrames, 60000);
        QCOMPARE(notPassive, 0);
        QCOMPARE(link.state(), oilink::LinkState::Streaming);
        link.close();
    }

private slots:
    void pulsesReachTheVirtualRobot()
    {
        ManualClock clock;
        SimLineTransport transport(oi::ProfileId::Create2, {}, clock);
        transport.open();
        sim::VirtualRobot &robot = transport.robot();
        robot.receive(kStartAndPower);
        QVERIFY(robot.asleep());
        oilink::BrcPulser pulser(clock);
        pulser.setTransport(&transport);
        QVERIFY(pulser.canPulse());
        QSignalSpy pulsed(&pulser, &oilink::BrcPulser::pulsed);
        QSignalSpy awake(&pulser, &oilink::BrcPulser::awake);
        QVERIFY(pulser.wake());
        clock.advance(oilink::BrcPulser::kWakePulseMs - 1);
        QVERIFY(pulsed.isEmpty());
        QVERIFY(robot.asleep()); // it wakes as the pulse ends
        clock.advance(1);
        QCOMPARE(pulsed.size(), 1);
        QVERIFY(!robot.asleep());
        clock.advance(oilink::BrcPulser::kWakeMs - 1);
        QVERIFY(awake.isEmpty()); // the robot's time to wake is still running
        clock.advance(1);
        QCOMPARE(awake.size(), 1);

        // Three pulses of 100 ms, 2 s after waking: 19200 baud.
        clock.advance(2000);
        QCOMPARE(robot.baud(), 115200);
        QVERIFY(pulser.pulseForBaud19200());
        clock.advance(3 * oilink::BrcPulser::kBaudPulseMs + 2 * oilink::BrcPulser::kBaudGapMs);
        QCOMPARE(pulsed.size(), 4);
        QCOMPARE(robot.baud(), 19200);
    }

    // The documents count any three pulses of 50 to 500 ms as the sequence
    // for 19200 baud, so a wake pulse (a link opened three times in a row) or
    // a keep-awake pulse must never be one of those.
    void wakeAndKeepAwakePulsesLeaveTheBaud()
    {
        ManualClock clock;
        SimLineTransport transport(oi::ProfileId::Create2, {}, clock);
        transport.open();
        sim::VirtualRobot &robot = transport.robot();
        oilink::BrcPulser pulser(clock);
        pulser.setTransport(&transport);
        QSignalSpy pulsed(&pulser, &oilink::BrcPulser::pulsed);
        for (int i = 0; i < 3; ++i)
            QVERIFY(pulser.wake());
        QVERIFY(clock.advanceUntil([&] { return pulsed.size() == 3; }, kTimeoutMs));
        QCOMPARE(robot.baud(), 115200);
        // A keep-awake every 400 ms would have pulsed for 100 ms.
        pulser.setKeepAwake(400);
        QVERIFY(clock.advanceUntil([&] { return pulsed.size() >= 6; }, kTimeoutMs));
        QCOMPARE(robot.baud(), 115200);
    }

    // ERRATA 17: the link sends Start (and anything else) once the robot it
    // woke listens, whether the profile is named or found by the probe. A
    // Start sent sooner is lost (tst_robot_sleep), and the link would report
    // no data and send Start again.
    void theLinksStartReachesARobotItWoke_data()
    {
        QTest::addColumn<bool>("named");
        QTest::addColumn<int>("starts"); // Start bytes sent before the first frame
        QTest::newRow("named profile") << true << 1;
        QTest::newRow("found by the probe") << false << 2; // the probe's and the stream's
    }
    void theLinksStartReachesARobotItWoke()
    {
        QFETCH(bool, named);
        QFETCH(int, starts);
        ManualClock clock;
        oilink::RobotLink link(clock);
        SimLineTransport *line = nullptr;
        link.setTransportFactory([&](const oilink::LinkSettings &) {
            line = new SimLineTransport(oi::ProfileId::Create2, {}, clock);
            line->robot().receive(kStartAndPower);
            return line;
        });
        QStringList errors;
        connect(&link, &oilink::RobotLink::errorOccurred, this, [&](const QString &e) { errors << e; });
        int startsSent = 0;
        connect(&link, &oilink::RobotLink::rawBytesSent, this,
                [&](const QByteArray &bytes) { startsSent += int(bytes.count(char(128))); });
        std::optional<oi::SensorSnapshot> first;
        int startsBeforeFirst = 0;
        QStringList errorsBeforeFirst;
        connect(&link, &oilink::RobotLink::snapshot, this, [&](const oi::SensorSnapshot &s) {
            if (first)
                return;
            first = s;
            startsBeforeFirst = startsSent;
            errorsBeforeFirst = errors;
        });
        link.open(testLine(named ? std::optional(oi::ProfileId::Create2) : std::nullopt));
        QVERIFY(line && line->robot().asleep());
        QVERIFY(clock.advanceUntil([&] { return first.has_value(); }, kTimeoutMs));
        QVERIFY2(errorsBeforeFirst.isEmpty(), qPrintable(errorsBeforeFirst.join(QStringLiteral(" | "))));
        QCOMPARE(startsBeforeFirst, starts);
        QCOMPARE(first->oiMode(), oi::OiMode::Passive);
        QCOMPARE(line->pinPulledLow, 1);
        link.close();
    }

    // The in-process robot is seen awake: no wake pulse to wait for, so the
    // stream is asked for as the link opens.
    void anAwakeInProcessRobotIsNotWaitedFor()
    {
        oilink::RobotLink link;
        link.setTransportFactory([](const oilink::LinkSettings &s) {
            return new sim::VirtualTransport(s.virtualRobot, s.virtualSeed);
        });
        QSignalSpy started(&link, &oilink::RobotLink::streamStarted);
        link.open(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QCOMPARE(started.size(), 1);
        link.close();
    }

    // ERRATA 17: keep-awake pulses go to the robots that sleep; the Create
    // never sleeps, and its BRC pin would only change its baud.
    void keepAwakeOnlyForRobotsThatSleep_data()
    {
        QTest::addColumn<int>("profile");
        QTest::addColumn<bool>("pulsed");
        QTest::newRow("create2") << int(oi::ProfileId::Create2) << true;
        QTest::newRow("roomba500") << int(oi::ProfileId::Roomba500) << true;
        QTest::newRow("create1") << int(oi::ProfileId::Create1) << false;
    }
    void keepAwakeOnlyForRobotsThatSleep()
    {
        QFETCH(int, profile);
        QFETCH(bool, pulsed);
        const auto id = oi::ProfileId(profile);
        ManualClock clock;
        oilink::RobotLink link(clock);
        SimLineTransport *line = nullptr;
        link.setTransportFactory([&](const oilink::LinkSettings &s) {
            line = new SimLineTransport(id, {}, clock);
            line->setBaud(s.baud);
            return line;
        });
        int frames = 0;
        connect(&link, &oilink::RobotLink::snapshot, this, [&] { ++frames; });
        oilink::LinkSettings settings = testLine(id);
        settings.keepAwakeMs = 100;
        link.open(settings);
        // 600 ms of frames: six keep-awake periods.
        QVERIFY(clock.advanceUntil([&] { return frames >= 40; }, kTimeoutMs));
        if (pulsed)
            QVERIFY2(line->pinPulledLow >= 4, qPrintable(QString::number(line->pinPulledLow)));
        else
            QCOMPARE(line->pinPulledLow, 0);
        link.close();
    }

    void rfc2217CarriesEveryByte()
    {
        rfc2217::Bytes data;
        for (int b = 0; b < 256; ++b)
            data.push_back(std::uint8_t(b));
        rfc2217::Bytes wire = rfc2217::escape(data.data(), data.size());
        QCOMPARE(wire.size(), data.size() + 1); // 0xFF doubled
        const rfc2217::Bytes control = rfc2217::setControl(rfc2217::kRtsOn);
        wire.insert(wire.begin() + 100, control.begin(), control.end());
        // A rate with 0xFF among its four bytes: doubled inside the subnegotiation.
        const rfc2217::Bytes rate = rfc2217::setBaudRate(0x0001C2FF);
        QCOMPARE(rate.size(), std::size_t(3 + 1 + 5 + 2));
        wire.insert(wire.begin() + 200, rate.begin(), rate.end());
        const rfc2217::Bytes will = rfc2217::willComPort();
        wire.insert(wire.begin(), will.begin(), will.end());
        // Fed a byte at a time: commands come out, the data goes through.
        rfc2217::Decoder decoder;
        rfc2217::Bytes out;
        std::vector<int> values;
        std::vector<std::uint32_t> rates;
        for (std::uint8_t b : wire) {
            const rfc2217::Bytes got = decoder.feed(&b, 1, [&](std::uint8_t command, const rfc2217::Bytes &value) {
                if (command == rfc2217::kSetBaudRate) {
                    rates.push_back(rfc2217::baudRateOf(value));
                    return;
                }
                QCOMPARE(command, rfc2217::kSetControl);
                QCOMPARE(value.size(), std::size_t(1));
                values.push_back(value[0]);
            });
            out.insert(out.end(), got.begin(), got.end());
        }
        QVERIFY(out == data);
        QCOMPARE(values, std::vector<int>{rfc2217::kRtsOn});
        QCOMPARE(rates, std::vector<std::uint32_t>{0x0001C2FF});
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
        staysAwakeForTenMinutes(oilink::LinkSettings::serial(sim.where(), oi::ProfileId::Create2));
    }

    // Over TCP the pulses need RFC 2217: the bridge's RTS line carries them.
    void rfc2217WakesARobotOverTcpAndKeepsItAwake()
    {
        sim::TcpRobotServer server(oi::profile(oi::ProfileId::Create2));
        server.setRfc2217(true);
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        server.robot().setTimeScale(100);
        const std::uint8_t startAndPower[] = {128, 133};
        server.robot().robot().receive(startAndPower);
        QVERIFY(server.robot().robot().asleep());
        oilink::LinkSettings settings =
            oilink::LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.serverPort(), oi::ProfileId::Create2);
        settings.tcpRfc2217 = true;
        staysAwakeForTenMinutes(settings);
    }

    void rawTcpCannotWakeIt()
    {
        sim::TcpRobotServer server(oi::profile(oi::ProfileId::Create2));
        QVERIFY(server.listen(QHostAddress::LocalHost, 0));
        const std::uint8_t startAndPower[] = {128, 133};
        server.robot().robot().receive(startAndPower);
        oilink::RobotLink link;
        QSignalSpy errors(&link, &oilink::RobotLink::errorOccurred);
        link.open(oilink::LinkSettings::tcp(QStringLiteral("127.0.0.1"), server.serverPort(), oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(!errors.isEmpty(), kTimeoutMs);
        QVERIFY2(errors.first().first().toString().contains(
                     QStringLiteral("raw TCP carries no modem lines, so it cannot wake the robot")),
                 qPrintable(errors.first().first().toString()));
        QVERIFY(server.robot().robot().asleep());
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
