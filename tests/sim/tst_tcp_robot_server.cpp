// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot on a TCP port: raw bytes, one client at a time.
#include "command_encoder.h"
#include "stream_parser.h"
#include "rfc2217.h"
#include "tcp_robot_server.h"

#include <QTcpSocket>
#include <QTest>

using namespace oi;

namespace {

QByteArray bytes(const EncodeResult &r)
{
    return QByteArray(reinterpret_cast<const char *>(r->data()), qsizetype(r->size()));
}

QByteArray bytes(const rfc2217::Bytes &b)
{
    return QByteArray(reinterpret_cast<const char *>(b.data()), qsizetype(b.size()));
}

// A client of the server: what it heard, as stream frames and raw bytes,
// through Telnet when the server speaks RFC 2217.
struct Client {
    Client(quint16 port, const RobotProfile &profile, bool rfc2217) : parser(profile), telnet(rfc2217)
    {
        parser.setSnapshotHandler([this](const SensorSnapshot &s, FrameKind kind) {
            if (kind == FrameKind::Stream)
                modes.push_back(s.oiMode());
        });
        QObject::connect(&socket, &QTcpSocket::readyRead, &socket, [this] {
            QByteArray data = socket.readAll();
            if (telnet) {
                const rfc2217::Bytes plain = decoder.feed(
                    reinterpret_cast<const std::uint8_t *>(data.constData()), std::size_t(data.size()),
                    [this](std::uint8_t command, const rfc2217::Bytes &value) {
                        if (command == rfc2217::kSetBaudRate + rfc2217::kServerOffset)
                            answeredRates.push_back(rfc2217::baudRateOf(value));
                    });
                data = bytes(plain);
            }
            raw += data;
            parser.feed(std::span(reinterpret_cast<const std::uint8_t *>(data.constData()), std::size_t(data.size())));
        });
        socket.connectToHost(QHostAddress::LocalHost, port);
        if (telnet)
            socket.write(bytes(rfc2217::willComPort()));
    }
    void send(const EncodeResult &r)
    {
        socket.write(telnet ? bytes(rfc2217::escape(r->data(), r->size())) : bytes(r));
    }

    QTcpSocket socket;
    StreamParser parser;
    bool telnet;
    rfc2217::Decoder decoder;
    std::vector<OiMode> modes;
    std::vector<std::uint32_t> answeredRates;
    QByteArray raw;
};

// Start, a stream of packet 35, then Baud 19200, which the line does not
// follow: junk comes, and Safe is not heard.
void startThenLoseTheRobot(Client &client, sim::TcpRobotServer &server, const CommandEncoder &encoder)
{
    client.send(encoder.start());
    client.send(encoder.stream(std::vector<int>{35}));
    QTRY_VERIFY_WITH_TIMEOUT(client.modes.size() >= 5, 5000);
    client.send(encoder.baud(oi::baudCodeFor(19200)));
    QTRY_COMPARE_WITH_TIMEOUT(server.robot().robot().baud(), 19200, 5000);
    QCOMPARE(server.lineBaud(), 115200);
    // Ten frames' time of junk: the robot's 100 ms to settle are over.
    client.raw.clear();
    QTRY_VERIFY_WITH_TIMEOUT(client.raw.size() >= 50, 5000);
    const std::size_t frames = client.modes.size();
    client.send(encoder.safe());
    client.raw.clear();
    QTRY_VERIFY_WITH_TIMEOUT(client.raw.size() >= 50, 5000);
    QCOMPARE(client.modes.size(), frames);
    QCOMPARE(server.robot().robot().mode(), OiMode::Passive);
}

} // namespace

class TestTcpRobotServer : public QObject {
    Q_OBJECT
private slots:
    void streamsToOneClientAtATime();
    void rawTcpKeepsTheLinesRate();
    void rfc2217SetsTheLinesRate();
};

void TestTcpRobotServer::streamsToOneClientAtATime()
{
    const RobotProfile &profile = oi::profile(ProfileId::Roomba500);
    const CommandEncoder encoder(profile);
    sim::TcpRobotServer server(profile);
    QString error;
    QVERIFY2(server.listen(QHostAddress::LocalHost, 0, &error), qPrintable(error));
    QVERIFY(server.serverPort() != 0);

    for (int round = 0; round < 2; ++round) {
        QTcpSocket client;
        client.connectToHost(QHostAddress::LocalHost, server.serverPort());
        QVERIFY(client.waitForConnected(5000));
        QTRY_VERIFY_WITH_TIMEOUT(server.clientConnected(), 5000);

        StreamParser parser(profile);
        int frames = 0;
        parser.setSnapshotHandler([&](const SensorSnapshot &s, FrameKind kind) {
            if (kind == FrameKind::Stream && s.oiMode() == OiMode::Safe)
                ++frames;
        });
        QObject::connect(&client, &QTcpSocket::readyRead, &client, [&] {
            const QByteArray data = client.readAll();
            parser.feed(std::span(reinterpret_cast<const std::uint8_t *>(data.constData()), std::size_t(data.size())));
        });
        client.write(bytes(encoder.start()) + bytes(encoder.safe()) + bytes(encoder.stream(std::vector<int>{35})));
        QTRY_VERIFY_WITH_TIMEOUT(frames >= 10, 5000);

        // A second client is turned away while the first is connected.
        QTcpSocket other;
        other.connectToHost(QHostAddress::LocalHost, server.serverPort());
        QTRY_VERIFY_WITH_TIMEOUT(other.state() == QAbstractSocket::UnconnectedState, 5000);
        QVERIFY(server.clientConnected());

        client.disconnectFromHost();
        QTRY_VERIFY_WITH_TIMEOUT(!server.clientConnected(), 5000);
    }
}

// A raw bridge's serial side stays at the rate it was set up with, so after
// Baud (129) the client has lost the robot, as with ser2net in raw mode.
void TestTcpRobotServer::rawTcpKeepsTheLinesRate()
{
    const RobotProfile &profile = oi::profile(ProfileId::Create2);
    const CommandEncoder encoder(profile);
    sim::TcpRobotServer server(profile);
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    Client client(server.serverPort(), profile, false);
    QTRY_VERIFY_WITH_TIMEOUT(server.clientConnected(), 5000);
    startThenLoseTheRobot(client, server, encoder);
    if (QTest::currentTestFailed())
        return;
    // Another connection gets the same line: still junk.
    client.socket.disconnectFromHost();
    QTRY_VERIFY_WITH_TIMEOUT(!server.clientConnected(), 5000);
    Client next(server.serverPort(), profile, false);
    QTRY_VERIFY_WITH_TIMEOUT(next.raw.size() >= 50, 5000);
    QVERIFY(next.modes.empty());
}

// Over RFC 2217 the client sets the line's rate (SET-BAUDRATE) and hears the
// robot again; the next connection starts at the rate the bridge was set up with.
void TestTcpRobotServer::rfc2217SetsTheLinesRate()
{
    const RobotProfile &profile = oi::profile(ProfileId::Create2);
    const CommandEncoder encoder(profile);
    sim::TcpRobotServer server(profile);
    server.setRfc2217(true);
    QVERIFY(server.listen(QHostAddress::LocalHost, 0));
    {
        Client client(server.serverPort(), profile, true);
        QTRY_VERIFY_WITH_TIMEOUT(server.clientConnected(), 5000);
        startThenLoseTheRobot(client, server, encoder);
        if (QTest::currentTestFailed())
            return;
        client.socket.write(bytes(rfc2217::setBaudRate(19200)));
        QTRY_COMPARE_WITH_TIMEOUT(client.answeredRates, std::vector<std::uint32_t>{19200}, 5000);
        QCOMPARE(server.lineBaud(), 19200);
        client.parser.reset();
        const std::size_t frames = client.modes.size();
        QTRY_VERIFY_WITH_TIMEOUT(client.modes.size() >= frames + 5, 5000);
        QCOMPARE(client.modes.back(), OiMode::Passive);
        client.send(encoder.safe());
        QTRY_COMPARE_WITH_TIMEOUT(client.modes.back(), OiMode::Safe, 5000);
        // Rate 0 asks without changing it.
        client.socket.write(bytes(rfc2217::setBaudRate(0)));
        QTRY_COMPARE_WITH_TIMEOUT(client.answeredRates.size(), std::size_t(2), 5000);
        QCOMPARE(client.answeredRates.back(), 19200u);
        client.socket.disconnectFromHost();
        QTRY_VERIFY_WITH_TIMEOUT(!server.clientConnected(), 5000);
    }
    Client next(server.serverPort(), profile, true);
    QTRY_VERIFY_WITH_TIMEOUT(server.clientConnected(), 5000);
    QCOMPARE(server.lineBaud(), 115200);
}

QTEST_GUILESS_MAIN(TestTcpRobotServer)
#include "tst_tcp_robot_server.moc"
