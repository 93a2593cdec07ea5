// SPDX-License-Identifier: GPL-3.0-or-later
// How long an hour's recording takes to write, to open for replay (as the
// dashboard does: the stream's description, then the replay loads and indexes
// the file once), to seek anywhere in, and to export as CSV. An hour of
// Create 2 streaming group 100 at 66.7 frames/s is 240,000 frames; the frames
// are synthetic, the file real.
//
//   bench_recording [FRAMES]
#include "recording_file.h"
#include "replay_transport.h"
#include "synthetic_recording.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTextStream>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace {

// A seek to a random time, to the frame's bytes handed to the link: p50, p99, max in ms.
void benchSeek(const QString &path)
{
    oilink::ReplayTransport replay(path);
    QElapsedTimer clock;
    clock.start();
    replay.open();
    const double openS = clock.nsecsElapsed() / 1e9;
    replay.controlReplay(oilink::ReplayCommand::pause());
    const qint64 durationUs = replay.status().durationUs;
    qint64 deliveredNs = 0;
    QObject::connect(&replay, &oilink::Transport::bytesReceived, [&] { deliveredNs = clock.nsecsElapsed(); });
    std::mt19937 random(15);
    std::vector<double> ms;
    for (int i = 0; i < 1000; ++i) {
        deliveredNs = -1;
        clock.restart();
        replay.controlReplay(oilink::ReplayCommand::seek(std::uniform_int_distribution<qint64>(0, durationUs)(random)));
        if (deliveredNs >= 0)
            ms.push_back(deliveredNs / 1e6);
    }
    std::sort(ms.begin(), ms.end());
    if (ms.empty()) {
        std::printf("seek    no frame delivered\n");
        return;
    }
    std::printf("replay  open %.2f s (the replay's own load and index)\n", openS);
    std::printf("seek    %zu seeks to the frame's bytes delivered: p50 %.3f ms, p99 %.3f ms, max %.3f ms\n",
                ms.size(), ms[ms.size() / 2], ms[ms.size() * 99 / 100], ms.back());
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    const int frames = argc > 1 ? std::atoi(argv[1]) : 240000;
    QTemporaryDir dir;
    const QString path = dir.filePath("hour.oirec");
    QElapsedTimer clock;
    clock.start();
    QString error;
    const bool written = writeSyntheticRecording(path, frames, [](int i, oi::SensorSnapshot &values) {
        values.set(22, 14000 + i % 2000); // voltage
        values.set(19, i % 7 - 3);        // distance
    }, &error);
    if (!written) {
        std::fprintf(stderr, "%s\n", qPrintable(error));
        return 1;
    }
    const double writeS = clock.nsecsElapsed() / 1e9;
    const double megabytes = QFile(path).size() / 1e6;

    clock.restart();
    const std::optional<oilink::Recording::StreamInfo> stream = oilink::Recording::readStream(path, &error);
    const double streamS = clock.nsecsElapsed() / 1e9;
    if (!stream) {
        std::fprintf(stderr, "reading the stream failed: %s\n", qPrintable(error));
        return 1;
    }
    clock.restart();
    const std::optional<oilink::Recording> recording = oilink::Recording::load(path, &error);
    const double loadS = clock.nsecsElapsed() / 1e9;
    if (!recording || int(recording->frames().size()) != frames) {
        std::fprintf(stderr, "load failed or lost frames: %s (%zu of %d)\n", qPrintable(error),
                     recording ? recording->frames().size() : 0, frames);
        return 1;
    }

    clock.restart();
    QFile csv(dir.filePath("hour.csv"));
    if (!csv.open(QIODevice::WriteOnly))
        return 1;
    QTextStream out(&csv);
    recording->writeCsv(out);
    out.flush();
    const double csvS = clock.nsecsElapsed() / 1e9;

    std::printf("frames %d, recording %.1f MB\n", frames, megabytes);
    std::printf("write   %.2f s (%.0f frames/s)\n", writeS, frames / writeS);
    std::printf("open    %.3f s (stream description %.4f s, then one load and index of every frame %.3f s, "
                "%.1f MB/s; target <= 0.3 s, read once)\n",
                streamS + loadS, streamS, loadS, megabytes / loadS);
    std::printf("csv     %.2f s (%.1f MB of CSV)\n", csvS, csv.size() / 1e6);
    benchSeek(path);
    return 0;
}
