// SPDX-License-Identifier: GPL-3.0-or-later
// The connection doctor names each cause on a virtual robot set up to show it.
#include "sim_line_transport.h"

#include "connection_doctor.h"

#include <QSignalSpy>
#include <QTest>

using namespace oilink;
using Finding = ConnectionDoctor::Finding;

namespace {
constexpr int kTimeoutMs = 30000;

const std::uint8_t kStart[] = {128};
const std::uint8_t kStartAndPower[] = {128, 133};

ConnectionDoctor::Report diagnose(SimLineTransport &line, std::optional<oi::ProfileId> profile, int baud = 0)
{
    line.open();
    ConnectionDoctor doctor(line, profile, baud);
    QObject::connect(&line, &Transport::bytesReceived, &doctor, &ConnectionDoctor::feed);
    QSignalSpy done(&doctor, &ConnectionDoctor::finished);
    doctor.start();
    if (!done.wait(kTimeoutMs))
        return {};
    return done.first().first().value<ConnectionDoctor::Report>();
}

QString explain(const ConnectionDoctor::Report &r)
{
    return r.summary + QStringLiteral(" | ") + r.steps.join(QStringLiteral(" | "));
}
} // namespace

class TestConnectionDoctor : public QObject {
    Q_OBJECT
private slots:
    void healthy()
    {
        SimLineTransport line(oi::ProfileId::Create2, {});
        const auto r = diagnose(line, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::Healthy, qPrintable(explain(r)));
        QCOMPARE(r.baud, 115200);
        QCOMPARE(r.profile, oi::ProfileId::Create2);
        QVERIFY2(r.steps.first().contains(QStringLiteral("after Start (it was in Off mode)")), qPrintable(explain(r)));
    }

    void nothingComesBack()
    {
        SimLineTransport line(oi::ProfileId::Create2, {115200, false});
        line.robot().disconnect();
        const auto r = diagnose(line, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::NothingComesBack, qPrintable(explain(r)));
        QCOMPARE(r.steps.size(), 4); // three bauds and the pin out of reach
        QVERIFY(r.steps.last().contains(QStringLiteral("no BRC pin")));
    }

    void wrongBaudNamesTheOneThatAnswers()
    {
        SimLineTransport line(oi::ProfileId::Create2, {});
        // Left streaming at 57600 by an earlier client.
        const std::uint8_t toBaud[] = {128, 129, 10};
        const std::uint8_t stream[] = {148, 1, 35};
        line.robot().receive(toBaud);
        line.robot().advance(std::chrono::milliseconds(100)); // what comes sooner may be lost
        line.robot().receive(stream);
        QCOMPARE(line.robot().baud(), 57600);
        const auto r = diagnose(line, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::WrongBaud, qPrintable(explain(r)));
        QCOMPARE(r.baud, 57600);
        QVERIFY2(r.summary.contains(QStringLiteral("answers at 57600 baud, not 115200")), qPrintable(r.summary));
        QVERIFY2(r.steps.first().contains(QStringLiteral("make no sense")), qPrintable(explain(r)));
    }

    void answersAt19200AfterThreePulses()
    {
        // An adapter that cannot go above 19200 baud.
        SimLineTransport line(oi::ProfileId::Create2, {19200, true});
        const auto r = diagnose(line, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::Baud19200AfterPulses, qPrintable(explain(r)));
        QCOMPARE(r.baud, 19200);
        QCOMPARE(line.robot().baud(), 19200);
    }

    void asleepAndWokeAfterAPulse()
    {
        SimLineTransport line(oi::ProfileId::Create2, {});
        line.robot().receive(kStartAndPower);
        QVERIFY(line.robot().asleep());
        const auto r = diagnose(line, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::WokeAfterPulse, qPrintable(explain(r)));
        QVERIFY(!line.robot().asleep());
    }

    void asleepOnTheDockWithOldFirmware()
    {
        SimLineTransport line(oi::ProfileId::Create2, {});
        line.robot().setFirmwareRelease("release-3.8.1");
        const sim::World::Dock dock = *line.robot().world().dock;
        line.robot().placeAt(oi::Pose{dock.x, dock.y, dock.headingRad + 3.14159265358979323846});
        line.robot().receive(kStartAndPower);
        const auto r = diagnose(line, oi::ProfileId::Create2);
        QVERIFY2(r.finding == Finding::AsleepDidNotWake, qPrintable(explain(r)));
        QVERIFY(r.summary.contains(QStringLiteral("on its dock with firmware before release-3.8.2")));
        QVERIFY(line.robot().asleep());
    }

    void answersAsAnotherProfile()
    {
        SimLineTransport line(oi::ProfileId::Create1, {});
        line.setBaud(57600);
        const auto r = diagnose(line, oi::ProfileId::Create2, 57600);
        QVERIFY2(r.finding == Finding::OtherProfile, qPrintable(explain(r)));
        QCOMPARE(r.profile, oi::ProfileId::Create1);
        QVERIFY2(r.summary.contains(QStringLiteral("answers as a Create, not as the Roomba 600 / Create 2")), qPrintable(r.summary));
    }

    void roomba500AndCreate2AnswerAlike()
    {
        SimLineTransport line(oi::ProfileId::Roomba500, {});
        line.robot().receive(kStart);
        const auto r = diagnose(line, std::nullopt);
        QVERIFY2(r.finding == Finding::RoombaOrCreate2, qPrintable(explain(r)));
        QVERIFY(r.summary.contains(QStringLiteral("Say which it is")));
        // Named, it is healthy: never Create 2 by itself.
        SimLineTransport named(oi::ProfileId::Roomba500, {});
        QCOMPARE(diagnose(named, oi::ProfileId::Roomba500).finding, Finding::Healthy);
    }
};

QTEST_GUILESS_MAIN(TestConnectionDoctor)
#include "tst_connection_doctor.moc"
