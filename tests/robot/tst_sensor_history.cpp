// SPDX-License-Identifier: GPL-3.0-or-later
#include "pseudo_translation.h"
#include "sensor_history.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <limits>

using oi::ProfileId;
using oi::SensorSnapshot;

namespace {

SensorSnapshot snapshotWith(std::initializer_list<std::pair<int, int>> values,
                            ProfileId profile = ProfileId::Create2)
{
    SensorSnapshot s(oi::profile(profile));
    for (const auto &[id, value] : values)
        s.set(id, value);
    return s;
}

// What a group 100 stream frame carries on a Create 2: every packet 7..58.
SensorSnapshot group100Snapshot(int seed)
{
    SensorSnapshot s(oi::profile(ProfileId::Create2));
    for (const oi::PacketInfo &info : oi::profile(ProfileId::Create2).packets())
        s.set(info.id, info.min + (seed + info.id) % (info.max - info.min + 1));
    return s;
}

QByteArray readAll(const QString &path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return f.readAll();
}

constexpr double kInf = std::numeric_limits<double>::infinity();

} // namespace

class TestSensorHistory : public QObject {
    Q_OBJECT
private slots:
    void recordsOnlyPresentPackets()
    {
        SensorHistory h;
        QVERIFY(h.isEmpty());
        QVERIFY(h.append(1.0, snapshotWith({{22, 14800}, {23, -300}})));
        QCOMPARE(h.sampleCount(22), std::size_t(1));
        QCOMPARE(h.sampleCount(23), std::size_t(1));
        QCOMPARE(h.sampleCount(24), std::size_t(0));
        QCOMPARE(h.sample(23, 0), (SensorHistory::Sample{1.0, -300}));
        QCOMPARE(h.newestTime(), 1.0);
        // Groups and unknown ids are not channels.
        QVERIFY(!h.isChannel(100));
        QVERIFY(!h.isChannel(3));
        QVERIFY(!h.isChannel(-1));
        QVERIFY(h.isChannel(58));
        QCOMPARE(h.sampleCount(100), std::size_t(0));
    }

    void refusesTimeGoingBackwards()
    {
        SensorHistory h;
        QVERIFY(h.append(5.0, snapshotWith({{22, 1}})));
        QVERIFY(!h.append(4.999, snapshotWith({{22, 2}})));
        QVERIFY(!h.append(std::nan(""), snapshotWith({{22, 3}})));
        QVERIFY(!h.append(kInf, snapshotWith({{22, 4}})));
        QVERIFY(h.append(5.0, snapshotWith({{22, 5}}))); // equal times are fine
        QCOMPARE(h.sampleCount(22), std::size_t(2));
        QCOMPARE(h.sample(22, 1).value, 5);
    }

    void wraparoundKeepsTheNewest()
    {
        SensorHistory h(oi::profile(ProfileId::Create2), 100);
        for (int i = 0; i < 250; ++i)
            QVERIFY(h.append(i * 0.5, snapshotWith({{22, 10000 + i}})));
        QCOMPARE(h.sampleCount(22), std::size_t(100));
        QCOMPARE(h.appendCount(22), std::uint64_t(250));
        for (int k = 0; k < 100; ++k)
            QCOMPARE(h.sample(22, std::size_t(k)), (SensorHistory::Sample{(150 + k) * 0.5, 10150 + k}));
        QCOMPARE(h.oldestTime(), 75.0);
        QCOMPARE(h.newestTime(), 124.5);
        QCOMPARE(h.sample(22, 100), SensorHistory::Sample{}); // past the end
    }

    void memoryIsBoundedAndStaysFlat()
    {
        const std::size_t capacity = 5000;
        SensorHistory h(oi::profile(ProfileId::Create2), capacity);
        const std::size_t empty = h.memoryBytes();
        h.append(0, snapshotWith({{22, 1}, {23, 2}, {45, 3}}));
        const std::size_t first = h.memoryBytes();
        QVERIFY(first > empty);
        // One time column, two bytes for voltage and current, one for the light bumper.
        const std::size_t full = capacity * (sizeof(double) + 2 + 2 + 1);
        QVERIFY(first < full / 2); // allocated as it fills
        for (std::size_t i = 1; i < capacity; ++i)
            h.append(double(i), snapshotWith({{22, 1}, {23, 2}, {45, 3}}));
        QVERIFY(h.memoryBytes() >= full);
        const std::size_t held = h.memoryBytes();
        QVERIFY(held < full + 1024); // and the runs, one per channel
        for (std::size_t i = capacity; i < 3 * capacity; ++i)
            h.append(double(i), snapshotWith({{22, 1}, {23, 2}, {45, 3}}));
        QCOMPARE(h.memoryBytes(), held);
        h.clear();
        QCOMPARE(h.memoryBytes(), empty);
        QVERIFY(h.isEmpty());
    }

    void anHourOfGroup100KeepsMemoryFlat()
    {
        // Every packet of the Create 2 at the 15 ms stream period for an hour:
        // once the hour is held, memory no longer grows, and it is one time
        // column plus the 80 bytes the frame itself carries.
        SensorHistory h;
        const auto &packets = oi::profile(ProfileId::Create2).packets();
        QCOMPARE(packets.size(), std::size_t(52));
        const std::size_t bound = SensorHistory::kDefaultCapacity * (sizeof(double) + 80);
        const SensorSnapshot a = group100Snapshot(1), b = group100Snapshot(2);
        std::size_t i = 0;
        for (; i < SensorHistory::kDefaultCapacity; ++i)
            h.append(double(i) * 0.015, i % 2 ? a : b);
        const std::size_t held = h.memoryBytes();
        QVERIFY(held >= bound);
        QVERIFY(held < bound + 64 * 1024);
        QVERIFY(held < 60'000'000); // the target for an hour of one robot
        for (; i < SensorHistory::kDefaultCapacity + 20'000; ++i) {
            h.append(double(i) * 0.015, i % 2 ? a : b);
            if (i % 4000 == 0)
                QCOMPARE(h.memoryBytes(), held);
        }
        QCOMPARE(h.memoryBytes(), held);
        for (const oi::PacketInfo &info : packets)
            QCOMPARE(h.sampleCount(info.id), SensorHistory::kDefaultCapacity);
        QCOMPARE(h.frameCount(), SensorHistory::kDefaultCapacity);
        QCOMPARE(h.oldestTime(), 20'000 * 0.015);
        const std::size_t last = SensorHistory::kDefaultCapacity - 1;
        QCOMPARE(h.sample(22, last), (SensorHistory::Sample{double(i - 1) * 0.015, a.raw(22)}));
    }

    void valuesAndTimesReadBackExactly()
    {
        // Each packet's own extremes, and values in between, on every profile.
        for (ProfileId id : oi::allProfiles()) {
            const oi::RobotProfile &profile = oi::profile(id);
            SensorHistory h(profile, 64);
            std::vector<double> times;
            for (int k = 0; k < 40; ++k) {
                SensorSnapshot s(profile);
                for (const oi::PacketInfo &info : profile.packets())
                    s.set(info.id, k % 3 == 0 ? info.min : k % 3 == 1 ? info.max : info.min + (info.max - info.min) / (k + 2));
                const double t = 1000.0 + k * 0.015 + k * k * 1e-6;
                times.push_back(t);
                QVERIFY(h.append(t, s));
            }
            for (const oi::PacketInfo &info : profile.packets()) {
                QCOMPARE(h.sampleCount(info.id), std::size_t(40));
                const auto all = h.samplesAt(info.id, 0, 40);
                QCOMPARE(all.size(), std::size_t(40));
                for (int k = 0; k < 40; ++k) {
                    const std::int32_t want =
                        k % 3 == 0 ? info.min : k % 3 == 1 ? info.max : info.min + (info.max - info.min) / (k + 2);
                    QCOMPARE(h.sample(info.id, std::size_t(k)), (SensorHistory::Sample{times[k], want}));
                    QCOMPARE(all[std::size_t(k)], (SensorHistory::Sample{times[k], want}));
                }
            }
        }
    }

    void aValueOutsideThePacketTableIsKeptWhole()
    {
        // The wall is 0 or 1 and stored in a byte; a value the table does not
        // allow widens the channel rather than being cut.
        SensorHistory h(oi::profile(ProfileId::Create2), 4000);
        for (int k = 0; k < 1500; ++k)
            h.append(k, snapshotWith({{8, k % 2}, {24, -20}}));
        const std::size_t narrow = h.memoryBytes();
        h.append(1500, snapshotWith({{8, 70000}, {24, -300}}));
        h.append(1501, snapshotWith({{8, -2}, {24, 12}}));
        QVERIFY(h.memoryBytes() > narrow);
        QCOMPARE(h.sampleCount(8), std::size_t(1502));
        for (int k = 0; k < 1500; ++k)
            QCOMPARE(h.sample(8, std::size_t(k)), (SensorHistory::Sample{double(k), k % 2}));
        QCOMPARE(h.sample(8, 1500).value, 70000);
        QCOMPARE(h.sample(8, 1501).value, -2);
        QCOMPARE(h.sample(24, 1499).value, -20);
        QCOMPARE(h.sample(24, 1500).value, -300);
        QCOMPARE(h.sample(24, 1501).value, 12);
    }

    void packetsThatComeAndGoShareTheTimeColumn()
    {
        // Voltage in every frame, the wall in every other, the current only
        // in frames 10..14: each reads back its own times, across the wrap.
        SensorHistory h(oi::profile(ProfileId::Create2), 10);
        for (int k = 0; k < 25; ++k) {
            SensorSnapshot s(oi::profile(ProfileId::Create2));
            s.set(22, 100 + k);
            if (k % 2 == 0)
                s.set(8, k % 4 == 0);
            if (k >= 10 && k < 15)
                s.set(23, -k);
            QVERIFY(h.append(k * 0.5, s));
        }
        QCOMPARE(h.frameCount(), std::size_t(10)); // frames 15..24
        QCOMPARE(h.sampleCount(22), std::size_t(10));
        QCOMPARE(h.sample(22, 0), (SensorHistory::Sample{7.5, 115}));
        QCOMPARE(h.sampleCount(8), std::size_t(5));
        for (int i = 0; i < 5; ++i)
            QCOMPARE(h.sample(8, std::size_t(i)), (SensorHistory::Sample{(16 + 2 * i) * 0.5, (16 + 2 * i) % 4 == 0}));
        QCOMPARE(h.appendCount(8), std::uint64_t(13));
        QCOMPARE(h.sampleCount(23), std::size_t(0)); // dropped with its frames
        QCOMPARE(h.appendCount(23), std::uint64_t(5));
        QCOMPARE(h.lowerBound(8, 9.0), std::size_t(1));
        QCOMPARE(h.upperBound(8, 9.0), std::size_t(2));
        QCOMPARE(h.samples(8, 8.5, 11.0), (std::vector<SensorHistory::Sample>{{9.0, 0}, {10.0, 1}, {11.0, 0}}));

        // The current comes back: a second run.
        h.append(13.0, snapshotWith({{23, 7}}));
        h.append(13.5, snapshotWith({{22, 1}, {23, 8}}));
        QCOMPARE(h.samples(23, -kInf, kInf), (std::vector<SensorHistory::Sample>{{13.0, 7}, {13.5, 8}}));
        QCOMPARE(h.sampleCount(22), std::size_t(9)); // not in the frame at 13.0
        QCOMPARE(h.sample(22, 8), (SensorHistory::Sample{13.5, 1}));
        QCOMPARE(h.oldestTime(), 8.5);
    }

    void anEmptySnapshotStoresNoFrame()
    {
        SensorHistory h;
        QVERIFY(h.append(1.0, SensorSnapshot(oi::profile(ProfileId::Create2))));
        QCOMPARE(h.frameCount(), std::size_t(0));
        QCOMPARE(h.newestTime(), 1.0);
        QVERIFY(!h.append(0.5, snapshotWith({{22, 1}})));
    }

    void reducedRateKeepsTheExtremes()
    {
        SensorHistory h(oi::profile(ProfileId::Create2), 1000);
        h.setReducedRate(true);
        QVERIFY(h.isReducedRate());
        const int n = SensorHistory::kReducedBlockFrames;
        // Three blocks of a flat voltage with one spike up and one dip, and a
        // current that falls then rises.
        for (int k = 0; k < 3 * n; ++k) {
            int voltage = 14000;
            if (k == 13)
                voltage = 16000;
            if (k == 17)
                voltage = 12000;
            int current = k < n ? -k : -n + (k - n);
            h.append(k * 0.015, snapshotWith({{22, voltage}, {23, current}}));
        }
        QCOMPARE(h.frameCount(), std::size_t(6)); // two frames per block
        QCOMPARE(h.samples(22, -kInf, kInf),
                 (std::vector<SensorHistory::Sample>{{0.0, 14000}, {(n - 1) * 0.015, 14000},
                                                     {n * 0.015, 16000}, {(2 * n - 1) * 0.015, 12000},
                                                     {2 * n * 0.015, 14000}, {(3 * n - 1) * 0.015, 14000}}));
        // Falling: the maximum came first, then the minimum.
        QCOMPARE(h.sample(23, 0).value, 0);
        QCOMPARE(h.sample(23, 1).value, -(n - 1));
        QCOMPARE(h.sample(23, 2).value, -n);
        QCOMPARE(h.sample(23, 3).value, -1);

        // Half a block, then the full rate: the half is stored at once and
        // new frames are kept whole.
        for (int k = 3 * n; k < 3 * n + 3; ++k)
            h.append(k * 0.015, snapshotWith({{22, 100 + k}}));
        QCOMPARE(h.frameCount(), std::size_t(6));
        const auto revision = h.revision();
        h.setReducedRate(false);
        QVERIFY(h.revision() != revision);
        QCOMPARE(h.frameCount(), std::size_t(8));
        QCOMPARE(h.sample(22, 6), (SensorHistory::Sample{3 * n * 0.015, 100 + 3 * n}));
        QCOMPARE(h.sample(22, 7), (SensorHistory::Sample{(3 * n + 2) * 0.015, 100 + 3 * n + 2}));
        for (int k = 0; k < 5; ++k)
            h.append(10.0 + k, snapshotWith({{22, k}}));
        QCOMPARE(h.frameCount(), std::size_t(13));
        QCOMPARE(h.sample(22, 12), (SensorHistory::Sample{14.0, 4}));
    }

    void reducedRateCostsAFifthOfTheMemory()
    {
        SensorHistory full, reduced;
        reduced.setReducedRate(true);
        const SensorSnapshot a = group100Snapshot(1), b = group100Snapshot(2);
        for (int k = 0; k < 20'000; ++k) {
            full.append(k * 0.015, k % 2 ? a : b);
            reduced.append(k * 0.015, k % 2 ? a : b);
        }
        QCOMPARE(reduced.frameCount(), full.frameCount() * 2 / SensorHistory::kReducedBlockFrames);
        QVERIFY(reduced.memoryBytes() * 4 < full.memoryBytes());
        // A clear keeps the rate.
        reduced.clear();
        QVERIFY(reduced.isReducedRate());
    }

    void rangeQueriesAcrossTheWrap()
    {
        SensorHistory h(oi::profile(ProfileId::Create2), 8);
        for (int i = 0; i < 12; ++i) // holds times 4..11
            h.append(double(i), snapshotWith({{22, i * 10}}));
        QCOMPARE(h.lowerBound(22, 5.0), std::size_t(1));
        QCOMPARE(h.upperBound(22, 5.0), std::size_t(2));
        QCOMPARE(h.lowerBound(22, 5.5), std::size_t(2));
        QCOMPARE(h.lowerBound(22, -1.0), std::size_t(0));
        QCOMPARE(h.upperBound(22, 99.0), std::size_t(8));

        const auto mid = h.samples(22, 5.5, 8.0);
        QCOMPARE(mid.size(), std::size_t(3));
        QCOMPARE(mid[0], (SensorHistory::Sample{6.0, 60}));
        QCOMPARE(mid[2], (SensorHistory::Sample{8.0, 80}));
        QCOMPARE(h.samples(22, -kInf, kInf).size(), std::size_t(8));
        QVERIFY(h.samples(22, 0.0, 3.0).empty()); // overwritten
        QVERIFY(h.samples(22, 20.0, 30.0).empty());
        QVERIFY(h.samples(22, 8.0, 5.0).empty());
        QVERIFY(h.samples(23, -kInf, kInf).empty());
        QCOMPARE(h.samples(22, 11.0, 11.0).size(), std::size_t(1));
    }

    void revisionAndGeneration()
    {
        SensorHistory h;
        const auto r0 = h.revision(), g0 = h.generation();
        h.append(0, snapshotWith({{22, 1}}));
        QVERIFY(h.revision() != r0);
        QCOMPARE(h.generation(), g0);
        h.clear();
        QVERIFY(h.generation() != g0);
    }

    void profileChangeClears()
    {
        SensorHistory h;
        h.append(1, snapshotWith({{46, 100}}));
        const auto g = h.generation();
        h.setProfile(oi::profile(ProfileId::Create2)); // same profile: kept
        QCOMPARE(h.sampleCount(46), std::size_t(1));
        QCOMPARE(h.generation(), g);
        h.setReducedRate(true);
        h.setProfile(oi::profile(ProfileId::Create1));
        QVERIFY(h.isReducedRate());
        QVERIFY(h.isEmpty());
        QVERIFY(!h.isChannel(46)); // light bumpers are not on the Create 1
        QVERIFY(h.isChannel(33));
    }

    void timeFormat()
    {
        QCOMPARE(SensorHistory::formatTime(0), QStringLiteral("0"));
        QCOMPARE(SensorHistory::formatTime(12), QStringLiteral("12"));
        QCOMPARE(SensorHistory::formatTime(1.5), QStringLiteral("1.5"));
        QCOMPARE(SensorHistory::formatTime(0.015), QStringLiteral("0.015"));
        QCOMPARE(SensorHistory::formatTime(3600.000125), QStringLiteral("3600.000125"));
    }

    void csvAlignsChannelsByTime()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        SensorHistory h;
        h.append(0.0, snapshotWith({{22, 14000}, {8, 0}}));
        h.append(0.015, snapshotWith({{22, 14010}}));      // no wall sample
        h.append(0.03, snapshotWith({{22, 14020}, {8, 1}}));
        h.append(0.045, snapshotWith({{8, 0}}));           // no voltage sample
        const QString path = dir.filePath(QStringLiteral("all.csv"));
        QString error;
        QVERIFY2(h.exportCsv(path, {22, 8}, -kInf, kInf, &error), qPrintable(error));
        QCOMPARE(readAll(path), QByteArray("time_s,voltage[mV],wall\n"
                                           "0,14000,0\n"
                                           "0.015,14010,\n"
                                           "0.03,14020,1\n"
                                           "0.045,,0\n"));

        // A time range, and the column order as asked.
        QVERIFY(h.exportCsv(path, {8, 22}, 0.01, 0.03, &error));
        QCOMPARE(readAll(path), QByteArray("time_s,wall,voltage[mV]\n"
                                           "0.015,,14010\n"
                                           "0.03,1,14020\n"));
    }

    void csvWithAChannelThatHasNoSamples()
    {
        QTemporaryDir dir;
        SensorHistory h;
        h.append(1.0, snapshotWith({{23, -250}}));
        h.append(2.0, snapshotWith({{23, -260}}));
        const QString path = dir.filePath(QStringLiteral("t.csv"));
        QVERIFY(h.exportCsv(path, {24, 23}, -kInf, kInf));
        QCOMPARE(readAll(path), QStringLiteral("time_s,temperature[\u00b0C],current[mA]\n"
                                               "1,,-250\n"
                                               "2,,-260\n")
                                    .toUtf8());
        // Nothing in range: only the header.
        QVERIFY(h.exportCsv(path, {23}, 5.0, 6.0));
        QCOMPARE(readAll(path), QByteArray("time_s,current[mA]\n"));
    }

    void csvTwoSamplesAtOneTimeGiveOneRow()
    {
        QTemporaryDir dir;
        SensorHistory h;
        h.append(1.0, snapshotWith({{22, 1}}));
        h.append(1.0, snapshotWith({{22, 2}, {23, 5}}));
        const QString path = dir.filePath(QStringLiteral("d.csv"));
        QVERIFY(h.exportCsv(path, {22, 23}, -kInf, kInf));
        QCOMPARE(readAll(path), QByteArray("time_s,voltage[mV],current[mA]\n1,2,5\n"));
    }

    void csvErrors()
    {
        QTemporaryDir dir;
        SensorHistory h;
        h.append(1.0, snapshotWith({{22, 1}}));
        QString error;
        const QString impossible = dir.filePath(QStringLiteral("no/such/folder/x.csv"));
        QVERIFY(!h.exportCsv(impossible, {22}, -kInf, kInf, &error));
        QVERIFY(error.contains(impossible));
        QVERIFY(!QFile::exists(impossible));

        // A refused export leaves an existing file as it was.
        const QString path = dir.filePath(QStringLiteral("keep.csv"));
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("precious\n");
        }
        error.clear();
        QVERIFY(!h.exportCsv(path, {22, 100}, -kInf, kInf, &error));
        QVERIFY(error.contains(QStringLiteral("100")));
        QCOMPARE(readAll(path), QByteArray("precious\n"));
        error.clear();
        QVERIFY(!h.exportCsv(path, {}, -kInf, kInf, &error));
        QVERIFY(!error.isEmpty());
        QVERIFY(!h.exportCsv(path, {22}, std::nan(""), 1.0)); // no error pointer: no crash
        QCOMPARE(readAll(path), QByteArray("precious\n"));
    }

    void translatesOnTheSpot()
    {
        QTemporaryDir dir;
        SensorHistory h;
        h.append(1.0, snapshotWith({{22, 1}}));
        const QString path = dir.filePath(QStringLiteral("v.csv"));
        QString error;
        {
            ScopedPseudoTranslation pseudo;
            QVERIFY(!h.exportCsv(path, {22, 100}, -kInf, kInf, &error));
            QVERIFY2(!looksUntranslated(error), qPrintable(error));
            QVERIFY(!h.exportCsv(path, {}, -kInf, kInf, &error));
            QVERIFY2(!looksUntranslated(error), qPrintable(error));
            // The file keeps its English keys, whatever the language.
            QVERIFY(h.exportCsv(path, {22}, -kInf, kInf, &error));
            QVERIFY(readAll(path).startsWith("time_s,voltage[mV]\n"));
        }
        QVERIFY(!h.exportCsv(path, {}, -kInf, kInf, &error));
        QCOMPARE(error, QString("No channels to export."));
    }
};

QTEST_MAIN(TestSensorHistory)
#include "tst_sensor_history.moc"
