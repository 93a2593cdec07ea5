// SPDX-License-Identifier: GPL-3.0-or-later
// Snapshots to JSON and back: every packet key, raw values, and a clear
// error for a value the packet cannot carry.

#include "snapshot_json.h"

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
