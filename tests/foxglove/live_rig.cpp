// SPDX-License-Identifier: GPL-3.0-or-later
// The live data server with robots the test controls, for the protocol's own
// client (client/live_check.js) to connect to. One scenario a run:
//   live_rig telemetry DIR SECONDS  a virtual robot driving for SECONDS of its own
//                                   time (ten times faster than real time) while
//                                   recording; then DIR/run.csv, the recording's CSV
//   live_rig replay DIR             a recording written here, replayed at 4x on the wall clock
//   live_rig fleet                  robots added and removed on command
//   live_rig slow QUEUE_BYTES       a robot driving ten times faster than real time,
//                                   QUEUE_BYTES the limit on what waits for a client
// It prints "url ws://..." once serving, then reads commands a line at a time
// on standard input ("go", "add", "remove rN", "quit") and says what it did on
// standard output.

#include "foxglove_server.h"
#include "link_status.h"
#include "live_robots.h"
#include "oirec_records.h"
#include "recording_file.h"
#include "replay_transport.h"
#include "stepped_session.h"
#include "stream_frames.h"
#include "transport_factory.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QTextStream>
#include <QThread>

#include <poll.h>
#include <unistd.h>

#include <cstdio>
#include <deque>
#include <memory>

namespace {

void say(const QString &line)
{
    std::printf("%s\n", qPrintable(line));
    std::fflush(stdout);
}

// The next line on standard input, serving the event loop meanwhile.
QString nextCommand()
{
    static QByteArray buffer;
    for (;;) {
        const qsizetype end = buffer.indexOf('\n');
        if (end >= 0) {
            const QString line = QString::fromUtf8(buffer.left(end)).trimmed();
            buffer.remove(0, end + 1);
            return line;
        }
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        pollfd in{STDIN_FILENO, POLLIN, 0};
        if (::poll(&in, 1, 5) > 0) {
            char chunk[256];
            const ssize_t n = ::read(STDIN_FILENO, chunk, sizeof chunk);
            if (n <= 0)
                return QStringLiteral("quit");
            buffer.append(chunk, n);
        }
    }
}

void serveUntilQuit()
{
    while (nextCommand() != QLatin1String("quit")) {
    }
}

bool listen(foxglove::Server &server)
{
    foxglove::ServerAddress address;
    address.port = 0;
    if (!server.listen(address)) {
        say(QStringLiteral("error %1").arg(server.errorString()));
        return false;
    }
    say(QStringLiteral("url %1").arg(server.url()));
    return true;
}

// Drives the robot on a wide curve for `seconds` of its time, at ten times
// real time, so that the odometry and the wheel readings change.
void drive(SteppedSession &s, double seconds, const std::function<bool()> &stop = {})
{
    s.send(oi::Command::Safe);
    s.send(oi::Command::Drive, {200, 800});
    QElapsedTimer wall;
    wall.start();
    for (qint64 ms = 0; ms < qint64(seconds * 1000) && !(stop && stop()); ms += 15) {
        s.clock.advance(15);
        QCoreApplication::processEvents();
        while (wall.nsecsElapsed() < ms * 100000) { // 10x
            QCoreApplication::processEvents();
            QThread::usleep(300);
        }
        if (ms == qint64(seconds * 500))
            s.robot.dropMarker(QStringLiteral("halfway"));
    }
    s.send(oi::Command::Drive, {0, 0});
}

int telemetry(const QString &dir, double seconds)
{
    SteppedSession s(oi::ProfileId::Create2);
    foxglove::Server server(QStringLiteral("live_rig"), s.clock);
    server.setLimits({50, 256 * 1024 * 1024}); // the checking client is never dropped
    LiveRobots live(server);
    live.setTruePose([&s](const RobotSession *) { return std::optional(s.line->robot().truePose()); });
    live.add(&s.robot);
    if (!s.live() || !listen(server))
        return 1;
    const QString path = dir + QStringLiteral("/run.oirec");
    s.robot.startRecording(path);
    s.clock.advance(15);
    QCoreApplication::processEvents();
    if (nextCommand() != QLatin1String("go"))
        return 1;
    drive(s, seconds);
    s.robot.stopRecording();
    s.clock.advance(100);
    QCoreApplication::processEvents();
    QString error;
    const std::optional<oilink::Recording> recording = oilink::Recording::load(path, &error);
    QFile csv(dir + QStringLiteral("/run.csv"));
    if (!recording || !csv.open(QIODevice::WriteOnly)) {
        say(QStringLiteral("error %1").arg(error));
        return 1;
    }
    QTextStream out(&csv);
    recording->writeCsv(out);
    out.flush();
    say(QStringLiteral("done %1").arg(csv.fileName()));
    serveUntilQuit();
    return 0;
}

int replay(const QString &dir)
{
    // Thirty seconds of a Create 2 in Safe mode, a frame every 15 ms: a
    // recording's times are its writer's wall clock, so it is made here.
    const QString path = dir + QStringLiteral("/replayed.oirec");
    QByteArray file = oirecHeader(3, R"({"format":"Roomba Dashboard recording","version":3,)"
                                     R"("started":"2026-01-02T03:04:05.000Z","link":"test"})");
    file += oirecRecord('S', 0, R"({"profile":"create2","baud":115200,"packets":[100]})");
    for (int i = 0; i < 2000; ++i)
        file += oirecRecord('R', 15000 * (i + 1), group100Frame(0, 2));
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly) || out.write(file) != file.size()) {
        say(QStringLiteral("error %1").arg(out.errorString()));
        return 1;
    }
    out.close();
    QString error;
    const std::optional<oilink::Recording::StreamInfo> stream = oilink::Recording::readStream(path, &error);
    if (!stream) {
        say(QStringLiteral("error %1").arg(error));
        return 1;
    }
    foxglove::Server server(QStringLiteral("live_rig"));
    LiveRobots live(server);
    RobotSession robot;
    robot.setTransportFactory(transports::transportFactory());
    live.add(&robot);
    if (!listen(server))
        return 1;
    if (nextCommand() != QLatin1String("go"))
        return 1;
    robot.connectTo(oilink::LinkSettings::replayOf(path, stream->profile->id, stream->baud, stream->packets));
    robot.controlReplay(oilink::ReplayCommand::setSpeed(4));
    robot.controlReplay(oilink::ReplayCommand::play());
    say(QStringLiteral("playing"));
    serveUntilQuit();
    return 0;
}

int fleet()
{
    std::deque<std::unique_ptr<SteppedSession>> robots;
    foxglove::Server server(QStringLiteral("live_rig"));
    LiveRobots live(server);
    if (!listen(server))
        return 1;
    for (QString command = nextCommand(); command != QLatin1String("quit"); command = nextCommand()) {
        if (command == QLatin1String("add")) {
            robots.push_back(std::make_unique<SteppedSession>(oi::ProfileId::Create2));
            live.add(&robots.back()->robot);
            say(QStringLiteral("added %1").arg(live.prefixOf(&robots.back()->robot)));
        } else if (command.startsWith(QLatin1String("remove "))) {
            const QString prefix = command.mid(7);
            const auto it = std::find_if(robots.begin(), robots.end(), [&](const auto &s) {
                return live.prefixOf(&s->robot) == prefix;
            });
            if (it == robots.end()) {
                say(QStringLiteral("error no robot %1").arg(prefix));
                continue;
            }
            live.remove(&(*it)->robot);
            robots.erase(it);
            say(QStringLiteral("removed %1").arg(prefix));
        }
    }
    return 0;
}

int slow(qint64 queueBytes)
{
    SteppedSession s(oi::ProfileId::Create2);
    foxglove::Server server(QStringLiteral("live_rig"), s.clock);
    // Its slow client stops reading for a minute: past the 30 s after which
    // a silent client is closed (tst_foxglove_server holds that rule).
    server.setLimits({50, queueBytes, 120000});
    LiveRobots live(server);
    live.add(&s.robot);
    if (!s.live() || !listen(server))
        return 1;
    if (nextCommand() != QLatin1String("go"))
        return 1;
    int dropped = 0;
    QObject::connect(&server, &foxglove::Server::clientDropped, [&](const QString &peer, const QString &why) {
        say(QStringLiteral("dropped %1 %2").arg(peer, why));
        ++dropped;
    });
    const qint64 startNs = s.clock.nowNs();
    qint64 most = 0;
    // A minute of robot time, the server's count of what waits looked at each tick.
    drive(s, 60, [&] { return most = std::max(most, server.queuedBytes()), false; });
    say(QStringLiteral("done %1 %2 %3").arg(double(s.clock.nowNs() - startNs) / 1e9, 0, 'f', 3).arg(most).arg(dropped));
    serveUntilQuit();
    return 0;
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    oilink::registerLinkMetaTypes();
    const QStringList a = app.arguments();
    const QString scenario = a.value(1);
    if (scenario == QLatin1String("telemetry") && a.size() == 4)
        return telemetry(a[2], a[3].toDouble());
    if (scenario == QLatin1String("replay") && a.size() == 3)
        return replay(a[2]);
    if (scenario == QLatin1String("fleet"))
        return fleet();
    if (scenario == QLatin1String("slow") && a.size() == 3)
        return slow(a[2].toLongLong());
    std::fprintf(stderr, "usage: live_rig telemetry DIR SECONDS | replay DIR | fleet | slow QUEUE_BYTES\n");
    return 2;
}
