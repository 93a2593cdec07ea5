// SPDX-License-Identifier: GPL-3.0-or-later
// The roomba-sim program as a user runs it: the device on the first line,
// a client streaming from it, a clean exit on SIGTERM, status 2 for bad
// arguments.
#include "command_encoder.h"
#include "stream_parser.h"

#include <QDeadlineTimer>
#include <QFileInfo>
#include <QMap>
#include <QProcess>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

using namespace oi;

namespace {

const QString kProgram = QStringLiteral(ROOMBA_SIM_PATH);

QByteArray bytes(const Bytes &b)
{
    return QByteArray(reinterpret_cast<const char *>(b.data()), qsizetype(b.size()));
}

QByteArray bytes(const EncodeResult &r) { return bytes(*r); }

// Starts roomba-sim and returns its first line, or an empty string.
QString startAndReadFirstLine(QProcess &process, const QStringList &arguments)
{
    process.start(kProgram, arguments);
    if (!process.waitForStarted(5000))
        return {};
    for (int i = 0; i < 50 && !process.canReadLine(); ++i)
        process.waitForReadyRead(100);
    return QString::fromLocal8Bit(process.readLine()).trimmed();
}

void stopCleanly(QProcess &process, int signal = SIGTERM)
{
    ::kill(pid_t(process.processId()), signal);
    QVERIFY(process.waitForFinished(5000));
    QCOMPARE(process.exitStatus(), QProcess::NormalExit);
    QCOMPARE(process.exitCode(), 0);
}

} // namespace

class TestRoombaSim : public QObject {
    Q_OBJECT
private slots:
    void servesAPseudoTerminal();
    void servesTcp();
    void refusesBadArguments_data();
    void refusesBadArguments();
    void helpAndVersion();
    void refusesABadRoom();
    void servesARoomAndEndsOnHangUp();
    void reportsTheTruePose();
};

void TestRoombaSim::servesAPseudoTerminal()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString link = dir.filePath(QStringLiteral("robot"));
    QVERIFY(QFile::link(QStringLiteral("/nonexistent"), link)); // an old link is replaced

    QProcess process;
    const QString device = startAndReadFirstLine(
        process, {QStringLiteral("--profile"), QStringLiteral("roomba500"), QStringLiteral("--link"), link,
                  QStringLiteral("--firmware"), QStringLiteral("release-3.4.1")});
    QVERIFY2(device.startsWith(QStringLiteral("/dev/")), qPrintable(device + process.readAllStandardError()));
    QCOMPARE(QFileInfo(link).symLinkTarget(), device);

    // Through the link, as a client configured with a fixed path would.
    const int fd = ::open(QFile::encodeName(link).constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    QVERIFY2(fd >= 0, std::strerror(errno));
    const RobotProfile &profile = oi::profile(ProfileId::Roomba500);
    const CommandEncoder encoder(profile);
    StreamParser parser(profile);
    std::vector<SensorSnapshot> frames;
    parser.setSnapshotHandler([&](const SensorSnapshot &s, FrameKind) { frames.push_back(s); });
    const QByteArray request = bytes(encoder.start()) + bytes(encoder.stream(std::vector<int>{35, 43, 44}));
    QCOMPARE(::write(fd, request.constData(), std::size_t(request.size())), ssize_t(request.size()));
    // Blocks until the robot, another process, writes; five seconds at most.
    std::uint8_t buffer[1024];
    const QDeadlineTimer deadline(5000);
    while (frames.size() < 10 && !deadline.hasExpired()) {
        pollfd ready{fd, POLLIN, 0};
        if (::poll(&ready, 1, int(deadline.remainingTime())) <= 0)
            continue;
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n > 0)
            parser.feed(std::span(buffer, std::size_t(n)));
    }
    QVERIFY(frames.size() >= 10);
    QCOMPARE(frames.back().oiMode(), OiMode::Passive);
    QVERIFY(frames.back().hasEncoders());
    ::close(fd);

    stopCleanly(process);
    QVERIFY(!QFileInfo::exists(link) && !QFileInfo(link).isSymLink());
}

void TestRoombaSim::servesTcp()
{
    QProcess process;
    // Wheels other than the documents' are taken (the virtual robot's tests show what they do).
    const QString where = startAndReadFirstLine(process, {QStringLiteral("--tcp"), QStringLiteral("0"),
                                                          QStringLiteral("--wheel-diameter"), QStringLiteral("74.88"),
                                                          QStringLiteral("--right-wheel-diameter"), QStringLiteral("73"),
                                                          QStringLiteral("--wheel-base"), QStringLiteral("228")});
    QVERIFY2(where.startsWith(QStringLiteral("tcp://127.0.0.1:")), qPrintable(where));
    const quint16 port = where.section(':', -1).toUShort();
    QVERIFY(port != 0);

    const RobotProfile &profile = oi::profile(ProfileId::Create2);
    const CommandEncoder encoder(profile);
    StreamParser parser(profile);
    int frames = 0;
    parser.setSnapshotHandler([&](const SensorSnapshot &, FrameKind kind) { frames += kind == FrameKind::Stream; });
    QTcpSocket client;
    QObject::connect(&client, &QTcpSocket::readyRead, &client, [&] {
        const QByteArray data = client.readAll();
        parser.feed(std::span(reinterpret_cast<const std::uint8_t *>(data.constData()), std::size_t(data.size())));
    });
    client.connectToHost(QHostAddress::LocalHost, port);
    QVERIFY(client.waitForConnected(5000));
    client.write(bytes(encoder.start()) + bytes(encoder.stream(std::vector<int>{100})));
    QTRY_VERIFY_WITH_TIMEOUT(frames >= 10, 5000);
    QCOMPARE(parser.counters().checksumFailures, 0u);
    stopCleanly(process, SIGINT);
}

void TestRoombaSim::refusesBadArguments_data()
{
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("unknown option") << QStringList{"--bogus"};
    QTest::newRow("stray argument") << QStringList{"robot"};
    QTest::newRow("unknown profile") << QStringList{"--profile", "roomba900"};
    QTest::newRow("corrupt above 1") << QStringList{"--corrupt", "1.5"};
    QTest::newRow("stray negative") << QStringList{"--stray", "-0.1"};
    QTest::newRow("drop not a number") << QStringList{"--drop", "often"};
    QTest::newRow("seed negative") << QStringList{"--seed", "-1"};
    QTest::newRow("port too big") << QStringList{"--tcp", "70000"};
    QTest::newRow("bad bind address") << QStringList{"--tcp", "0", "--bind", "no.where"};
    QTest::newRow("bind without tcp") << QStringList{"--bind", "127.0.0.1"};
    QTest::newRow("link with tcp") << QStringList{"--tcp", "0", "--link", "/tmp/x"};
    QTest::newRow("firmware not a release") << QStringList{"--firmware", "3.8"};
    QTest::newRow("firmware on create1") << QStringList{"--profile", "create1", "--firmware", "release-3.8.2"};
    QTest::newRow("missing value") << QStringList{"--seed"};
    QTest::newRow("room not there") << QStringList{"--room", "/nonexistent/room.json"};
    QTest::newRow("wheel not a number") << QStringList{"--wheel-diameter", "big"};
    QTest::newRow("wheel twice the documents'") << QStringList{"--left-wheel-diameter", "144"};
    QTest::newRow("wheel of nothing") << QStringList{"--right-wheel-diameter", "0"};
    QTest::newRow("wheel base negative") << QStringList{"--wheel-base", "-235"};
    QTest::newRow("the Create never sleeps") << QStringList{"--profile", "create1", "--sleeps-while-pulsed"};
    QTest::newRow("wired to no line") << QStringList{"--brc-wired", "cts"};
    QTest::newRow("wired to both") << QStringList{"--brc-wired", "both"};
    QTest::newRow("wake time negative") << QStringList{"--wake-time", "-1"};
    QTest::newRow("wake time not a number") << QStringList{"--wake-time", "slow"};
    QTest::newRow("wake time too long") << QStringList{"--wake-time", "60000"};
    QTest::newRow("battery faded past all use") << QStringList{"--battery-fade", "95"};
    QTest::newRow("battery fade not a number") << QStringList{"--battery-fade", "old"};
    QTest::newRow("battery resistance of nothing") << QStringList{"--battery-resistance", "0"};
    QTest::newRow("battery charged past full") << QStringList{"--battery-charge", "120"};
}

void TestRoombaSim::refusesBadArguments()
{
    QFETCH(QStringList, arguments);
    QProcess process;
    process.start(kProgram, arguments);
    QVERIFY(process.waitForFinished(5000));
    QCOMPARE(process.exitStatus(), QProcess::NormalExit);
    QCOMPARE(process.exitCode(), 2);
    QVERIFY(process.readAllStandardOutput().isEmpty());
    const QByteArray err = process.readAllStandardError();
    QVERIFY2(err.startsWith("roomba-sim: "), err.constData());
    QCOMPARE(err.count('\n'), 1);
}

void TestRoombaSim::helpAndVersion()
{
    QProcess process;
    process.start(kProgram, {QStringLiteral("--help")});
    QVERIFY(process.waitForFinished(5000));
    QCOMPARE(process.exitCode(), 0);
    const QByteArray help = process.readAllStandardOutput();
    QVERIFY(help.contains("--profile") && help.contains("--tcp") && help.contains("--link"));
    QVERIFY(help.contains("--sleeps-while-pulsed") && help.contains("release-3.2.x"));
    QVERIFY(help.contains("--mode-off-by-one") && help.contains("one too high"));
    QVERIFY(help.contains("--brc-wired") && help.contains("--wake-time"));
    QVERIFY(help.contains("--on-dock") && help.contains("charging status") && help.contains("battery drains"));
    process.start(kProgram, {QStringLiteral("--version")});
    QVERIFY(process.waitForFinished(5000));
    QCOMPARE(process.exitCode(), 0);
    QVERIFY(process.readAllStandardOutput().startsWith("roomba-sim "));
}

void TestRoombaSim::refusesABadRoom()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("bad.json"));
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(R"({"format": "roomba-room", "version": 1, "wals": []})");
    file.close();
    QProcess process;
    process.start(kProgram, {QStringLiteral("--room"), path});
    QVERIFY(process.waitForFinished(5000));
    QCOMPARE(process.exitCode(), 2);
    const QByteArray err = process.readAllStandardError();
    QCOMPARE(err, QByteArray("roomba-sim: --room: bad.json: unknown key \"wals\"\n"));
}

// In the corridor the robot starts beside a wall, which its wall sensor
// sees; a hang-up ends the program cleanly and the client sees the end.
void TestRoombaSim::servesARoomAndEndsOnHangUp()
{
    QProcess process;
    const QString where = startAndReadFirstLine(
        process, {QStringLiteral("--tcp"), QStringLiteral("0"), QStringLiteral("--room"),
                  QStringLiteral(ROOMBA_ROOMS_DIR "/corridor.json")});
    QVERIFY2(where.startsWith(QStringLiteral("tcp://")), qPrintable(where + process.readAllStandardError()));
    const RobotProfile &profile = oi::profile(ProfileId::Create2);
    const CommandEncoder encoder(profile);
    StreamParser parser(profile);
    std::optional<SensorSnapshot> wall;
    parser.setSnapshotHandler([&](const SensorSnapshot &s, FrameKind) { wall = s; });
    QTcpSocket client;
    QObject::connect(&client, &QTcpSocket::readyRead, &client, [&] {
        const QByteArray data = client.readAll();
        parser.feed(std::span(reinterpret_cast<const std::uint8_t *>(data.constData()), std::size_t(data.size())));
    });
    client.connectToHost(QHostAddress::LocalHost, where.section(':', -1).toUShort());
    QVERIFY(client.waitForConnected(5000));
    const std::uint8_t ids[] = {27};
    parser.expectReply(ids);
    client.write(bytes(encoder.start()) + bytes(encoder.sensors(27)));
    QTRY_VERIFY_WITH_TIMEOUT(wall.has_value(), 5000);
    QVERIFY(wall->wallSignal() > 0);
    stopCleanly(process, SIGHUP);
    QTRY_COMPARE_WITH_TIMEOUT(client.state(), QAbstractSocket::UnconnectedState, 5000);
}

// --report-pose: the robot's true travel and turn, a line each second, for
// a calibration with no tape measure.
void TestRoombaSim::reportsTheTruePose()
{
    QProcess process;
    const QString where = startAndReadFirstLine(process, {QStringLiteral("--tcp"), QStringLiteral("0"),
                                                          QStringLiteral("--report-pose")});
    QVERIFY2(where.startsWith(QStringLiteral("tcp://127.0.0.1:")), qPrintable(where));
    const auto nextPose = [&process]() -> QMap<QString, double> {
        for (int i = 0; i < 60 && !process.canReadLine(); ++i)
            process.waitForReadyRead(100);
        const QString line = QString::fromLocal8Bit(process.readLine()).trimmed();
        QMap<QString, double> fields;
        if (!line.startsWith(QLatin1String("pose ")))
            return fields;
        for (const QString &part : line.split(' ', Qt::SkipEmptyParts))
            if (part.contains('='))
                fields.insert(part.section('=', 0, 0), part.section('=', 1).toDouble());
        return fields;
    };
    QMap<QString, double> pose = nextPose();
    QVERIFY(pose.contains("from_start") && pose.contains("turned") && pose.contains("off_line"));
    QCOMPARE(pose.value("from_start"), 0.0);

    QTcpSocket client;
    client.connectToHost(QHostAddress::LocalHost, where.section(':', -1).toUShort());
    QVERIFY(client.waitForConnected(5000));
    const CommandEncoder encoder(oi::profile(ProfileId::Create2));
    // Straight ahead until the report says it went 150 mm, then a turn to the left.
    client.write(bytes(encoder.start()) + bytes(encoder.safe()) + bytes(encoder.drive(200, kRadiusStraight)));
    QVERIFY(client.waitForBytesWritten(5000));
    QDeadlineTimer deadline(20000);
    while (pose.value("from_start") < 150 && !deadline.hasExpired())
        pose = nextPose();
    QVERIFY2(pose.value("from_start") >= 150, qPrintable(QString::number(pose.value("from_start"))));
    QVERIFY(std::abs(pose.value("turned")) < 1 && std::abs(pose.value("off_line")) < 2);
    client.write(bytes(encoder.drive(100, kRadiusTurnInPlaceCounterClockwise)));
    QVERIFY(client.waitForBytesWritten(5000));
    while (pose.value("turned") < 200 && !deadline.hasExpired())
        pose = nextPose();
    // Past half a turn the heading wraps, the turn does not.
    QVERIFY2(pose.value("turned") >= 200, qPrintable(QString::number(pose.value("turned"))));
    client.write(bytes(encoder.stopMotion()));
    QVERIFY(client.waitForBytesWritten(5000));
    stopCleanly(process);
}

QTEST_GUILESS_MAIN(TestRoombaSim)
#include "tst_roomba_sim.moc"
