// SPDX-License-Identifier: GPL-3.0-or-later
// RobotLink over real pseudo-terminals (and TCP) against the roomba-sim
// executable: noise on the line, stalls, the robot going away and coming
// back, and the bytes a close leaves on the line.
#include "link_test_support.h"
#include "manual_clock.h"
#include "sim_process.h"

#include "profile_probe.h"
#include "pty_robot_server.h"
#include "link_event_spy.h"
#include "local_robot_port.h"

#include <QDeadlineTimer>
#include <QProcess>
#include <QSet>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <sys/prctl.h>
#include <sys/types.h>
#include <unistd.h>

using oilink::LinkSettings;
using oilink::LinkState;
using oilink::LocalRobotPort;

namespace {

constexpr int kTimeoutMs = 10000;

// A pseudo-terminal whose master side the test holds, playing the robot.
class PtyPair {
public:
    PtyPair()
    {
        m_master = ::posix_openpt(O_RDWR | O_NOCTTY);
        if (m_master >= 0 && ::grantpt(m_master) == 0 && ::unlockpt(m_master) == 0)
            m_slave = QString::fromLocal8Bit(::ptsname(m_master));
    }
    PtyPair(const PtyPair &) = delete;
    PtyPair &operator=(const PtyPair &) = delete;
    ~PtyPair()
    {
        if (m_master >= 0)
            ::close(m_master);
    }
    QString slavePath() const { return m_slave; }

    // Reads until `count` bytes have come or the time is up.
    QByteArray read(qsizetype count, int timeoutMs = kTimeoutMs)
    {
        QByteArray out;
        const QDeadlineTimer deadline(timeoutMs);
        while (out.size() < count && !deadline.hasExpired()) {
            pollfd p{m_master, POLLIN, 0};
            if (::poll(&p, 1, 50) <= 0 || !(p.revents & POLLIN))
                continue;
            char buf[256];
            const ssize_t n = ::read(m_master, buf, sizeof buf);
            if (n > 0)
                out.append(buf, n);
        }
        return out;
    }
    // Everything still on the line once the other side has hung up; a
    // closed port can send nothing more.
    QByteArray readToHangup(int timeoutMs = kTimeoutMs)
    {
        QByteArray out;
        const QDeadlineTimer deadline(timeoutMs);
        while (!deadline.hasExpired()) {
            pollfd p{m_master, POLLIN, 0};
            if (::poll(&p, 1, 50) <= 0)
                continue;
            char buf[256];
            const ssize_t n = ::read(m_master, buf, sizeof buf);
            if (n > 0)
                out.append(buf, n);
            else if (n < 0 && errno == EIO)
                return out; // no slave open: hung up, and nothing left
        }
        out.append("(no hangup)");
        return out;
    }
    void write(const QByteArray &data) { [[maybe_unused]] const ssize_t n = ::write(m_master, data.constData(), size_t(data.size())); }

private:
    int m_master = -1;
    QString m_slave;
};

// Everything a LocalRobotPort said, gathered on the test thread.
struct Recorder {
    explicit Recorder(LocalRobotPort &link)
        : snapshots(link), states(link), errors(link), started(link)
    {
        // The context dies with the recorder: the link, destroyed later,
        // still delivers what it had queued.
        oilink::connectEvent<oilink::event::BytesReceived>(&link, &context,
                         [this](const QByteArray &data) { raw += data; });
    }
    bool sawState(LinkState state) const
    {
        for (const QList<QVariant> &args : states)
            if (args.at(0).value<LinkState>() == state)
                return true;
        return false;
    }
    QStringList errorList() const
    {
        QStringList out;
        for (const QList<QVariant> &args : errors)
            out.append(args.at(0).toString());
        return out;
    }

    QObject context;
    LinkEventSpy<oilink::event::Frame> snapshots;
    LinkEventSpy<oilink::event::State> states;
    LinkEventSpy<oilink::event::Error> errors;
    LinkEventSpy<oilink::event::StreamStarted> started;
    QByteArray raw;
};

LinkSettings create2At(const QString &path)
{
    return LinkSettings::serial(path, oi::ProfileId::Create2);
}

} // namespace

class TestRobotLinkPty : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { oilink::registerLinkMetaTypes(); }

    void streamsOverAPty()
    {
        SimProcess sim;
        QVERIFY(sim.start({QStringLiteral("--profile"), QStringLiteral("create2")}));
        QVERIFY(sim.where().startsWith(QStringLiteral("/dev/")));
        LocalRobotPort link;
        Recorder r(link);
        link.post(oilink::request::Open{create2At(sim.where())});
        QTRY_VERIFY_WITH_TIMEOUT(r.snapshots.size() >= 30, kTimeoutMs);
        QCOMPARE(link.state(), LinkState::Streaming);
        link.closeAndWait();
        const oilink::LinkStats s = link.lastStatistics();
        QCOMPARE(s.frames, quint64(r.snapshots.size()));
        QCOMPARE(s.checksumFailures, quint64(0));
        QCOMPARE(s.resyncs, quint64(0));
        QCOMPARE(r.errors.size(), 0);
        QCOMPARE(link.state(), LinkState::Closed);
    }

    void findsTheProfileOverAPty_data()
    {
        QTest::addColumn<QString>("robot");
        QTest::addColumn<oi::ProfileId>("found");
        QTest::addColumn<int>("baud");
        QTest::addColumn<QList<int>>("packets");
        QTest::newRow("create2") << "create2" << oi::ProfileId::Create2 << 115200 << QList<int>{100};
        QTest::newRow("roomba500") << "roomba500" << oi::ProfileId::Create2 << 115200 << QList<int>{100};
        // The Create talks at 57600: at 115200 the link hears junk and moves on.
        QTest::newRow("create1") << "create1" << oi::ProfileId::Create1 << 57600 << QList<int>{1, 17, 18, 19, 3, 4, 5};
        // The SCI (2005) at 57600: found by its answers, polled for group 0's packets 7..26.
        QList<int> groupZero;
        for (int id = 7; id <= 26; ++id)
            groupZero << id;
        QTest::newRow("roomba400") << "roomba400" << oi::ProfileId::Roomba400 << 57600 << groupZero;
    }
    void findsTheProfileOverAPty()
    {
        QFETCH(QString, robot);
        QFETCH(oi::ProfileId, found);
        QFETCH(int, baud);
        QFETCH(QList<int>, packets);
        SimProcess sim;
        QVERIFY(sim.start({QStringLiteral("--profile"), robot}));
        LocalRobotPort link;
        Recorder r(link);
        link.post(oilink::request::Open{LinkSettings::serial(sim.where())});
        QTRY_COMPARE_WITH_TIMEOUT(r.started.size(), 1, kTimeoutMs);
        QCOMPARE(r.started.at(0).at(0).value<oi::ProfileId>(), found);
        QCOMPARE(r.started.at(0).at(1).toInt(), baud);
        QCOMPARE(r.started.at(0).at(2).value<QList<int>>(), packets);
        QTRY_VERIFY_WITH_TIMEOUT(r.snapshots.size() >= 5, kTimeoutMs);
        QCOMPARE(r.errors.size(), 0);
    }

    // The probe finds each robot at each baud it tries, the robot having
    // been set to that baud (Baud, 129) beforehand. The Roomba 500 and the
    // Create 2 are found as their family, Create 2 assumed and said so; the
    // Create is told apart.
    void findsEachRobotAtEachBaud_data()
    {
        QTest::addColumn<oi::ProfileId>("robot");
        QTest::addColumn<int>("baud");
        for (const oi::ProfileId robot : oi::allProfiles())
            for (const int baud : oilink::ProfileProbe::defaultBauds())
                QTest::addRow("%s at %d", oi::profile(robot).key.data(), baud) << robot << baud;
    }
    void findsEachRobotAtEachBaud()
    {
        QFETCH(oi::ProfileId, robot);
        QFETCH(int, baud);
        sim::PtyRobotServer server(oi::profile(robot));
        QString error;
        QVERIFY2(server.open(&error), qPrintable(error));
        server.robot().write(QByteArray("\x80\x81", 2) + char(oi::baudCodeFor(baud))); // Start, Baud
        QTRY_COMPARE(server.robot().robot().baud(), baud);
        LocalRobotPort link;
        Recorder r(link);
        LinkEventSpy<oilink::event::ProfileAssumed> assumed(link);
        link.post(oilink::request::Open{LinkSettings::serial(server.slavePath())});
        QTRY_COMPARE_WITH_TIMEOUT(r.started.size(), 1, kTimeoutMs);
        const bool family = oilink::ProfileProbe::isAmbiguous(robot);
        const oi::ProfileId found = family ? oi::ProfileId::Create2 : robot;
        QCOMPARE(r.started.at(0).at(0).value<oi::ProfileId>(), found);
        QCOMPARE(r.started.at(0).at(1).toInt(), baud);
        QCOMPARE(assumed.size(), family ? 1 : 0);
        if (family)
            QCOMPARE(assumed.at(0).at(0).value<oi::ProfileId>(), oi::ProfileId::Create2);
        QTRY_VERIFY_WITH_TIMEOUT(r.snapshots.size() >= 3, kTimeoutMs);
        QCOMPARE(r.snapshots.last().at(0).value<oi::SensorSnapshot>().robotProfile().id, found);
    }

    // ERRATA 2 end to end. The robot puts a stray 19 before 0.5 % of its
    // bytes, some inside frames (which destroys those frames) and some
    // between them. Every frame that reached the port intact must come out
    // as a snapshot: the link's count must equal the count found by trying
    // every offset of the raw bytes it received.
    void noFrameLostToStrayHeaders()
    {
        SimProcess sim;
        QVERIFY(sim.start({QStringLiteral("--stray"), QStringLiteral("0.005"), QStringLiteral("--seed"),
                           QStringLiteral("7")}));
        LocalRobotPort link;
        Recorder r(link);
        link.post(oilink::request::Open{create2At(sim.where())});
        QTRY_VERIFY_WITH_TIMEOUT(r.snapshots.size() >= 150, kTimeoutMs * 2);
        link.closeAndWait();
        const oilink::LinkStats s = link.lastStatistics();
        const int intact = countIntactGroup100Frames(r.raw);
        qInfo("%d intact frames on the line, %llu decoded, %llu bytes discarded, %llu resyncs, "
              "%llu checksum failures", intact, s.frames, s.bytesDiscarded, s.resyncs, s.checksumFailures);
        QCOMPARE(s.bytesReceived, quint64(r.raw.size()));
        QCOMPARE(s.frames, quint64(intact));
        QCOMPARE(quint64(r.snapshots.size()), s.frames);
        QVERIFY(s.bytesDiscarded > 0); // the strays were there, and were dropped
        QVERIFY(s.resyncs + s.checksumFailures > 0);
    }

    void corruptedFramesAreCounted()
    {
        SimProcess sim;
        QVERIFY(sim.start({QStringLiteral("--corrupt"), QStringLiteral("0.003"), QStringLiteral("--seed"),
                           QStringLiteral("3")}));
        LocalRobotPort link;
        Recorder r(link);
        link.post(oilink::request::Open{create2At(sim.where())});
        QTRY_VERIFY_WITH_TIMEOUT(r.snapshots.size() >= 150, kTimeoutMs * 2);
        link.closeAndWait();
        const oilink::LinkStats s = link.lastStatistics();
        const int intact = countIntactGroup100Frames(r.raw);
        qInfo("%d intact frames on the line, %llu decoded, %llu checksum failures, %llu resyncs", intact,
              s.frames, s.checksumFailures, s.resyncs);
        QVERIFY(s.checksumFailures > 0);
        QCOMPARE(s.frames, quint64(intact));
        QVERIFY(s.bytesDiscarded >= s.checksumFailures);
    }

    // The link's clock is the test's: it moves while the robot is stopped,
    // and the link, hearing nothing more, calls the data stale.
    void staleWhileTheRobotIsStopped()
    {
        SimProcess sim;
        QVERIFY(sim.start({}));
        ManualClock clock;
        LocalRobotPort link;
        link.setClock(clock);
        Recorder r(link);
        link.post(oilink::request::Open{create2At(sim.where())});
        // Through the wake pulse and the robot's time to wake, 10 ms a step.
        QVERIFY(QTest::qWaitFor([&] {
            clock.advance(10);
            return link.state() == LinkState::Streaming;
        }, kTimeoutMs));
        sim.signal(SIGSTOP);
        // A frame still on its way restarts the watchdog: move on until none comes.
        QVERIFY(QTest::qWaitFor([&] {
            clock.advance(oilink::RobotLink::kStaleAfterMs);
            return link.state() == LinkState::Stale;
        }, kTimeoutMs));
        sim.signal(SIGCONT);
        QTRY_COMPARE_WITH_TIMEOUT(link.state(), LinkState::Streaming, kTimeoutMs);
        QCOMPARE(r.errors.size(), 0);
    }

    void reconnectsWhenTheRobotComesBack()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("roomba"));
        SimProcess first;
        QVERIFY(first.start({QStringLiteral("--link"), path}));
        std::atomic<int> attempts{0};
        ManualClock clock;
        LocalRobotPort link;
        link.setClock(clock);
        link.setTransportFactory(countedTransports(attempts));
        Recorder r(link);
        link.post(oilink::request::Open{create2At(path)});
        // The link's time moves 10 ms a step: through the wake, and later the backoff.
        const auto untilMoving = [&](auto done, int stepMs = 10) {
            return QTest::qWaitFor([&] {
                clock.advance(stepMs);
                return done();
            }, kTimeoutMs);
        };
        QVERIFY(untilMoving([&] { return link.state() == LinkState::Streaming; }));

        // Ended as a user ends it, so it removes its link: a link left
        // dangling would point at whichever program gets the same
        // pseudo-terminal number next, perhaps another test's robot.
        first.stop();
        QTRY_COMPARE_WITH_TIMEOUT(link.state(), LinkState::Reconnecting, kTimeoutMs);
        QVERIFY(r.sawState(LinkState::Lost));
        // Several attempts fail while nothing is there, one per backoff.
        const int lost = attempts;
        QVERIFY(untilMoving([&] { return attempts >= lost + 3; }, oilink::RobotLink::kMaxBackoffMs));
        QCOMPARE(link.state(), LinkState::Reconnecting);

        SimProcess second;
        QVERIFY(second.start({QStringLiteral("--link"), path}));
        const qsizetype before = r.snapshots.size();
        QVERIFY(untilMoving([&] { return link.state() == LinkState::Streaming; }));
        QTRY_VERIFY_WITH_TIMEOUT(r.snapshots.size() > before + 5, kTimeoutMs);
        link.closeAndWait();
        QCOMPARE(link.lastStatistics().reconnects, quint32(1));

        // One message per cause, however many attempts failed.
        const QStringList errors = r.errorList();
        QVERIFY2(!errors.isEmpty() && errors.first() == path + QStringLiteral(": the port went away"),
                 qPrintable(errors.join(QStringLiteral(" | "))));
        QCOMPARE(QSet<QString>(errors.begin(), errors.end()).size(), errors.size());
        QVERIFY2(errors.size() <= 2, qPrintable(errors.join(QStringLiteral(" | "))));
    }

    void closeLeavesTheStopBytesOnTheLine()
    {
        PtyPair pty;
        QVERIFY(!pty.slavePath().isEmpty());
        LocalRobotPort link;
        Recorder r(link);
        link.post(oilink::request::Open{create2At(pty.slavePath())});
        const qsizetype finishing = qsizetype(oilink::ProfileProbe::finishingStarts().size());
        QCOMPARE(pty.read(7 + finishing + 11), bytes({137, 0, 0, 0, 0, 138, 0}) + QByteArray(finishing, char(128))
                                                    + bytes({137, 0, 0, 0, 0, 138, 0, 128, 148, 1, 100}));
        pty.write(group100Frame() + group100Frame());
        QTRY_COMPARE_WITH_TIMEOUT(r.snapshots.size(), 2, kTimeoutMs);
        link.closeAndWait();
        QCOMPARE(pty.read(10), bytes({150, 0, 137, 0, 0, 0, 0, 138, 0, 128}));
        QCOMPARE(pty.readToHangup(), QByteArray()); // and nothing after, up to the close of the port
    }

    void streamsOverTcpAndReconnects()
    {
        SimProcess first;
        QVERIFY(first.start({QStringLiteral("--tcp"), QStringLiteral("0")}));
        QVERIFY(first.where().startsWith(QStringLiteral("tcp://")));
        const quint16 port = first.tcpPort();
        std::atomic<int> attempts{0};
        LocalRobotPort link;
        link.setTransportFactory(countedTransports(attempts));
        Recorder r(link);
        link.post(oilink::request::Open{LinkSettings::tcp(QStringLiteral("127.0.0.1"), port, oi::ProfileId::Create2)});
        QTRY_VERIFY_WITH_TIMEOUT(r.snapshots.size() >= 10, kTimeoutMs);

        first.kill();
        QTRY_COMPARE_WITH_TIMEOUT(link.state(), LinkState::Reconnecting, kTimeoutMs);
        // A few attempts are refused before the robot is back.
        const int lost = attempts;
        QTRY_VERIFY_WITH_TIMEOUT(attempts >= lost + 2, kTimeoutMs);
        SimProcess second;
        QVERIFY(second.start({QStringLiteral("--tcp"), QString::number(port)}));
        const qsizetype before = r.snapshots.size();
        QTRY_VERIFY_WITH_TIMEOUT(r.snapshots.size() > before + 5, kTimeoutMs);
        QCOMPARE(link.state(), LinkState::Streaming);
        const QStringList errors = r.errorList();
        QCOMPARE(QSet<QString>(errors.begin(), errors.end()).size(), errors.size());
        QVERIFY2(errors.contains(QStringLiteral("127.0.0.1:%1: the bridge closed the connection").arg(port)),
                 qPrintable(errors.join(QStringLiteral(" | "))));
    }

    void missingPortIsOneMessage()
    {
        std::atomic<int> attempts{0};
        ManualClock clock;
        LocalRobotPort link;
        link.setClock(clock);
        link.setTransportFactory(countedTransports(attempts));
        Recorder r(link);
        link.post(oilink::request::Open{create2At(QStringLiteral("/dev/roomba-dashboard-no-such-port"))});
        QTRY_COMPARE_WITH_TIMEOUT(r.errors.size(), 1, kTimeoutMs);
        QCOMPARE(r.errors.at(0).at(0).toString(), QStringLiteral("/dev/roomba-dashboard-no-such-port: no such port"));
        // Several more attempts as the backoff's time passes; each one's error
        // was sent before the next attempt began, so it has reached this
        // thread once events are taken.
        QVERIFY(QTest::qWaitFor([&] {
            clock.advance(oilink::RobotLink::kMaxBackoffMs);
            return attempts >= 5;
        }, kTimeoutMs));
        QCoreApplication::processEvents();
        QCOMPARE(r.errors.size(), 1);
        QCOMPARE(link.state(), LinkState::Reconnecting);
    }

    void busyPortIsSaidSo()
    {
        SimProcess sim;
        QVERIFY(sim.start({}));
        LocalRobotPort first;
        first.post(oilink::request::Open{create2At(sim.where())});
        QTRY_COMPARE_WITH_TIMEOUT(first.state(), LinkState::Streaming, kTimeoutMs);
        LocalRobotPort second;
        Recorder r(second);
        second.post(oilink::request::Open{create2At(sim.where())});
        QTRY_COMPARE_WITH_TIMEOUT(r.errors.size(), 1, kTimeoutMs);
        QCOMPARE(r.errors.at(0).at(0).toString(), sim.where() + QStringLiteral(": port busy (another program has it open)"));
        // Once the first lets go, the second gets it.
        first.stop();
        QTRY_COMPARE_WITH_TIMEOUT(second.state(), LinkState::Streaming, kTimeoutMs);
        QCOMPARE(r.errors.size(), 1);
    }
};

QTEST_GUILESS_MAIN(TestRobotLinkPty)
#include "tst_robot_link_pty.moc"
