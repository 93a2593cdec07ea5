// SPDX-License-Identifier: GPL-3.0-or-later
// The TCP transport against a real ser2net on loopback, bridging to a
// roomba-sim pseudo-terminal: streaming, commands, and recovery when ser2net
// restarts. The test functions run in order and share one robot, one bridge
// and one link.
#include "link_test_support.h"
#include "sim_process.h"
#include "typed_command_bytes.h"

#include "command_encoder.h"
#include "song.h"
#include "link_event_spy.h"
#include "local_robot_port.h"

#include <QFile>
#include <QProcess>
#include <QSet>
#include <QStandardPaths>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QTest>

#include <array>
#include <atomic>
#include <memory>

using oilink::LinkSettings;
using oilink::LinkState;
using oilink::LocalRobotPort;

namespace {

constexpr int kTimeoutMs = 15000;
constexpr int kVelocity = 200; // mm/s

QString findSer2net()
{
    return QStandardPaths::findExecutable(QStringLiteral("ser2net"),
                                          {QStringLiteral("/usr/sbin"), QStringLiteral("/usr/local/sbin"),
                                           QStringLiteral("/usr/bin"), QStringLiteral("/usr/local/bin")});
}

// A loopback port nobody uses at the moment.
quint16 freeLoopbackPort()
{
    QTcpServer server;
    if (!server.listen(QHostAddress::LocalHost, 0))
        return 0;
    return server.serverPort();
}

// Whether something listens on 127.0.0.1:port. Read from the kernel rather
// than by connecting: a connection would make ser2net open the robot's port
// and could take the one connection it allows from the link.
bool isListening(quint16 port)
{
    QFile table(QStringLiteral("/proc/net/tcp"));
    if (!table.open(QIODevice::ReadOnly))
        return false;
    const QByteArray local = "0100007F:" + QByteArray::number(port, 16).toUpper().rightJustified(4, '0');
    const QByteArray listen = "0A";
    for (const QByteArray &line : table.readAll().split('\n')) {
        const QList<QByteArray> fields = line.simplified().split(' ');
        if (fields.size() > 3 && fields.at(1) == local && fields.at(3) == listen)
            return true;
    }
    return false;
}

// ser2net in the foreground, bridging raw TCP on 127.0.0.1:port to a serial
// device. Its log is kept for failure messages.
class Ser2netProcess {
public:
    Ser2netProcess() = default;
    Ser2netProcess(const Ser2netProcess &) = delete;
    Ser2netProcess &operator=(const Ser2netProcess &) = delete;
    ~Ser2netProcess() { kill(); }

    // Writes the configuration into `dir`.
    bool configure(const QString &program, const QString &dir, quint16 port, const QString &device, int baud)
    {
        m_program = program;
        m_dir = dir;
        m_port = port;
        QFile config(configPath());
        if (!config.open(QIODevice::WriteOnly | QIODevice::Truncate))
            return false;
        // `local` ignores the modem lines, which a pseudo-terminal lacks.
        const QString yaml = QStringLiteral("connection: &robot\n"
                                            "  accepter: tcp,127.0.0.1,%1\n"
                                            "  connector: serialdev,%2,%3n81,local\n")
                                 .arg(port)
                                 .arg(device)
                                 .arg(baud);
        return config.write(yaml.toUtf8()) > 0;
    }

    // Starts it and waits until it listens.
    bool start()
    {
        m_process.setProgram(m_program);
        // -n: stay in the foreground; -u: no UUCP lock files, which need
        // /var/lock and would outlive a killed ser2net.
        m_process.setArguments({QStringLiteral("-n"), QStringLiteral("-u"), QStringLiteral("-c"), configPath(),
                                QStringLiteral("-P"), m_dir + QStringLiteral("/ser2net.pid")});
        m_process.setProcessChannelMode(QProcess::MergedChannels);
        m_process.setChildProcessModifier([] { ::prctl(PR_SET_PDEATHSIG, SIGKILL); });
        m_process.start();
        if (!m_process.waitForStarted(kTimeoutMs))
            return false;
        const QDeadlineTimer deadline(kTimeoutMs);
        while (!isListening(m_port) && !deadline.hasExpired() && m_process.state() == QProcess::Running)
            m_process.waitForFinished(50);
        return m_process.state() == QProcess::Running && isListening(m_port);
    }

    void kill()
    {
        if (m_process.state() == QProcess::NotRunning)
            return;
        m_process.kill();
        m_process.waitForFinished(kTimeoutMs);
    }

    bool isRunning() const { return m_process.state() == QProcess::Running; }
    QString configPath() const { return m_dir + QStringLiteral("/ser2net.yaml"); }
    QString commandLine() const { return m_program + QLatin1Char(' ') + m_process.arguments().join(QLatin1Char(' ')); }
    QString log() { return QString::fromLocal8Bit(m_process.readAll()).trimmed(); }

private:
    QProcess m_process;
    QString m_program;
    QString m_dir;
    quint16 m_port = 0;
};

// Why a streamed Create 2 snapshot is not plausible, or nothing.
QString implausible(const oi::SensorSnapshot &s)
{
    if (s.robotProfile().id != oi::ProfileId::Create2)
        return QStringLiteral("not decoded as a Create 2");
    for (int id = 7; id <= 58; ++id) {
        const oi::PacketValue v = s.value(id);
        if (!v.present)
            return QStringLiteral("packet %1 missing (group 100 carries 7..58)").arg(id);
        if (v.outOfRange())
            return QStringLiteral("packet %1 = %2 is out of range").arg(id).arg(v.value);
    }
    if (s.voltageMv() < 12000 || s.voltageMv() > 17500)
        return QStringLiteral("battery voltage %1 mV").arg(s.voltageMv());
    if (s.batteryCapacityMah() <= 0 || s.batteryChargeMah() > s.batteryCapacityMah())
        return QStringLiteral("battery charge %1 of %2 mAh").arg(s.batteryChargeMah()).arg(s.batteryCapacityMah());
    return {};
}

QByteArray toBytes(const oi::EncodeResult &command)
{
    return QByteArray(reinterpret_cast<const char *>(command->data()), qsizetype(command->size()));
}

// The robot's answer to a question, read from `socket` into `reply`: the
// stream frames that come before it are skipped and counted (an answer
// never starts with 19: the questions here ask for a mode or a flag).
// Returns the frames, or -1 when the bytes are no frame, or nothing came.
int framesBeforeAnswer(QTcpSocket &socket, QByteArray &pending, qsizetype answerSize, QByteArray &reply)
{
    const QDeadlineTimer deadline(kTimeoutMs);
    const auto have = [&](qsizetype n) {
        while (pending.size() < n && socket.state() == QAbstractSocket::ConnectedState && !deadline.hasExpired())
            if (socket.waitForReadyRead(100))
                pending += socket.readAll();
        return pending.size() >= n;
    };
    int frames = 0;
    while (have(1) && std::uint8_t(pending.front()) == 19) {
        if (!have(2) || !have(std::uint8_t(pending.at(1)) + 3))
            return -1;
        const qsizetype size = std::uint8_t(pending.at(1)) + 3;
        unsigned sum = 0;
        for (qsizetype i = 0; i < size; ++i)
            sum += std::uint8_t(pending.at(i));
        if (sum % 256 != 0)
            return -1;
        pending.remove(0, size);
        ++frames;
    }
    if (!have(answerSize))
        return -1;
    reply = pending.left(answerSize);
    pending.remove(0, answerSize);
    return frames;
}

// Asks the robot its OI mode and requested velocity (Query List 35 35 35
// 35 39) and finds the answer among whatever reaches the socket first: the
// tail of a frame cut when the link hung up, frames that were on their way.
// Four equal modes of 1 to 3 mark where the answer starts; no stream frame
// holds that. Returns the mode and the velocity's two bytes, or nothing when
// no answer came.
QByteArray modeAndVelocity(const oi::CommandEncoder &encoder, QTcpSocket &socket, QByteArray &pending)
{
    const std::array<int, 5> ids{35, 35, 35, 35, 39};
    socket.write(toBytes(encoder.queryList(ids)));
    const QDeadlineTimer deadline(kTimeoutMs);
    for (;;) {
        for (qsizetype at = 0; at + 6 <= pending.size(); ++at) {
            const char mode = pending.at(at);
            if (mode >= 1 && mode <= 3 && pending.mid(at, 4) == QByteArray(4, mode)) {
                const QByteArray answer = mode + pending.mid(at + 4, 2);
                pending.remove(0, at + 6);
                return answer;
            }
        }
        if (socket.state() != QAbstractSocket::ConnectedState || deadline.hasExpired())
            return {};
        if (socket.waitForReadyRead(100))
            pending += socket.readAll();
    }
}

} // namespace

class TestSer2net : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void streams();
    void commandsReachTheRobot();
    void recoversWhenSer2netRestarts();
    void closeLeavesTheRobotPassive();
    void init();
    void cleanup();
    void cleanupTestCase();

private:
    void sendSafeAndDrive();
    bool sawState(LinkState state) const { return m_states.contains(state); }
    QString errors() const { return m_errors.join(QStringLiteral(" | ")); }
    QString bridgeMessage(const QString &what) const
    {
        return QStringLiteral("127.0.0.1:%1: %2").arg(m_port).arg(what);
    }

    const oi::CommandEncoder m_encoder{oi::profile(oi::ProfileId::Create2)};
    QTemporaryDir m_dir;
    SimProcess m_sim;
    Ser2netProcess m_ser2net;
    quint16 m_port = 0;
    std::atomic<int> m_attempts{0}; // transports the link made: one per attempt to connect
    std::unique_ptr<LocalRobotPort> m_link;

    QList<LinkState> m_states;
    QStringList m_errors;
    QList<QVariantList> m_streamStarts;
    qsizetype m_snapshots = 0;
    oi::SensorSnapshot m_last;
    QString m_firstImplausible;
    int m_distanceMm = 0;
    QString m_failedStep;
};

void TestSer2net::initTestCase()
{
    oilink::registerLinkMetaTypes();
    const QString program = findSer2net();
    if (program.isEmpty())
        QFAIL("ser2net is not installed (Debian package ser2net; .ci/install-deps installs it)");
    QVERIFY(m_dir.isValid());

    QVERIFY2(m_sim.start({QStringLiteral("--profile"), QStringLiteral("create2")}), "roomba-sim did not start");
    QVERIFY2(m_sim.where().startsWith(QStringLiteral("/dev/")), qPrintable(m_sim.where()));

    m_port = freeLoopbackPort();
    QVERIFY(m_port != 0);
    const int baud = oi::profile(oi::ProfileId::Create2).defaultBaud;
    QCOMPARE(baud, 115200);
    QVERIFY(m_ser2net.configure(program, m_dir.path(), m_port, m_sim.where(), baud));
    QVERIFY2(m_ser2net.start(), qPrintable(QStringLiteral("%1 did not listen on port %2: %3")
                                               .arg(m_ser2net.commandLine())
                                               .arg(m_port)
                                               .arg(m_ser2net.log())));

    m_link = std::make_unique<LocalRobotPort>();
    m_attempts = 0;
    m_link->setTransportFactory(countedTransports(m_attempts));
    oilink::connectEvent<oilink::event::State>(m_link.get(), this, [this](LinkState s) { m_states.append(s); });
    oilink::connectEvent<oilink::event::Error>(m_link.get(), this, [this](const QString &e) { m_errors.append(e); });
    oilink::connectEvent<oilink::event::StreamStarted>(m_link.get(), this,
            [this](oi::ProfileId profile, int baud, const QList<int> &packets) {
                m_streamStarts.append({QVariant::fromValue(profile), baud, QVariant::fromValue(packets)});
            });
    oilink::connectEvent<oilink::event::Frame>(m_link.get(), this, [this](const oi::SensorSnapshot &s) {
        ++m_snapshots;
        m_last = s;
        m_distanceMm += s.distanceMm();
        if (m_firstImplausible.isEmpty())
            m_firstImplausible = implausible(s);
    });
    m_link->post(oilink::request::Open{LinkSettings::tcp(QStringLiteral("127.0.0.1"), m_port, oi::ProfileId::Create2)});
}

// Frames come through the bridge and decode to sane values.
void TestSer2net::streams()
{
    QTRY_VERIFY2_WITH_TIMEOUT(m_snapshots >= 50, qPrintable(errors() + QLatin1Char(' ') + m_ser2net.log()),
                              kTimeoutMs);
    QCOMPARE(m_link->state(), LinkState::Streaming);
    QCOMPARE(m_states.first(), LinkState::Connecting);
    QCOMPARE(m_streamStarts.size(), 1);
    QCOMPARE(m_streamStarts.at(0).at(0).value<oi::ProfileId>(), oi::ProfileId::Create2);
    QCOMPARE(m_streamStarts.at(0).at(1).toInt(), 115200);
    QCOMPARE(m_streamStarts.at(0).at(2).value<QList<int>>(), QList<int>{100});
    QVERIFY2(m_firstImplausible.isEmpty(), qPrintable(m_firstImplausible));
    QCOMPARE(m_last.oiMode(), oi::OiMode::Passive); // nothing asked for more yet
    QVERIFY2(m_errors.isEmpty(), qPrintable(errors()));
}

// Bytes sent reach the robot through the bridge: its mode, the velocity it
// was asked for and the distance it covers come back in the stream.
void TestSer2net::commandsReachTheRobot()
{
    sendSafeAndDrive();
    m_distanceMm = 0;
    QTRY_VERIFY2_WITH_TIMEOUT(m_distanceMm >= 50, qPrintable(QString::number(m_distanceMm)), kTimeoutMs);
    QVERIFY2(m_firstImplausible.isEmpty(), qPrintable(m_firstImplausible));
    QVERIFY2(m_errors.isEmpty(), qPrintable(errors()));
}

// ser2net dies and comes back on the same port: the link reports it once,
// keeps trying, and streams again without being opened again.
void TestSer2net::recoversWhenSer2netRestarts()
{
    m_ser2net.kill();
    QTRY_COMPARE_WITH_TIMEOUT(m_link->state(), LinkState::Reconnecting, kTimeoutMs);
    QVERIFY(sawState(LinkState::Lost));
    QVERIFY2(m_errors.contains(bridgeMessage(QStringLiteral("the bridge closed the connection"))), qPrintable(errors()));
    // Several attempts are refused while nothing listens; each one's error
    // was sent before the next attempt began.
    const int lost = m_attempts;
    QTRY_VERIFY_WITH_TIMEOUT(m_attempts >= lost + 4, kTimeoutMs);
    QCoreApplication::processEvents();
    QCOMPARE(m_link->state(), LinkState::Reconnecting);
    QVERIFY2(m_errors.contains(bridgeMessage(QStringLiteral("connection refused"))), qPrintable(errors()));

    const qsizetype before = m_snapshots;
    QVERIFY2(m_ser2net.start(), qPrintable(m_ser2net.log()));
    QTRY_COMPARE_WITH_TIMEOUT(m_link->state(), LinkState::Streaming, kTimeoutMs);
    QTRY_VERIFY_WITH_TIMEOUT(m_snapshots >= before + 50, kTimeoutMs);
    QVERIFY2(m_firstImplausible.isEmpty(), qPrintable(m_firstImplausible));
    // The link started the stream again with Start, which left Safe mode.
    QCOMPARE(m_last.oiMode(), oi::OiMode::Passive);
    QCOMPARE(m_streamStarts.size(), 2);

    // Each cause once, however many attempts failed.
    const QSet<QString> expected{bridgeMessage(QStringLiteral("the bridge closed the connection")),
                                 bridgeMessage(QStringLiteral("connection refused"))};
    QCOMPARE(m_errors.size(), 2);
    QCOMPARE(QSet<QString>(m_errors.begin(), m_errors.end()), expected);
}

// Closing leaves the robot stopped and in Passive mode. It is driving in Safe
// mode first, so the change can only come from the bytes the close sent.
void TestSer2net::closeLeavesTheRobotPassive()
{
    sendSafeAndDrive();
    m_link->closeAndWait();
    QCOMPARE(m_link->state(), LinkState::Closed);
    QCOMPARE(m_link->lastStatistics().reconnects, quint32(1));
    QCOMPARE(m_link->lastStatistics().checksumFailures, quint64(0));

    // Ask the robot itself over a connection of our own: its OI mode and
    // requested velocity (modeAndVelocity). ser2net serves one client at a
    // time, and on a busy machine it may not yet have seen the link's
    // connection end: it then hangs up on ours, so connect again until it
    // keeps ours open.
    QTcpSocket socket;
    QByteArray pending;
    QByteArray reply;
    const QDeadlineTimer servedBy(kTimeoutMs);
    while (!servedBy.hasExpired()) {
        socket.abort();
        pending.clear();
        socket.connectToHost(QHostAddress::LocalHost, m_port);
        QVERIFY2(socket.waitForConnected(kTimeoutMs), qPrintable(socket.errorString()));
        reply = modeAndVelocity(m_encoder, socket, pending);
        if (socket.state() == QAbstractSocket::ConnectedState)
            break;
    }
    QCOMPARE(socket.state(), QAbstractSocket::ConnectedState);
    QVERIFY2(!reply.isEmpty(), pending.toHex(' ').constData());
    QCOMPARE(int(reply.at(0)), int(oi::OiMode::Passive));
    QCOMPARE(reply.mid(1), QByteArray(2, '\0'));

    // The stream is off: while the robot plays a song of a quarter of a
    // second by its own clock (about 17 stream periods), asked again and
    // again whether it still plays (packet 37), it answers with no frame
    // before any answer. Play needs Safe mode.
    oi::Song quarterSecond;
    quarterSecond.notes = {{72, 16}};
    socket.write(toBytes(m_encoder.safe()) + toBytes(m_encoder.song(0, quarterSecond)) + toBytes(m_encoder.play(0)));
    int answers = 0;
    bool played = false;
    const QDeadlineTimer songBy(kTimeoutMs);
    do {
        QVERIFY2(!songBy.hasExpired(), played ? "the song never ended" : "the song never played");
        socket.write(toBytes(m_encoder.sensors(37)));
        QCOMPARE(framesBeforeAnswer(socket, pending, 1, reply), 0);
        ++answers;
        played = played || reply.at(0) == 1;
    } while (!played || reply.at(0) == 1);
    QVERIFY2(answers >= 2, qPrintable(QString::number(answers)));
    socket.write(toBytes(m_encoder.start())); // back to Passive
}

// Each step builds on the one before: after a failure, the rest fail at once
// instead of each waiting out its time limit.
void TestSer2net::init()
{
    if (!m_failedStep.isEmpty())
        QFAIL(qPrintable(QStringLiteral("not tried: %1() failed").arg(m_failedStep)));
}

void TestSer2net::cleanup()
{
    if (QTest::currentTestFailed() && m_failedStep.isEmpty())
        m_failedStep = QString::fromLatin1(QTest::currentTestFunction());
}

void TestSer2net::cleanupTestCase()
{
    m_link.reset();
    m_ser2net.kill();
    m_sim.stop();
}

// Safe mode and a drive straight ahead, seen coming back in the stream.
void TestSer2net::sendSafeAndDrive()
{
    m_link->post(oilink::request::Send{commandsOf(toBytes(m_encoder.safe()))});
    m_link->post(oilink::request::Send{commandsOf(toBytes(m_encoder.drive(kVelocity, oi::kRadiusStraight)))});
    QTRY_VERIFY2_WITH_TIMEOUT(m_last.oiMode() == oi::OiMode::Safe && m_last.requestedVelocity() == kVelocity,
                              qPrintable(QStringLiteral("mode %1, velocity %2")
                                             .arg(int(m_last.oiMode()))
                                             .arg(m_last.requestedVelocity())),
                              kTimeoutMs);
}

QTEST_GUILESS_MAIN(TestSer2net)
#include "tst_ser2net.moc"
