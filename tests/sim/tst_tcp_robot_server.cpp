// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot on a TCP port: raw bytes, one client at a time.
#include "command_encoder.h"
#include "stream_parser.h"
#include "tcp_robot_server.h"

#include <QTcpSocket>
#include <QTest>

using namespace oi;

namespace {

QByteArray bytes(const EncodeResult &r)
{
    return QByteArray(reinterpret_cast<const char *>(r->data()), qsizetype(r->size()));
}

} // namespace

class TestTcpRobotServer : public QObject {
    Q_OBJECT
private slots:
    void streamsToOneClientAtATime();
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

QTEST_GUILESS_MAIN(TestTcpRobotServer)
#include "tst_tcp_robot_server.moc"
