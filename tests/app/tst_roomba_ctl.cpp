// SPDX-License-Identifier: GPL-3.0-or-later
// roomba-ctl as a script sees it: output, standard error and exit status.
#include "process_run.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

namespace {

struct Outcome {
    int status = -1;
    QString out;
    QString err;
};

Outcome run(const QStringList &args, const QByteArray &input = {})
{
    const ProcessRun r = runProcess(QStringLiteral(ROOMBA_CTL_PATH), args, {}, 30000, input);
    return {r.exitCode, QString::fromUtf8(r.out), QString::fromUtf8(r.err)};
}

} // namespace

class TestRoombaCtl : public QObject {
    Q_OBJECT
private slots:
    void encodeExamples_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("out");
        QTest::newRow("drive") << QStringList{"encode", "drive", "-200", "500"} << "137 255 56 1 244\n";
        QTest::newRow("hex") << QStringList{"encode", "--hex", "drive", "-200", "500"} << "89 FF 38 01 F4\n";
        QTest::newRow("profile") << QStringList{"encode", "--profile", "create1", "wait-event", "-5"} << "158 251\n";
        QTest::newRow("song") << QStringList{"encode", "song", "0", "60:32", "62:32"} << "140 0 2 60 32 62 32\n";
        QTest::newRow("digits") << QStringList{"encode", "digit-leds-ascii", "ABCD"} << "164 65 66 67 68\n";
        QTest::newRow("schedule") << QStringList{"encode", "schedule", "wed 15:00, fri 10:36"}
                                  << "167 40 0 0 0 0 0 0 15 0 0 0 10 36 0 0\n";
        QTest::newRow("script") << QStringList{"encode", "--profile", "create", "script",
                                               "drive 300 0; wait-distance 400; drive 0 0"}
                                << "152 13 137 1 44 0 0 156 1 144 137 0 0 0 0\n";
    }
    void encodeExamples()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, out);
        const Outcome o = run(args);
        QCOMPARE(o.status, 0);
        QCOMPARE(o.out, out);
        QCOMPARE(o.err, QString());
    }

    void errors_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("status");
        QTest::addColumn<QString>("message");
        QTest::newRow("range") << QStringList{"encode", "drive", "900", "0"} << 1 << "velocity: 900 is outside -500..500";
        QTest::newRow("missing opcode") << QStringList{"encode", "--profile", "create1", "seek-dock"} << 1
                                        << "Seek Dock (143) is not available on the Create";
        QTest::newRow("not a number") << QStringList{"encode", "play", "one"} << 1 << "'one' is not a number";
        QTest::newRow("unknown profile") << QStringList{"encode", "--profile", "roomba900", "start"} << 2
                                         << "unknown profile 'roomba900'";
        QTest::newRow("no name") << QStringList{"encode"} << 2 << "encode needs a command name";
        QTest::newRow("unknown subcommand") << QStringList{"fly"} << 2 << "unknown command 'fly'";
        QTest::newRow("unknown option") << QStringList{"decode", "--fast"} << 2 << "unknown option '--fast'";
        QTest::newRow("bad reply ids") << QStringList{"decode", "--reply", "7,x"} << 2 << "--reply needs";
        QTest::newRow("reply id not on profile") << QStringList{"decode", "--profile", "create1", "--reply", "43"} << 2
                                                 << "not all of '43' are packets";
        QTest::newRow("disassemble") << QStringList{"disassemble", "--profile", "create1", "137", "1"} << 1
                                     << "Drive needs 4 data bytes; 1 remain";
        QTest::newRow("no command") << QStringList{} << 2 << "no command given";
        // Measurements that cannot be right: nothing is computed.
        const QStringList straight{"calibrate", "--compute", "--straight", "1000", "--measured"};
        QTest::newRow("measured zero") << straight + QStringList{"0"} << 1 << "0 mm cannot be";
        QTest::newRow("measured negative") << straight + QStringList{"-1040"} << 1 << "cannot be";
        QTest::newRow("measured text") << straight + QStringList{"a metre"} << 1 << "not a number";
        QTest::newRow("measured absurd") << straight + QStringList{"1600"} << 1 << "more than 50 % off";
        QTest::newRow("angle absurd") << QStringList{"calibrate", "--compute", "--turns", "2", "--measured-angle", "100"}
                                      << 1 << "measured angle: 100 degrees is more than 50 % off the 720";
        QTest::newRow("measured alone") << QStringList{"calibrate", "--compute", "--measured", "1000"} << 2
                                        << "needs --straight MM --measured MM";
        QTest::newRow("straight alone") << QStringList{"calibrate", "--compute", "--straight", "1000"} << 2
                                        << "--straight and --measured go together";
        QTest::newRow("turns not whole") << QStringList{"calibrate", "--compute", "--turns", "1.5", "--measured-angle", "540"}
                                         << 2 << "not a whole number of turns";
        QTest::newRow("calibrate no robot") << QStringList{"calibrate", "--straight", "1000"} << 2
                                            << "calibrate needs one of --port PATH";
        QTest::newRow("calibrate both runs") << QStringList{"calibrate", "--sim", "--straight", "1000", "--turns", "2"} << 2
                                             << "calibrate needs one run";
    }
    void errors()
    {
        QFETCH(QStringList, args);
        QFETCH(int, status);
        QFETCH(QString, message);
        const Outcome o = run(args);
        QCOMPARE(o.status, status);
        QCOMPARE(o.out, QString());
        QVERIFY2(o.err.startsWith("roomba-ctl: ") && o.err.contains(message), qPrintable(o.err));
        if (status == 1)
            QCOMPARE(o.err.count('\n'), 1); // one line
    }

    // What the dashboard kept per robot, read back as one JSON line per
    // robot (or words); a robot measured for a moment is not measured yet.
    void batteryHealth()
    {
        QTemporaryDir config;
        qputenv("XDG_CONFIG_HOME", config.path().toUtf8());
        const Outcome none = run({"battery"});
        QCOMPARE(none.status, 1);
        QVERIFY2(none.err.contains("no robot's battery has been measured yet"), qPrintable(none.err));
        {
            QSettings kept(QStringLiteral("RoombaDashboard"), QStringLiteral("roomba-dashboard"));
            kept.beginGroup(QStringLiteral("battery/serial%3A%2Fdev%2FttyUSB0"));
            kept.setValue("robotName", "Robot 3");
            kept.beginWriteArray("measurements", 1);
            kept.setArrayIndex(0);
            kept.setValue("at", "2026-12-01T10:00:00");
            kept.setValue("claimedCapacityMah", 3000);
            kept.setValue("capacityMah", 1350.4);
            kept.setValue("resistanceMohm", 900);
            kept.setValue("resistanceSamples", 12);
            kept.setValue("cycleSeen", 0.4);
            kept.endArray();
            kept.endGroup();
        }
        const Outcome kept = run({"battery"});
        QCOMPARE(kept.status, 0);
        const QJsonObject o = jsonObjectOf(kept.out.trimmed());
        QCOMPARE(o.value("robot").toString(), QString("serial:/dev/ttyUSB0"));
        QCOMPARE(o.value("name").toString(), QString("Robot 3"));
        QCOMPARE(o.value("condition").toString(), QString("replace"));
        QCOMPARE(o.value("capacity_mah").toInt(), 1350);
        QCOMPARE(o.value("resistance_mohm").toInt(), 900);
        QVERIFY(o.value("earlier_session").toBool());
        const Outcome text = run({"battery", "--text"});
        QVERIFY2(text.out.startsWith("serial:/dev/ttyUSB0 (Robot 3): Replace: holds 1350 of the 3000 mAh it claims (45 %)"),
                 qPrintable(text.out));

        const Outcome sim = run({"battery", "--sim", "--seconds", "1"});
        QCOMPARE(sim.status, 0);
        const QJsonObject measured = jsonObjectOf(sim.out.trimmed());
        QCOMPARE(measured.value("condition").toString(), QString("unknown"));
        QCOMPARE(measured.value("claimed_capacity_mah").toInt(), 3000);
        QCOMPARE(run({"battery", "--watch"}).status, 2);
        qunsetenv("XDG_CONFIG_HOME");
    }

    void calibrateCompute()
    {
        const Outcome o = run({"calibrate", "--compute", "--straight", "1000", "--measured", "1040", "--turns", "2",
                               "--measured-angle", "700"});
        QCOMPARE(o.status, 0);
        QCOMPARE(o.err, QString());
        const QJsonObject result = jsonObjectOf(o.out);
        // 4 % farther than counted: wheels 4 % larger; 700 of 720 degrees with them: a wider base.
        QVERIFY(std::abs(result["leftWheelDiameterMm"].toDouble() - 74.88) < 1e-6);
        QVERIFY(std::abs(result["rightWheelDiameterMm"].toDouble() - 74.88) < 1e-6);
        QVERIFY(std::abs(result["leftWheelScale"].toDouble() - 1.04) < 1e-9);
        QVERIFY(std::abs(result["wheelBaseMm"].toDouble() - 720 * 1.04 * 235 / 700) < 1e-6);
        QVERIFY(result["squareErrorBeforeMm"].toDouble() > result["squareErrorAfterMm"].toDouble());
    }

    void warningKeepsSuccess()
    {
        const Outcome o = run({"encode", "song", "4", "C4:8"});
        QCOMPARE(o.status, 0);
        QCOMPARE(o.out, QString("140 4 1 60 8\n"));
        QVERIFY(o.err.contains("warning: song slot 4 may not play"));
    }

    void decodeFrames()
    {
        // Junk, the Create 2 example, a bad checksum, the example again, a cut frame.
        const QByteArray input = QByteArray::fromHex("0102") + QByteArray::fromHex("13051d02190d00a3")
                                 + QByteArray::fromHex("13051d02190d00b6") + QByteArray::fromHex("13051d02190d00a3")
                                 + QByteArray::fromHex("13051d");
        const Outcome o = run({"decode"}, input);
        QCOMPARE(o.status, 0);
        const QStringList lines = o.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3);
        for (int i = 0; i < 2; ++i) {
            const QJsonObject frame = jsonObjectOf(lines[i]);
            QCOMPARE(frame["kind"].toString(), QString("stream"));
            QCOMPARE(frame["packets"].toObject()["cliff_front_left_signal"].toInt(), 537);
            QCOMPARE(frame["packets"].toObject()["virtual_wall"].toInt(), 0);
        }
        const QJsonObject counters = jsonObjectOf(lines[2])["counters"].toObject();
        QCOMPARE(counters["frames_good"].toInt(), 2);
        QCOMPARE(counters["checksum_failures"].toInt(), 1);
        QCOMPARE(counters["length_mismatches"].toInt(), 0);
        // The cut frame at the end is scanned again and given up.
        QCOMPARE(counters["bytes_discarded"].toInt(), 2 + 8 + 3);
        QCOMPARE(counters["bytes_pending"].toInt(), 0);
    }

    void decodeKeepsTheLastFramesBehindAStray19()
    {
        // A stray 19 whose "length" (48) runs past the end of the file.
        const QByteArray frame = QByteArray::fromHex("13051d02190d00a3");
        const Outcome o = run({"decode"}, QByteArray::fromHex("1330") + frame + frame);
        QCOMPARE(o.status, 0);
        const QStringList lines = o.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3);
        QCOMPARE(jsonObjectOf(lines[1])["packets"].toObject()["cliff_front_left_signal"].toInt(), 537);
        const QJsonObject counters = jsonObjectOf(lines[2])["counters"].toObject();
        QCOMPARE(counters["frames_good"].toInt(), 2);
        QCOMPARE(counters["bytes_discarded"].toInt(), 2);
        QCOMPARE(counters["bytes_pending"].toInt(), 0);
    }

    void decodeReplies()
    {
        const Outcome o = run({"decode", "--numbers", "--reply", "7,22"}, "3 62 128 1 0 0x02");
        QCOMPARE(o.status, 0);
        const QStringList lines = o.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3);
        const QJsonObject first = jsonObjectOf(lines[0]);
        QCOMPARE(first["kind"].toString(), QString("reply"));
        QCOMPARE(first["packets"].toObject()["bumps_wheel_drops"].toInt(), 3);
        QCOMPARE(first["packets"].toObject()["voltage"].toInt(), 16000);
        QCOMPARE(jsonObjectOf(lines[1])["packets"].toObject()["voltage"].toInt(), 2);
        QCOMPARE(jsonObjectOf(lines[2])["counters"].toObject()["replies_good"].toInt(), 2);
    }

    void decodeBadText()
    {
        const Outcome o = run({"decode", "--numbers"}, "19 5 300");
        QCOMPARE(o.status, 2);
        QVERIFY(o.err.contains("'300' is not a byte value"));
        QCOMPARE(o.out, QString());
    }

    void tables()
    {
        const Outcome create = run({"packets", "--profile", "create1"});
        QCOMPARE(create.status, 0);
        QVERIFY(create.out.contains("Cargo Bay Analog Signal"));
        QVERIFY(!create.out.contains("Light Bump"));
        const Outcome roomba = run({"packets", "--profile", "roomba500"});
        QVERIFY(roomba.out.contains("Right Encoder Counts"));
        QVERIFY(roomba.out.contains("  100  7..58      80"));
        const Outcome commands = run({"commands", "--profile", "create1"});
        QVERIFY(commands.out.contains("wait-event"));
        QVERIFY(!commands.out.contains("seek-dock"));
        const Outcome help = run({"--help"});
        QCOMPARE(help.status, 0);
        QVERIFY(help.out.startsWith("Usage: roomba-ctl"));
    }
};

QTEST_GUILESS_MAIN(TestRoombaCtl)
#include "tst_roomba_ctl.moc"
