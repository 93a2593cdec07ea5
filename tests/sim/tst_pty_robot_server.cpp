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
#include <termios.h>
#include <unistd.h>

using namespace oi;

namespace {

// Reads what the robot sends until `done` holds or five seconds pass; the
// robot runs on this thread's event loop meanwhile. Keeps the raw bytes in
// `raw` when given.
bool readUntil(int fd, StreamParser &parser, const std::function<bool()> &done, QByteArray *raw = nullptr)
{
    return QTest::qWaitFor(
        [&] {
            std::uint8_t buffer[1024];
            for (;;) {
                const ssize_t n = ::read(fd, buffer, sizeof buffer);
                if (n <= 0)
                    break;
                parser.feed(std::span(buffer, std::size_t(n)));
                if (raw)
                    raw->append(reinterpret_cast<const char *>(buffer), n);
            }
            return done();
        },
        5000);
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
    void theLineHasTheClientsRate();
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
        // query goes with a pause of the stream: the robot answers after it
        // stopped streaming, and its two bytes, which are no frame, follow
        // the last whole frame on the line.
        const std::uint8_t id = 26;
        Bytes pauseAndAsk = encoder.pauseResumeStream(0).value();
        const Bytes ask = encoder.sensors(id).value();
        pauseAndAsk.insert(pauseAndAsk.end(), ask.begin(), ask.end());
        const std::uint64_t discarded = parser.counters().bytesDiscarded;
        QByteArray raw;
        QVERIFY(writeAll(fd, pauseAndAsk));
        QVERIFY(readUntil(fd, parser, [&] { return parser.counters().bytesDiscarded >= discarded + 2; }, &raw));
        QCOMPARE(parser.counters().bytesDiscarded, discarded + 2);
        QCOMPARE(parser.pendingBytes(), std::size_t(0)); // no frame after the reply
        StreamParser replyParser(profile);
        replyParser.setSnapshotHandler([&](const SensorSnapshot &s, FrameKind kind) {
            if (kind == FrameKind::Reply)
                replies.push_back(s);
        });
        replyParser.expectReply(std::span(&id, 1));
        const QByteArray reply = raw.right(2);
        replyParser.feed(std::span(reinterpret_cast<const std::uint8_t *>(reply.constData()), std::size_t(reply.size())));
        QCOMPARE(replies.size(), std::size_t(1));
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

// After Baud (129) the robot talks at the new rate. A client that stays at
// the old one hears junk and is not heard; once it sets the same rate on its
// port, frames come again.
void TestPtyRobotServer::theLineHasTheClientsRate()
{
    const RobotProfile &profile = oi::profile(ProfileId::Create2);
    sim::PtyRobotServer server(profile);
    QVERIFY(server.open());
    const CommandEncoder encoder(profile);
    const int fd = ::open(QFile::encodeName(server.slavePath()).constData(), O_RDWR | O_NOCTTY | O_NONBLOCK);
    QVERIFY2(fd >= 0, std::strerror(errno));
    // A client that sets no rate gets the robot's.
    termios tio{};
    QCOMPARE(tcgetattr(fd, &tio), 0);
    QCOMPARE(cfgetospeed(&tio), speed_t(B115200));
    QTRY_VERIFY_WITH_TIMEOUT(server.clientConnected(), 5000);
    QCOMPARE(server.clientBaud(), 115200);

    StreamParser parser(profile);
    std::vector<OiMode> modes;
    parser.setSnapshotHandler([&](const SensorSnapshot &s, FrameKind kind) {
        if (kind == FrameKind::Stream)
            modes.push_back(s.oiMode());
    });
    Bytes start = encoder.start().value();
    const Bytes stream = encoder.stream(std::vector<int>{35}).value();
    start.insert(start.end(), stream.begin(), stream.end());
    QVERIFY(writeAll(fd, start));
    QVERIFY(readUntil(fd, parser, [&] { return modes.size() >= 5; }));

    // To 19200; the client stays at 115200.
    QVERIFY(writeAll(fd, encoder.baud(oi::baudCodeFor(19200)).value()));
    QTRY_COMPARE_WITH_TIMEOUT(server.robot().robot().baud(), 19200, 5000);
    // Ten frames' time of junk: the robot's 100 ms to settle are over, and
    // the frames it sent at the old rate before it read the Baud are in.
    // How many those are depends on how busy the machine is; after them,
    // nothing more is heard as a frame.
    const auto junkGrows = [&] {
        const std::uint64_t from = parser.counters().bytesDiscarded;
        return readUntil(fd, parser, [&] { return parser.counters().bytesDiscarded >= from + 50; });
    };
    QVERIFY(junkGrows());
    std::size_t framesBefore = modes.size();
    QVERIFY(junkGrows());
    QCOMPARE(modes.size(), framesBefore);
    // Safe at the old rate is not heard.
    QVERIFY(writeAll(fd, encoder.safe().value()));
    QVERIFY(junkGrows());
    QCOMPARE(modes.size(), framesBefore);
    QCOMPARE(server.robot().robot().mode(), OiMode::Passive);

    // The client follows: frames again, still Passive; then Safe is heard.
    cfsetspeed(&tio, B19200);
    QCOMPARE(tcsetattr(fd, TCSANOW, &tio), 0);
    QCOMPARE(server.clientBaud(), 19200);
    parser.reset();
    QVERIFY(readUntil(fd, parser, [&] { return modes.size() >= framesBefore + 5; }));
    QCOMPARE(modes.back(), OiMode::Passive);
    QVERIFY(writeAll(fd, encoder.safe().value()));
    QVERIFY(readUntil(fd, parser, [&] { return modes.back() == OiMode::Safe; }));
    ::close(fd);
}

QTEST_GUILESS_MAIN(TestPtyRobotServer)
#include "tst_pty_robot_server.moc"
