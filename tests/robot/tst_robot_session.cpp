// SPDX-License-Identifier: GPL-3.0-or-later
// One robot's model: requests through the link's queue, firmware corrections
// applied to its odometry, and its history on the link's clock.
#include "calibration_drive.h"
#include "command_encoder.h"
#include "crowded_recording.h" // tests/common
#include "manual_clock.h" // tests/common
#include "recording_file.h"
#include "typed_command_bytes.h"
#include "recording_transport.h" // tests/common
#include "robot_session.h"
#include "saved_robots.h"
#include "transport.h"
#include "transport_factory.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

#include <algorithm>
#include <atomic>
#include <numbers>

namespace {

QByteArray toBytes(const oi::Bytes &b)
{
    return QByteArray(reinterpret_cast<const char *>(b.data()), qsizetype(b.size()));
}

// A Create 2 that streams distance (19) and angle (20) only when the test says,
// and prints a firmware banner after Reset (7). Lives on the link's thread.
class BannerRobot : public oilink::Transport {
public:
    explicit BannerRobot(std::string release) : m_release(std::move(release)) {}
    void open() override
    {
        m_open = true;
        emit opened();
    }
    void close() override { m_open = false; }
    bool isOpen() const override { return m_open; }
    bool write(const QByteArray &bytes) override
    {
        // Frames once the stream is asked for, as from a robot.
        if (bytes.contains(char(148)))
            streamAsked = true;
        // The banner comes after the Reset has gone out, as from a robot.
        if (bytes == QByteArray(1, char(7)))
            QMetaObject::invokeMethod(this, [this] {
                emit bytesReceived(QByteArray::fromStdString("bl-start\r\n2015-01-01\r\nr3_robot/tags/" + m_release
                                                             + ":4975 CLEAN\r\nbattery-current-zero 252\r\n"));
            }, Qt::QueuedConnection);
        return m_open;
    }
    void flush(int) override {}
    QString describe() const override { return QStringLiteral("/dev/banner-robot"); }

    // [19][6][19 d d][20 a a][checksum]
    void sendMotion(int distanceMm, int angleRaw)
    {
        QByteArray f;
        f.append(char(19)).append(char(6));
        f.append(char(19)).append(char((distanceMm >> 8) & 0xFF)).append(char(distanceMm & 0xFF));
        f.append(char(20)).append(char((angleRaw >> 8) & 0xFF)).append(char(angleRaw & 0xFF));
        unsigned sum = 0;
        for (char c : f)
            sum += static_cast<unsigned char>(c);
        f.append(char(-sum & 0xFF));
        emit bytesReceived(f);
    }

    std::atomic<bool> streamAsked{false};

private:
    std::string m_release;
    std::atomic<bool> m_open{false}; // read by the test's thread
};

// The BannerRobot a session's link makes on its thread, for the test to drive.
struct BannerLine {
    std::atomic<BannerRobot *> robot{nullptr};

    // Connects `session` to a BannerRobot that prints `release`, streaming
    // distance and angle, and waits until it is open.
    // With `clock` (the session's link clock), the link's time is moved on
    // until then.
    void connect(RobotSession &session, std::string release,
                 const QString &port = QStringLiteral("/dev/banner-robot"), ManualClock *clock = nullptr)
    {
        session.setTransportFactory([this, release](const oilink::LinkSettings &) {
            auto *t = new BannerRobot(release);
            robot = t;
            return t;
        });
        session.connectTo(settings(port));
        QTRY_VERIFY_WITH_TIMEOUT((clock && (clock->advance(10), true),
                                  robot.load() && robot.load()->isOpen() && robot.load()->streamAsked),
                                 5000);
    }
    static oilink::LinkSettings settings(const QString &port)
    {
        oilink::LinkSettings s = oilink::LinkSettings::serial(port, oi::ProfileId::Create2);
        s.streamPackets = {19, 20};
        return s;
    }
    // One frame of motion, once the session has it.
    void move(RobotSession &session, int distanceMm, int rawAngle)
    {
        const quint64 before = session.snapshotCount();
        QMetaObject::invokeMethod(robot.load(), [t = robot.load(), distanceMm, rawAngle] {
            t->sendMotion(distanceMm, rawAngle);
        });
        QTRY_VERIFY_WITH_TIMEOUT(session.snapshotCount() > before, 5000);
    }
};

double degrees(double radians)
{
    return radians * 180.0 / std::numbers::pi;
}

} // namespace

class TestRobotSession : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    // Show Script goes through the link's queue: the link pauses and resumes
    // its own stream, so it neither marks the data stale nor sends Start (which
    // would drop the robot out of Safe mode) while it waits for the reply.
    void showScriptKeepsTheRobotInSafeMode()
    {
        RobotSession robot;
        robot.setTransportFactory(transports::transportFactory());
        robot.connectTo(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create1, oi::ProfileId::Create1));
        QTRY_VERIFY_WITH_TIMEOUT(robot.isLive(), 5000);
        const oi::CommandEncoder encoder(oi::profile(oi::ProfileId::Create1));
        robot.send(commandsOf(toBytes(*encoder.safe())));
        QTRY_COMPARE_WITH_TIMEOUT(robot.latest().oiMode(), oi::OiMode::Safe, 5000);
        const std::vector<std::uint8_t> script{137, 0, 0, 0, 0, 156, 1, 144};
        QSignalSpy sent(&robot, &RobotSession::bytesSent);
        robot.send(commandsOf(toBytes(*encoder.script(script)), encoder.robotProfile()));
        QVERIFY(sent.wait(5000));
        sent.clear();

        QSignalSpy states(&robot, &RobotSession::stateChanged);
        QSignalSpy shown(&robot, &RobotSession::scriptShown);
        // Each write is told first as the typed commands it is.
        QStringList told;
        QObject listening; // gone before `told`, before the robot's last words
        connect(&robot, &RobotSession::commandsSent, &listening, [&told](const std::vector<oi::OiCommand> &commands) {
            for (const oi::OiCommand &c : commands)
                told << QString::number(int(c.command));
        });
        connect(&robot, &RobotSession::bytesSent, &listening, [&told] { told << QStringLiteral("bytes"); });
        robot.showScript();
        QVERIFY(shown.wait(5000));
        QCOMPARE(shown.at(0).at(0).toByteArray(), QByteArray(reinterpret_cast<const char *>(script.data()), qsizetype(script.size())));
        // The stream comes back, and the robot is still in Safe mode.
        const quint64 after = robot.snapshotCount();
        QTRY_VERIFY_WITH_TIMEOUT(robot.snapshotCount() > after + 3, 5000);
        QCOMPARE(robot.latest().oiMode(), oi::OiMode::Safe);
        for (const QList<QVariant> &s : states)
            QVERIFY2(s.at(0).value<oilink::LinkState>() == oilink::LinkState::Streaming, "the link left Streaming");
        QStringList bytesSent;
        for (const QList<QVariant> &s : sent)
            bytesSent << byteText(s.at(0).toByteArray());
        QCOMPARE(bytesSent, (QStringList{"150 0", "154", "150 1"}));
        QCOMPARE(told, (QStringList{QString::number(int(oi::Command::PauseResumeStream)), "bytes",
                                    QString::number(int(oi::Command::ShowScript)), "bytes",
                                    QString::number(int(oi::Command::PauseResumeStream)), "bytes"}));
    }

    // ERRATA 20: played in Passive, a script's Drive is ignored, its Wait
    // Distance never ends and the robot hears nothing more. The robot's
    // model enters Safe first, so the robot drives its 40 cm.
    void playScriptInPassiveEntersSafeFirst_data()
    {
        QTest::addColumn<bool>("passive");
        QTest::addColumn<QStringList>("expected");
        QTest::newRow("passive") << true << QStringList{"131", "153"};
        QTest::newRow("safe") << false << QStringList{"153"};
    }
    void playScriptInPassiveEntersSafeFirst()
    {
        QFETCH(bool, passive);
        QFETCH(QStringList, expected);
        RobotSession robot;
        robot.setTransportFactory(transports::transportFactory());
        robot.connectTo(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create1, oi::ProfileId::Create1));
        QTRY_VERIFY_WITH_TIMEOUT(robot.isLive(), 5000);
        if (!passive) {
            QVERIFY(robot.requestMode(oi::Command::Safe));
            QTRY_COMPARE_WITH_TIMEOUT(robot.mode().reported(), std::optional(oi::OiMode::Safe), 5000);
        }
        QCOMPARE(robot.mode().reported(), std::optional(passive ? oi::OiMode::Passive : oi::OiMode::Safe));
        // "drive 300 straight; wait-distance 400; drive 0 0"
        const oi::Bytes body{137, 1, 44, 128, 0, 156, 1, 144, 137, 0, 0, 0, 0};
        QVERIFY(robot.send(oi::OiCommand{oi::Command::Script, {}, body}));
        QSignalSpy sent(&robot, &RobotSession::bytesSent);
        QTRY_VERIFY_WITH_TIMEOUT(!sent.isEmpty() && sent.last().at(0).toByteArray().startsWith(char(152)), 5000);
        sent.clear();
        QVERIFY(robot.playScript());
        // Safe and Play Script, in the order written (the link's own stream
        // requests may come between).
        const auto modeAndPlay = [&sent] {
            QStringList out;
            for (const QList<QVariant> &s : sent)
                if (const QString text = byteText(s.at(0).toByteArray()); text == "131" || text == "153")
                    out << text;
            return out;
        };
        QTRY_COMPARE_WITH_TIMEOUT(modeAndPlay(), expected, 5000);
        // The robot drives its 40 cm in Safe, and streams on.
        QTRY_COMPARE_WITH_TIMEOUT(robot.mode().reported(), std::optional(oi::OiMode::Safe), 5000);
    }

    // What was uploaded is the robot's, whoever sent it; a cleaning or a
    // script that starts one leaves the robot running a command of its own
    // until Safe, which the bridge's stop reads from the mode.
    void theRobotKeepsItsScriptAndItsOwnCommand()
    {
        RobotSession robot;
        robot.setTransportFactory(transports::transportFactory());
        robot.connectTo(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create1, oi::ProfileId::Create1));
        QTRY_VERIFY_WITH_TIMEOUT(robot.isLive(), 5000);
        QVERIFY(!robot.uploadedScript());
        QVERIFY(!robot.mode().runsOwnCommand());

        const oi::Bytes drives{137, 1, 44, 128, 0};
        QVERIFY(robot.send(oi::OiCommand{oi::Command::Script, {}, drives}));
        QCOMPARE(robot.uploadedScript(), std::optional(QByteArray::fromHex("89012c8000")));
        QVERIFY(robot.send(oi::OiCommand{oi::Command::PlayScript, {}, {}}));
        QVERIFY(!robot.mode().runsOwnCommand()); // a script that only drives

        QVERIFY(robot.send(oi::OiCommand{oi::Command::Script, {}, {136, 0}})); // Demo 0 (Cover)
        QVERIFY(robot.send(oi::OiCommand{oi::Command::PlayScript, {}, {}}));
        QVERIFY(robot.mode().runsOwnCommand());
        QVERIFY(robot.requestMode(oi::Command::Safe));
        QVERIFY(!robot.mode().runsOwnCommand());

        // Stop all ends a Create's script (ERRATA 20): nothing is left to play.
        robot.teleop().stopAll();
        QCOMPARE(robot.uploadedScript(), std::optional(QByteArray()));
        QVERIFY(robot.send(oi::OiCommand{oi::Command::PlayScript, {}, {}}));
        QVERIFY(!robot.mode().runsOwnCommand());

        QVERIFY(robot.requestMode(oi::Command::Demo, 1));
        QVERIFY(robot.mode().runsOwnCommand());
        // A new connection knows nothing of the last one's.
        robot.connectTo(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create1, oi::ProfileId::Create1));
        QVERIFY(!robot.uploadedScript());
        QVERIFY(!robot.mode().runsOwnCommand());
    }

    // While a Create's script waits it hears nothing (ERRATA 20), so the
    // session's own angle query cannot pause the stream: that is asked again
    // later, and no error is shown, since the user asked for nothing.
    void anInternalQueryThatFailsIsAskedAgainQuietly()
    {
        RobotSession robot;
        robot.setTransportFactory(transports::transportFactory());
        robot.connectTo(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create1, oi::ProfileId::Create1));
        QTRY_VERIFY_WITH_TIMEOUT(robot.isLive(), 5000);
        QVERIFY(robot.requestMode(oi::Command::Safe));
        QTRY_COMPARE_WITH_TIMEOUT(robot.mode().reported(), std::optional(oi::OiMode::Safe), 5000);
        // Turn on the spot, then wait 3 s: the turn makes the angle due.
        QVERIFY(robot.send(oi::OiCommand{oi::Command::Script, {}, {137, 0, 100, 0, 1, 155, 30, 137, 0, 0, 0, 0}}));
        QSignalSpy errors(&robot, &RobotSession::errorOccurred);
        QSignalSpy angles(&robot, &RobotSession::angleRead);
        int pauses = 0;
        connect(&robot, &RobotSession::commandsSent, this, [&pauses](const std::vector<oi::OiCommand> &commands) {
            for (const oi::OiCommand &c : commands)
                pauses += c.command == oi::Command::PauseResumeStream && c.fields == std::vector<int>{0};
        });
        QVERIFY(robot.playScript());
        const int anglesBefore = angles.count();
        // Asked at least twice (the first while the script waits), then answered once it ends.
        QTRY_VERIFY_WITH_TIMEOUT(pauses >= 2 && angles.count() > anglesBefore, 10000);
        QCOMPARE(errors.count(), 0);
    }

    void showScriptOnARobotWithoutScriptsSaysSo()
    {
        RobotSession robot;
        robot.setTransportFactory(transports::transportFactory());
        robot.connectTo(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(robot.isLive(), 5000);
        QSignalSpy failed(&robot, &RobotSession::scriptFailed);
        QSignalSpy sent(&robot, &RobotSession::bytesSent);
        robot.showScript();
        QVERIFY(failed.wait(5000));
        QVERIFY2(failed.at(0).at(0).toString().contains("no scripts"), qPrintable(failed.at(0).at(0).toString()));
        QCOMPARE(sent.count(), 0);
    }

    // A Wi-Fi Roomba 600 that reports its mode one too high (the virtual
    // robot's option): the session reports the real mode, Passive after
    // Start and Safe after Safe, never the Safe it reads in Passive; the
    // robot is remembered as one that does, and its next session reads true
    // from its first frame.
    void aRobotReportingItsModeOneHighShowsItsTrueMode()
    {
        oilink::LinkSettings settings = oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2);
        settings.virtualModeOneHigh = true;
        settings.modeCheckAfterStart = true;
        QList<int> reported; // each change of the mode the first session reports
        QList<int> modes;    // every frame's mode in the second
        {
            RobotSession robot;
            robot.setTransportFactory(transports::transportFactory());
            connect(&robot, &RobotSession::modeChanged, this, [&] {
                if (const auto mode = robot.mode().reported(); mode && (reported.isEmpty() || reported.last() != int(*mode)))
                    reported << int(*mode);
            });
            QSignalSpy errors(&robot, &RobotSession::errorOccurred);
            robot.connectTo(settings);
            QTRY_VERIFY_WITH_TIMEOUT(robot.firmware().modeReportedOneHigh(), 5000);
            QTRY_COMPARE_WITH_TIMEOUT(robot.mode().reported(), std::optional(oi::OiMode::Passive), 5000);
            QVERIFY(robot.firmware().correctionsText().contains("one too high"));
            QVERIFY(!errors.isEmpty() && errors.last().at(0).toString().contains("one too high"));
            QVERIFY(robot.requestMode(oi::Command::Safe));
            QTRY_COMPARE_WITH_TIMEOUT(robot.mode().reported(), std::optional(oi::OiMode::Safe), 5000);
            QCOMPARE(reported, (QList<int>{int(oi::OiMode::Passive), int(oi::OiMode::Safe)}));
            QCOMPARE(robot.latest().oiMode(), oi::OiMode::Safe);
        }
        RobotSession again;
        again.setTransportFactory(transports::transportFactory());
        connect(&again, &RobotSession::frameReceived, this,
                [&](double, const oi::SensorSnapshot &frame) { modes << frame.raw(35); });
        again.connectTo(settings);
        QVERIFY(again.firmware().modeReportedOneHigh());
        QTRY_VERIFY_WITH_TIMEOUT(modes.size() >= 5, 5000);
        QCOMPARE(modes.count(int(oi::OiMode::Passive)), modes.size());
    }

    void sensorQueryGoesThroughTheLink()
    {
        RobotSession robot;
        robot.setTransportFactory(transports::transportFactory());
        robot.connectTo(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(robot.isLive(), 5000);
        QSignalSpy replies(&robot, &RobotSession::sensorReply);
        robot.querySensors({22, 25});
        QVERIFY(replies.wait(5000));
        const auto reply = replies.at(0).at(0).value<oi::SensorSnapshot>();
        QVERIFY(reply.has(22));
        QVERIFY(reply.has(25));
        QVERIFY(reply.voltageMv() > 10000);
    }

    // ERRATA 16: up to 3.4.0 the angle packet counts in units of 0.324°. A
    // 90° turn reads 29 raw; once the banner names the firmware, it reads 90°.
    void firmwareCorrectionsChangeTheOdometry()
    {
        BannerLine line;
        RobotSession robot;
        line.connect(robot, "release-3.4.0");
        line.move(robot, 0, 29);
        QCOMPARE(degrees(robot.odometry().pose().thetaRad), 29.0);
        QVERIFY(!robot.odometry().corrections().angleDivisor);

        QSignalSpy firmware(&robot, &RobotSession::firmwareChanged);
        robot.send(commandsOf(QByteArray(1, char(7))));
        QVERIFY(firmware.wait(5000));
        QCOMPARE(firmware.at(0).at(0).toString(), QString("release-3.4.0"));
        QVERIFY(robot.odometry().corrections().angleDivisor);
        robot.odometry().reset();
        line.move(robot, 0, 29);
        QVERIFY2(std::abs(degrees(robot.odometry().pose().thetaRad) - 29 / 0.324056) < 1e-6,
                 qPrintable(QString::number(degrees(robot.odometry().pose().thetaRad))));
    }

    // The firmware belongs to the robot it came from: another port forgets
    // it, the same port brings it back without a Reset, in this run and the next.
    void correctionsFollowTheRobot()
    {
        BannerLine line;
        RobotSession robot;
        line.connect(robot, "release-3.2.9");
        QSignalSpy read(&robot.firmware(), &RobotFirmware::read);
        QCOMPARE(robot.readFirmwareVersion(), QString());
        QVERIFY(read.wait(5000));
        QCOMPARE(robot.firmwareRelease(), QString("release-3.2.9"));
        QVERIFY(robot.corrections().distanceUnreliable);
        QVERIFY(robot.odometry().corrections().angleDivisor);

        QSignalSpy changed(&robot, &RobotSession::firmwareChanged);
        robot.connectTo(oilink::LinkSettings::serial("/dev/another-robot", oi::ProfileId::Create2));
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed.at(0).at(0).toString(), QString());
        QVERIFY(!robot.corrections().any());
        QVERIFY(!robot.odometry().corrections().any());

        // The same robot at another baud is still that robot.
        QSignalSpy sent(&robot, &RobotSession::bytesSent);
        auto sameRobot = BannerLine::settings("/dev/banner-robot");
        sameRobot.baud = 19200;
        robot.connectTo(sameRobot);
        QCOMPARE(robot.firmwareRelease(), QString("release-3.2.9"));
        QVERIFY(robot.corrections().distanceUnreliable);
        QVERIFY(robot.odometry().corrections().angleDivisor);
        robot.closeAndWait();
        for (const QList<QVariant> &bytes : sent)
            QVERIFY(!bytes.at(0).toByteArray().startsWith(char(7)));

        RobotSession nextRun;
        nextRun.setTransportFactory([](const oilink::LinkSettings &) { return new BannerRobot("release-3.2.9"); });
        QVERIFY(nextRun.firmwareRelease().isEmpty());
        nextRun.connectTo(BannerLine::settings("/dev/banner-robot"));
        QCOMPARE(nextRun.firmwareRelease(), QString("release-3.2.9"));
        QVERIFY(nextRun.corrections().distanceUnreliable);
    }

    // ERRATA 16: once the banner names firmware up to 3.4.0, the angle every
    // view reads is in degrees: the latest values, each frame handed on, the
    // history the plots draw and the CSV written from it.
    void correctedAngleReachesHistoryAndCsv()
    {
        BannerLine line;
        RobotSession robot;
        line.connect(robot, "release-3.4.0");
        QSignalSpy frames(&robot, &RobotSession::frameReceived);
        line.move(robot, 10, 29);
        QCOMPARE(robot.latest().raw(20), 29);
        QSignalSpy read(&robot.firmware(), &RobotFirmware::read);
        QCOMPARE(robot.readFirmwareVersion(), QString());
        QVERIFY(read.wait(5000));
        line.move(robot, 10, -29);
        QCOMPARE(frames.last().at(1).value<oi::SensorSnapshot>().raw(20), -89);
        QCOMPARE(robot.latest().raw(20), -89);
        QCOMPARE(robot.latest().raw(19), 10);
        const SensorHistory &h = robot.history();
        QCOMPARE(h.sample(20, 0).value, 29);
        QCOMPARE(h.sample(20, h.sampleCount(20) - 1).value, -89);

        QTemporaryDir dir;
        const QString csv = dir.filePath("turn.csv");
        QVERIFY(h.exportCsv(csv, {20}, h.oldestTime(), h.newestTime()));
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = file.readAll().trimmed().split('\n');
        QCOMPARE(lines.size(), 3);
        QVERIFY2(lines.first().startsWith("time_s,angle"), lines.first().constData());
        QVERIFY2(lines.at(1).endsWith(",29"), lines.at(1).constData());
        QVERIFY2(lines.at(2).endsWith(",-89"), lines.at(2).constData());
    }

    // Typed commands go out as the profile's bytes; a Reset among them makes
    // the firmware read the banner; a refused one sends nothing and says why.
    void sendsTypedCommands()
    {
        BannerLine line;
        RobotSession robot;
        line.connect(robot, "release-3.3.0");
        QSignalSpy sent(&robot, &RobotSession::bytesSent);
        QSignalSpy read(&robot.firmware(), &RobotFirmware::read);
        QVERIFY(robot.send(std::vector<oi::OiCommand>{{oi::Command::Safe, {}, {}},
                                                      {oi::Command::Drive, {-200, 500}, {}}}));
        // Both in one write (the link's own Start and Stream may come too).
        const auto wrote = [&sent](const QByteArray &bytes) {
            return std::any_of(sent.cbegin(), sent.cend(), [&](const QList<QVariant> &s) { return s.at(0).toByteArray() == bytes; });
        };
        QTRY_VERIFY_WITH_TIMEOUT(wrote(QByteArray::fromHex("8389ff3801f4")), 5000);

        QVERIFY(robot.send(oi::OiCommand{oi::Command::Reset, {}, {}}));
        QVERIFY(read.wait(5000));
        QCOMPARE(read.at(0).at(0).toString(), QString("release-3.3.0"));

        QSignalSpy errors(&robot, &RobotSession::errorOccurred);
        QVERIFY(!robot.send(std::vector<oi::OiCommand>{{oi::Command::Safe, {}, {}},
                                                       {oi::Command::Drive, {600, 0}, {}}}));
        QCOMPARE(errors.count(), 1);
        QVERIFY2(errors.at(0).at(0).toString().contains("velocity: 600 is outside -500..500"),
                 qPrintable(errors.at(0).at(0).toString()));
        QVERIFY(!robot.send(oi::OiCommand{oi::Command::PlayScript, {}, {}})); // a Create's command
        QCOMPARE(errors.count(), 2);
        // The link keeps order: once a Start sent after them is out, the
        // refused commands would have been too.
        QVERIFY(robot.send(oi::OiCommand{oi::Command::Start, {}, {}}));
        QTRY_VERIFY_WITH_TIMEOUT(sent.last().at(0).toByteArray() == QByteArray(1, char(128)), 5000);
        for (const QList<QVariant> &bytes : sent) {
            QVERIFY(!bytes.at(0).toByteArray().contains(QByteArray::fromHex("890258")));
            QVERIFY(!bytes.at(0).toByteArray().contains(char(153)));
        }
    }

    void readingFirmwareNeedsTheRobotItself()
    {
        RobotSession robot;
        QVERIFY(robot.readFirmwareVersion().contains("Connect to the robot first"));
        robot.setTransportFactory([](const oilink::LinkSettings &) { return new BannerRobot("release-3.4.0"); });
        robot.connectTo(oilink::LinkSettings::replayOf("/tmp/none.oirec", oi::ProfileId::Create2, 115200, {}));
        QVERIFY(robot.readFirmwareVersion().contains("connect to the robot itself"));
    }

    // The bytes the inspector shows carry the time the link read them, not
    // when the window took them in: two reads 60 ms apart on the link's
    // clock that reach the window together are stamped 60 ms apart.
    void receivedBytesCarryTheirReadTime()
    {
        ManualClock clock;
        RobotSession session;
        session.setLinkClock(clock);
        BannerLine line;
        line.connect(session, "release-3.4.0", QStringLiteral("/dev/banner-robot"), &clock);
        QSignalSpy received(&session, &RobotSession::bytesReceived);
        const auto readOnTheLinkThread = [&](int distanceMm) {
            QMetaObject::invokeMethod(
                line.robot.load(), [t = line.robot.load(), distanceMm] { t->sendMotion(distanceMm, 0); },
                Qt::BlockingQueuedConnection);
        };
        readOnTheLinkThread(10);
        clock.advance(60);
        readOnTheLinkThread(20);
        QTRY_VERIFY_WITH_TIMEOUT(received.size() >= 2, 5000);
        const qint64 first = received.at(received.size() - 2).at(1).toLongLong();
        const qint64 second = received.last().at(1).toLongLong();
        QCOMPARE(second - first, 60);
    }

    // Frames carry the time the link read them: the history's clock.
    void historyRunsOnTheLinkClock()
    {
        RobotSession robot;
        robot.setTransportFactory(transports::transportFactory());
        robot.connectTo(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(robot.snapshotCount() >= 10, 5000);
        const SensorHistory &h = robot.history();
        QVERIFY(h.sampleCount(7) >= 10);
        double previous = -1;
        for (std::size_t i = 0; i < h.sampleCount(7); ++i) {
            QVERIFY(h.sample(7, i).time >= previous);
            previous = h.sample(7, i).time;
        }
        QVERIFY(previous > 0);
        QVERIFY(previous < 60);
    }

    // Markers dropped while recording (added, renamed, deleted) are in the
    // file; a replay of it shows them, and its changes go back into the file;
    // the CSV export carries them.
    void markersSurviveRecordReplayAndExport()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("marked.oirec");
        RobotSession robot;
        robot.setTransportFactory(transports::transportFactory());
        QString error;
        QCOMPARE(robot.dropMarker("too early", &error), 0);
        QVERIFY(error.contains("recording"));
        robot.connectTo(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(robot.snapshotCount() >= 5, 5000);
        robot.startRecording(path);
        QTRY_VERIFY_WITH_TIMEOUT(robot.recording().active, 5000);
        QVERIFY(robot.markers().canChange());
        QSignalSpy changed(&robot.markers(), &RobotMarkers::changed);
        const auto dropAfterFrames = [&](const QString &note) {
            const quint64 until = robot.snapshotCount() + 5;
            if (!QTest::qWaitFor([&] { return robot.snapshotCount() >= until; }, 5000))
                return 0;
            return robot.dropMarker(note);
        };
        QCOMPARE(dropAfterFrames("start"), 1);
        const double startSeconds = robot.markers().seconds(robot.markers().list().first());
        QVERIFY(std::abs(startSeconds - robot.history().newestTime()) <= 0.5e-6); // kept in whole µs
        QCOMPARE(dropAfterFrames(""), 2);
        QCOMPARE(dropAfterFrames("oops"), 3);
        QVERIFY(robot.markers().rename(2, "  hit the   table leg "));
        QVERIFY(robot.markers().remove(3));
        QVERIFY(!robot.markers().remove(3, &error));
        QCOMPARE(dropAfterFrames("turned"), 3); // the id of a deleted marker is free again
        QCOMPARE(changed.size(), 6);
        const QList<oilink::RecordingMarker> made = robot.markers().list();
        QCOMPARE(made.size(), 3);
        QCOMPARE(made[1].note, QString("hit the table leg"));
        QVERIFY(made[0].timeUs < made[1].timeUs && made[1].timeUs < made[2].timeUs);
        QTRY_VERIFY_WITH_TIMEOUT(robot.snapshotCount() >= 40, 5000);
        robot.stopRecording();
        QTRY_VERIFY_WITH_TIMEOUT(!robot.recording().active, 5000);
        QVERIFY(!robot.markers().canChange());
        QCOMPARE(robot.markers().list(), made);

        std::optional<oilink::Recording> file = oilink::Recording::load(path, &error);
        QVERIFY2(file, qPrintable(error));
        QCOMPARE(file->markers(), made);
        QVERIFY(made.last().timeUs <= file->durationUs());
        // The CSV: each label once, on a frame at or after its marker.
        QString csv;
        QTextStream out(&csv);
        file->writeCsv(out);
        out.flush();
        QStringList labels;
        for (const QString &line : csv.split('\n', Qt::SkipEmptyParts).mid(1)) {
            const QString cell = line.section(',', -1);
            if (!cell.isEmpty()) {
                labels << cell;
                QVERIFY(line.section(',', 0, 0).toDouble() * 1e6 >= double(made[labels.size() - 1].timeUs) - 1);
            }
        }
        QCOMPARE(labels, (QStringList{"start", "hit the table leg", "turned"}));

        // A replay of the file: its markers, on the recording's clock; next
        // and previous from a moment; a change kept in the file.
        RobotSession replay;
        const auto stream = oilink::Recording::readStream(path, &error);
        QVERIFY(stream);
        replay.connectTo(oilink::LinkSettings::replayOf(path, stream->profile->id, stream->baud, stream->packets));
        QTRY_COMPARE_WITH_TIMEOUT(replay.markers().list(), made, 5000);
        QCOMPARE(replay.markers().seconds(made[1]), double(made[1].timeUs) / 1e6);
        QCOMPARE(replay.markers().next(replay.markers().seconds(made[0]))->id, made[1].id);
        QCOMPARE(replay.markers().previous(replay.markers().seconds(made[0])), std::nullopt);
        QCOMPARE(replay.markers().previous(100.0)->id, made[2].id);
        QVERIFY(replay.markers().rename(made[0].id, "the very start", &error));
        QVERIFY(replay.markers().remove(made[2].id, &error));
        file = oilink::Recording::load(path, &error);
        QVERIFY2(file, qPrintable(error));
        QCOMPARE(file->markers(), replay.markers().list());
        QCOMPARE(file->markers().size(), 2);
        QCOMPARE(file->markers()[0].note, QString("the very start"));
    }

    // A replayed file with more markers than a recording holds shows the
    // first oilink::kMaxMarkers and counts the rest; no marker is added to
    // it, and the file is left as it was.
    void aReplayShowsItsFirstThousandMarkers()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("crowded.oirec");
        QVERIFY(writeCrowdedRecording(path, oilink::kMaxMarkers + 40));
        const qint64 size = QFileInfo(path).size();

        RobotSession replay;
        replay.connectTo(oilink::LinkSettings::replayOf(path, oi::ProfileId::Create2, 115200, {7}));
        QTRY_COMPARE_WITH_TIMEOUT(replay.markers().list().size(), oilink::kMaxMarkers, 5000);
        QCOMPARE(replay.markers().leftOut(), 40);
        QString error;
        QCOMPARE(replay.markers().add(0, "one more", &error), 0);
        QCOMPARE(error, QString("A recording holds at most 1000 markers."));
        QCOMPARE(replay.markers().list().size(), oilink::kMaxMarkers);
        QCOMPARE(QFileInfo(path).size(), size);
        // Deleting one makes room for one.
        QVERIFY(replay.markers().remove(1, &error));
        QVERIFY(replay.markers().add(0, "one more", &error));
        QCOMPARE(oilink::Recording::load(path, &error)->markers(), replay.markers().list());
    }

    // Closing stops the robot and leaves it in Passive, from the model.
    void closingStopsAndLeavesPassive_data()
    {
        QTest::addColumn<bool>("linkHere");
        QTest::newRow("link on its own thread") << false;
        QTest::newRow("link on the session's thread") << true;
    }
    void closingStopsAndLeavesPassive()
    {
        QFETCH(bool, linkHere);
        Recording recording;
        recording.mode = 2;
        RobotSession robot;
        robot.setLinkOnThisThread(linkHere);
        robot.setTransportFactory([&recording](const oilink::LinkSettings &) { return new RecordingTransport(&recording); });
        robot.connectTo(oilink::LinkSettings::serial("/dev/recording", oi::ProfileId::Create2));
        // Live is not enough: motion waits for the robot to report its mode.
        QTRY_VERIFY_WITH_TIMEOUT(robot.isLive(), 5000);
        QTRY_COMPARE_WITH_TIMEOUT(robot.mode().reported(), std::optional(oi::OiMode::Safe), 5000);
        robot.teleop().requestMotion(MotionCommand{MotionCommand::Kind::Drive, 200, oi::kRadiusStraight});
        QTRY_VERIFY_WITH_TIMEOUT(robot.teleop().isMoving(), 5000);
        recording.take();
        robot.closeAndWait();
        QStringList writes;
        for (const QByteArray &w : recording.take())
            writes << byteText(w);
        const oi::CommandEncoder encoder(oi::profile(oi::ProfileId::Create2));
        QVERIFY2(!writes.isEmpty(), "nothing was sent on close");
        QCOMPARE(writes.last(), byteText(toBytes(encoder.shutdownSequence())));
    }

    // The bridge's way: no worker thread; frames, commands and the mode
    // the robot reports go through the session's own event loop.
    void theLinkCanRunOnTheSessionsThread()
    {
        const auto linkThreads = [] {
            int n = 0;
            for (const QFileInfo &task : QDir(QStringLiteral("/proc/self/task")).entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot)) {
                QFile comm(task.filePath() + QStringLiteral("/comm"));
                n += comm.open(QIODevice::ReadOnly) && comm.readAll().trimmed() == "robot link";
            }
            return n;
        };
        const int before = linkThreads();
        RobotSession robot;
        robot.setLinkOnThisThread(true);
        robot.setTransportFactory(transports::transportFactory());
        QList<double> frameTimes;
        connect(&robot, &RobotSession::frameReceived, this, [&](double t, const oi::SensorSnapshot &) {
            QCOMPARE(QThread::currentThread(), thread());
            frameTimes.append(t);
        });
        robot.connectTo(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(frameTimes.size() >= 10, 5000);
        QCOMPARE(linkThreads(), before);
        QVERIFY(std::is_sorted(frameTimes.cbegin(), frameTimes.cend()));
        QVERIFY(robot.send(oi::OiCommand{oi::Command::Safe, {}, {}}));
        QTRY_COMPARE_WITH_TIMEOUT(robot.mode().reported(), std::optional(oi::OiMode::Safe), 5000);
        robot.closeAndWait();
        QCOMPARE(robot.state(), oilink::LinkState::Closed);
    }

    // ERRATA 20: leaving a Create's Safe or Full mode (Stop all, Start from
    // any command path) first ends a script that may be running, so a
    // looping script stops and the robot still hears.
    void leavingACreateEndsItsScript()
    {
        RobotSession robot;
        robot.setTransportFactory(transports::transportFactory());
        robot.connectTo(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create1, oi::ProfileId::Create1));
        QTRY_VERIFY_WITH_TIMEOUT(robot.isLive(), 5000);
        // The document's "Drive in a square", which plays itself again, in Full.
        robot.send(commandsOf(QByteArray(1, char(132))));
        const oi::Bytes square{152, 17, 137, 1, 44, 128, 0, 156, 1, 144, 137, 1, 44, 0, 1, 157, 0, 90, 153};
        robot.send(commandsOf(toBytes(square), oi::profile(oi::ProfileId::Create1)));
        robot.send(commandsOf(QByteArray(1, char(153)), oi::profile(oi::ProfileId::Create1)));
        QTRY_VERIFY_WITH_TIMEOUT(robot.latest().requestedVelocity() == 300, 5000);

        QSignalSpy sent(&robot, &RobotSession::bytesSent);
        robot.teleop().stopAll();
        robot.send(commandsOf(QByteArray(1, char(128)))); // Passive
        QTRY_COMPARE_WITH_TIMEOUT(sent.size(), 4, 5000);
        QStringList bytesSent;
        for (const QList<QVariant> &s : sent)
            bytesSent << byteText(s.at(0).toByteArray());
        QCOMPARE(bytesSent, (QStringList{"152 0", "137 0 0 0 0 138 0", "152 0", "128"}));
        // Once the loop it was in ends, the robot is in Passive, stopped and listening.
        QTRY_VERIFY_WITH_TIMEOUT(robot.latest().oiMode() == oi::OiMode::Passive, 10000);
        QCOMPARE(robot.latest().requestedVelocity(), 0);
        QSignalSpy shown(&robot, &RobotSession::scriptShown);
        QSignalSpy failed(&robot, &RobotSession::scriptFailed);
        robot.showScript();
        QTRY_VERIFY_WITH_TIMEOUT(shown.size() + failed.size() > 0, 5000);
        QCOMPARE(failed.size(), 0);
        QCOMPARE(shown.at(0).at(0).toByteArray(), QByteArray()); // the empty script
    }

    // A bump during a calibration run aborts it with the reason, and the
    // robot is stopped: Drive 0 0 and the motors off, sent last.
    void bumpAbortsACalibrationRun()
    {
        Recording recording;
        recording.mode = 2; // Safe
        RobotSession robot;
        robot.setTransportFactory([&recording](const oilink::LinkSettings &) { return new RecordingTransport(&recording); });
        robot.connectTo(oilink::LinkSettings::serial("/dev/recording", oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(robot.isLive(), 5000);
        CalibrationDrive drive(robot);
        QSignalSpy aborted(&drive, &CalibrationDrive::aborted);
        QVERIFY(drive.start(oi::EncoderRun::Kind::Straight, 1000));
        // Slowly ahead, by Drive Direct (145): 100 mm/s on both wheels.
        QTRY_VERIFY_WITH_TIMEOUT(recording.written().contains(bytes({145, 0, 100, 0, 100})), 5000);
        QVERIFY(aborted.isEmpty());

        recording.bumps = oi::bit::BumpLeft;
        QTRY_COMPARE_WITH_TIMEOUT(aborted.size(), 1, 5000);
        QVERIFY2(aborted.first().first().toString().contains(QStringLiteral("bumped")),
                 qPrintable(aborted.first().first().toString()));
        QVERIFY(!drive.isRunning());
        const QByteArray stop = bytes({137, 0, 0, 0, 0, 138, 0});
        QTRY_VERIFY_WITH_TIMEOUT(recording.written().endsWith(stop), 5000);
        recording.take();

        // The step can be run again once the way is clear.
        recording.bumps = 0;
        QTRY_VERIFY_WITH_TIMEOUT(!robot.latest().bumpLeft(), 5000);
        QVERIFY(drive.start(oi::EncoderRun::Kind::Straight, 1000));
        QTRY_VERIFY_WITH_TIMEOUT(recording.written().contains(bytes({145, 0, 100, 0, 100})), 5000);
        drive.stop();
        QCOMPARE(aborted.size(), 2);
        QTRY_VERIFY_WITH_TIMEOUT(recording.written().endsWith(stop), 5000);
    }

    // A calibration is kept per robot with its name and date, comes back
    // when the robot connects again (after a restart), and resets.
    void calibrationIsKeptPerRobot()
    {
        const oi::WheelGeometry measured{74.9, 75.1, 228.0};
        const auto serial = oilink::LinkSettings::serial("/dev/recording", oi::ProfileId::Create2);
        {
            RobotSession robot;
            robot.setName(QStringLiteral("Robbie"));
            robot.setTransportFactory([](const oilink::LinkSettings &) { return new RecordingTransport(); });
            robot.connectTo(serial);
            QVERIFY(!robot.calibration());
            QSignalSpy changed(&robot, &RobotSession::calibrationChanged);
            QVERIFY(!robot.applyCalibration(oi::WheelGeometry{0, 72, 235}));
            QVERIFY(changed.isEmpty());
            QVERIFY(robot.applyCalibration(measured));
            QCOMPARE(changed.size(), 1);
            QCOMPARE(robot.odometry().wheels(), measured);
        }
        {
            // Another run of the program: the same robot gets its wheels back.
            RobotSession robot;
            robot.setTransportFactory([](const oilink::LinkSettings &) { return new RecordingTransport(); });
            robot.connectTo(serial);
            QVERIFY(robot.calibration());
            QCOMPARE(robot.calibration()->wheels, measured);
            QCOMPARE(robot.calibration()->robotName, QStringLiteral("Robbie"));
            QVERIFY(robot.calibration()->measuredAt.isValid());
            QCOMPARE(robot.odometry().wheels(), measured);
            // Another robot does not.
            robot.connectTo(oilink::LinkSettings::serial("/dev/other", oi::ProfileId::Create2));
            QVERIFY(!robot.calibration());
            QCOMPARE(robot.odometry().wheels(), oi::WheelGeometry{});
            // Reset: the documented wheels, for good.
            robot.connectTo(serial);
            QCOMPARE(robot.odometry().wheels(), measured);
            robot.resetCalibration();
            QVERIFY(!robot.calibration());
            QCOMPARE(robot.odometry().wheels(), oi::WheelGeometry{});
        }
        RobotSession robot;
        robot.setTransportFactory([](const oilink::LinkSettings &) { return new RecordingTransport(); });
        robot.connectTo(serial);
        QVERIFY(!robot.calibration());
    }

    // A virtual robot given wrong wheels keeps them in the robot list; a
    // value that cannot be wheels comes back as the documents'.
    void virtualWheelsAreKeptWithTheRobotList()
    {
        oilink::LinkSettings worn = oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2);
        worn.virtualWheels = oi::WheelGeometry{74.88, 73.0, 228.0};
        QSettings settings;
        saveRobots(settings, {SavedRobot{QStringLiteral("Wobbly"), {}, worn, true}});
        QCOMPARE(loadSavedRobots(settings).value(0).link.virtualWheels, worn.virtualWheels);
        settings.setValue(QStringLiteral("robots/1/virtualWheelBaseMm"), -5);
        QCOMPARE(loadSavedRobots(settings).value(0).link.virtualWheels, oi::WheelGeometry{});
    }

    // The wake line is kept with the robot like its baud; a value that is
    // not a wake line comes back as RTS, the default, and the robot stays.
    void theWakeLineIsKeptWithTheRobotList()
    {
        oilink::LinkSettings cable = oilink::LinkSettings::serial(QStringLiteral("/dev/ttyUSB0"), oi::ProfileId::Create2, 57600);
        cable.brcLine = oi::BrcLine::Dtr;
        QSettings settings;
        saveRobots(settings, {SavedRobot{QStringLiteral("Dee"), {}, cable, true}});
        QCOMPARE(settings.value(QStringLiteral("robots/1/brcLine")).toString(), QStringLiteral("dtr"));
        QCOMPARE(loadSavedRobots(settings).value(0).link, cable);
        settings.setValue(QStringLiteral("robots/1/brcLine"), QStringLiteral("cts"));
        const QList<SavedRobot> back = loadSavedRobots(settings);
        QCOMPARE(back.size(), 1);
        QCOMPARE(back[0].link.brcLine, oi::BrcLine::Rts);
        QCOMPARE(back[0].link.baud, 57600);
    }
};

QTEST_MAIN(TestRobotSession)
#include "tst_robot_session.moc"
