// SPDX-License-Identifier: GPL-3.0-or-later
// A recording exported as MCAP: what each channel holds, read back by the
// official reader (@mcap/core, installed with npm) and by our own record
// walker; damaged recordings; paths that cannot be written; roomba-ctl mcap.
#include "mcap_records.h"
#include "typed_command_bytes.h"
#include "npm_packages.h" // tests/common
#include "oirec_records.h" // tests/common
#include "recording_mcap.h"
#include "robot_link.h"
#include "snapshot_json.h"
#include "stream_frames.h"
#include "transport_factory.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QtEndian>

#include <set>

using oilink::Recording;

namespace {
constexpr int kTimeoutMs = 15000;

QByteArray fileBytes(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeFile(const QString &path, const QByteArray &bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

Recording load(const QString &path)
{
    QString error;
    std::optional<Recording> r = Recording::load(path, &error);
    if (!r)
        qFatal("cannot load %s: %s", qPrintable(path), qPrintable(error));
    return *r;
}

// A Create 2 streaming group 100 every 15 ms from 2026-01-02 03:04:05 UTC:
// frame i has the bumps and mode `frame(i)` gives; Safe is sent at the start.
QByteArray syntheticRecording(int frames, const std::function<std::pair<int, int>(int)> &frame)
{
    QByteArray file = oirecHeader(1, R"({"format":"Roomba Dashboard recording","version":1,)"
                                     R"("started":"2026-01-02T03:04:05.000Z","link":"test"})");
    file += oirecRecord('T', 0, bytes({128, 131}));
    file += oirecRecord('S', 0, R"({"profile":"create2","baud":115200,"packets":[100]})");
    for (int i = 0; i < frames; ++i) {
        const auto [bumps, mode] = frame(i);
        file += oirecRecord('R', 15000 * (i + 1), group100Frame(std::uint8_t(bumps), mode));
    }
    return file;
}

constexpr quint64 kSyntheticStartNs = 1767323045000000000ull; // 2026-01-02T03:04:05Z

// The events channel's messages, in order, from an uncompressed export.
QStringList eventsOf(const QByteArray &mcapFile, quint16 channel)
{
    QStringList out;
    for (const mcap_test::Message &m : mcap_test::messagesOf(mcapFile))
        if (m.channel == channel)
            out << QJsonDocument::fromJson(m.data).object().value("message").toString();
    return out;
}

// Channel ids by topic, from the summary of a file.
QMap<QString, quint16> channelsOf(const QByteArray &mcapFile)
{
    QMap<QString, quint16> out;
    for (const mcap_test::Record &r : mcap_test::fileRecords(mcapFile))
        if (r.opcode == 0x04) {
            mcap_test::Fields f(r.content);
            const auto id = f.get<quint16>();
            f.get<quint16>();
            out.insert(f.string(), id);
        }
    return out;
}

} // namespace

class TestMcapExport : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QString m_recording; // on the virtual robot, driving
    QString m_readerDir; // node_modules with @mcap/core, and read_mcap.js

    // The official reader's account of `path`, as read_mcap.js prints it.
    QJsonObject readWithMcapCore(const QString &path)
    {
        const ProcessRun r =
            runProcess(QStringLiteral("node"), {QDir(m_readerDir).filePath("read_mcap.js"), path}, m_readerDir);
        if (r.exitCode != 0)
            qWarning("read_mcap.js: %s", r.err.constData());
        return QJsonDocument::fromJson(r.out).object();
    }

private slots:
    void initTestCase()
    {
        oilink::registerLinkMetaTypes();
        QVERIFY(m_dir.isValid());
        // A run on the virtual Create 2: Passive, then Safe and straight ahead.
        m_recording = m_dir.filePath("run.oirec");
        oilink::RobotLink link;
        link.setTransportFactory(transports::transportFactory());
        QSignalSpy snapshots(&link, &oilink::RobotLink::snapshot);
        link.open(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, oi::ProfileId::Create2));
        QVERIFY(snapshots.wait(kTimeoutMs));
        link.startRecording(m_recording);
        link.markRecording(oilink::MarkerEdit::add({1, 0, "start"}));
        snapshots.clear();
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.size() >= 10, kTimeoutMs);
        link.markRecording(oilink::MarkerEdit::add({2, 100000, ""}));
        link.markRecording(oilink::MarkerEdit::add({3, 150000, "hit the table leg"}));
        link.markRecording(oilink::MarkerEdit::add({4, 120000, "gone"}));
        link.markRecording(oilink::MarkerEdit::remove(4));
        QCOMPARE(snapshots.last().at(0).value<oi::SensorSnapshot>().oiMode(), oi::OiMode::Passive);
        link.send(commandsOf(bytes({131, 137, 0, 200, 0x80, 0x00})));
        snapshots.clear();
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.size() >= 40, kTimeoutMs);
        link.close();
        QVERIFY(load(m_recording).frames().size() >= 40);
    }

    // The official reader, installed once into the build directory.
    void installTheOfficialReader()
    {
        m_readerDir = QStringLiteral(MCAP_READER_DIR);
        const NpmInstall npm = installNpmPackages(m_readerDir, QStringLiteral(MCAP_READER_SOURCE),
                                                  {"package.json", "read_mcap.js"}, {"@mcap/core", "@mcap/support"});
        if (!npm.unreachable.isEmpty())
            QSKIP(qPrintable(QStringLiteral("npm cannot reach its registry (%1), so @mcap/core, the official MCAP "
                                            "reader, is not installed and no independent reader checks the export. "
                                            "Run the test again with the registry reachable.")
                                 .arg(npm.unreachable)));
        QVERIFY2(npm.error.isEmpty(), qPrintable(npm.error));
    }

    void officialReaderOpensEveryExport_data()
    {
        QTest::addColumn<QString>("compression");
        QTest::newRow("zstd") << "zstd";
        QTest::newRow("lz4") << "lz4";
        QTest::newRow("none") << "none";
    }

    void officialReaderOpensEveryExport()
    {
        QFETCH(QString, compression);
        if (!QFile::exists(QDir(m_readerDir).filePath("node_modules/@mcap/core/package.json")))
            QSKIP("@mcap/core is not installed: see installTheOfficialReader");
        oilink::McapExportOptions options;
        QVERIFY(mcap::compressionFromName(compression, &options.compression));
        const Recording recording = load(m_recording);
        const QString out = m_dir.filePath("run-" + compression + ".mcap");
        mcap::Statistics written;
        QCOMPARE(oilink::exportRecordingMcap(recording, out, options, &written), QString());

        const QJsonObject read = readWithMcapCore(out);
        QVERIFY2(!read.isEmpty(), "the official reader could not open the file");
        QCOMPARE(read.value("library").toString(), QString("Roomba Dashboard " ROOMBA_VERSION));
        QCOMPARE(read.value("compression").toArray(),
                 QJsonArray{compression == "none" ? QString() : compression});
        QVERIFY(read.value("streamDone").toBool());
        QCOMPARE(read.value("summaryOffsets").toArray(), (QJsonArray{3, 4, 8, 11, 13}));

        // Channels and schemas by name; messages counted against the recording.
        const QJsonObject channels = read.value("channels").toObject();
        QCOMPARE(channels.keys(), (QStringList{"/r1/bytes_received", "/r1/bytes_sent", "/r1/events",
                                               "/r1/markers", "/r1/pose", "/r1/room_tf", "/r1/telemetry",
                                               "/r1/tf", "/r1/true_pose"}));
        const auto channel = [&](const char *topic) { return channels.value(topic).toObject(); };
        QCOMPARE(channel("/r1/telemetry").value("schema").toString(), QString("roomba.Telemetry.create2"));
        QCOMPARE(channel("/r1/pose").value("schema").toString(), QString("foxglove.PoseInFrame"));
        QCOMPARE(channel("/r1/true_pose").value("schema").toString(), QString("foxglove.PoseInFrame"));
        QCOMPARE(channel("/r1/tf").value("schema").toString(), QString("foxglove.FrameTransform"));
        // Where the odometry's frame lies in the room: once, from the start.
        QCOMPARE(channel("/r1/room_tf").value("schema").toString(), QString("foxglove.FrameTransform"));
        QCOMPARE(channel("/r1/room_tf").value("count").toInt(), 1);
        QCOMPARE(channel("/r1/room_tf").value("last").toObject().value("parent_frame_id").toString(), QString("room"));
        QCOMPARE(channel("/r1/room_tf").value("last").toObject().value("child_frame_id").toString(), QString("r1/odom"));
        QCOMPARE(channel("/r1/events").value("schema").toString(), QString("foxglove.Log"));
        QCOMPARE(channel("/r1/bytes_sent").value("schema").toString(), QString("roomba.Bytes"));
        for (const QString &topic : channels.keys()) {
            QCOMPARE(channels.value(topic).toObject().value("messageEncoding").toString(), QString("json"));
            QCOMPARE(channels.value(topic).toObject().value("schemaEncoding").toString(), QString("jsonschema"));
        }
        QVERIFY(!recording.firmware()); // so the frames are exported as recorded
        const int frames = int(recording.frames().size());
        QCOMPARE(channel("/r1/telemetry").value("count").toInt(), frames);
        // The pose once for each time the recording holds: frames read
        // together (on a busy machine) share one.
        std::set<qint64> readTimes;
        for (const Recording::Frame &f : recording.frames())
            readTimes.insert(f.timeUs);
        QCOMPARE(channel("/r1/pose").value("count").toInt(), int(readTimes.size()));
        QCOMPARE(channel("/r1/tf").value("count").toInt(), int(readTimes.size()));
        // The virtual robot's true pose: one message per P record, in the room's frame, in metres.
        QVERIFY(recording.truePoses().size() >= 40);
        QCOMPARE(channel("/r1/true_pose").value("count").toInt(), int(recording.truePoses().size()));
        const QJsonObject lastTrue = channel("/r1/true_pose").value("last").toObject();
        QCOMPARE(lastTrue.value("frame_id").toString(), QString("room"));
        const QJsonObject truePosition = lastTrue.value("pose").toObject().value("position").toObject();
        QVERIFY(std::abs(truePosition.value("x").toDouble() - recording.truePoses().back().pose.xMm / 1000) < 1e-5);
        QVERIFY(std::abs(truePosition.value("y").toDouble() - recording.truePoses().back().pose.yMm / 1000) < 1e-5);
        QCOMPARE(channel("/r1/true_pose").value("lastTime").toString().toULongLong() -
                     channel("/r1/true_pose").value("firstTime").toString().toULongLong(),
                 quint64(recording.truePoses().back().timeUs - recording.truePoses().front().timeUs) * 1000);
        QCOMPARE(channel("/r1/bytes_received").value("count").toInt(), int(recording.chunks().size()));
        QCOMPARE(channel("/r1/bytes_sent").value("count").toInt(), int(recording.sentChunks().size()));
        QVERIFY(recording.sentChunks().size() >= 2);

        // The schema lists every packet of the stream, with its unit.
        const QJsonObject properties =
            channel("/r1/telemetry").value("schemaData").toObject().value("properties").toObject();
        QCOMPARE(properties.size(), int(recording.streamedPackets().size()));
        QVERIFY(properties.value("distance").toObject().value("description").toString().contains("mm"));

        // First and last values: the frames as snapshotToJson writes them.
        std::vector<oi::SensorSnapshot> snapshots;
        recording.forEachSnapshot([&](qint64, const oi::SensorSnapshot &s) { snapshots.push_back(s); });
        QCOMPARE(channel("/r1/telemetry").value("first").toObject(), oilink::snapshotToJson(snapshots.front()));
        QCOMPARE(channel("/r1/telemetry").value("last").toObject(), oilink::snapshotToJson(snapshots.back()));
        QCOMPARE(channel("/r1/telemetry").value("lastTime").toString().toULongLong() -
                     channel("/r1/telemetry").value("firstTime").toString().toULongLong(),
                 quint64(recording.frames().back().timeUs - recording.frames().front().timeUs) * 1000);
        // The robot drove straight ahead: the pose's x grew, y stayed near 0.
        const QJsonObject lastPosition = channel("/r1/pose").value("last").toObject().value("pose").toObject()
                                             .value("position").toObject();
        QVERIFY2(lastPosition.value("x").toDouble() > 0.01, qPrintable(QString::number(lastPosition.value("x").toDouble())));
        QVERIFY(std::abs(lastPosition.value("y").toDouble()) < 0.01);
        QCOMPARE(channel("/r1/pose").value("last").toObject().value("frame_id").toString(), QString("r1/odom"));
        // The first bytes sent decode to what was sent.
        QCOMPARE(QByteArray::fromBase64(channel("/r1/bytes_sent").value("first").toObject().value("data")
                                            .toString().toLatin1()),
                 recording.sentBytes().left(recording.sentChunks().front().end));
        // The mode went to Safe, and the log says so.
        QVERIFY2(channel("/r1/events").value("messages").toArray().contains("Mode Passive → Safe"),
                 QJsonDocument(channel("/r1/events").value("messages").toArray()).toJson().constData());
        // One message per marker the recording holds.
        QCOMPARE(channel("/r1/markers").value("count").toInt(), int(recording.markers().size()));

        // The summary's statistics match what the file holds, and what we wrote.
        const QJsonObject st = read.value("statistics").toObject();
        int counted = 0;
        for (const QString &topic : channels.keys()) {
            const int count = channels.value(topic).toObject().value("count").toInt();
            counted += count;
            QCOMPARE(st.value("channelMessageCounts").toObject().value(topic).toInt(), count);
        }
        QCOMPARE(st.value("messageCount").toInt(), counted);
        QCOMPARE(quint64(counted), written.messageCount);
        QCOMPARE(st.value("channelCount").toInt(), 9);
        QCOMPARE(st.value("schemaCount").toInt(), 5);
        QCOMPARE(st.value("chunkCount").toInt(), read.value("chunkIndexes").toInt());
        QCOMPARE(st.value("chunkCount").toInt(), read.value("streamed").toObject().value("Chunk").toInt());
        QCOMPARE(st.value("metadataCount").toInt(), read.value("metadataIndexes").toInt());
        // Streamed from the start, every CRC checked: the same messages, one data end, one footer.
        const QJsonObject streamed = read.value("streamed").toObject();
        QCOMPARE(streamed.value("Message").toInt(), counted);
        QCOMPARE(streamed.value("Metadata").toInt(), st.value("metadataCount").toInt());
        QCOMPARE(streamed.value("DataEnd").toInt(), 1);
        QCOMPARE(streamed.value("Footer").toInt(), 1);
        quint64 first = std::numeric_limits<quint64>::max(), last = 0;
        for (const QString &topic : channels.keys()) {
            first = std::min(first, channels.value(topic).toObject().value("firstTime").toString().toULongLong());
            last = std::max(last, channels.value(topic).toObject().value("lastTime").toString().toULongLong());
        }
        QCOMPARE(st.value("messageStartTime").toString().toULongLong(), first);
        QCOMPARE(st.value("messageEndTime").toString().toULongLong(), last);

        // The profile as metadata.
        const QJsonObject meta = read.value("metadata").toObject().value("recording").toObject();
        QCOMPARE(meta.value("profile").toString(), QString("create2"));
        QCOMPARE(meta.value("packets").toString(), QString("100"));
        QCOMPARE(meta.value("link").toString(), recording.header().value("link").toString());
    }

    // The markers made while recording, read back from the file, are log
    // messages of their own channel, in time order, at their times.
    void markersInTheRecordingAreWritten()
    {
        if (!QFile::exists(QDir(m_readerDir).filePath("node_modules/@mcap/core/package.json")))
            QSKIP("@mcap/core is not installed: see installTheOfficialReader");
        const Recording recording = load(m_recording);
        QCOMPARE(recording.markers().size(), 3);
        const QString out = m_dir.filePath("markers.mcap");
        QCOMPARE(oilink::exportRecordingMcap(recording, out, {}), QString());
        const QJsonObject read = readWithMcapCore(out);
        const QJsonObject markers = read.value("channels").toObject().value("/r1/markers").toObject();
        QCOMPARE(markers.value("schema").toString(), QString("foxglove.Log"));
        QCOMPARE(markers.value("messages").toArray(), (QJsonArray{"start", "#2", "hit the table leg"}));
        const qint64 started = QDateTime::fromString(recording.header().value("started").toString(), Qt::ISODateWithMs)
                                   .toMSecsSinceEpoch();
        QJsonArray times;
        for (const oilink::RecordingMarker &m : recording.markers())
            times.append(QString::number(started * 1000000 + m.timeUs * 1000));
        QCOMPARE(markers.value("logTimes").toArray(), times);
    }

    void bumpsCliffsAndModesAreLogged()
    {
        // Passive, a left bump in frames 3..5, Safe from frame 7, a right
        // wheel drop from frame 9.
        const QByteArray oirec = syntheticRecording(12, [](int i) {
            const int bumps = (i >= 3 && i <= 5 ? oi::bit::BumpLeft : 0) | (i >= 9 ? oi::bit::WheelDropRight : 0);
            return std::pair{bumps, i >= 7 ? 2 : 1};
        });
        const QString in = m_dir.filePath("events.oirec");
        QVERIFY(writeFile(in, oirec));
        const QString out = m_dir.filePath("events.mcap");
        QCOMPARE(oilink::exportRecordingMcap(load(in), out, {mcap::Compression::None}), QString());
        const QByteArray file = fileBytes(out);
        const quint16 events = channelsOf(file).value("/r1/events");
        QCOMPARE(eventsOf(file, events), (QStringList{"Mode Passive", "Bump Left", "Bump Left cleared",
                                                      "Mode Passive → Safe", "Wheel Drop Right"}));
        // Each at its frame's time, from the recording's start in UTC.
        QList<quint64> times;
        for (const mcap_test::Message &m : mcap_test::messagesOf(file))
            if (m.channel == events)
                times << m.logTime;
        QCOMPARE(times, (QList<quint64>{kSyntheticStartNs + 15'000'000, kSyntheticStartNs + 4 * 15'000'000,
                                        kSyntheticStartNs + 7 * 15'000'000, kSyntheticStartNs + 8 * 15'000'000,
                                        kSyntheticStartNs + 10 * 15'000'000}));
        const QJsonObject bump = QJsonDocument::fromJson([&] {
            for (const mcap_test::Message &m : mcap_test::messagesOf(file))
                if (m.channel == events && m.data.contains("\"Bump Left\""))
                    return m.data;
            return QByteArray();
        }()).object();
        QCOMPARE(bump.value("level").toInt(), 3); // WARNING
        QCOMPARE(bump.value("timestamp").toObject().value("sec").toInteger(), qint64(kSyntheticStartNs / 1000000000));
        QCOMPARE(bump.value("timestamp").toObject().value("nsec").toInt(), 4 * 15'000'000);
    }

    // Uncompressed, an export is a small multiple of its recording whatever
    // its frames: each frame's telemetry, and once per read a pose (when the
    // frame measures motion) and one log line of what changed. 524,288 frames
    // of the bumpers alone, read together, wrote 100 times the file before.
    void uncompressedExportIsBoundedByItsRecording_data()
    {
        QTest::addColumn<QByteArray>("packets");
        QTest::addColumn<bool>("oneReadEach");
        QTest::addColumn<int>("poses");
        QTest::addColumn<int>("events"); // a change in each read but the first (none; group 100: its mode)
        QTest::newRow("the bumpers alone, read together") << QByteArray("[7]") << false << 1 << 1;
        QTest::newRow("the bumpers alone, a read each") << QByteArray("[7]") << true << 1 << 1999;
        QTest::newRow("bumpers flipping and the distance, a read each") << QByteArray("[7,19]") << true << 2000 << 1999;
        QTest::newRow("group 100, a read each") << QByteArray("[100]") << true << 2000 << 2000;
    }

    void uncompressedExportIsBoundedByItsRecording()
    {
        QFETCH(QByteArray, packets);
        QFETCH(bool, oneReadEach);
        QFETCH(int, poses);
        QFETCH(int, events);
        constexpr int kFrames = 2000;
        QByteArray file = oirecHeader(3, R"({"format":"Roomba Dashboard recording","version":3,)"
                                         R"("started":"2026-01-02T03:04:05.000Z"})");
        file += oirecRecord('S', 0, R"({"profile":"create2","baud":115200,"packets":)" + packets + "}");
        QByteArray together;
        for (int i = 0; i < kFrames; ++i) {
            // Every bumper and wheel drop flips each frame; the robot moves 1 to 8 mm.
            const char flips = char(i % 2 ? 15 : 0);
            const QByteArray frame = packets == "[100]"  ? group100Frame(std::uint8_t(flips))
                                     : packets == "[7]" ? streamFrame(bytes({7, flips}))
                                                        : streamFrame(bytes({7, flips, 19, 0, 1 + i % 8}));
            if (oneReadEach)
                file += oirecRecord('R', 15000 * (i + 1), frame);
            else
                together += frame;
        }
        if (!oneReadEach)
            file += oirecRecord('R', 15000, together);
        const QString in = m_dir.filePath("shape.oirec");
        QVERIFY(writeFile(in, file));
        const QString out = m_dir.filePath("shape.mcap");
        QCOMPARE(oilink::exportRecordingMcap(load(in), out, {mcap::Compression::None}), QString());
        const QByteArray written = fileBytes(out);
        QVERIFY2(written.size() <= 40 * file.size(),
                 qPrintable(QString("%1 bytes from %2, %3 times").arg(written.size()).arg(file.size())
                                .arg(double(written.size()) / double(file.size()), 0, 'f', 1)));
        const QMap<QString, quint16> channels = channelsOf(written);
        QMap<quint16, int> counts;
        for (const mcap_test::Message &m : mcap_test::messagesOf(written))
            ++counts[m.channel];
        QCOMPARE(counts.value(channels.value("/r1/telemetry")), kFrames); // nothing of the data is lost
        QCOMPARE(counts.value(channels.value("/r1/pose")), poses);
        QCOMPARE(counts.value(channels.value("/r1/tf")), poses);
        QCOMPARE(counts.value(channels.value("/r1/events")), events);
    }

    // A recording without true poses (a real robot) has no true-pose channel.
    void noTruePoseChannelWithoutTruePoses()
    {
        const QString in = m_dir.filePath("real.oirec");
        QVERIFY(writeFile(in, syntheticRecording(5, [](int) { return std::pair{0, 1}; })));
        QVERIFY(load(in).truePoses().empty());
        const QString out = m_dir.filePath("real.mcap");
        QCOMPARE(oilink::exportRecordingMcap(load(in), out, {mcap::Compression::None}), QString());
        const QMap<QString, quint16> channels = channelsOf(fileBytes(out));
        QVERIFY(channels.contains("/r1/pose"));
        QVERIFY(!channels.contains("/r1/true_pose"));
        QVERIFY(!channels.contains("/r1/room_tf"));
    }

    void damagedRecordingExportsUpToTheDamage()
    {
        const QByteArray whole = syntheticRecording(100, [](int) { return std::pair{0, 1}; });
        const QString cut = m_dir.filePath("cut.oirec");
        QVERIFY(writeFile(cut, whole.left(whole.size() * 2 / 3)));
        const Recording damaged = load(cut);
        QVERIFY(damaged.damage());
        const QString out = m_dir.filePath("cut.mcap");
        std::optional<oilink::RecordingDamage> damage;
        QCOMPARE(oilink::exportRecordingMcap(cut, out, {mcap::Compression::None}, &damage), QString());
        QVERIFY(damage);
        QCOMPARE(damage->byteOffset, damaged.damage()->byteOffset);
        const QByteArray file = fileBytes(out);
        const quint16 telemetry = channelsOf(file).value("/r1/telemetry");
        int frames = 0;
        for (const mcap_test::Message &m : mcap_test::messagesOf(file))
            frames += m.channel == telemetry;
        QCOMPARE(frames, int(damaged.frames().size()));
        QVERIFY(frames > 50 && frames < 100);

        // roomba-ctl writes the same and names the damage.
        const QString ctlOut = m_dir.filePath("cut-ctl.mcap");
        const ProcessRun ctl = runProcess(ROOMBA_CTL_PATH, {"mcap", cut, "-o", ctlOut, "--compression", "none"});
        QCOMPARE(ctl.exitCode, 1);
        QVERIFY2(ctl.err.contains(QString("truncated record at byte %1").arg(damage->byteOffset).toUtf8()),
                 ctl.err.constData());
        QVERIFY(ctl.err.contains("exported up to there"));
        QCOMPARE(mcap_test::messagesOf(fileBytes(ctlOut)).size(), mcap_test::messagesOf(file).size());
    }

    void unwritablePathLeavesNothingBehind()
    {
        const QString nowhere = m_dir.filePath("no-such-folder/out.mcap");
        const QString error = oilink::exportRecordingMcap(m_recording, nowhere, {});
        QVERIFY2(error.startsWith(nowhere), qPrintable(error));
        QVERIFY(!QFile::exists(nowhere));
        // A folder in the way: the error names it, and the folder stays.
        const QString folder = m_dir.filePath("a-folder.mcap");
        QVERIFY(QDir().mkpath(folder));
        QVERIFY(oilink::exportRecordingMcap(m_recording, folder, {}).startsWith(folder));
        QVERIFY(QFileInfo(folder).isDir());
        // Not a recording: refused with the reason, nothing written.
        const QString notRecording = m_dir.filePath("notes.oirec");
        QVERIFY(writeFile(notRecording, "hello"));
        const QString out = m_dir.filePath("notes.mcap");
        QVERIFY(oilink::exportRecordingMcap(notRecording, out, {}).contains("not a Roomba Dashboard recording"));
        QVERIFY(!QFile::exists(out));
    }

    void roombaCtlChecksItsArguments()
    {
        const ProcessRun noOut = runProcess(ROOMBA_CTL_PATH, {"mcap", m_recording});
        QCOMPARE(noOut.exitCode, 2);
        QVERIFY2(noOut.err.contains("-o OUT.mcap"), noOut.err.constData());
        const ProcessRun badCompression = runProcess(ROOMBA_CTL_PATH, {"mcap", m_recording, "-o", m_dir.filePath("x.mcap"),
                                                         "--compression", "gzip"});
        QCOMPARE(badCompression.exitCode, 2);
        QVERIFY2(badCompression.err.contains("unknown compression 'gzip'; use zstd, lz4 or none"),
                 badCompression.err.constData());
        QVERIFY(!QFile::exists(m_dir.filePath("x.mcap")));
        const QString out = m_dir.filePath("ctl.mcap");
        const ProcessRun ok = runProcess(ROOMBA_CTL_PATH, {"mcap", m_recording, "-o", out, "--compression", "lz4"});
        QCOMPARE(ok.exitCode, 0);
        QVERIFY(fileBytes(out).startsWith("\x89MCAP0\r\n"));
        // Success is said, with where the file went.
        QVERIFY2(ok.err.contains("wrote " + out.toUtf8()) && ok.err.contains("bytes"), ok.err.constData());
    }
};

QTEST_GUILESS_MAIN(TestMcapExport)
#include "tst_mcap_export.moc"
