// SPDX-License-Identifier: GPL-3.0-or-later
// How long an hour's recording takes to export as MCAP, and how large the
// file is, with zstd, lz4 and no compression. An hour of a Create 2
// streaming group 100 at 66.7 frames/s is 240,000 frames; the frames are
// synthetic (the robot drives a slow circle, the battery drains), the
// files real. Target: an hour exports in <= 5 s.
//
//   bench_mcap [FRAMES]
#include "recording_file.h"
#include "recording_mcap.h"
#include "synthetic_recording.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>

#include <cstdio>
#include <cstdlib>

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const int frames = argc > 1 ? std::atoi(argv[1]) : 240000;
    QTemporaryDir dir;
    const QString path = dir.filePath("hour.oirec");
    QString error;
    const bool written = writeSyntheticRecording(path, frames, [](int i, oi::SensorSnapshot &values) {
        values.set(35, 2);                          // Safe
        values.set(22, 16000 - i / 100);            // voltage drains
        values.set(23, -1200 + i % 37);             // current
        values.set(43, (i * 3) % 65536 - 32768);    // left encoder
        values.set(44, (i * 4) % 65536 - 32768);    // right encoder
        values.set(19, 3);                          // distance
        values.set(20, i % 3 == 0 ? 1 : 0);         // angle
        values.set(7, (i / 500) % 20 == 0 ? 1 : 0); // a bump now and then
        values.set(27, (i * 7) % 1024);             // wall signal
    }, &error);
    if (!written) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    const double recordingMb = QFile(path).size() / 1e6;

    QElapsedTimer clock;
    clock.start();
    const std::optional<oilink::Recording> recording = oilink::Recording::load(path, &error);
    if (!recording) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    const double loadS = clock.nsecsElapsed() / 1e9;
    std::printf("frames %d, recording %.1f MB, loaded in %.2f s\n", frames, recordingMb, loadS);
    for (const char *name : {"zstd", "lz4", "none"}) {
        oilink::McapExportOptions options;
        mcap::compressionFromName(QString::fromLatin1(name), &options.compression);
        const QString out = dir.filePath(QStringLiteral("hour-%1.mcap").arg(QLatin1String(name)));
        mcap::Statistics st;
        clock.restart();
        error = oilink::exportRecordingMcap(*recording, out, options, &st);
        const double exportS = clock.nsecsElapsed() / 1e9;
        if (!error.isEmpty()) {
            std::fprintf(stderr, "%s\n", qPrintable(error));
            return 1;
        }
        const double mb = QFile(out).size() / 1e6;
        std::printf("%-5s export %.2f s (load + export %.2f s; target <= 5 s), %.1f MB = %.2f x the recording, "
                    "%llu messages in %u chunks\n",
                    name, exportS, loadS + exportS, mb, mb / recordingMb, static_cast<unsigned long long>(st.messageCount),
                    st.chunkCount);
    }
    return 0;
}
