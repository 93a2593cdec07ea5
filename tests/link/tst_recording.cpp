// SPDX-License-Identifier: GPL-3.0-or-later
// Recordings: the file format, flushing, record-then-replay, damaged files,
// seeking and stepping, and the CSV export.
#include "recording_file.h"
#include "replay_transport.h"
#include "robot_link.h"
#include "transport_factory.h"
#include "virtual_transport.h"
#include "real_time_robot.h"
#include "typed_command_bytes.h"

#include "crowded_recording.h" // tests/common
#include "manual_clock.h"      // tests/common
#include "not_regular_files.h" // tests/common
#include "stream_parser.h"

#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QtEndian>

#include <chrono>
#include <cmath>
#include <sys/stat.h>
#include <random>

using oilink::LinkSettings;
using oilink::LinkState;
using oilink::MarkerEdit;
using oilink::RecordingMarker;
using oilink::Recording;
using oilink::RecordingWriter;
using oilink::ReplayCommand;
using oilink::ReplayStatus;
using oilink::ReplayTransport;
using oilink::RobotLink;
using oilink::recording::RecordKind;

namespace {
constexpr int kTimeoutMs = 15000;
constexpr int kFrames = 60;

QList<oi::SensorSnapshot> snapshotsOf(const QSignalSpy &spy)
{
    QList<oi::SensorSnapshot> out;
    for (const QList<QVariant> &args : spy)
        out << args.at(0).value<oi::SensorSnapshot>();
    return out;
}

// Records the virtual Create 2 for kFrames frames; returns the snapshots the
// link emitted while it recorded.
QList<oi::SensorSnapshot> recordVirtualRobot(const QString &path)
{
    RobotLink link;
    link.setTransportFactory(transports::transportFactory());
    QSignalSpy snapshots(&link, &RobotLink::snapshot);
    link.open(LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
    link.startRecording(path);
    if (!QTest::qWaitFor([&] { return snapshots.size() >= kFrames; }, kTimeoutMs))
        return {};
    link.close(); // stops the recording after the stop bytes
    return snapshotsOf(snapshots);
}

Recording load(const QString &path)
{
    QString error;
    std::optional<Recording> r = Recording::load(path, &error);
    if (!r)
        qFatal("cannot load %s: %s", qPrintable(path), qPrintable(error));
    return *r;
}

QByteArray fileBytes(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    QCOMPARE(f.write(bytes), bytes.size());
}

// Where the first record starts: after magic, version, header length, header.
qsizetype firstRecordOffset(const QByteArray &file)
{
    return 14 + qFromLittleEndian<quint32>(file.constData() + 10);
}

QList<oi::SensorSnapshot> parse(const Recording &r, const QByteArray &bytes)
{
    QList<oi::SensorSnapshot> out;
    oi::StreamParser parser(r.robotProfile());
    parser.setSnapshotHandler([&](const oi::SensorSnapshot &s, oi::FrameKind) { out << s; });
    parser.feed({reinterpret_cast<const std::uint8_t *>(bytes.constData()), static_cast<std::size_t>(bytes.size())});
    return out;
}

// The recording's CSV, line by line.
QStringList csvLines(const Recording &r)
{
    QString csv;
    QTextStream out(&csv);
    r.writeCsv(out);
    out.flush();
    return csv.split('\n', Qt::SkipEmptyParts);
}

QList<oi::SensorSnapshot> allSnapshots(const Recording &r)
{
    QList<oi::SensorSnapshot> out;
    r.forEachSnapshot([&](qint64, const oi::SensorSnapshot &s) { out << s; });
    return out;
}

// Plays `path` on `link` at ten times its speed until `statuses` (the
// link's replayStatus()) says it finished.
void replayToTheEnd(RobotLink &link, const QString &path, QSignalSpy &statuses)
{
    const Recording r = load(path);
    link.open(LinkSettings::replayOf(path, r.robotProfile().id, r.stream().baud, r.stream().packets));
    link.controlReplay(ReplayCommand::setSpeed(10));
    QTRY_VERIFY_WITH_TIMEOUT(!statuses.isEmpty() && statuses.last().at(0).value<ReplayStatus>().finished,
                             kTimeoutMs);
}
} // namespace

class TestRecording : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { oilink::registerLinkMetaTypes(); }

    void checksumIsQtsChecksum()
    {
        // Files written with qChecksum are read with recording::checksum.
        std::mt19937 random(7);
        for (int size = 0; size < 300; ++size) {
            QByteArray bytes(size, Qt::Uninitialized);
            for (char &c : bytes)
                c = char(random());
            QCOMPARE(oilink::recording::checksum(bytes), qChecksum(bytes));
        }
    }

    void writerAndReaderAgree()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("a.oirec");
        RecordingWriter writer;
        QVERIFY2(writer.open(path, {{"link", "test"}}), qPrintable(writer.errorString()));
        QVERIFY(writer.append(RecordKind::Sent, QByteArray("\x80\x83", 2)));
        QVERIFY(writer.appendStreamStarted(oi::ProfileId::Create2, 115200, {7}));
        // One Stream frame for packet 7 (bumps = 3), split over two records.
        QVERIFY(writer.append(RecordKind::Received, QByteArray("\x13\x02\x07", 3)));
        QVERIFY(writer.append(RecordKind::Received, QByteArray("\x03\xE1", 2)));
        writer.close();

        const Recording r = load(path);
        QCOMPARE(r.header().value("link").toString(), QString("test"));
        QCOMPARE(r.header().value("version").toInt(), int(oilink::recording::kVersion));
        QCOMPARE(r.robotProfile().id, oi::ProfileId::Create2);
        QCOMPARE(r.stream().baud, 115200);
        QCOMPARE(r.stream().packets, QList<int>{7});
        QCOMPARE(r.recordCount(), 4);
        QCOMPARE(r.bytesSent(), 2);
        QCOMPARE(r.receivedBytes(), QByteArray("\x13\x02\x07\x03\xE1", 5));
        QCOMPARE(r.frames().size(), std::size_t(1));
        QCOMPARE(r.frames()[0].end, qsizetype(5));
        QVERIFY(!r.damage());
        const QList<oi::SensorSnapshot> s = allSnapshots(r);
        QCOMPARE(s.size(), 1);
        QCOMPARE(s[0].raw(7), 3);
    }

    void longPayloadsAreSplit()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("long.oirec");
        RecordingWriter writer;
        QVERIFY(writer.open(path, {}));
        QVERIFY(writer.appendStreamStarted(oi::ProfileId::Create2, 115200, {7}));
        QVERIFY(writer.append(RecordKind::Received, QByteArray(70000, 'x')));
        writer.close();
        const Recording r = load(path);
        QCOMPARE(r.receivedBytes().size(), 70000);
        QCOMPARE(r.recordCount(), 3);
    }

    // `started` keeps whole milliseconds; `started` plus a record's time is
    // still the wall time the record was written, to well under one, so a
    // reader comparing it with its own clock (a stop's latency) is not off
    // by up to a millisecond. Many files: each truncates `started` differently.
    void recordTimesAreWallTimes()
    {
        using namespace std::chrono;
        const auto wallUs = [] { return duration_cast<microseconds>(system_clock::now().time_since_epoch()).count(); };
        QTemporaryDir dir;
        for (int i = 0; i < 20; ++i) {
            const QString path = dir.filePath(QStringLiteral("t%1.oirec").arg(i));
            RecordingWriter writer;
            QVERIFY(writer.open(path, {}));
            QVERIFY(writer.appendStreamStarted(oi::ProfileId::Create2, 115200, {7}));
            const qint64 before = wallUs();
            QVERIFY(writer.append(RecordKind::Sent, QByteArray("\x89\0\0\0\0", 5)));
            const qint64 after = wallUs();
            writer.close();
            const Recording r = load(path);
            const QDateTime started = QDateTime::fromString(r.header().value("started").toString(), Qt::ISODateWithMs);
            QVERIFY(started.isValid());
            QCOMPARE(r.sentChunks().size(), std::size_t(1));
            const qint64 written = started.toMSecsSinceEpoch() * 1000 + r.sentChunks()[0].timeUs;
            constexpr qint64 kSlackUs = 50; // the clocks' reading, not the header's rounding
            QVERIFY2(written >= before - kSlackUs && written <= after + kSlackUs,
                     qPrintable(QStringLiteral("written at %1 µs, appended between %2 and %3")
                                    .arg(written).arg(before).arg(after)));
        }
    }

    void flushedWhileRecording()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("live.oirec");
        RobotLink link;
        link.setTransportFactory(transports::transportFactory());
        QSignalSpy status(&link, &RobotLink::recordingStatus);
        link.open(LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        link.startRecording(path);
        QVERIFY(!status.isEmpty());
        QVERIFY(status.last().at(0).value<oilink::RecordingStatus>().active);
        // Without closing anything, frames reach the disk: what a crash would leave.
        QTRY_VERIFY_WITH_TIMEOUT(fileBytes(path).size() > 2000, kTimeoutMs);
        QString error;
        const std::optional<Recording> partial = Recording::load(path, &error);
        QVERIFY2(partial, qPrintable(error));
        QVERIFY(!partial->frames().empty());
        link.stopRecording();
        QVERIFY(!status.last().at(0).value<oilink::RecordingStatus>().active);
        QVERIFY(status.last().at(0).value<oilink::RecordingStatus>().error.isEmpty());
    }

    void unwritablePathIsReported()
    {
        RobotLink link;
        link.setTransportFactory(transports::transportFactory());
        QSignalSpy status(&link, &RobotLink::recordingStatus);
        link.startRecording("/nonexistent-dir/x.oirec");
        QCOMPARE(status.size(), 1);
        const auto s = status.at(0).at(0).value<oilink::RecordingStatus>();
        QVERIFY(!s.active);
        QVERIFY2(s.error.contains("cannot create the recording"), qPrintable(s.error));
    }

    void recordThenReplayGivesIdenticalSnapshots()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("run.oirec");
        const QList<oi::SensorSnapshot> live = recordVirtualRobot(path);
        QVERIFY(live.size() >= kFrames);
        const Recording r = load(path);
        QCOMPARE(int(r.frames().size()), live.size());
        QVERIFY(r.bytesSent() > 0);

        RobotLink replay;
        QSignalSpy snapshots(&replay, &RobotLink::snapshot);
        QSignalSpy statuses(&replay, &RobotLink::replayStatus);
        replayToTheEnd(replay, path, statuses);
        QCOMPARE(snapshotsOf(snapshots), live);
        const ReplayStatus last = statuses.last().at(0).value<ReplayStatus>();
        QCOMPARE(last.frame, live.size() - 1);
        QCOMPARE(last.frameCount, live.size());
        QVERIFY(last.damage.isEmpty());
    }

    // A replay that ends falls silent by design: however long the link
    // waits (on the test's clock) it wakes no robot, sends nothing and says
    // nothing of a robot asleep; the replay's own status says it finished.
    void aReplaysEndIsNotARobotAsleep()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("run.oirec");
        QVERIFY(recordVirtualRobot(path).size() >= kFrames);
        ManualClock clock;
        RobotLink replay(clock);
        QSignalSpy statuses(&replay, &RobotLink::replayStatus);
        QSignalSpy errors(&replay, &RobotLink::errorOccurred);
        QSignalSpy states(&replay, &RobotLink::stateChanged);
        replayToTheEnd(replay, path, statuses);
        QSignalSpy sent(&replay, &RobotLink::rawBytesSent);
        for (int ms = 0; ms < 30'000; ms += 15) {
            clock.advance(15);
            QCoreApplication::processEvents();
        }
        // The watchdog ran: the data is no longer fresh.
        QCOMPARE(states.last().at(0).value<oilink::LinkState>(), oilink::LinkState::Stale);
        QVERIFY2(errors.isEmpty(), qPrintable(errors.isEmpty() ? QString() : errors.first().first().toString()));
        QCOMPARE(sent.count(), 0);
    }

    void seekAndStepLandOnWholeFrames()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("run.oirec");
        QVERIFY(!recordVirtualRobot(path).isEmpty());
        const Recording r = load(path);
        const QList<oi::SensorSnapshot> all = allSnapshots(r);
        QVERIFY(all.size() >= kFrames);

        ReplayTransport replay(path);
        QByteArray delivered;
        connect(&replay, &oilink::Transport::bytesReceived, [&](const QByteArray &b) { delivered += b; });
        replay.open();
        replay.controlReplay(ReplayCommand::pause());
        const int middle = all.size() / 2;
        delivered.clear();
        replay.controlReplay(ReplayCommand::seek(r.frames()[middle].timeUs));
        QCOMPARE(parse(r, delivered), QList<oi::SensorSnapshot>{all[middle]});
        QCOMPARE(replay.status().frame, middle);
        QCOMPARE(replay.status().positionUs, r.frames()[middle].timeUs);

        delivered.clear();
        replay.controlReplay(ReplayCommand::step(1));
        QCOMPARE(parse(r, delivered), QList<oi::SensorSnapshot>{all[middle + 1]});
        delivered.clear();
        replay.controlReplay(ReplayCommand::step(-1));
        QCOMPARE(parse(r, delivered), QList<oi::SensorSnapshot>{all[middle]});
        QVERIFY(!replay.status().playing);

        // Stepping stops at the ends rather than wrapping.
        replay.controlReplay(ReplayCommand::step(-10000));
        QCOMPARE(replay.status().frame, 0);
        replay.controlReplay(ReplayCommand::step(10000));
        QCOMPARE(replay.status().frame, all.size() - 1);
    }

    void speedStaysWithinItsRange()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("run.oirec");
        QVERIFY(!recordVirtualRobot(path).isEmpty());
        ReplayTransport replay(path);
        replay.open();
        replay.controlReplay(ReplayCommand::setSpeed(0.25));
        QCOMPARE(replay.status().speed, 0.25);
        replay.controlReplay(ReplayCommand::setSpeed(10));
        QCOMPARE(replay.status().speed, 10.0);
        replay.controlReplay(ReplayCommand::setSpeed(20));
        QCOMPARE(replay.status().speed, 10.0);
        replay.controlReplay(ReplayCommand::setSpeed(0.1));
        QCOMPARE(replay.status().speed, 10.0);
    }

    void truncatedRecordingReplaysUpToTheDamage()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("run.oirec");
        QVERIFY(!recordVirtualRobot(path).isEmpty());
        const QByteArray whole = fileBytes(path);
        const Recording intact = load(path);
        const QString cut = dir.filePath("cut.oirec");
        writeFile(cut, whole.left(whole.size() * 2 / 3));

        const Recording r = load(cut);
        QVERIFY(r.damage());
        QCOMPARE(r.damage()->reason, QString("truncated record"));
        QVERIFY(r.damage()->byteOffset < whole.size() * 2 / 3);
        QVERIFY(r.frames().size() > 10);
        QVERIFY(r.frames().size() < intact.frames().size());
        // What remains is exactly the start of the intact recording.
        const QList<oi::SensorSnapshot> head = allSnapshots(r);
        QCOMPARE(head, allSnapshots(intact).mid(0, head.size()));

        RobotLink replay;
        QSignalSpy snapshots(&replay, &RobotLink::snapshot);
        QSignalSpy statuses(&replay, &RobotLink::replayStatus);
        replay.open(LinkSettings::replayOf(cut, r.robotProfile().id, r.stream().baud, r.stream().packets));
        replay.controlReplay(ReplayCommand::setSpeed(10));
        QTRY_VERIFY_WITH_TIMEOUT(!statuses.isEmpty() && statuses.last().at(0).value<ReplayStatus>().finished,
                                 kTimeoutMs);
        QCOMPARE(snapshots.size(), head.size());
        const QString damage = statuses.last().at(0).value<ReplayStatus>().damage;
        QVERIFY2(damage.contains(QString("at byte %1").arg(r.damage()->byteOffset)), qPrintable(damage));
    }

    void corruptedRecordIsFound()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("run.oirec");
        QVERIFY(!recordVirtualRobot(path).isEmpty());
        QByteArray bytes = fileBytes(path);
        const qsizetype flipped = firstRecordOffset(bytes) + (bytes.size() - firstRecordOffset(bytes)) / 2;
        bytes[flipped] = static_cast<char>(bytes[flipped] ^ 0x5A);
        const QString bad = dir.filePath("bad.oirec");
        writeFile(bad, bytes);

        const Recording r = load(bad);
        QVERIFY(r.damage());
        QVERIFY2(r.damage()->reason == "checksum mismatch" || r.damage()->reason.startsWith("unknown record type")
                     || r.damage()->reason == "truncated record",
                 qPrintable(r.damage()->reason));
        // The damaged record starts at or before the flipped byte, and within one record of it.
        QVERIFY(r.damage()->byteOffset <= flipped);
        QVERIFY(flipped - r.damage()->byteOffset < 11 + 0xFFFF + 2);
        QVERIFY(!r.frames().empty());
    }

    void unusableFilesAreRefusedWithAReason_data()
    {
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("reason");
        QTest::newRow("empty") << QByteArray() << "not a Roomba Dashboard recording";
        QTest::newRow("text") << QByteArray("time,wall\n0,1\n") << "not a Roomba Dashboard recording";
        QByteArray v4("OIRECORD\x04\x00\x02\x00\x00\x00{}", 16);
        QTest::newRow("newer version") << v4 << "recording format version 4; this program reads versions 1 to 3";
        QByteArray cutHeader("OIRECORD\x01\x00\xFF\x00\x00\x00{", 15);
        QTest::newRow("truncated header") << cutHeader << "header is truncated";
        QByteArray badJson("OIRECORD\x01\x00\x02\x00\x00\x00{x", 16);
        QTest::newRow("bad header") << badJson << "not valid JSON";
        QByteArray noStream("OIRECORD\x01\x00\x02\x00\x00\x00{}", 16);
        QTest::newRow("no stream") << noStream << "no sensor stream";
    }

    void unusableFilesAreRefusedWithAReason()
    {
        QFETCH(QByteArray, content);
        QFETCH(QString, reason);
        QTemporaryDir dir;
        const QString path = dir.filePath("x.oirec");
        writeFile(path, content);
        QString error;
        QVERIFY(!Recording::load(path, &error));
        QVERIFY2(error.contains(reason), qPrintable(error));
        QVERIFY(error.startsWith(path));
        // A replay of it fails to open with the same reason.
        ReplayTransport replay(path);
        QSignalSpy errors(&replay, &oilink::Transport::errorOccurred);
        replay.open();
        QCOMPARE(errors.size(), 1);
        QCOMPARE(errors.at(0).at(0).toString(), error);
        QVERIFY(!replay.isOpen());
    }

    // A robot with firmware 3.4.0, reset while recorded, then turning: the
    // banner in the recording names the firmware, so the CSV has the angle
    // in degrees (ERRATA 16), as the dashboard showed it.
    void csvCorrectsTheAngleByTheRecordedBanner()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("old.oirec");
        RobotLink link;
        link.setTransportFactory([](const LinkSettings &settings) {
            auto *t = new sim::VirtualTransport(settings.virtualRobot, settings.virtualSeed);
            QObject::connect(t, &oilink::Transport::opened, t,
                             [t] { t->robot()->robot().setFirmwareRelease("release-3.4.0"); });
            return t;
        });
        QSignalSpy snapshots(&link, &RobotLink::snapshot);
        QSignalSpy states(&link, &RobotLink::stateChanged);
        link.open(LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QVERIFY(snapshots.wait(kTimeoutMs));
        link.startRecording(path);
        states.clear();
        link.send(commandsOf(QByteArray(1, char(7))));
        // The reboot stops the stream; the link starts the robot again. Then
        // Safe, and turn in place at full speed.
        QTRY_VERIFY_WITH_TIMEOUT(!states.isEmpty() && states.last().at(0).value<oilink::LinkState>()
                                                          == oilink::LinkState::Streaming, kTimeoutMs);
        link.send(commandsOf(QByteArray::fromHex("838901F40001")));
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(snapshotsOf(snapshots).last().angleDegrees()) > 0, kTimeoutMs);
        snapshots.clear();
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.size() >= 20, kTimeoutMs);
        link.close();

        const Recording r = load(path);
        const QStringList lines = csvLines(r);
        const int angle = lines[0].split(QLatin1Char(',')).indexOf("angle[deg]");
        QVERIFY(angle > 0);
        const QList<oi::SensorSnapshot> raw = allSnapshots(r);
        QCOMPARE(lines.size(), raw.size() + 1);
        int turning = 0;
        for (qsizetype i = 0; i < raw.size(); ++i) {
            const int expected = int(std::lround(raw[i].angleDegrees() / 0.324056));
            QCOMPARE(lines[i + 1].split(',')[angle].toInt(), expected);
            turning += expected != raw[i].angleDegrees();
        }
        QVERIFY(turning > 5);
    }

    // A file the previous program wrote (format version 1, a few seconds of
    // the virtual Create 2) still opens whole, and takes markers.
    void versionOneRecordingsStillOpen()
    {
        const QString fixture = QStringLiteral(ROOMBA_TEST_DATA "/version1.oirec");
        QCOMPARE(qFromLittleEndian<quint16>(fileBytes(fixture).constData() + 8), quint16(1));
        const Recording r = load(fixture);
        QVERIFY(!r.damage());
        QCOMPARE(r.robotProfile().id, oi::ProfileId::Create2);
        QCOMPARE(r.frames().size(), std::size_t(257));
        QVERIFY(r.markers().isEmpty());

        QTemporaryDir dir;
        const QString path = dir.filePath("old.oirec");
        QVERIFY(QFile::copy(fixture, path));
        QString error;
        QVERIFY2(Recording::saveMarkerEdits(path, {MarkerEdit::add({1, 500000, "half a second"})}, &error),
                 qPrintable(error));
        const QByteArray after = fileBytes(path);
        QCOMPARE(qFromLittleEndian<quint16>(after.constData() + 8), oilink::recording::kVersion);
        const Recording marked = load(path);
        QVERIFY(!marked.damage());
        QCOMPARE(marked.receivedBytes(), r.receivedBytes());
        QCOMPARE(marked.sentBytes(), r.sentBytes());
        QCOMPARE(marked.markers(), (QList<RecordingMarker>{{1, 500000, "half a second"}}));
    }

    // Markers written while recording, then added, renamed and deleted in
    // the file, read back in time order with their last notes.
    void markersSurviveWritingAndEditing()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("m.oirec");
        RecordingWriter writer;
        QVERIFY(writer.open(path, {}));
        QVERIFY(writer.appendStreamStarted(oi::ProfileId::Create2, 115200, {7}));
        QVERIFY(writer.appendMarkerEdit(MarkerEdit::add({1, 0, "start"})));
        QVERIFY(writer.append(RecordKind::Received, QByteArray("\x13\x02\x07\x03\xE1", 5)));
        QVERIFY(writer.appendMarkerEdit(MarkerEdit::add({2, 0, ""})));
        QVERIFY(writer.appendMarkerEdit(MarkerEdit::rename(1, "the start")));
        writer.close();
        QCOMPARE(load(path).markers(), (QList<RecordingMarker>{{1, 0, "the start"}, {2, 0, ""}}));

        QString error;
        QVERIFY(Recording::saveMarkerEdits(path,
                                           {MarkerEdit::remove(1), MarkerEdit::add({3, 0, "hit, \"hard\""}),
                                            MarkerEdit::rename(9, "no such marker"),
                                            MarkerEdit::add({4, 10000000, "after the frames"})},
                                           &error));
        const Recording r = load(path);
        QVERIFY(!r.damage());
        QCOMPARE(r.markers(), (QList<RecordingMarker>{{2, 0, ""}, {3, 0, "hit, \"hard\""}, {4, 10000000, "after the frames"}}));
        QCOMPARE(r.markers()[0].label(), QString("#2"));
        QCOMPARE(r.recordCount(), 9);
        // In the CSV: on the frame at or after each marker, quoted as CSV
        // quotes; one after the last frame on a row of its own.
        const QStringList lines = csvLines(r);
        QCOMPARE(lines[0], QString("time_s,bumps_wheel_drops,marker"));
        QCOMPARE(lines.size(), 3);
        QVERIFY2(lines[1].endsWith(",3,\"#2; hit, \"\"hard\"\"\""), qPrintable(lines[1]));
        QCOMPARE(lines[2], QString("10,,after the frames"));
    }

    // An intact file takes a marker on its end: the same file, grown by the
    // marker's record, not a copy written anew.
    void aMarkerIsAppendedToAnIntactFile()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("a.oirec");
        RecordingWriter writer;
        QVERIFY(writer.open(path, {}));
        QVERIFY(writer.appendStreamStarted(oi::ProfileId::Create2, 115200, {7}));
        QVERIFY(writer.append(RecordKind::Received, QByteArray("\x13\x02\x07\x03\xE1", 5)));
        writer.close();
        const QByteArray before = fileBytes(path);
        struct stat was {};
        QCOMPARE(::stat(QFile::encodeName(path).constData(), &was), 0);

        QString error;
        QVERIFY2(Recording::saveMarkerEdits(path, {MarkerEdit::add({1, 0, "here"})}, &error), qPrintable(error));
        struct stat is {};
        QCOMPARE(::stat(QFile::encodeName(path).constData(), &is), 0);
        QCOMPARE(is.st_ino, was.st_ino);
        const QByteArray after = fileBytes(path);
        QVERIFY(after.startsWith(before));
        const Recording r = load(path);
        QVERIFY(!r.damage());
        QCOMPARE(r.markers(), (QList<RecordingMarker>{{1, 0, "here"}}));
        QCOMPARE(r.frames().size(), std::size_t(1));
    }

    // A damaged tail is kept; the new markers go before it, where they are read.
    void markersGoBeforeADamagedTail()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("d.oirec");
        RecordingWriter writer;
        QVERIFY(writer.open(path, {}));
        QVERIFY(writer.appendStreamStarted(oi::ProfileId::Create2, 115200, {7}));
        QVERIFY(writer.append(RecordKind::Received, QByteArray("\x13\x02\x07\x03\xE1", 5)));
        writer.close();
        QByteArray bytes = fileBytes(path);
        const QByteArray tail("R\x01\x02", 3); // a record cut short
        bytes += tail;
        writeFile(path, bytes);

        QString error;
        QVERIFY(Recording::saveMarkerEdits(path, {MarkerEdit::add({1, 7, "before the damage"})}, &error));
        const QByteArray after = fileBytes(path);
        QVERIFY(after.endsWith(tail));
        const Recording r = load(path);
        QCOMPARE(r.markers().size(), 1);
        QVERIFY(r.damage());
        QCOMPARE(r.damage()->byteOffset, after.size() - tail.size());
    }

    void unreadableMarkerIsDamage()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("u.oirec");
        RecordingWriter writer;
        QVERIFY(writer.open(path, {}));
        QVERIFY(writer.appendStreamStarted(oi::ProfileId::Create2, 115200, {7}));
        QVERIFY(writer.append(RecordKind::Marker, "{\"op\":\"move\",\"id\":1}"));
        writer.close();
        const Recording r = load(path);
        QVERIFY(r.damage());
        QCOMPARE(r.damage()->reason, QString("unreadable marker"));
    }

    // A file of the format before true poses (version 2, with a marker) opens whole.
    void versionTwoRecordingsStillOpen()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("v2.oirec");
        writeFile(path, oirecHeader(2, R"({"format":"Roomba Dashboard recording","version":2})")
                            + oirecRecord('S', 0, R"({"profile":"create2","baud":115200,"packets":[7]})")
                            + oirecRecord('R', 15000, QByteArray("\x13\x02\x07\x03\xE1", 5))
                            + oirecRecord('M', 15000, R"({"op":"add","id":1,"time_us":0,"note":"go"})"));
        const Recording r = load(path);
        QVERIFY(!r.damage());
        QCOMPARE(r.frames().size(), std::size_t(1));
        QCOMPARE(r.markers(), (QList<RecordingMarker>{{1, 0, "go"}}));
        QVERIFY(r.truePoses().empty());
    }

    // Each frame of a virtual robot is followed by where the robot truly is
    // in its room: the pose the room holds when the link hands the frame on.
    void virtualRobotRecordsItsTruePose()
    {
        auto room = std::make_shared<sim::Room>(sim::World::classroom());
        const sim::RobotId id = room->placeNewRobot();
        QTemporaryDir dir;
        const QString path = dir.filePath("true.oirec");
        RobotLink link;
        link.setTransportFactory(transports::transportFactory(room, id));
        QSignalSpy snapshots(&link, &RobotLink::snapshot);
        link.open(LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QVERIFY(snapshots.wait(kTimeoutMs));
        link.startRecording(path);
        std::vector<oi::Pose> seen;
        connect(&link, &RobotLink::snapshot, this, [&] { seen.push_back(room->robot(id)->pose); });
        link.send(commandsOf(QByteArray("\x83\x89\x00\xC8\x80\x00", 6))); // Safe, straight ahead at 200 mm/s
        QTRY_VERIFY_WITH_TIMEOUT(seen.size() >= 30, kTimeoutMs);
        link.close();

        const Recording r = load(path);
        QVERIFY(!r.damage());
        QCOMPARE(r.truePoses().size(), seen.size());
        for (std::size_t i = 0; i < seen.size(); ++i) {
            QCOMPARE(r.truePoses()[i].pose.xMm, seen[i].xMm);
            QCOMPARE(r.truePoses()[i].pose.yMm, seen[i].yMm);
            QCOMPARE(r.truePoses()[i].pose.thetaRad, seen[i].thetaRad);
        }
        QVERIFY2(std::hypot(seen.back().xMm - seen.front().xMm, seen.back().yMm - seen.front().yMm) > 20,
                 "the robot did not move");
        QVERIFY(r.truePoses().front().timeUs >= r.frames().front().timeUs);
        QVERIFY(r.truePoses().back().timeUs <= r.durationUs());
    }

    void truePoseOfTheWrongSizeIsDamage()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("p.oirec");
        RecordingWriter writer;
        QVERIFY(writer.open(path, {}));
        QVERIFY(writer.appendStreamStarted(oi::ProfileId::Create2, 115200, {7}));
        QVERIFY(writer.appendTruePose({1.5, -2.25, 0.5}));
        QVERIFY(writer.append(RecordKind::TruePose, QByteArray(16, 0)));
        writer.close();
        const Recording r = load(path);
        QCOMPARE(r.truePoses().size(), std::size_t(1));
        QCOMPARE(r.truePoses()[0].pose.yMm, -2.25);
        QVERIFY(r.damage());
        QCOMPARE(r.damage()->reason, QString("unreadable true pose"));
    }

    // A file that cannot be read is left as it was, with the reason.
    void markersIntoAnUnreadableFileAreRefused()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("x.oirec");
        writeFile(path, "not a recording");
        QString error;
        QVERIFY(!Recording::saveMarkerEdits(path, {MarkerEdit::add({1, 0, "x"})}, &error));
        QVERIFY2(error.contains("not a Roomba Dashboard recording"), qPrintable(error));
        QCOMPARE(fileBytes(path), QByteArray("not a recording"));
    }

    // A stream description is what the robot can send, or the file is
    // refused with why: group 100 named 2,000 times made each CSV row
    // 100,000 empty cells, 2.6 GB from a 1.2 MB file.
    void aStreamNoRobotSendsIsRefused_data()
    {
        QTest::addColumn<QByteArray>("stream");
        QTest::addColumn<QString>("why");
        QByteArray twoThousand = "100";
        for (int i = 1; i < 2000; ++i)
            twoThousand += ",100";
        QTest::newRow("group 100, 2,000 times")
            << R"({"profile":"create2","baud":115200,"packets":[)" + twoThousand + "]}"
            << "number of packets: 2000 is outside 0..108";
        QTest::newRow("a packet twice") << QByteArray(R"({"profile":"create2","baud":115200,"packets":[7,22,7]})")
                                        << "packet 7 is in it twice";
        QTest::newRow("a packet and its group") << QByteArray(R"({"profile":"create2","baud":115200,"packets":[1,7]})")
                                                << "packet 7 is in it twice";
        QTest::newRow("two groups that overlap") << QByteArray(R"({"profile":"create2","baud":115200,"packets":[100,6]})")
                                                 << "packet 7 is in it twice";
        QTest::newRow("a frame too long for its baud")
            << QByteArray(R"({"profile":"create2","baud":19200,"packets":[100]})")
            << "stream frame size: a frame of 84 bytes does not fit in 15 ms at 19200 baud (at most 28 bytes)";
    }

    void aStreamNoRobotSendsIsRefused()
    {
        QFETCH(QByteArray, stream);
        QFETCH(QString, why);
        QByteArray file = oirecHeader(3, R"({"format":"Roomba Dashboard recording","version":3})");
        file += oirecRecord('S', 0, stream);
        for (int i = 0; i < 100; ++i) // tiny frames of packet 7 alone
            file += oirecRecord('R', 15000 * i, QByteArray("\x13\x02\x07\x00\xE4", 5));
        QString error;
        QVERIFY(!Recording::fromBytes(file, "run.oirec", &error));
        QCOMPARE(error, "run.oirec: damaged before the stream started: a stream no robot sends (" + why +
                            ") at byte 65 (record 0, after 0.000 s)");
    }

    // The first 1,000 markers a file adds are read, the rest counted: 60,000
    // froze the window for 43 s. No marker is added beyond them.
    void aRecordingKeepsItsFirstThousandMarkers()
    {
        // A rename of a marker left out changes nothing; of one kept, its note.
        const QByteArray file = crowdedRecording(oilink::kMaxMarkers + 500)
                                + oirecRecord('M', 0, MarkerEdit::rename(oilink::kMaxMarkers + 1, "left out").toJson())
                                + oirecRecord('M', 0, MarkerEdit::rename(1, "first").toJson());
        QString error;
        const Recording r = *Recording::fromBytes(file, "m.oirec", &error);
        QVERIFY(!r.damage());
        QCOMPARE(r.markers().size(), oilink::kMaxMarkers);
        QCOMPARE(r.markersLeftOut(), 500);
        QCOMPARE(r.markers().first().note, QString("first"));
        QCOMPARE(r.markers().last().id, oilink::kMaxMarkers);
        QCOMPARE(oilink::markersLeftOutNotice(r.markersLeftOut()),
                 QString("500 markers beyond the first 1000 were left out: a recording holds at most 1000"));
        QList<RecordingMarker> markers = r.markers();
        QVERIFY(!oilink::applyMarkerEdit(markers, MarkerEdit::add({5000, 0, "one more"})));
        QCOMPARE(markers, r.markers());
    }

    // A recording is read only as a regular file of at most 1 GB: a named
    // pipe blocked the window for good, /dev/zero was read until memory ran out.
    void aFileThatIsNoRecordingIsRefusedUnread()
    {
        QTemporaryDir dir;
        const QString big = dir.filePath("big.oirec");
        QFile file(big);
        QVERIFY(file.open(QIODevice::WriteOnly) && file.resize(oilink::recording::kMaxFileBytes + 1)); // sparse
        file.close();
        const NotRegularFiles no = makeNotRegularFiles(dir.path(), "oirec");
        QVERIFY(!no.pipe.isEmpty());
        // Each of the three readers: the whole file, its stream, its markers.
        const auto refusedBy = [](const QString &path) {
            QStringList errors(3);
            const bool none = !Recording::load(path, &errors[0]) && !Recording::readStream(path, &errors[1])
                              && !Recording::saveMarkerEdits(path, {MarkerEdit::add({1, 0, "x"})}, &errors[2]);
            return none ? errors : QStringList();
        };
        QCOMPARE(refusedBy(big),
                 QStringList(3, big + ": 1073741825 bytes, larger than the 1 GB this program reads of such a file"));
        QCOMPARE(QFileInfo(big).size(), oilink::recording::kMaxFileBytes + 1);
        QCOMPARE(refusedBy(no.device), QStringList(3, no.device + ": not a regular file but a device"));
        QCOMPARE(refusedBy(no.pipe), QStringList(3, no.pipe + ": not a regular file but a named pipe"));
    }

    void csvHasOneRowPerFrame()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("run.oirec");
        QVERIFY(!recordVirtualRobot(path).isEmpty());
        const Recording r = load(path);
        const QStringList lines = csvLines(r);
        QCOMPARE(lines.size(), int(r.frames().size()) + 1);
        const QStringList columns = lines[0].split(',');
        QCOMPARE(columns.first(), QString("time_s"));
        // Group 100: packets 7..58, but for the three the document reserves
        // (16, 32, 33: always 0); no markers, no marker column.
        QCOMPARE(columns.size(), 1 + 52 - 3);
        QVERIFY(!lines[0].contains("unused"));
        QCOMPARE(columns[1], QString("bumps_wheel_drops"));
        const int voltage = columns.indexOf("voltage[mV]");
        QVERIFY(voltage > 0);
        const QList<oi::SensorSnapshot> all = allSnapshots(r);
        const QStringList row = lines[5].split(',');
        QCOMPARE(row.size(), columns.size());
        QCOMPARE(row[voltage].toInt(), all[4].raw(22));
        QCOMPARE(row[0].toDouble(), double(r.frames()[4].timeUs) / 1e6);
    }
};

QTEST_GUILESS_MAIN(TestRecording)
#include "tst_recording.moc"
