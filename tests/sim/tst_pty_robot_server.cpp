// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot behind a pseudo-terminal, reached with plain POSIX calls
// as any serial client would, closed and opened again.
#include "command_encoder.h"
#include "pty_robot_server.h"
#include "stream_parser.h"

#include <QFile>
#include <QTest>

#include <cerrno>
#include <cstring>
#include <functional>
#include <fcntl.h>
#include <unistd.h>

using namespace oi;

namespace {

// Reads what the robot sends until `done` holds or five seconds pass.
bool readUntil(int fd, StreamParser &parser, const std::function<bool()> &done)
{
    std::uint8_t buffer[1024];
    for (int i = 0; i < 500 && !done(); ++i) {
        for (;;) {
            const ssize_t n = ::read(fd, buffer, sizeof buffer);
            if (n <= 0)
                break;
            parser.feed(std::span(buffer, std::size_t(n)));
        }
        if (!done())
            QTest::qWait(10);
    }
    return done();
}

bool writeAll(int fd, const Bytes &bytes)
{
    return ::write(fd, bytes.data(), bytes.size()) == ssize_t(bytes.size());
}

} // namespace

class TestPtyRobotServer : public QObject {
    Q_OBJECT
private slots:
    void streamsToAClientThatComesBack();
    void closeRemovesTheDevice();
};

void TestPtyRobotServer::streamsToAClientThatComesBack()
{
    const RobotProfile &profile = oi::profile(ProfileId::Create2);
    sim::PtyRobotServer server(profile);
    QString error;
    QVERIFY2(server.open(&error), qPrintable(error));
    QVERIFY(server.slavePath().startsWith("/dev/"));
    QVERIFY(!server.clientConnected());
    const CommandEncoder encoder(profile);

    for (int round = 0; round < 3; ++round) {
        const int fd = ::open(QFile::encodeName(server.slavePath()).constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
        QVERIFY2(fd >= 0, std::strerror(errno));
        StreamParser parser(profile);
        std::vector<SensorSnapshot> frames, replies;
        parser.setSnapshotHandler([&](const SensorSnapshot &s, FrameKind kind) {
            (kind == FrameKind::Stream ? frames : replies).push_back(s);
        });
        if (round == 0) {
            // The first client starts the robot and its stream; the robot keeps
            // it going for the clients after.
            Bytes start = encoder.start().value();
            const Bytes stream = encoder.stream(std::vector<int>{35, 7}).value();
            start.insert(start.end(), stream.begin(), stream.end());
            QVERIFY(writeAll(fd, start));
        }
        QVERIFY(readUntil(fd, parser, [&] { return frames.size() >= 10; }));
        QCOMPARE(frames.back().oiMode(), OiMode::Passive);
        QCOMPARE(parser.counters().checksumFailures, 0u);
        QVERIFY(server.clientConnected());

        // And a query is answered. Replies are not framed (ERRATA 3), so the
        // stream pauses first and what is still on the line is let go.
        QVERIFY(writeAll(fd, encoder.pauseResumeStream(0).value()));
        QTest::qWait(100);
        std::uint8_t junk[4096];
        while (::read(fd, junk, sizeof junk) > 0) {
        }
        parser.reset();
        const std::uint8_t id = 26;
        parser.expectReply(std::span(&id, 1));
        QVERIFY(writeAll(fd, encoder.sensors(id).value()));
        QVERIFY(readUntil(fd, parser, [&] { return !replies.empty(); }));
        QCOMPARE(replies.back().batteryCapacityMah(), 3000);
        QVERIFY(writeAll(fd, encoder.pauseResumeStream(1).value()));

        ::close(fd);
        QTRY_VERIFY_WITH_TIMEOUT(!server.clientConnected(), 5000);
    }
}

void TestPtyRobotServer::closeRemovesTheDevice()
{
    sim::PtyRobotServer server(oi::profile(ProfileId::Roomba500));
    QVERIFY(server.open());
    const QString path = server.slavePath();
    QVERIFY(QFile::exists(path));
    server.close();
    QVERIFY(!server.isOpen());
    QVERIFY(server.slavePath().isEmpty());
    QTRY_VERIFY_WITH_TIMEOUT(!QFile::exists(path), 5000);
}

QTEST_GUILESS_MAIN(TestPtyRobotServer)
#include "tst_pty_robot_server.moc"
