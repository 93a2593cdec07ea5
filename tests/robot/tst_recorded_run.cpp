// SPDX-License-Identifier: GPL-3.0-or-later
// A recording read whole for comparing runs: its history, odometry path and
// markers, from runs of the virtual robot on a clock the test advances.
#include "recorded_run.h"

#include "oirec_records.h" // tests/common
#include "virtual_robot.h"

#include <QTemporaryDir>
#include <QTest>

namespace {

QByteArray toBytes(const oi::Bytes &b)
{
    return QByteArray(reinterpret_cast<const char *>(b.data()), qsizetype(b.size()));
}

// Two seconds of the virtual Create 2 driving straight ahead at 200 mm/s, on
// an empty floor or with a wall 150 mm ahead of its front, recorded as the
// link records: every byte with its time on the robot's own clock. A marker
// "go" where it starts to drive.
QByteArray virtualRun(bool wallAhead)
{
    sim::VirtualRobot robot(oi::profile(oi::ProfileId::Create2), 7);
    sim::World world;
    if (wallAhead)
        world.walls.push_back({320, -1000, 320, 1000}); // the body's radius is about 170 mm
    robot.setWorld(world);
    robot.placeAt({0, 0, 0});
    QByteArray file = oirecHeader(2, R"({"format":"Roomba Dashboard recording","version":2,"link":"test"})");
    const auto send = [&](const QByteArray &bytes) {
        file += oirecRecord('T', robot.now().count(), bytes);
        robot.receive({reinterpret_cast<const std::uint8_t *>(bytes.constData()), std::size_t(bytes.size())});
    };
    send(QByteArray::fromHex("8083")); // Start, Safe
    file += oirecRecord('S', robot.now().count(), R"({"profile":"create2","baud":115200,"packets":[100]})");
    send(QByteArray::fromHex("940164")); // Stream group 100
    for (int tick = 0; tick < 134; ++tick) {
        if (tick == 10) {
            file += oirecRecord('M', robot.now().count(), R"({"op":"add","id":1,"time_us":150000,"note":"go"})");
            send(QByteArray::fromHex("8900C88000")); // Drive 200 mm/s straight
        }
        robot.advance(sim::VirtualRobot::kStreamPeriod);
        const QByteArray out = toBytes(robot.takeOutput());
        if (!out.isEmpty())
            file += oirecRecord('R', robot.now().count(), out);
    }
    return file;
}

RecordedRun runOf(const QByteArray &bytes)
{
    QString error;
    const std::optional<oilink::Recording> r = oilink::Recording::fromBytes(bytes, "run.oirec", &error);
    if (!r)
        qFatal("%s", qPrintable(error));
    return RecordedRun(*r, "run.oirec");
}

// Packet `id`'s samples where the two histories differ.
int differences(const SensorHistory &a, const SensorHistory &b, int id)
{
    int count = 0;
    const std::size_t n = std::max(a.sampleCount(id), b.sampleCount(id));
    for (std::size_t i = 0; i < n; ++i)
        count += i >= a.sampleCount(id) || i >= b.sampleCount(id) || !(a.sample(id, i) == b.sample(id, i));
    return count;
}

int bumpSamples(const SensorHistory &h)
{
    int count = 0;
    for (std::size_t i = 0; i < h.sampleCount(7); ++i)
        count += (h.sample(7, i).value & 0x03) != 0;
    return count;
}

} // namespace

class TestRecordedRun : public QObject {
    Q_OBJECT
private slots:
    void historyPathAndMarkersAreRead()
    {
        const RecordedRun run = runOf(virtualRun(false));
        QCOMPARE(run.history().frameCount(), std::size_t(134)); // one a tick
        QCOMPARE(run.startSeconds(), 0.015);
        QCOMPARE(run.markers(), (QList<oilink::RecordingMarker>{{1, 150000, "go"}}));
        // Straight ahead along +x, about 200 mm/s for 1.8 s.
        QVERIFY(run.pathMm().size() > 100);
        QCOMPARE(run.pathMm().first(), QPointF(0, 0));
        QVERIFY2(std::abs(run.pathMm().last().x() - 360) < 40, qPrintable(QString::number(run.pathMm().last().x())));
        QVERIFY(std::abs(run.pathMm().last().y()) < 1);
        QVERIFY(!run.damage());
        QCOMPARE(run.name(), QString("run.oirec"));
    }

    // The same run recorded twice: every packet of every frame the same, the same path.
    void twoRecordingsOfTheSameRunDifferByZero()
    {
        const RecordedRun a = runOf(virtualRun(false));
        const RecordedRun b = runOf(virtualRun(false));
        QCOMPARE(a.history().frameCount(), b.history().frameCount());
        for (int id = 7; id <= 58; ++id)
            QCOMPARE(differences(a.history(), b.history(), id), 0);
        QCOMPARE(a.pathMm(), b.pathMm());
    }

    // A wall ahead in one run: the bump is in that run's trace only, and its
    // path stops short; before the bump the two agree.
    void aBumpShowsInOneTraceOnly()
    {
        const RecordedRun clear = runOf(virtualRun(false));
        const RecordedRun walled = runOf(virtualRun(true));
        QCOMPARE(bumpSamples(clear.history()), 0);
        QVERIFY(bumpSamples(walled.history()) > 0);
        QVERIFY(differences(clear.history(), walled.history(), 7) > 0);
        QCOMPARE(clear.history().sample(7, 20), walled.history().sample(7, 20));
        QVERIFY(walled.pathMm().last().x() < clear.pathMm().last().x() - 50);
    }

    void unreadableFilesAreRefused()
    {
        QTemporaryDir dir;
        QString error;
        QVERIFY(!RecordedRun::load(dir.filePath("missing.oirec"), &error));
        QVERIFY2(error.contains("missing.oirec"), qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestRecordedRun)
#include "tst_recorded_run.moc"
