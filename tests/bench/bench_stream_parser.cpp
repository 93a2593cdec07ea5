// SPDX-License-Identifier: GPL-3.0-or-later
// Throughput of StreamParser on a Create 2 group-100 stream, decoding into
// SensorSnapshot included. Not a test: run it by hand on a quiet machine.
#include "stream_parser.h"

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

namespace {

constexpr std::size_t kTargetBytes = 64u * 1024u * 1024u;
constexpr std::uint8_t kGroup = 100;
constexpr int kRepetitions = 5;
constexpr double kCorruptFraction = 0.01;

struct Stream {
    std::vector<std::uint8_t> bytes;
    std::uint64_t frames = 0;
    std::uint64_t corrupted = 0;
    std::size_t frameSize = 0;
};

// Values a robot driving around a room would send: status bits mostly clear,
// slowly varying battery figures, signals spread over their documented range.
std::int32_t realisticValue(const oi::PacketInfo &p, std::mt19937 &rng)
{
    auto uniform = [&](std::int32_t lo, std::int32_t hi) {
        return std::uniform_int_distribution<std::int32_t>(lo, hi)(rng);
    };
    auto rarely = [&](std::int32_t value) { return uniform(0, 19) == 0 ? value : 0; };
    switch (p.id) {
    case 7: return rarely(uniform(1, p.max));
    case 8: case 9: case 10: case 11: case 12: case 13: return rarely(1);
    case 14: return rarely(uniform(1, p.max));
    case 17: case 52: case 53: return uniform(0, 3) == 0 ? uniform(160, 175) : 0;
    case 18: return rarely(uniform(1, p.max));
    case 19: return uniform(-20, 20);
    case 20: return uniform(-15, 15);
    case 21: return uniform(0, 5);
    case 22: return uniform(13000, 16800);
    case 23: return uniform(-2000, 1500);
    case 24: return uniform(18, 45);
    case 25: return uniform(0, 2696);
    case 26: return 2696;
    case 35: return uniform(1, 3);
    case 36: return uniform(0, 4);
    case 38: return 1;
    case 40: return uniform(0, 4) == 0 ? 32767 : uniform(-2000, 2000);
    case 43: case 44: return uniform(p.min, p.max);
    case 45: return rarely(uniform(1, p.max));
    case 54: case 55: return uniform(-400, 400);
    case 56: case 57: return uniform(0, 300);
    default: return uniform(p.min, p.max);
    }
}

Stream makeStream(const oi::RobotProfile &profile)
{
    const oi::PacketGroup *group = profile.group(kGroup);
    Stream s;
    s.frameSize = 2 + 1 + group->bytes + 1; // [19][n][100][data][checksum]
    const std::size_t count = kTargetBytes / s.frameSize;
    s.bytes.reserve(count * s.frameSize);

    std::mt19937 rng(20240607u);
    std::bernoulli_distribution corrupt(kCorruptFraction);
    std::vector<std::uint8_t> frame(s.frameSize);
    for (std::size_t f = 0; f < count; ++f) {
        std::size_t at = 0;
        frame[at++] = 19;
        frame[at++] = static_cast<std::uint8_t>(1 + group->bytes);
        frame[at++] = kGroup;
        for (int id = group->first; id <= group->last; ++id) {
            const oi::PacketInfo &p = *profile.packet(id);
            const auto u = static_cast<std::uint32_t>(realisticValue(p, rng));
            if (p.bytes == 2)
                frame[at++] = static_cast<std::uint8_t>(u >> 8);
            frame[at++] = static_cast<std::uint8_t>(u);
        }
        unsigned sum = 0;
        for (std::size_t i = 0; i < at; ++i)
            sum += frame[i];
        frame[at] = static_cast<std::uint8_t>(-sum); // ERRATA 1: header included
        if (corrupt(rng)) {
            // Any non-zero change to one data byte moves the sum off zero.
            const std::size_t where = std::uniform_int_distribution<std::size_t>(3, at - 1)(rng);
            const auto mask = static_cast<std::uint8_t>(std::uniform_int_distribution<int>(1, 255)(rng));
            frame[where] ^= mask;
            ++s.corrupted;
        }
        s.bytes.insert(s.bytes.end(), frame.begin(), frame.end());
        ++s.frames;
    }
    return s;
}

struct RunResult {
    double seconds = 0;
    oi::ParserCounters counters;
    std::size_t pending = 0;
    std::uint64_t handled = 0;
    std::int64_t checksum = 0;
};

RunResult runOnce(const Stream &s, std::size_t chunk)
{
    static constexpr std::uint8_t kExpected[] = {kGroup};
    auto parser = std::make_unique<oi::StreamParser>(oi::profile(oi::ProfileId::Create2));
    parser->setExpectedStream(kExpected);
    RunResult r;
    parser->setSnapshotHandler([&r](const oi::SensorSnapshot &snap, oi::FrameKind) {
        ++r.handled;
        r.checksum += snap.raw(22) + snap.bumpLeft() + snap.raw(43) + snap.lightBumpSignal(oi::LightBumper::Right);
    });

    const std::uint8_t *data = s.bytes.data();
    const std::size_t size = s.bytes.size();
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t at = 0; at < size; at += chunk)
        parser->feed({data + at, std::min(chunk, size - at)});
    const auto stop = std::chrono::steady_clock::now();

    r.seconds = std::chrono::duration<double>(stop - start).count();
    r.counters = parser->counters();
    r.pending = parser->pendingBytes() + parser->pendingTextBytes();
    return r;
}

// Every uncorrupted frame must come out, and nothing else.
bool verify(const Stream &s, const RunResult &r)
{
    const std::uint64_t good = s.frames - s.corrupted;
    const std::uint64_t consumed = r.counters.framesGood * s.frameSize;
    bool ok = true;
    if (r.counters.framesGood != good) {
        std::printf("ERROR: frames good %" PRIu64 ", expected %" PRIu64 "\n", r.counters.framesGood, good);
        ok = false;
    }
    if (r.handled != r.counters.framesGood) {
        std::printf("ERROR: handler called %" PRIu64 " times for %" PRIu64 " good frames\n", r.handled,
                    r.counters.framesGood);
        ok = false;
    }
    if (r.counters.checksumFailures < s.corrupted) {
        std::printf("ERROR: %" PRIu64 " checksum failures for %" PRIu64 " corrupted frames\n",
                    r.counters.checksumFailures, s.corrupted);
        ok = false;
    }
    if (r.counters.bytesDiscarded + r.counters.textBytes + consumed + r.pending != s.bytes.size()) {
        std::printf("ERROR: discarded %" PRIu64 " + consumed %" PRIu64 " + pending %zu != fed %zu\n",
                    r.counters.bytesDiscarded, consumed, r.pending, s.bytes.size());
        ok = false;
    }
    return ok;
}

bool bench(const Stream &s, std::size_t chunk)
{
    std::vector<double> seconds;
    RunResult last;
    for (int i = 0; i < kRepetitions; ++i) {
        last = runOnce(s, chunk);
        if (!verify(s, last))
            return false;
        seconds.push_back(last.seconds);
    }
    std::sort(seconds.begin(), seconds.end());
    const double best = seconds.front(), median = seconds[seconds.size() / 2];
    const double mb = static_cast<double>(s.bytes.size()) / 1e6;
    const double frames = static_cast<double>(last.counters.framesGood);
    std::printf("chunk %zu bytes, %d runs:\n", chunk, kRepetitions);
    std::printf("  best   %8.1f MB/s  %12.0f frames/s  (%.4f s)\n", mb / best, frames / best, best);
    std::printf("  median %8.1f MB/s  %12.0f frames/s  (%.4f s)\n", mb / median, frames / median, median);
    std::printf("  counters: frames good %" PRIu64 ", checksum failures %" PRIu64
                ", length mismatches %" PRIu64 ", bytes discarded %" PRIu64 ", pending %zu\n",
                last.counters.framesGood, last.counters.checksumFailures, last.counters.lengthMismatches,
                last.counters.bytesDiscarded, last.pending);
    std::printf("  (value sum %" PRId64 ")\n", last.checksum);
    return true;
}

} // namespace

int main()
{
    const Stream s = makeStream(oi::profile(oi::ProfileId::Create2));
    std::printf("stream: %zu bytes, %" PRIu64 " group-100 frames of %zu bytes, %" PRIu64
                " corrupted, %" PRIu64 " good\n",
                s.bytes.size(), s.frames, s.frameSize, s.corrupted, s.frames - s.corrupted);
    std::printf("target: >= 300 MB/s\n");
    bool ok = true;
    for (std::size_t chunk : {std::size_t{4096}, std::size_t{64}})
        ok = bench(s, chunk) && ok;
    return ok ? 0 : 1;
}
