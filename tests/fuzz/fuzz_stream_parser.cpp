// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target for StreamParser.
//
// Input layout (missing bytes read as 0):
//   byte 0   bits 0-1 profile (0 Roomba 500, 1 Create 2, 2 Create 1, 3 Create 2)
//            bit  2   legacy checksum mode (header left out of the sum)
//            bits 3-4 number of expected stream ids (0 = no expected stream)
//            bits 5-6 number of expectReply() calls
//   byte 1   bits 0-3 length of the split pattern
//   then     the expected stream ids, raw
//   then     per expectReply() call: one byte (bits 0-1 ids - 1, bits 2-3
//            times), then the ids, raw
//   then     the split pattern: piece sizes 0..255, used in turn
//   the rest is what the robot sends.
//
// Invariants (abort() on violation):
// - the same bytes fed in one piece and in the chosen pieces give identical
//   counters, pending state and snapshot sequences (kind, presence and raw
//   value of ids 0..58);
// - at each snapshot, bytesDiscarded + textBytes + pendingTextBytes() +
//   bytes of earlier good frames and replies is where the frame or reply
//   starts in the input: a stream frame
//   there starts with 19, has arrived in full and has a zero checksum;
// - at the end, bytesDiscarded + textBytes + bytes of good frames and
//   replies + pendingBytes() + pendingTextBytes() == bytes fed;
// - every text line is printable and at least StreamParser::kMinTextLine long;
// - every present value is a packet of the profile, within the range of its
//   byte count and signedness.
#include "stream_parser.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

namespace {

using Bytes = std::vector<std::uint8_t>;

void check(bool ok, const char *what)
{
    if (!ok) {
        std::fprintf(stderr, "invariant violated: %s\n", what);
        std::abort();
    }
}

class Reader {
public:
    explicit Reader(std::span<const std::uint8_t> data) : m_data(data) {}
    std::uint8_t next()
    {
        if (m_at >= m_data.size())
            return 0;
        return m_data[m_at++];
    }
    Bytes take(std::size_t n)
    {
        Bytes out;
        for (std::size_t i = 0; i < n; ++i)
            out.push_back(next());
        return out;
    }
    std::span<const std::uint8_t> rest() const { return m_data.subspan(std::min(m_at, m_data.size())); }

private:
    std::span<const std::uint8_t> m_data;
    std::size_t m_at = 0;
};

struct ReplyRequest {
    Bytes ids;
    std::size_t times = 0;
};

struct Config {
    const oi::RobotProfile *profile = nullptr;
    oi::StreamParser::ChecksumMode mode = oi::StreamParser::ChecksumMode::IncludeHeader;
    bool hasExpected = false;
    Bytes expected;
    std::vector<ReplyRequest> replies;
    Bytes split;
    std::span<const std::uint8_t> stream;
};

Config readConfig(std::span<const std::uint8_t> data)
{
    static constexpr oi::ProfileId kProfiles[] = {oi::ProfileId::Roomba500, oi::ProfileId::Create2,
                                                  oi::ProfileId::Create1, oi::ProfileId::Create2};
    Reader r(data);
    Config c;
    const std::uint8_t flags = r.next();
    const std::uint8_t splitLength = r.next() & 0x0F;
    c.profile = &oi::profile(kProfiles[flags & 3]);
    if (flags & 0x04)
        c.mode = oi::StreamParser::ChecksumMode::LegacyExcludeHeader;
    const std::size_t expectedCount = (flags >> 3) & 3;
    c.hasExpected = expectedCount > 0;
    c.expected = r.take(expectedCount);
    const std::size_t replyCalls = (flags >> 5) & 3;
    for (std::size_t i = 0; i < replyCalls; ++i) {
        const std::uint8_t spec = r.next();
        ReplyRequest req;
        req.times = (spec >> 2) & 3;
        req.ids = r.take((spec & 3) + 1u);
        c.replies.push_back(std::move(req));
    }
    c.split = r.take(splitLength);
    c.stream = r.rest();
    return c;
}

struct Record {
    oi::FrameKind kind;
    std::uint64_t present = 0;
    std::int32_t values[oi::kMaxPacketId + 1] = {};
    friend bool operator==(const Record &, const Record &) = default;
};

struct Outcome {
    std::vector<Record> records;
    oi::ParserCounters counters;
    std::size_t pendingBytes = 0;
    std::size_t pendingTextBytes = 0;
    std::size_t pendingReplies = 0;
    std::uint64_t textLines = 0;
};

void checkRanges(const oi::RobotProfile &profile, const oi::SensorSnapshot &s)
{
    for (int id = 0; id <= oi::kMaxPacketId; ++id) {
        if (!s.has(id))
            continue;
        const oi::PacketInfo *info = profile.packet(id);
        check(info != nullptr, "a present value is not a packet of the profile");
        const std::int32_t v = s.raw(id);
        std::int32_t lo = 0, hi = 0;
        if (info->bytes == 1) {
            lo = info->isSigned ? -128 : 0;
            hi = info->isSigned ? 127 : 255;
        } else {
            check(info->bytes == 2, "a packet is neither 1 nor 2 bytes");
            lo = info->isSigned ? -32768 : 0;
            hi = info->isSigned ? 32767 : 65535;
        }
        check(v >= lo && v <= hi, "a value is outside its packet's byte range");
    }
}

Outcome run(const Config &c, bool split)
{
    auto parser = std::make_unique<oi::StreamParser>(*c.profile);
    parser->setChecksumMode(c.mode);
    if (c.hasExpected)
        parser->setExpectedStream(c.expected);

    // What the parser should read as replies, in order: (bytes, times left).
    std::deque<std::pair<std::size_t, std::size_t>> replyModel;
    for (const ReplyRequest &req : c.replies) {
        std::size_t bytes = 0;
        for (std::uint8_t id : req.ids)
            bytes += static_cast<std::size_t>(std::max(0, c.profile->replySize(id)));
        const bool accepted = parser->expectReply(req.ids, req.times);
        if (accepted && req.times > 0)
            replyModel.emplace_back(bytes, req.times);
    }
    check(parser->pendingReplies() == [&] {
        std::size_t n = 0;
        for (const auto &r : replyModel)
            n += r.second;
        return n;
    }(), "pendingReplies() disagrees with the accepted expectReply() calls");

    const std::span<const std::uint8_t> input = c.stream;
    std::size_t fed = 0;     // bytes handed to feed() so far, this call's included
    std::size_t consumed = 0; // bytes of good frames and replies so far
    Outcome out;
    parser->setSnapshotHandler([&](const oi::SensorSnapshot &s, oi::FrameKind kind) {
        const std::size_t start = parser->counters().bytesDiscarded + parser->counters().textBytes
                                  + parser->pendingTextBytes() + consumed;
        std::size_t size = 0;
        if (kind == oi::FrameKind::Stream) {
            check(start + 2 <= fed, "a stream frame starts beyond the bytes fed");
            check(input[start] == 19, "a stream frame does not start with 19");
            size = std::size_t{input[start + 1]} + 3;
            check(start + size <= fed, "a stream frame ends beyond the bytes fed");
            unsigned sum = 0;
            const std::size_t from = c.mode == oi::StreamParser::ChecksumMode::IncludeHeader ? 0 : 1;
            for (std::size_t i = from; i < size; ++i)
                sum += input[start + i];
            check((sum & 0xFF) == 0, "a stream frame was accepted with a bad checksum");
        } else {
            check(!replyModel.empty(), "a reply arrived that was not expected");
            size = replyModel.front().first;
            if (--replyModel.front().second == 0)
                replyModel.pop_front();
            check(start + size <= fed, "a reply ends beyond the bytes fed");
        }
        consumed += size;
        checkRanges(*c.profile, s);

        Record rec{kind};
        for (int id = 0; id <= oi::kMaxPacketId; ++id) {
            if (s.has(id)) {
                rec.present |= std::uint64_t{1} << id;
                rec.values[id] = s.raw(id);
            }
        }
        out.records.push_back(rec);
    });

    parser->setTextHandler([&](std::string_view line) {
        check(line.size() >= oi::StreamParser::kMinTextLine, "a text line shorter than the shortest");
        for (const char ch : line)
            check((ch >= 0x20 && ch < 0x7F) || ch == '\t', "a text line with a byte that is not printable");
        ++out.textLines;
    });

    if (!split) {
        fed = input.size();
        parser->feed(input);
    } else {
        bool anyNonZero = false;
        for (std::uint8_t b : c.split)
            anyNonZero = anyNonZero || b != 0;
        std::size_t at = 0, turn = 0;
        while (at < input.size()) {
            std::size_t piece = anyNonZero ? c.split[turn++ % c.split.size()] : 1;
            piece = std::min(piece, input.size() - at);
            fed += piece;
            parser->feed(input.subspan(at, piece)); // a zero piece feeds nothing, harmlessly
            at += piece;
        }
    }

    out.counters = parser->counters();
    out.pendingBytes = parser->pendingBytes();
    out.pendingReplies = parser->pendingReplies();
    check(out.counters.framesGood + out.counters.repliesGood == out.records.size(),
          "frame and reply counters disagree with the snapshots delivered");
    out.pendingTextBytes = parser->pendingTextBytes();
    check(out.counters.textLines == out.textLines, "textLines disagrees with the lines delivered");
    check(out.counters.bytesDiscarded + out.counters.textBytes + consumed + out.pendingBytes + out.pendingTextBytes
              == input.size(),
          "discarded + text + consumed + pending != bytes fed");
    std::size_t modelPending = 0;
    for (const auto &r : replyModel)
        modelPending += r.second;
    check(out.pendingReplies == modelPending, "pendingReplies() disagrees with the replies read");
    return out;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const Config config = readConfig({data, size});
    const Outcome whole = run(config, false);
    const Outcome pieces = run(config, true);
    check(whole.counters == pieces.counters, "counters depend on how the bytes were split");
    check(whole.pendingBytes == pieces.pendingBytes, "pending bytes depend on the split");
    check(whole.pendingTextBytes == pieces.pendingTextBytes, "pending text depends on the split");
    check(whole.pendingReplies == pieces.pendingReplies, "pending replies depend on the split");
    check(whole.records == pieces.records, "snapshots depend on how the bytes were split");
    return 0;
}
