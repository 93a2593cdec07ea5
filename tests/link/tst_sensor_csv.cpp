// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensor_csv.h"

#include <QTest>

#include <optional>
#include <vector>

using oilink::SensorCsv;

class TestSensorCsv : public QObject {
    Q_OBJECT
private slots:
    void headerNamesEachPacketWithItsUnit()
    {
        const oi::RobotProfile &create2 = oi::profile(oi::ProfileId::Create2);
        const SensorCsv csv({create2.packet(22), create2.packet(8), create2.packet(24)});
        QByteArray out;
        csv.appendHeader(out);
        QCOMPARE(out, QStringLiteral("time_s,voltage[mV],wall,temperature[\u00b0C]\n").toUtf8());
    }

    void rowLeavesMissingValuesEmpty()
    {
        const oi::RobotProfile &create2 = oi::profile(oi::ProfileId::Create2);
        SensorCsv csv({create2.packet(22), create2.packet(8), create2.packet(23)});
        QByteArray out;
        const std::vector<std::optional<std::int32_t>> row{14000, std::nullopt, -1200};
        csv.appendRow(out, 0.015, row);
        csv.appendRow(out, 1.5, std::vector<std::optional<std::int32_t>>{std::nullopt, 1});
        QCOMPARE(out, QByteArray("0.015,14000,,-1200\n1.5,,1,\n"));
    }

    // Each marker on the first row at or after it, quoted where CSV needs;
    // one after the last row on a row of its own.
    void markersFillTheLastColumn()
    {
        const oi::RobotProfile &create2 = oi::profile(oi::ProfileId::Create2);
        SensorCsv csv({create2.packet(22)}, {{0.01, "start"}, {0.015, "a, \"b\""}, {0.02, "c"}, {9, "after"}});
        QByteArray out;
        csv.appendHeader(out);
        for (double t : {0.0, 0.015, 0.03, 0.045})
            csv.appendRow(out, t, std::vector<std::optional<std::int32_t>>{14000});
        csv.finish(out);
        QCOMPARE(out, QByteArray("time_s,voltage[mV],marker\n"
                                 "0,14000,\n"
                                 "0.015,14000,\"start; a, \"\"b\"\"\"\n"
                                 "0.03,14000,c\n"
                                 "0.045,14000,\n"
                                 "9,,after\n"));
    }

    void timeText_data()
    {
        QTest::addColumn<double>("seconds");
        QTest::addColumn<QByteArray>("text");
        QTest::newRow("whole") << 12.0 << QByteArray("12");
        QTest::newRow("microseconds") << 1.000001 << QByteArray("1.000001");
        QTest::newRow("below a microsecond") << 1.0000004 << QByteArray("1");
        QTest::newRow("trailing zeros") << 0.25 << QByteArray("0.25");
        QTest::newRow("negative zero") << -0.0000001 << QByteArray("0");
        QTest::newRow("negative") << -1.5 << QByteArray("-1.5");
    }
    void timeText()
    {
        QFETCH(double, seconds);
        QFETCH(QByteArray, text);
        QCOMPARE(SensorCsv::timeText(seconds), text);
    }
};

QTEST_GUILESS_MAIN(TestSensorCsv)
#include "tst_sensor_csv.moc"
