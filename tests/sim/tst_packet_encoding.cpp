// SPDX-License-Identifier: GPL-3.0-or-later
// appendPacketData must be the exact inverse of SensorSnapshot::decode, and
// a stream frame made with it must read as oi::packetsAsSent says, without bytes.
#include "packets_as_sent.h"
#include "packets_as_sent.h"
#include "stream_parser.h"

#include <QTest>

#include <random>

using namespace oi;

Q_DECLARE_METATYPE(oi::ProfileId)

class TestPacketEncoding : public QObject {
    Q_OBJECT
private slots:
    void roundTrip_data();
    void roundTrip();
    void bytesAreBigEndianAndTwosComplement();
    void outOfRangeValuesSaturate();
    void unknownIdsWriteNothing();
    void packetsAsSentAreTheStreamFrame_data();
    void packetsAsSentAreTheStreamFrame();
};

void TestPacketEncoding::roundTrip_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::addColumn<int>("id");
    for (ProfileId p : allProfiles()) {
        const RobotProfile &profile = oi::profile(p);
        for (const PacketInfo &info : profile.packets())
            if (profile.isValidSensorId(info.id)) // the SCI sends its packets in groups only
                QTest::addRow("%s/%d", profile.key.data(), info.id) << p << int(info.id);
        for (const PacketGroup &g : profile.groups())
            QTest::addRow("%s/group%d", profile.key.data(), g.id) << p << int(g.id);
    }
}

void TestPacketEncoding::roundTrip()
{
    QFETCH(ProfileId, profile);
    QFETCH(int, id);
    const RobotProfile &p = oi::profile(profile);
    std::mt19937 rng(std::uint32_t(id) * 7919u + std::uint32_t(profile));
    for (int round = 0; round < 50; ++round) {
        SensorSnapshot values(p);
        for (const PacketInfo &info : p.packets()) {
            // The whole representable range of the packet's bytes, not just the
            // documented one: the encoder must not lose bits either way.
            const bool two = info.bytes == 2;
            const std::int32_t lo = info.isSigned ? (two ? -32768 : -128) : 0;
            const std::int32_t hi = info.isSigned ? (two ? 32767 : 127) : (two ? 65535 : 255);
            values.set(info.id, std::uniform_int_distribution<std::int32_t>(lo, hi)(rng));
        }
        Bytes out;
        const std::size_t written = oi::appendPacketData(values, id, out);
        QCOMPARE(int(written), p.replySize(id));
        QCOMPARE(int(out.size()), p.replySize(id));
        SensorSnapshot decoded(p);
        QCOMPARE(decoded.decode(id, out), written);
        int first = id, last = id;
        if (const PacketGroup *g = p.group(id)) {
            first = g->first;
            last = g->last;
        }
        for (int packet = first; packet <= last; ++packet)
            QCOMPARE(decoded.raw(packet), values.raw(packet));
    }
}

void TestPacketEncoding::bytesAreBigEndianAndTwosComplement()
{
    SensorSnapshot values(profile(ProfileId::Create2));
    values.set(23, -200);  // current, signed 16-bit
    values.set(22, 15000); // voltage, unsigned 16-bit
    values.set(24, -5);    // temperature, signed 8-bit
    Bytes out;
    oi::appendPacketData(values, 23, out);
    oi::appendPacketData(values, 22, out);
    oi::appendPacketData(values, 24, out);
    QCOMPARE(out, (Bytes{0xFF, 0x38, 0x3A, 0x98, 0xFB}));
}

void TestPacketEncoding::outOfRangeValuesSaturate()
{
    SensorSnapshot values(profile(ProfileId::Create2));
    values.set(19, 40000);
    values.set(7, -3);
    Bytes out;
    oi::appendPacketData(values, 19, out);
    oi::appendPacketData(values, 7, out);
    QCOMPARE(out, (Bytes{0x7F, 0xFF, 0x00}));
}

void TestPacketEncoding::unknownIdsWriteNothing()
{
    Bytes out;
    QCOMPARE(oi::appendPacketData(SensorSnapshot(profile(ProfileId::Create1)), 43, out), std::size_t(0));
    QCOMPARE(oi::appendPacketData(SensorSnapshot(profile(ProfileId::Create1)), 100, out), std::size_t(0));
    QCOMPARE(oi::appendPacketData(SensorSnapshot(profile(ProfileId::Create2)), 59, out), std::size_t(0));
    QVERIFY(out.empty());
}

// A robot on the broker streams values, not bytes: its link must get the
// snapshot the robot's own stream of the same packets would have given,
// packets missing from the values and values out of range included.
void TestPacketEncoding::packetsAsSentAreTheStreamFrame_data()
{
    QTest::addColumn<ProfileId>("profile");
    QTest::addColumn<std::vector<int>>("ids");
    for (ProfileId p : allProfiles()) {
        const RobotProfile &profile = oi::profile(p);
        if (profile.polled())
            continue; // the SCI streams nothing
        for (const PacketGroup &g : profile.groups())
            if (g.bytes + 1 <= 255)
                QTest::addRow("%s/group%d", profile.key.data(), g.id) << p << std::vector<int>{g.id};
        QTest::addRow("%s/7-35-22-19-0", profile.key.data()) << p << std::vector<int>{7, 35, 22, 19, 0};
    }
}

void TestPacketEncoding::packetsAsSentAreTheStreamFrame()
{
    QFETCH(ProfileId, profile);
    QFETCH(std::vector<int>, ids);
    const RobotProfile &p = oi::profile(profile);
    std::mt19937 rng(std::uint32_t(ids.front()) * 31u + std::uint32_t(profile));
    for (int round = 0; round < 20; ++round) {
        SensorSnapshot values(p);
        for (const PacketInfo &info : p.packets())
            if (rng() % 4 != 0) // a quarter of them never told
                values.set(info.id, std::uniform_int_distribution<std::int32_t>(-70000, 70000)(rng));
        // [19][n][id][data]...[checksum], as the robot streams it.
        Bytes body;
        for (int id : ids) {
            body.push_back(std::uint8_t(id));
            QVERIFY(oi::appendPacketData(values, id, body) > 0);
        }
        Bytes frame{19, std::uint8_t(body.size())};
        frame.insert(frame.end(), body.begin(), body.end());
        std::uint8_t sum = 0;
        for (std::uint8_t b : frame)
            sum = std::uint8_t(sum + b);
        frame.push_back(std::uint8_t(-sum));

        StreamParser parser(p);
        const std::vector<std::uint8_t> expected(ids.begin(), ids.end());
        QVERIFY(parser.setExpectedStream(expected));
        std::vector<SensorSnapshot> read;
        parser.setSnapshotHandler([&](const SensorSnapshot &s, FrameKind) { read.push_back(s); });
        parser.feed(frame);
        QCOMPARE(read.size(), std::size_t(1));
        QVERIFY(read.front() == packetsAsSent(values, ids));
    }
}

QTEST_GUILESS_MAIN(TestPacketEncoding)
#include "tst_packet_encoding.moc"
