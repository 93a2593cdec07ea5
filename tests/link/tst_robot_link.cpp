// SPDX-License-Identifier: GPL-3.0-or-later
// RobotLink against a recording transport: the exact bytes it sends, what it
// makes of the bytes it gets, and how it behaves when the port fails. Its
// timed rules run on a clock the test advances.
#include "link_test_support.h"
#include "profile_probe.h"
#include "manual_clock.h"
#include "recording_transport.h"
#include "typed_command_bytes.h"

#include "command_encoder.h"
#include "robot_link.h"
#include "stream_packets.h"
#include "tcp_transport.h"
#include "transport.h"

#include <QPointer>
#include <QSignalSpy>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTest>

#include <cerrno>
#include <cstring>
#include <future>
#include <thread>

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

using oilink::LinkSettings;
using oilink::LinkState;
using oilink::RobotLink;

namespace {

QList<int> stateList(const QSignalSpy &spy)
{
    QList<int> out;
    for (const QList<QVariant> &args : spy)
        out.append(static_cast<int>(args.at(0).value<LinkState>()));
    return out;
}

QList<int> states(std::initializer_list<LinkState> list)
{
    QList<int> out;
    for (LinkState s : list)
        out.append(static_cast<int>(s));
    return out;
}

int frameBytes(const oi::RobotProfile &profile, const std::vector<int> &ids)
{
    int total = 3;
    for (int id : ids)
        total += 1 + profile.replySize(id);
    return total;
}

const QByteArray kShutdown = bytes({150, 0, 137, 0, 0, 0, 0, 138, 0, 128});

} // namespace

class TestRobotLink : public QObject {
    Q_OBJECT

    ManualClock m_clock;
    RobotLink *m_link = nullptr;
    QList<QPointer<RecordingTransport>> m_transports;
    QStringList m_failures; // open failures for the next transports, in order

    RecordingTransport *current() const { return m_transports.isEmpty() ? nullptr : m_transports.last().data(); }

    LinkSettings create2() const { return LinkSettings::serial(QStringLiteral("/dev/recording"), oi::ProfileId::Create2); }
    // What the link sends first on a port it opens: the stop, then the
    // finishing Starts (ProfileProbe::finishingStarts).
    const QByteArray kFinishing = bytes({137, 0, 0, 0, 0, 138, 0})
                                  + QByteArray(qsizetype(oilink::ProfileProbe::finishingStarts().size()), char(128));
    // What the finishing Starts bring back is dropped for a moment; then the link greets the robot.
    void settle() { m_clock.advance(oilink::ProfileProbe::kDrainMs); }

private slots:
    void init()
    {
        m_transports.clear();
        m_failures.clear();
        m_link = new RobotLink(m_clock);
        m_link->setTransportFactory([this](const LinkSettings &) {
            auto *t = new RecordingTransport(RecordingTransport::Robot::Silent);
            if (!m_failures.isEmpty())
                t->failOpenWith(m_failures.takeFirst());
            m_transports.append(t);
            return t;
        });
    }
    void cleanup()
    {
        delete m_link;
        m_link = nullptr;
    }

    // ERRATA 18: the largest candidate that fits the baud, computed.
    void streamChoice_data()
    {
        QTest::addColumn<oi::ProfileId>("profile");
        QTest::addColumn<int>("baud");
        QTest::addColumn<QList<int>>("packets");
        // A Create 1 streams all but its angle, which is read now and then.
        const QList<int> create1All{1, 17, 18, 19, 3, 4, 5};
        const QList<int> shortList{1, 19, 21, 22, 35};
        const QList<int> encoderList{1, 43, 44, 21, 22, 35};
        QTest::newRow("create2 115200") << oi::ProfileId::Create2 << 115200 << QList<int>{100};
        QTest::newRow("create2 57600") << oi::ProfileId::Create2 << 57600 << QList<int>{100};
        QTest::newRow("create2 38400") << oi::ProfileId::Create2 << 38400 << QList<int>{6};
        QTest::newRow("create1 38400") << oi::ProfileId::Create1 << 38400 << QList<int>{1, 19, 3, 4, 5};
        QTest::newRow("create2 19200") << oi::ProfileId::Create2 << 19200 << encoderList;
        QTest::newRow("roomba500 19200") << oi::ProfileId::Roomba500 << 19200 << encoderList;
        QTest::newRow("roomba500 115200") << oi::ProfileId::Roomba500 << 115200 << QList<int>{100};
        QTest::newRow("roomba500 57600") << oi::ProfileId::Roomba500 << 57600 << QList<int>{100};
        QTest::newRow("create1 115200") << oi::ProfileId::Create1 << 115200 << create1All;
        QTest::newRow("create1 57600") << oi::ProfileId::Create1 << 57600 << create1All;
        QTest::newRow("create1 19200") << oi::ProfileId::Create1 << 19200 << shortList;
        QTest::newRow("create2 9600") << oi::ProfileId::Create2 << 9600 << QList<int>{1};
        QTest::newRow("create2 4800") << oi::ProfileId::Create2 << 4800 << QList<int>{7};
        QTest::newRow("create2 2400") << oi::ProfileId::Create2 << 2400 << QList<int>{};
    }
    void streamChoice()
    {
        QFETCH(oi::ProfileId, profile);
        QFETCH(int, baud);
        QFETCH(QList<int>, packets);
        const oi::RobotProfile &p = oi::profile(profile);
        const std::vector<int> chosen = oilink::chooseStreamPackets(p, baud);
        QCOMPARE(QList<int>(chosen.begin(), chosen.end()), packets);
        if (!chosen.empty())
            QVERIFY(frameBytes(p, chosen) <= oi::maxStreamFrameBytes(baud));
    }

    void frameSizesBehindTheChoice()
    {
        const oi::RobotProfile &c2 = oi::profile(oi::ProfileId::Create2);
        QCOMPARE(frameBytes(c2, {100}), 84);
        QCOMPARE(oi::maxStreamFrameBytes(115200), 172);
        QCOMPARE(frameBytes(c2, {6}), 56);
        QCOMPARE(frameBytes(c2, {6, 101}), 85);
        QCOMPARE(oi::maxStreamFrameBytes(57600), 86);
        QCOMPARE(frameBytes(c2, {1, 19, 20, 21, 22, 35}), 27);
        QCOMPARE(frameBytes(c2, {1, 43, 44, 21, 22, 35}), 27);
        QCOMPARE(oi::maxStreamFrameBytes(19200), 28);
        // Group 100 fits at 57600 as well; the same packets as 6 + 101 take a byte more.
        QVERIFY(frameBytes(c2, {100}) <= oi::maxStreamFrameBytes(57600));
        QVERIFY(frameBytes(c2, {100}) > oi::maxStreamFrameBytes(38400));
        QVERIFY(frameBytes(c2, {6}) <= oi::maxStreamFrameBytes(38400));
    }

    void openSendsStartThenStream_data()
    {
        QTest::addColumn<LinkSettings>("settings");
        QTest::addColumn<QByteArray>("expected");
        LinkSettings s = create2();
        QTest::newRow("create2") << s << bytes({137, 0, 0, 0, 0, 138, 0, 128, 148, 1, 100});
        s.baud = 38400;
        QTest::newRow("create2 at 38400") << s << bytes({137, 0, 0, 0, 0, 138, 0, 128, 148, 1, 6});
        s.baud = 19200;
        QTest::newRow("create2 at 19200") << s << bytes({137, 0, 0, 0, 0, 138, 0, 128, 148, 6, 1, 43, 44, 21, 22, 35});
        s = LinkSettings::serial(QStringLiteral("/dev/recording"), oi::ProfileId::Create1);
        // Start on a Create ends a script first (ERRATA 20); a stop comes
        // before Start everywhere, for a robot that a program which died left driving.
        // A Create 1 streams all but its angle (read apart: AngleReadSchedule).
        QTest::newRow("create1") << s << bytes({152, 0, 137, 0, 0, 0, 0, 138, 0, 128, 148, 7, 1, 17, 18, 19, 3, 4, 5});
        s = create2();
        s.streamPackets = {7, 35};
        QTest::newRow("chosen packets") << s << bytes({137, 0, 0, 0, 0, 138, 0, 128, 148, 2, 7, 35});
    }
    void openSendsStartThenStream()
    {
        QFETCH(LinkSettings, settings);
        QFETCH(QByteArray, expected);
        QSignalSpy started(m_link, &RobotLink::streamStarted);
        m_link->open(settings);
        QVERIFY(current());
        // First the Starts that finish a command an earlier program left
        // half sent; what they bring back is dropped for a moment.
        QCOMPARE(current()->written(), kFinishing);
        QCOMPARE(started.size(), 0);
        settle();
        QCOMPARE(current()->written(), kFinishing + expected);
        QCOMPARE(m_link->state(), LinkState::Connecting);
        QCOMPARE(started.size(), 1);
    }

    // Over raw TCP the bridge's rate cannot follow a Baud command, so none
    // goes out, from any command path; over RFC 2217 it can.
    void baudOverRawTcpIsRefused()
    {
        LinkSettings raw = LinkSettings::tcp(QStringLiteral("pi"), 3333, oi::ProfileId::Create2);
        QSignalSpy errors(m_link, &RobotLink::errorOccurred);
        m_link->open(raw);
        QVERIFY(current());
        current()->clearWritten();
        m_link->send(commandsOf(bytes({129, 11})));
        m_link->send(commandsOf(bytes({128, 129, 11})));
        QCOMPARE(current()->written(), QByteArray());
        QCOMPARE(errors.size(), 2);
        const QString message = errors.at(0).at(0).toString();
        QVERIFY2(message.startsWith(QStringLiteral("pi:3333: Baud is not sent over raw TCP")) && message.contains(QStringLiteral("ser2net's config")),
                 qPrintable(message));
        m_link->send(commandsOf(bytes({139, 0, 0, 0}))); // other commands go out
        QCOMPARE(current()->written(), bytes({139, 0, 0, 0}));

        raw.tcpRfc2217 = true;
        m_link->open(raw);
        current()->clearWritten();
        m_link->send(commandsOf(bytes({129, 11})));
        QCOMPARE(current()->written(), bytes({129, 11}));
    }

    void closeSendsTheShutdownSequence_data()
    {
        QTest::addColumn<oi::ProfileId>("profile");
        QTest::newRow("create2") << oi::ProfileId::Create2;
        QTest::newRow("roomba500") << oi::ProfileId::Roomba500;
        QTest::newRow("create1") << oi::ProfileId::Create1;
    }
    void closeSendsTheShutdownSequence()
    {
        QFETCH(oi::ProfileId, profile);
        QSignalSpy stateSpy(m_link, &RobotLink::stateChanged);
        m_link->open(LinkSettings::serial(QStringLiteral("/dev/recording"), profile));
        QPointer<RecordingTransport> t = current();
        t->clearWritten();
        m_link->close();
        QVERIFY(t);
        // The Create ends a script first (ERRATA 20).
        QCOMPARE(t->written(), profile == oi::ProfileId::Create1 ? bytes({150, 0, 152, 0, 137, 0, 0, 0, 0, 138, 0, 128})
                                                                 : kShutdown);
        const oi::Bytes expected = oi::CommandEncoder(oi::profile(profile)).shutdownSequence();
        QCOMPARE(t->written(), QByteArray(reinterpret_cast<const char *>(expected.data()), qsizetype(expected.size())));
        QCOMPARE(t->flushes(), 1);
        QVERIFY(!t->isOpen());
        QCOMPARE(m_link->state(), LinkState::Closed);
        QCOMPARE(stateList(stateSpy), states({LinkState::Connecting, LinkState::Closed}));
        const QByteArray once = t->written();
        m_link->close(); // a second close sends nothing
        QVERIFY(!t || t->written() == once);
    }

    void oversizeStreamIsRefused()
    {
        LinkSettings s = create2();
        s.streamPackets = {100, 100, 100};
        QSignalSpy errors(m_link, &RobotLink::errorOccurred);
        m_link->open(s);
        settle();
        QCOMPARE(errors.size(), 1);
        const QString message = errors.at(0).at(0).toString();
        QVERIFY2(message.contains(QStringLiteral("does not fit in 15 ms")), qPrintable(message));
        QCOMPARE(m_link->state(), LinkState::Closed);
        // Only the finishing Starts, which every robot takes.
        QVERIFY(m_transports.first().isNull() || m_transports.first()->written() == kFinishing);
    }

    void framesBecomeSnapshotsAndStatistics()
    {
        QSignalSpy snapshots(m_link, &RobotLink::snapshot);
        QSignalSpy stats(m_link, &RobotLink::statistics);
        QSignalSpy received(m_link, &RobotLink::rawBytesReceived);
        m_link->open(create2());
        settle();
        RecordingTransport *t = current();
        QByteArray corrupt = group100Frame();
        corrupt[10] = static_cast<char>(corrupt[10] + 1);
        // Junk, a good frame cut in two, a corrupted frame, a stray 19, a good frame.
        const QByteArray good = group100Frame(0x03);
        t->inject(bytes({1, 2}) + good.left(30));
        t->inject(good.mid(30) + corrupt + bytes({19}) + group100Frame());
        QCOMPARE(snapshots.size(), 2);
        const auto first = snapshots.at(0).at(0).value<oi::SensorSnapshot>();
        QVERIFY(first.bumpLeft() && first.bumpRight());
        QVERIFY(first.has(58) && first.has(7));
        QCOMPARE(m_link->state(), LinkState::Streaming);
        QCOMPARE(received.size(), 2);

        const oilink::LinkStats now = m_link->currentStatistics();
        QCOMPARE(now.frames, quint64(2));
        QCOMPARE(now.checksumFailures, quint64(1));
        QCOMPARE(now.bytesDiscarded, quint64(2 + 84 + 1));
        QCOMPARE(now.resyncs, quint64(1)); // the stray 19 claimed a length of 19
        QCOMPARE(now.bytesReceived, quint64(2 + 84 * 3 + 1));
        QCOMPARE(now.bytesSent, quint64(kFinishing.size() + 7 + 4)); // the stop and finishing Starts, the stop, Start and Stream
        QVERIFY(now.lastFrameTime.isValid());
        // The failure is reported soon, not only at the next one-second tick.
        stats.clear();
        m_clock.advance(100);
        QCOMPARE(stats.size(), 1);
        QCOMPARE(stats.last().at(0).value<oilink::LinkStats>().checksumFailures, quint64(1));
    }

    void staleAfterSilenceThenStreamingAgain()
    {
        QSignalSpy stateSpy(m_link, &RobotLink::stateChanged);
        m_link->open(create2());
        settle();
        current()->inject(group100Frame());
        QCOMPARE(m_link->state(), LinkState::Streaming);
        m_clock.advance(RobotLink::kStaleAfterMs - 1);
        QCOMPARE(m_link->state(), LinkState::Streaming);
        m_clock.advance(1);
        QCOMPARE(m_link->state(), LinkState::Stale);
        current()->inject(group100Frame());
        QCOMPARE(m_link->state(), LinkState::Streaming);
        QCOMPARE(stateList(stateSpy), states({LinkState::Connecting, LinkState::Streaming, LinkState::Stale,
                                              LinkState::Streaming}));
    }

    void noDataIsReportedOnceAndStartAndStreamAreRepeated()
    {
        QSignalSpy errors(m_link, &RobotLink::errorOccurred);
        m_link->open(create2());
        settle();
        const QByteArray startAndStream = bytes({137, 0, 0, 0, 0, 138, 0, 128, 148, 1, 100});
        // Re-armed after 1 s, then 2 s: three copies in all.
        m_clock.advance(999);
        QCOMPARE(current()->written().count(startAndStream), 1);
        m_clock.advance(1);
        QCOMPARE(current()->written().count(startAndStream), 2);
        m_clock.advance(1999);
        QCOMPARE(current()->written().count(startAndStream), 2);
        m_clock.advance(1);
        QCOMPARE(current()->written().count(startAndStream), 3);
        QCOMPARE(errors.size(), 1);
        QCOMPARE(errors.at(0).at(0).toString(),
                 QStringLiteral("/dev/recording: no data: is the robot on, and is the baud right? "
                                "(If it is asleep: /dev/recording cannot reach the robot's BRC pin.)"));
        QCOMPARE(m_link->state(), LinkState::Connecting);
        current()->inject(group100Frame());
        QCOMPARE(m_link->state(), LinkState::Streaming);
    }

    void lostPortReconnectsAndResumes()
    {
        QSignalSpy stateSpy(m_link, &RobotLink::stateChanged);
        QSignalSpy errors(m_link, &RobotLink::errorOccurred);
        m_link->open(create2());
        settle();
        current()->inject(group100Frame());
        current()->inject(group100Frame().left(40)); // cut off by the loss
        current()->vanish();
        QCOMPARE(m_link->state(), LinkState::Reconnecting);
        m_clock.advance(RobotLink::kFirstBackoffMs);
        QCOMPARE(m_transports.size(), 2);
        settle(); // the new port gets its finishing Starts too
        QCOMPARE(current()->written(), kFinishing + bytes({137, 0, 0, 0, 0, 138, 0, 128, 148, 1, 100}));
        current()->inject(group100Frame());
        QCOMPARE(m_link->state(), LinkState::Streaming);
        QCOMPARE(stateList(stateSpy), states({LinkState::Connecting, LinkState::Streaming, LinkState::Lost,
                                              LinkState::Reconnecting, LinkState::Streaming}));
        QCOMPARE(errors.size(), 1);
        const oilink::LinkStats s = m_link->currentStatistics();
        QCOMPARE(s.reconnects, quint32(1));
        QCOMPARE(s.frames, quint64(2));
        QCOMPARE(s.bytesDiscarded, quint64(40)); // the cut frame
    }

    void openFailuresAreReportedOnceWhileRetrying()
    {
        m_failures = QStringList(5, QStringLiteral("/dev/recording: no such port"));
        QSignalSpy errors(m_link, &RobotLink::errorOccurred);
        m_link->open(create2());
        QCOMPARE(m_link->state(), LinkState::Reconnecting);
        // Backoff 100, 200, 400, 800, 1600 ms, then the sixth try opens:
        // each try comes when its wait is over, not a millisecond before.
        for (const int waitMs : {100, 200, 400, 800, 1600}) {
            const qsizetype tries = m_transports.size();
            m_clock.advance(waitMs - 1);
            QCOMPARE(m_transports.size(), tries);
            m_clock.advance(1);
            QCOMPARE(m_transports.size(), tries + 1);
        }
        QCOMPARE(m_transports.size(), 6);
        settle();
        QCOMPARE(current()->written(), kFinishing + bytes({137, 0, 0, 0, 0, 138, 0, 128, 148, 1, 100}));
        QCOMPARE(errors.size(), 1);
        QCOMPARE(errors.at(0).at(0).toString(), QStringLiteral("/dev/recording: no such port"));
        current()->inject(group100Frame());
        QCOMPARE(m_link->state(), LinkState::Streaming);
    }

    void closeWhileReconnectingStops()
    {
        m_failures = QStringList(50, QStringLiteral("/dev/recording: no such port"));
        m_link->open(create2());
        m_clock.advance(RobotLink::kFirstBackoffMs);
        QCOMPARE(m_transports.size(), 2);
        m_link->close();
        QCOMPARE(m_link->state(), LinkState::Closed);
        const qsizetype tries = m_transports.size();
        // Nothing is left to try again: every timer of the link has stopped,
        // the reconnect timer among them.
        const QList<oilink::ClockTimer *> timers = m_link->findChildren<oilink::ClockTimer *>(Qt::FindDirectChildrenOnly);
        QVERIFY(!timers.isEmpty());
        for (const oilink::ClockTimer *timer : timers)
            QVERIFY2(!timer->isActive(), qPrintable(QString::number(timer->interval())));
        QCOMPARE(m_clock.msToNextDeadline(), -1);
        m_clock.advance(RobotLink::kMaxBackoffMs);
        QCoreApplication::processEvents();
        QCOMPARE(m_transports.size(), tries);
    }

    void sensorQueryPausesAndResumesTheStream()
    {
        QSignalSpy replies(m_link, &RobotLink::sensorReply);
        QSignalSpy snapshots(m_link, &RobotLink::snapshot);
        m_link->open(create2());
        settle();
        RecordingTransport *t = current();
        t->inject(group100Frame());
        t->clearWritten();
        m_link->querySensors({7});
        QCOMPARE(t->written(), bytes({150, 0}));
        t->inject(group100Frame()); // a frame still on its way when the pause went out
        m_clock.advance(49); // the stream has not yet drained: 50 ms of quiet
        QCOMPARE(t->written(), bytes({150, 0}));
        m_clock.advance(1);
        QCOMPARE(t->written(), bytes({150, 0, 142, 7}));
        t->inject(bytes({0x02}));
        QCOMPARE(replies.size(), 1);
        QVERIFY(replies.at(0).at(0).value<oi::SensorSnapshot>().bumpLeft());
        QCOMPARE(t->written(), bytes({150, 0, 142, 7, 150, 1}));
        QCOMPARE(snapshots.size(), 2);

        t->clearWritten();
        m_link->querySensors({7, 22});
        m_clock.advance(50);
        QCOMPARE(t->written(), bytes({150, 0, 149, 2, 7, 22}));
        t->inject(bytes({0x01, 0x3E}));
        t->inject(bytes({0x80}));
        QCOMPARE(replies.size(), 2);
        const auto reply = replies.at(1).at(0).value<oi::SensorSnapshot>();
        QVERIFY(reply.bumpRight());
        QCOMPARE(reply.voltageMv(), 16000);
        QCOMPARE(m_link->currentStatistics().replies, quint64(2));
    }

    void unansweredQueryTimesOutAndResumes()
    {
        QSignalSpy errors(m_link, &RobotLink::errorOccurred);
        m_link->open(create2());
        settle();
        current()->inject(group100Frame());
        current()->clearWritten();
        m_link->querySensors({35});
        m_clock.advance(50);
        QCOMPARE(current()->written(), bytes({150, 0, 142, 35}));
        m_clock.advance(499);
        QCOMPARE(errors.size(), 0);
        m_clock.advance(1);
        QCOMPARE(errors.size(), 1);
        QCOMPARE(errors.at(0).at(0).toString(), QStringLiteral("/dev/recording: no reply to the sensor query"));
        QCOMPARE(current()->written(), bytes({150, 0, 142, 35, 150, 1}));
        current()->inject(group100Frame());
        QCOMPARE(m_link->state(), LinkState::Streaming);
    }

    // roomba-ctl send: no Start, no stream, nothing on close; a query
    // pauses a stream an earlier client may have left running, and does not
    // resume it.
    void withoutStreamingTheLinkOnlySendsAndAsks()
    {
        LinkSettings settings = create2();
        settings.streaming = false;
        QSignalSpy ready(m_link, &RobotLink::requestsReady);
        QSignalSpy replies(m_link, &RobotLink::sensorReply);
        QSignalSpy failed(m_link, &RobotLink::sensorQueryFailed);
        m_link->open(settings);
        QPointer<RecordingTransport> t = current();
        QCOMPARE(ready.size(), 1);
        QCOMPARE(ready.at(0).at(0).value<oi::ProfileId>(), oi::ProfileId::Create2);
        QCOMPARE(t->written(), QByteArray());

        m_link->querySensors({7});
        QCOMPARE(t->written(), bytes({150, 0}));
        m_clock.advance(50);
        QCOMPARE(t->written(), bytes({150, 0, 142, 7}));
        t->inject(bytes({0x01}));
        QCOMPARE(replies.size(), 1);
        QVERIFY(replies.at(0).at(0).value<oi::SensorSnapshot>().bumpRight());
        QCOMPARE(t->written(), bytes({150, 0, 142, 7})); // not resumed

        m_link->querySensors({35});
        m_clock.advance(550);
        QCOMPARE(failed.size(), 1);
        QCOMPARE(failed.at(0).at(0).toString(), QStringLiteral("/dev/recording: no reply to the sensor query"));

        t->clearWritten();
        m_link->send(commandsOf(bytes({137, 0, 200, 128, 0})));
        m_link->close();
        QVERIFY(t);
        QCOMPARE(t->written(), bytes({137, 0, 200, 128, 0})); // no shutdown: the robot drives on
        QCOMPARE(t->flushes(), 1);
    }

    void badQueriesAreRefused()
    {
        QSignalSpy errors(m_link, &RobotLink::errorOccurred);
        m_link->querySensors({7});
        QCOMPARE(errors.size(), 1);
        QVERIFY(errors.at(0).at(0).toString().startsWith(QStringLiteral("not connected")));
        m_link->open(LinkSettings::serial(QStringLiteral("/dev/recording"), oi::ProfileId::Create1));
        current()->clearWritten();
        m_link->querySensors({43});
        QCOMPARE(errors.size(), 2);
        QVERIFY(errors.at(1).at(0).toString().contains(QStringLiteral("43 is not a packet or group of the Create")));
        QVERIFY(current()->written().isEmpty());
    }

    void sendWritesEncodedCommands()
    {
        QSignalSpy sent(m_link, &RobotLink::rawBytesSent);
        QSignalSpy errors(m_link, &RobotLink::errorOccurred);
        m_link->send(commandsOf(bytes({131})));
        QCOMPARE(errors.size(), 1);
        QVERIFY(errors.at(0).at(0).toString().startsWith(QStringLiteral("not connected")));
        m_link->open(create2());
        current()->clearWritten();
        const oi::Bytes drive = *oi::CommandEncoder(oi::profile(oi::ProfileId::Create2)).drive(-200, 500);
        const QByteArray driveBytes(reinterpret_cast<const char *>(drive.data()), qsizetype(drive.size()));
        m_link->send(commandsOf(driveBytes));
        QCOMPARE(current()->written(), bytes({137, 255, 56, 1, 244}));
        QCOMPARE(sent.last().at(0).toByteArray(), driveBytes);
    }

    // Typed commands go out as their exact bytes, encoded once with the
    // robot's profile, in one write that the transport is told was asked for.
    void typedCommandsReachTheTransportAsTheirBytes()
    {
        using C = oi::Command;
        m_link->open(LinkSettings::serial(QStringLiteral("/dev/recording"), oi::ProfileId::Create1));
        Recording &r = current()->recording();
        current()->clearWritten();
        QSignalSpy errors(m_link, &RobotLink::errorOccurred);
        QSignalSpy sent(m_link, &RobotLink::rawBytesSent);
        const std::vector<oi::OiCommand> commands{oi::OiCommand{C::Safe, {}, {}},
                                                  oi::OiCommand{C::Drive, {-200, 500}, {}},
                                                  oi::OiCommand{C::Song, {3}, {60, 32, 62, 16}},
                                                  oi::OiCommand{C::LowSideDrivers, {5}, {}}, // the Create's 138
                                                  oi::OiCommand{C::WaitTime, {10}, {}}};
        m_link->send(commands);
        QCOMPARE(errors.size(), 0);
        const QByteArray expected = bytes({131, 137, 255, 56, 1, 244, 140, 3, 2, 60, 32, 62, 16, 138, 5, 155, 10});
        QCOMPARE(r.writes, QList<QByteArray>{expected});
        QCOMPARE(r.commands, QList<QByteArray>{expected});
        // Readers learn what was sent from the commands beside the bytes.
        QCOMPARE(sent.size(), 1);
        QCOMPARE(sent.first().at(0).toByteArray(), expected);
        QCOMPARE(sent.first().at(1).value<std::vector<oi::OiCommand>>(), commands);

        // One the profile refuses sends nothing, and says which field.
        m_link->send({oi::OiCommand{C::Safe, {}, {}}, oi::OiCommand{C::Drive, {600, 0}, {}}});
        QCOMPARE(r.writes.size(), 1);
        QCOMPARE(errors.size(), 1);
        QVERIFY2(errors.at(0).at(0).toString().startsWith(QStringLiteral("Not sent: ")) &&
                     errors.at(0).at(0).toString().contains(QStringLiteral("velocity")),
                 qPrintable(errors.at(0).at(0).toString()));
    }

    // What the link is asked to send reaches the transport as a command;
    // its own Start, Stream and the script end before a Start do not (nor
    // its stop on closing: tst_network_robot), so a transport that hands commands on can tell them
    // apart by the path alone.
    void askedCommandsAreToldApartFromTheLinksOwn()
    {
        m_link->open(LinkSettings::serial(QStringLiteral("/dev/recording"), oi::ProfileId::Create1));
        settle();
        Recording &r = current()->recording();
        QCOMPARE(r.written(), kFinishing + bytes({152, 0, 137, 0, 0, 0, 0, 138, 0, 128, 148, 7, 1, 17, 18, 19, 3, 4, 5}));
        QVERIFY(r.commands.isEmpty());
        m_link->send(commandsOf(bytes({128}))); // Passive, asked for
        m_link->send(commandsOf(bytes({137, 0, 100, 128, 0})));
        QCOMPARE(r.writes.mid(4), QList<QByteArray>({bytes({152, 0}), bytes({128}), bytes({137, 0, 100, 128, 0})}));
        QCOMPARE(r.commands, QList<QByteArray>({bytes({128}), bytes({137, 0, 100, 128, 0})}));
    }

    // A slot that closes the link on a snapshot runs inside the parser.
    void closingFromASnapshotSlotIsSafe()
    {
        QSignalSpy snapshots(m_link, &RobotLink::snapshot);
        QSignalSpy stats(m_link, &RobotLink::statistics);
        connect(m_link, &RobotLink::snapshot, m_link, &RobotLink::close);
        m_link->open(create2());
        settle();
        QPointer<RecordingTransport> t = current();
        t->clearWritten();
        t->inject(group100Frame() + group100Frame() + group100Frame());
        QCOMPARE(snapshots.size(), 1);
        QCOMPARE(m_link->state(), LinkState::Closed);
        QVERIFY(t);
        QCOMPARE(t->written(), kShutdown);
        // The statistics given out on closing count the one frame taken.
        QVERIFY(!stats.isEmpty());
        QCOMPARE(stats.last().at(0).value<oilink::LinkStats>().frames, quint64(1));
    }

    // A bridge that cannot open its serial device says so, then hangs up.
    void bridgeReasonIsKept_data()
    {
        QTest::addColumn<QByteArray>("lastWords");
        QTest::addColumn<QString>("expectedEnd");
        QTest::newRow("ser2net text") << QByteArray("Device open failure: No such file or directory\r\n")
                                      << ": the bridge closed the connection: Device open failure: No such file or directory";
        QTest::newRow("robot bytes") << QByteArray("\x13\x02\x07\x00\xE4", 5) << ": the bridge closed the connection";
    }
    void bridgeReasonIsKept()
    {
        QFETCH(QByteArray, lastWords);
        QFETCH(QString, expectedEnd);
        QTcpServer bridge;
        QVERIFY(bridge.listen(QHostAddress::LocalHost));
        connect(&bridge, &QTcpServer::newConnection, &bridge, [&] {
            QTcpSocket *peer = bridge.nextPendingConnection();
            peer->write(lastWords);
            peer->flush();
            peer->disconnectFromHost();
        });
        oilink::RobotLink link;
        QSignalSpy errors(&link, &oilink::RobotLink::errorOccurred);
        link.open(oilink::LinkSettings::tcp("127.0.0.1", bridge.serverPort(), oi::ProfileId::Create2));
        QTRY_VERIFY_WITH_TIMEOUT(!errors.isEmpty(), 10000);
        const QString message = errors.first().at(0).toString();
        QVERIFY2(message.endsWith(expectedEnd), qPrintable(message));
        QVERIFY(message.startsWith(QString("127.0.0.1:%1").arg(bridge.serverPort())));
        link.close();
    }

    // A bridge that is still streaming when the link says its last words:
    // unread bytes on a socket that closes reset the connection, and a reset
    // may lose the last Stop before the bridge passes it on. The link's end
    // hangs up cleanly after its last bytes instead. The bridge here is a
    // plain socket that tells a clean end (read returns 0) from a reset.
    void closingOverTcpEndsCleanlyWithBytesUnread()
    {
        const int listener = ::socket(AF_INET, SOCK_STREAM, 0);
        QVERIFY(listener >= 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t length = sizeof address;
        QVERIFY(::bind(listener, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0);
        QVERIFY(::listen(listener, 1) == 0);
        QVERIFY(::getsockname(listener, reinterpret_cast<sockaddr *>(&address), &length) == 0);

        std::promise<void> streamNow;
        std::promise<void> streamed;
        QByteArray heard;
        int endErrno = -1; // 0: a clean end
        std::thread bridge([&] {
            const int peer = ::accept(listener, nullptr, nullptr);
            if (peer < 0)
                return;
            streamNow.get_future().wait();
            // It streams on, as fast as it can, until the link hangs up.
            const QByteArray frames(256, '\x13');
            char buffer[256];
            bool first = true;
            for (;;) {
                [[maybe_unused]] const ssize_t sent =
                    ::send(peer, frames.constData(), std::size_t(frames.size()), MSG_DONTWAIT | MSG_NOSIGNAL);
                if (first)
                    streamed.set_value();
                first = false;
                const ssize_t n = ::recv(peer, buffer, sizeof buffer, MSG_DONTWAIT);
                if (n > 0) {
                    heard.append(buffer, n);
                    continue;
                }
                if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK))
                    continue;
                endErrno = n == 0 ? 0 : errno;
                break;
            }
            ::close(peer);
        });

        oilink::TcpTransport transport(QStringLiteral("127.0.0.1"), ntohs(address.sin_port));
        QSignalSpy opened(&transport, &oilink::Transport::opened);
        transport.open();
        QTRY_VERIFY_WITH_TIMEOUT(!opened.isEmpty(), 5000);
        streamNow.set_value();
        streamed.get_future().wait();
        const QByteArray stop("\x96\x00\x89\x00\x00\x00\x00\x80", 8);
        QVERIFY(transport.write(stop));
        transport.flush(5000);
        transport.close();
        bridge.join();
        ::close(listener);
        QCOMPARE(heard, stop);
        QVERIFY2(endErrno == 0, std::strerror(endErrno));
    }

    // The link knows no simulator: asked for a virtual robot without a
    // transport factory, it says so once and closes.
    void aVirtualRobotNeedsAFactory()
    {
        oilink::RobotLink link;
        QSignalSpy errors(&link, &oilink::RobotLink::errorOccurred);
        QSignalSpy states(&link, &oilink::RobotLink::stateChanged);
        link.open(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QCOMPARE(link.state(), oilink::LinkState::Closed);
        QCOMPARE(errors.size(), 1);
        QCOMPARE(errors.first().at(0).toString(), QString("virtual Roomba 600 / Create 2: no transport for this kind of connection"));
        QCOMPARE(states.last().at(0).value<oilink::LinkState>(), oilink::LinkState::Closed);
        QVERIFY(!link.transport());
    }
};

QTEST_GUILESS_MAIN(TestRobotLink)
#include "tst_robot_link.moc"
