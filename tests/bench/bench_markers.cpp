// SPDX-License-Identifier: GPL-3.0-or-later
// How long a recording with markers takes to open: an hour of a Create 2
// streaming group 100 (240,000 synthetic frames) with 1,000 markers written
// while it recorded (and every tenth renamed), against the same hour without
// them; then the same file read whole as a run to compare with, and one
// marker added in a replay (the file checked, the marker appended).
//
//   bench_markers [FRAMES] [MARKERS]
#include "recorded_run.h"
#include "recording_file.h"
#include "synthetic_recording.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>

#include <cstdio>
#include <cstdlib>

namespace {

bool write(const QString &path, int frames, int markers)
{
    const int every = markers > 0 ? std::max(1, frames / markers) : 0;
    QString error;
    const bool ok = writeSyntheticRecording(
        path, frames,
        [](int i, oi::SensorSnapshot &values) {
            values.set(22, 16000 - i / 100);
            values.set(7, (i / 500) % 20 == 0 ? 1 : 0);
        },
        &error,
        [&](int i, oilink::RecordingWriter &writer) {
            if (!every || i % every != 0 || i / every >= markers)
                return true;
            const int id = i / every + 1;
            const qint64 timeUs = qint64(i) * 15000;
            bool written = writer.appendMarkerEdit(
                oilink::MarkerEdit::add({id, timeUs, QStringLiteral("marker %1 of the run").arg(id)}));
            if (id % 10 == 0)
                written = written && writer.appendMarkerEdit(oilink::MarkerEdit::rename(id, QStringLiteral("renamed %1").arg(id)));
            return written;
        });
    if (!ok)
        std::fprintf(stderr, "%s\n", qPrintable(error));
    return ok;
}

// The fastest of three, in seconds.
template <typename F>
double best(F &&run)
{
    double fastest = 1e9;
    for (int i = 0; i < 3; ++i) {
        QElapsedTimer clock;
        clock.start();
        if (!run())
            return -1;
        fastest = std::min(fastest, clock.nsecsElapsed() / 1e9);
    }
    return fastest;
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const int frames = argc > 1 ? std::atoi(argv[1]) : 240000;
    const int markers = argc > 2 ? std::atoi(argv[2]) : 1000;
    QTemporaryDir dir;
    const QString plain = dir.filePath("plain.oirec");
    const QString marked = dir.filePath("marked.oirec");
    if (!write(plain, frames, 0) || !write(marked, frames, markers))
        return 1;

    QString error;
    int found = 0;
    const auto open = [&](const QString &path) {
        return best([&] {
            const std::optional<oilink::Recording> r = oilink::Recording::load(path, &error);
            found = r ? int(r->markers().size()) : -1;
            return r.has_value();
        });
    };
    const double plainS = open(plain);
    const double markedS = open(marked);
    if (plainS < 0 || markedS < 0 || found != markers) {
        std::fprintf(stderr, "%s (markers read: %d)\n", qPrintable(error), found);
        return 1;
    }
    std::printf("frames %d, recording %.1f MB\n", frames, QFile(plain).size() / 1e6);
    std::printf("open without markers:   %.3f s\n", plainS);
    std::printf("open with %d markers: %.3f s (%+.3f s)\n", markers, markedS, markedS - plainS);

    const double runS = best([&] { return RecordedRun::load(marked, &error).has_value(); });
    std::printf("read whole to compare:  %.3f s\n", runS);

    int next = markers + 1;
    const double saveS = best([&] {
        return oilink::Recording::saveMarkerEdits(marked, {oilink::MarkerEdit::add({next++, 1000000, "added in a replay"})},
                                                  &error);
    });
    if (saveS < 0) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    std::printf("a marker added in a replay (file checked, marker appended): %.3f s\n", saveS);
    return 0;
}
