// SPDX-License-Identifier: GPL-3.0-or-later
// Snapshots to JSON and back: every packet key, raw values, and a clear
// error for a value the packet cannot carry. And the telemetry that tells
// only what changed: nothing lost, odometry adds up.

#include "snapshot_json.h"
#include "telemetry_changes.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QTest>

using namespace oilink;

class TestSnapshotJson : public QObject {
    Q_OBJECT

private slots:
    void everyPacketRoundTrips_data()
    {
        QTest::addColumn<int>("profile");
        QTest::newRow("roomba500") << int(oi::ProfileId::Roomba500);
        QTest::newRow("create2") << int(oi::ProfileId::Create2);
        QTest::newRow("create1") << int(oi::ProfileId::Create1);
    }
    void everyPacketRoundTrips()
    {
        QFETCH(int, profile);
        const oi::RobotProfile &p = oi::profile(oi::ProfileId(profile));
        oi::SensorSnapshot s(p);
        int i = 0;
        for (const oi::PacketInfo &info : p.packets())
            s.set(info.id, (i++ % 2) ? info.min : info.max); // both ends of each range
        const QJsonObject o = snapshotToJson(s);
        QCOMPARE(o.size(), s.packetCount());
        QString error;
        const auto back = snapshotFromJson(o, p, &error);
        QVERIFY2(back, qPrintable(error));
        QVERIFY(*back == s);
    }

    // The text exports write is the same object, for every packet and both
    // ends of its range.
    void textIsTheSameObject_data() { everyPacketRoundTrips_data(); }
    void textIsTheSameObject()
    {
        QFETCH(int, profile);
        const oi::RobotProfile &p = oi::profile(oi::ProfileId(profile));
        for (bool low : {false, true}) {
            oi::SensorSnapshot s(p);
            for (const oi::PacketInfo &info : p.packets())
                s.set(info.id, low ? info.min : info.max);
            QJsonParseError error;
            const QJsonDocument text = QJsonDocument::fromJson(snapshotToJsonText(s), &error);
            QVERIFY2(text.isObject(), qPrintable(error.errorString()));
            QCOMPARE(text.object(), snapshotToJson(s));
        }
        // An empty snapshot is an empty object.
        QCOMPARE(snapshotToJsonText(oi::SensorSnapshot(p)), QByteArray("{}"));
    }

    void keysAreThePacketKeys()
    {
        oi::SensorSnapshot s(oi::profile(oi::ProfileId::Create2));
        s.set(22, 15640);
        s.set(23, -220);
        const QByteArray json = QJsonDocument(snapshotToJson(s)).toJson(QJsonDocument::Compact);
        QCOMPARE(json, QByteArray(R"({"current":-220,"voltage":15640})"));
    }

    void otherKeysAreIgnored()
    {
        const QJsonObject o{{"timestamp", 1795000000.125}, {"voltage", 15000}, {"no_such_packet", 3}};
        QString error;
        const auto s = snapshotFromJson(o, oi::profile(oi::ProfileId::Create2), &error);
        QVERIFY2(s, qPrintable(error));
        QCOMPARE(s->packetCount(), 1);
        QCOMPARE(s->voltageMv(), 15000);
    }

    void badValuesAreRefused_data()
    {
        QTest::addColumn<QJsonValue>("voltage");
        QTest::newRow("too large for two bytes") << QJsonValue(65536);
        QTest::newRow("negative, unsigned") << QJsonValue(-1);
        QTest::newRow("fraction") << QJsonValue(12.5);
        QTest::newRow("string") << QJsonValue("15000");
        QTest::newRow("null") << QJsonValue(QJsonValue::Null);
        QTest::newRow("array") << QJsonValue(QJsonArray{1});
    }
    void badValuesAreRefused()
    {
        QFETCH(QJsonValue, voltage);
        QString error;
        const auto s = snapshotFromJson(QJsonObject{{"voltage", voltage}}, oi::profile(oi::ProfileId::Create2), &error);
        QVERIFY(!s);
        QVERIFY2(error.contains(QStringLiteral("voltage")) && error.contains(QStringLiteral("65535")),
                 qPrintable(error));
    }

    void signedTwoBytes()
    {
        QString error;
        const auto p = &oi::profile(oi::ProfileId::Create2);
        QVERIFY(snapshotFromJson(QJsonObject{{"current", -32768}}, *p, &error));
        QVERIFY(!snapshotFromJson(QJsonObject{{"current", -32769}}, *p, &error));
        QVERIFY(error.contains(QStringLiteral("-32768")));
    }

    // Frames 15 ms apart, as the robot streams them.
    static oi::SensorSnapshot frameWith(int bumps, int voltage, int distance)
    {
        oi::SensorSnapshot f(oi::profile(oi::ProfileId::Create2));
        for (const oi::PacketInfo &info : f.robotProfile().packets())
            f.set(info.id, 0);
        f.set(7, bumps);
        f.set(22, voltage);
        f.set(19, distance);
        f.set(35, int(oi::OiMode::Safe));
        return f;
    }

    void aKeyFrameCarriesEveryPacketEverySecond()
    {
        TelemetryChanges changes;
        int keyFrames = 0;
        for (qint64 t = 0; t <= 3000; t += 15) {
            const auto m = changes.next(frameWith(0, 15000, 0), t);
            if (m.keyFrame) {
                ++keyFrames;
                QCOMPARE(m.packets.packetCount(), frameWith(0, 15000, 0).packetCount());
            } else {
                QCOMPARE(m.packets.packetCount(), 0); // nothing changed: the time alone, or nothing
            }
        }
        QCOMPARE(keyFrames, 3); // at 0, 1005 and 2010 ms: 1000 ms or more apart
        changes.restart();
        QVERIFY(changes.next(frameWith(0, 15000, 0), 3015).keyFrame);
    }

    void aBumpOfOneFrameIsToldAndSoIsItsRelease()
    {
        TelemetryChanges changes;
        changes.next(frameWith(0, 15000, 0), 0);
        QList<int> told;
        const int bumps[] = {0, 0, 1, 0, 0, 2, 2, 0};
        qint64 t = 15;
        for (int b : bumps) {
            const auto m = changes.next(frameWith(b, 15000, 0), t += 15);
            if (m.packets.has(7))
                told << m.packets.raw(7);
        }
        QCOMPARE(told, (QList<int>{1, 0, 2, 0}));
    }

    void aMeasurementIsToldAtMostTenTimesASecondAndCatchesUp()
    {
        TelemetryChanges changes;
        changes.next(frameWith(0, 15000, 0), 0);
        int told = 0, last = 0;
        qint64 t = 0;
        for (int i = 1; i < 60; ++i) { // 885 ms of a voltage that changes every frame
            const auto m = changes.next(frameWith(0, 15000 + i, 0), t += 15);
            if (m.packets.has(22)) {
                ++told;
                last = m.packets.raw(22);
            }
        }
        QVERIFY2(told >= 8 && told <= 9, qPrintable(QString::number(told)));
        // Then it stops changing: its last value is told within 100 ms.
        for (int i = 0; i < 7; ++i) {
            const auto m = changes.next(frameWith(0, 15100, 0), t += 15);
            if (m.packets.has(22))
                last = m.packets.raw(22);
        }
        QCOMPARE(last, 15100);
    }

    void distanceAddsUpOverTheMessages()
    {
        TelemetryChanges changes;
        int driven = 0, told = 0;
        qint64 t = 0;
        for (int i = 0; i < 200; ++i) {
            const int d = (i * 7) % 11 - 3; // forward and back, some frames none
            driven += d;
            const auto m = changes.next(frameWith(0, 15000, d), t += 15);
            told += m.packets.raw(19);
            if (!m.keyFrame)
                QVERIFY(!m.packets.has(19) || m.packets.raw(19) != 0);
        }
        // A key frame tells what is left.
        changes.restart();
        told += changes.next(frameWith(0, 15000, 0), t += 15).packets.raw(19);
        QCOMPARE(told, driven);
    }

    // What a watcher that merges the messages knows equals the robot's
    // frame in every one-byte packet at every message.
    void aWatcherKnowsEveryEventAsItHappens()
    {
        TelemetryChanges changes;
        oi::SensorSnapshot known(oi::profile(oi::ProfileId::Create2));
        qint64 t = 0;
        for (int i = 0; i < 300; ++i) {
            oi::SensorSnapshot f = frameWith((i / 3) % 4, 14000 + i % 17, i % 5);
            f.set(17, 160 + (i / 7) % 3); // an IR character
            f.set(35, (i / 50) % 4);      // the mode
            known.merge(changes.next(f, t += 15).packets);
            for (const oi::PacketInfo &info : f.robotProfile().packets())
                if (info.bytes == 1)
                    QCOMPARE(known.raw(info.id), f.raw(info.id));
        }
    }

    // A frame with nothing to tell is sent only when the two before it were
    // not; a frame with something to tell always is, and a watcher merging
    // the messages still knows every event.
    void aStillRobotIsToldAliveEveryThirdFrame()
    {
        TelemetryChanges changes;
        QVERIFY(changes.next(frameWith(0, 15000, 0), 0).send); // the first is a key frame
        QList<bool> sent;
        qint64 t = 0;
        for (int i = 0; i < 9; ++i)
            sent << changes.next(frameWith(0, 15000, 0), t += 15).send;
        QCOMPARE(sent, (QList<bool>{false, false, true, false, false, true, false, false, true}));
        // A bump in a frame that would not have been sent: sent, with the bump;
        // the count of frames unsent starts again from it.
        QVERIFY(!changes.next(frameWith(0, 15000, 0), t += 15).send);
        const auto bump = changes.next(frameWith(1, 15000, 0), t += 15);
        QVERIFY(bump.send);
        QCOMPARE(bump.packets.raw(7), 1);
        QVERIFY(!changes.next(frameWith(1, 15000, 0), t += 15).send);
        QVERIFY(!changes.next(frameWith(1, 15000, 0), t += 15).send);
        QVERIFY(changes.next(frameWith(1, 15000, 0), t += 15).send);
    }

    void statisticsRoundTrip()
    {
        LinkStats st;
        st.frames = 1234;
        st.framesPerSecond = 66.66;
        st.checksumFailures = 2;
        st.bytesReceived = 99999;
        st.reconnects = 3;
        st.lastFrameTime = QDateTime::fromMSecsSinceEpoch(1795000000125, Qt::UTC);
        const QJsonObject o = statisticsToJson(st);
        QCOMPARE(o.value("frames_per_second").toDouble(), 66.7);
        QString error;
        const auto back = statisticsFromJson(o, &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->frames, st.frames);
        QCOMPARE(back->checksumFailures, st.checksumFailures);
        QCOMPARE(back->bytesReceived, st.bytesReceived);
        QCOMPARE(back->reconnects, st.reconnects);
        QCOMPARE(back->lastFrameTime, st.lastFrameTime);
        QVERIFY(!statisticsFromJson(QJsonObject{{"frames", "many"}}, &error));
        QVERIFY(error.contains(QStringLiteral("frames")));
    }
};

QTEST_GUILESS_MAIN(TestSnapshotJson)
#include "tst_snapshot_json.moc"
