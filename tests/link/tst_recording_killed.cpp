// SPDX-License-Identifier: GPL-3.0-or-later
// A recording whose writer is killed with SIGKILL while it records (a crash,
// a power cut of the program) still opens and replays up to its last second.
#include "recording_file.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>
#include <optional>

namespace {

constexpr int kFramesPerSecond = 1000000 / 15000; // a stream frame every 15 ms
constexpr int kTimeoutMs = 20000;

std::size_t framesOnDisk(const QString &path)
{
    const std::optional<oilink::Recording> r = oilink::Recording::load(path, nullptr);
    return r ? r->frames().size() : 0;
}

} // namespace

class TestRecordingKilled : public QObject {
    Q_OBJECT
private slots:
    void replaysUpToTheLastSecond()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath("killed.oirec");
        QProcess recorder;
        recorder.start(RECORD_UNTIL_KILLED_PATH, {path});
        QVERIFY2(recorder.waitForStarted(kTimeoutMs), qPrintable(recorder.errorString()));

        // Two seconds of frames have reached the disk: the flush is working.
        const std::size_t before = 2 * kFramesPerSecond;
        QTRY_VERIFY_WITH_TIMEOUT(framesOnDisk(path) >= before, kTimeoutMs);
        QCOMPARE(recorder.state(), QProcess::Running);
        ::kill(static_cast<pid_t>(recorder.processId()), SIGKILL);
        QVERIFY(recorder.waitForFinished(kTimeoutMs));
        QCOMPARE(recorder.exitStatus(), QProcess::CrashExit);

        // The last count the recorder printed: frames it had been handed,
        // so frames whose bytes it had recorded.
        long long live = 0;
        const QRegularExpression count(QStringLiteral("^frames (\\d+)$"), QRegularExpression::MultilineOption);
        for (auto it = count.globalMatch(QString::fromLatin1(recorder.readAllStandardOutput())); it.hasNext();)
            live = it.next().captured(1).toLongLong();
        QVERIFY(live >= qint64(before));

        QString error;
        const std::optional<oilink::Recording> recording = oilink::Recording::load(path, &error);
        QVERIFY2(recording, qPrintable(error));
        // Cut short at worst, in the middle of a record; never garbled.
        if (recording->damage())
            QVERIFY2(recording->damage()->reason.contains("truncated"), qPrintable(recording->damage()->describe()));
        const qint64 kept = qint64(recording->frames().size());
        QVERIFY(kept >= qint64(before));
        // Flushed at least once a second: about a second lost at most.
        const qint64 lost = live - kept;
        qInfo("%lld frames live, %lld replayable, %lld lost", live, kept, lost);
        QVERIFY2(lost <= kFramesPerSecond * 3 / 2, qPrintable(QString::number(lost)));

        std::size_t replayed = 0;
        recording->forEachSnapshot([&](qint64, const oi::SensorSnapshot &) { ++replayed; });
        QCOMPARE(replayed, recording->frames().size());
        QCOMPARE(recording->robotProfile().id, oi::ProfileId::Create2);
    }
};

QTEST_GUILESS_MAIN(TestRecordingKilled)
#include "tst_recording_killed.moc"
