// SPDX-License-Identifier: GPL-3.0-or-later
#include "oi_test_support.h"
#include "stream_parser.h"

#include <QTest>

#include <random>

using namespace oi;
using namespace oi_test;

namespace {

// What one snapshot carried: (id, value) for every present packet.
using Values = std::vector<std::pair<int, int>>;

Values valuesOf(const SensorSnapshot &s)
{
    Values out;
    for (int id = 0; id <= kMaxPacketId; ++id)
        if (s.has(id))
            out.emplace_back(id, s.raw(id));
    return out;
}

struct Run {
    std::vector<Values> frames;
    std::vector<FrameKind> kinds;
    ParserCounters counters;
    std::size_t pending = 0;
};

// Feeds `input` in pieces whose sizes come from `splits` (cycled); an empty
// `splits` feeds it whole.
Run feedInPieces(StreamParser &parser, const Bytes &input, const std::vector<std::size_t> &splits)
{
    Run run;
    parser.setSnapshotHandler([&run](const SensorSnapshot &s, FrameKind k) {
        run.frames.push_back(valuesOf(s));
        run.kinds.push_back(k);
    });
    std::size_t at = 0, i = 0;
    while (at < input.size()) {
        const std::size_t n = splits.empty() ? input.size() : std::min(splits[i++ % splits.size()], input.size() - at);
        parser.feed(std::span(input).subspan(at, n));
        at += n;
    }
    run.counters = parser.counters();
    run.pending = parser.pendingBytes();
    return run;
}

// A frame for the stream 29 (2 bytes), 13 (1), 22 (2) with this data, which
// the caller keeps free of 19s where a test needs exact counters.
Bytes frameFor(int cliff, int virtualWall, int voltage)
{
    return streamFrame({29, std::uint8_t(cliff >> 8), std::uint8_t(cliff), 13, std::uint8_t(virtualWall),
                        22, std::uint8_t(voltage >> 8), std::uint8_t(voltage)});
}
const std::uint8_t kStreamIds[] = {29, 13, 22};

Values expectedValues(int cliff, int virtualWall, int voltage)
{
    return {{13, virtualWall}, {22, voltage}, {29, cliff}};
}

} // namespace

class TestStreamParser : public QObject {
    Q_OBJECT
private slots:
    void create2Example()
    {
        // ERRATA 1: the Create 2 document's example, header included in the sum.
        StreamParser parser(profile(ProfileId::Create2));
        const Run run = feedInPieces(parser, bytesFrom("19 5 29 2 25 13 0 163"), {});
        QCOMPARE(int(run.frames.size()), 1);
        // The document calls this 549 (0x0225), reading "25" as hex; the bytes are
        // decimal (the checksum only balances with 25), so the value is 2*256+25.
        const Values expected = {{13, 0}, {29, 537}};
        QCOMPARE(run.frames[0], expected);
        QCOMPARE(run.counters, (ParserCounters{1, 0, 0, 0, 0}));
    }

    void randomSplits_data()
    {
        QTest::addColumn<bool>("expectStream");
        QTest::addColumn<int>("seed");
        for (int seed = 1; seed <= 20; ++seed) {
            QTest::newRow(qPrintable(QString("expected, seed %1").arg(seed))) << true << seed;
            QTest::newRow(qPrintable(QString("unknown, seed %1").arg(seed))) << false << seed;
        }
    }
    void randomSplits()
    {
        // Frames whose data may hold 19s, fed in random pieces: every split
        // gives every frame, with the same values and counters.
        QFETCH(bool, expectStream);
        QFETCH(int, seed);
        std::mt19937 rng(seed);
        Bytes input;
        std::vector<Values> expected;
        for (int i = 0; i < 300; ++i) {
            const int cliff = int(rng() % 4096), vw = int(rng() % 2), volts = int(rng() % 65536);
            const Bytes f = frameFor(cliff, vw, volts);
            input.insert(input.end(), f.begin(), f.end());
            expected.push_back(expectedValues(cliff, vw, volts));
        }
        std::vector<std::size_t> splits;
        for (int i = 0; i < 64; ++i)
            splits.push_back(1 + rng() % (i % 3 == 0 ? 3 : 40));

        StreamParser whole(profile(ProfileId::Create2)), pieces(profile(ProfileId::Create2));
        if (expectStream) {
            QVERIFY(whole.setExpectedStream(kStreamIds));
            QVERIFY(pieces.setExpectedStream(kStreamIds));
        }
        const Run a = feedInPieces(whole, input, {});
        const Run b = feedInPieces(pieces, input, splits);
        QCOMPARE(a.frames, expected);
        QCOMPARE(b.frames, expected);
        QCOMPARE(a.counters, (ParserCounters{300, 0, 0, 0, 0}));
        QCOMPARE(b.counters, a.counters);
        QCOMPARE(b.pending, std::size_t(0));
    }

    void junkBeforeAndBetweenFrames()
    {
        // Junk without 19s: exactly the junk is discarded, no frame is lost.
        std::mt19937 rng(7);
        Bytes input;
        std::uint64_t junk = 0;
        for (int i = 0; i < 100; ++i) {
            const int n = int(rng() % 20);
            for (int j = 0; j < n; ++j) {
                std::uint8_t b = std::uint8_t(rng());
                if (b == 19)
                    b = 20;
                input.push_back(b);
            }
            junk += std::uint64_t(n);
            const Bytes f = frameFor(1000 + i, 1, 14000);
            input.insert(input.end(), f.begin(), f.end());
        }
        for (bool expectStream : {false, true}) {
            StreamParser parser(profile(ProfileId::Create2));
            if (expectStream)
                parser.setExpectedStream(kStreamIds);
            const Run run = feedInPieces(parser, input, {5, 1, 17});
            QCOMPARE(int(run.frames.size()), 100);
            for (int i = 0; i < 100; ++i)
                QCOMPARE(run.frames[i], expectedValues(1000 + i, 1, 14000));
            QCOMPARE(run.counters, (ParserCounters{100, 0, 0, 0, junk}));
        }
    }

    void frameEndsInTheBytesFed()
    {
        // Junk, frames and a reply fed in any pieces: each handler call knows
        // the offset just after its frame, counted over everything fed.
        Bytes input = bytesFrom("7 7");
        std::vector<std::uint64_t> expected;
        for (int i = 0; i < 20; ++i) {
            const Bytes f = frameFor(1000 + i, 1, 14000);
            input.insert(input.end(), f.begin(), f.end());
            expected.push_back(input.size());
            input.push_back(std::uint8_t(i % 5)); // junk between frames
        }
        for (const std::vector<std::size_t> &splits : {std::vector<std::size_t>{}, {1}, {3, 7}, {64}}) {
            StreamParser parser(profile(ProfileId::Create2));
            parser.setExpectedStream(kStreamIds);
            std::vector<std::uint64_t> ends;
            parser.setSnapshotHandler([&](const SensorSnapshot &, FrameKind) { ends.push_back(parser.frameEndOffset()); });
            std::size_t at = 0, i = 0;
            while (at < input.size()) {
                const std::size_t n = splits.empty() ? input.size() : std::min(splits[i++ % splits.size()], input.size() - at);
                parser.feed(std::span(input).subspan(at, n));
                at += n;
            }
            QCOMPARE(ends, expected);
            // A reply's end too, after the frames.
            const std::uint8_t query[] = {13};
            QVERIFY(parser.expectReply(query));
            parser.feed(bytesFrom("1 9"));
            QCOMPARE(ends.back(), std::uint64_t(input.size() + 1));
            // reset() counts from zero again.
            parser.reset();
            parser.setExpectedStream(kStreamIds);
            const Bytes f = frameFor(5, 0, 14000);
            parser.feed(f);
            QCOMPARE(ends.back(), std::uint64_t(f.size()));
        }
    }

    void framesOnlyFindsTheSameFramesWithoutTheirValues()
    {
        // Good frames, one whose ids are swapped (right length and checksum),
        // one with a bad checksum and junk: both modes keep the same frames
        // and say they end at the same bytes.
        Bytes input = bytesFrom("7 7");
        for (int i = 0; i < 12; ++i) {
            const Bytes f = i == 4   ? streamFrame({13, 1, 29, 3, 232, 22, 54, 176})
                            : i == 7 ? [] { Bytes b = frameFor(1000, 1, 14000); b.back() ^= 1; return b; }()
                                     : frameFor(1000 + i, i % 2, 14000 + i);
            input.insert(input.end(), f.begin(), f.end());
            input.push_back(std::uint8_t(i % 5));
        }
        const auto run = [&input](bool framesOnly) {
            StreamParser parser(profile(ProfileId::Create2));
            parser.setExpectedStream(kStreamIds);
            parser.setFramesOnly(framesOnly);
            std::vector<std::uint64_t> ends;
            std::vector<Values> values;
            parser.setSnapshotHandler([&](const SensorSnapshot &s, FrameKind) {
                ends.push_back(parser.frameEndOffset());
                values.push_back(valuesOf(s));
            });
            parser.feed(input);
            return std::pair(ends, values);
        };
        const auto [decodedEnds, decodedValues] = run(false);
        const auto [onlyEnds, onlyValues] = run(true);
        QCOMPARE(decodedEnds.size(), std::size_t(10));
        QCOMPARE(onlyEnds, decodedEnds);
        QCOMPARE(decodedValues.front(), (Values{{13, 0}, {22, 14000}, {29, 1000}}));
        for (const Values &v : onlyValues)
            QVERIFY(v.empty());
    }

    void strayHeadersBeforeAndInsideFrames()
    {
        // A frame whose data holds 19s, then stray 19s before frames.
        const Bytes dataWith19 = frameFor(19 * 256 + 19, 1, 19);
        Bytes input = dataWith19;
        for (int i = 0; i < 10; ++i) {
            input.push_back(19);
            if (i % 3 == 0)
                input.push_back(19); // two in a row
            const Bytes f = frameFor(i, 0, 15000);
            input.insert(input.end(), f.begin(), f.end());
        }
        StreamParser parser(profile(ProfileId::Create2));
        parser.setExpectedStream(kStreamIds);
        const Run run = feedInPieces(parser, input, {3});
        QCOMPARE(int(run.frames.size()), 11);
        QCOMPARE(run.frames[0], expectedValues(19 * 256 + 19, 1, 19));
        for (int i = 0; i < 10; ++i)
            QCOMPARE(run.frames[1 + i], expectedValues(i, 0, 15000));
        // Each stray 19 names n-bytes 19 or 11 where 11 is expected: refused at once.
        QCOMPARE(run.counters, (ParserCounters{11, 0, 0, 14, 14}));
    }

    void badChecksums()
    {
        // Every third frame's checksum is wrong. The data holds no 19s, so
        // scanning on from the failed header lands on the next frame.
        Bytes input;
        int good = 0;
        for (int i = 0; i < 30; ++i) {
            Bytes f = frameFor(100 + i, 0, 16000);
            if (i % 3 == 1)
                f.back() = std::uint8_t(f.back() + 1);
            else
                ++good;
            input.insert(input.end(), f.begin(), f.end());
        }
        for (bool expectStream : {false, true}) {
            StreamParser parser(profile(ProfileId::Create2));
            if (expectStream)
                parser.setExpectedStream(kStreamIds);
            const Run run = feedInPieces(parser, input, {7});
            QCOMPARE(int(run.frames.size()), good);
            QCOMPARE(run.counters, (ParserCounters{std::uint64_t(good), 0, 10, 0, 10 * 11}));
        }
    }

    void corruptedDataLengthMismatch()
    {
        // A frame with a correct checksum whose packets do not add up to
        // n-bytes (29 needs 2 bytes; only one follows).
        StreamParser parser(profile(ProfileId::Create2));
        const Bytes bad = streamFrame({29, 1});
        const Bytes unknownId = streamFrame({99, 1, 1});
        Bytes input = bad;
        input.insert(input.end(), unknownId.begin(), unknownId.end());
        const Bytes good = streamFrame({7, 3});
        input.insert(input.end(), good.begin(), good.end());
        const Run run = feedInPieces(parser, input, {});
        QCOMPARE(int(run.frames.size()), 1);
        QCOMPARE(run.counters, (ParserCounters{1, 0, 0, 2, std::uint64_t(bad.size() + unknownId.size())}));
        // With an expected list, a frame for another list is refused too.
        StreamParser expecting(profile(ProfileId::Create2));
        expecting.setExpectedStream(kStreamIds);
        const Bytes otherList = streamFrame({22, 1, 2, 29, 1, 2, 13, 0}); // same size, other order
        const Run r2 = feedInPieces(expecting, otherList, {});
        QCOMPARE(int(r2.frames.size()), 0);
        QCOMPARE(r2.counters.lengthMismatches, 1u);
    }

    void truncation()
    {
        const Bytes f = frameFor(5, 1, 14500);
        for (std::size_t cut = 1; cut < f.size(); ++cut) {
            StreamParser parser(profile(ProfileId::Create2));
            Bytes input = f;
            input.insert(input.end(), f.begin(), f.begin() + std::ptrdiff_t(cut));
            const Run run = feedInPieces(parser, input, {});
            QCOMPARE(int(run.frames.size()), 1);
            QCOMPARE(run.pending, cut);
            QCOMPARE(run.counters, (ParserCounters{1, 0, 0, 0, 0}));
            // The rest arrives later: the frame completes.
            parser.feed(std::span(f).subspan(cut));
            QCOMPARE(parser.counters().framesGood, 2u);
            QCOMPARE(parser.pendingBytes(), std::size_t(0));
        }
    }

    void repliesBetweenFrames()
    {
        StreamParser parser(profile(ProfileId::Roomba500));
        Run run;
        parser.setSnapshotHandler([&run](const SensorSnapshot &s, FrameKind k) {
            run.frames.push_back(valuesOf(s));
            run.kinds.push_back(k);
        });
        const Bytes f = streamFrame({7, 1});
        parser.feed(f);
        const std::uint8_t query[] = {24, 13};
        QVERIFY(parser.expectReply(query, 2));
        QCOMPARE(parser.pendingReplies(), std::size_t(2));
        parser.feed(bytesFrom("19 1 2 0")); // two replies; 19 is data here
        QCOMPARE(parser.pendingReplies(), std::size_t(0));
        parser.feed(f);
        QCOMPARE(int(run.frames.size()), 4);
        const std::vector<FrameKind> kinds = {FrameKind::Stream, FrameKind::Reply, FrameKind::Reply,
                                              FrameKind::Stream};
        QCOMPARE(run.kinds, kinds);
        QCOMPARE(run.frames[1], (Values{{13, 1}, {24, 19}}));
        QCOMPARE(run.frames[2], (Values{{13, 0}, {24, 2}}));
        QCOMPARE(parser.counters(), (ParserCounters{2, 2, 0, 0, 0}));
        // A reply that never comes can be cancelled.
        parser.expectReply(query);
        parser.cancelReplies();
        parser.feed(f);
        QCOMPARE(parser.counters().framesGood, 3u);
    }

    void groupsInStreams()
    {
        // A stream of group 100 on the Create 2: 80 data bytes, every packet 7..58.
        Bytes payload{100};
        for (int i = 0; i < 80; ++i)
            payload.push_back(std::uint8_t(i));
        StreamParser parser(profile(ProfileId::Create2));
        const std::uint8_t ids[] = {100};
        QVERIFY(parser.setExpectedStream(ids));
        const Run run = feedInPieces(parser, streamFrame(payload), {});
        QCOMPARE(int(run.frames.size()), 1);
        QCOMPARE(int(run.frames[0].size()), 52);
        // The Create has no group 100.
        StreamParser create(profile(ProfileId::Create1));
        QVERIFY(!create.setExpectedStream(ids));
        const Run none = feedInPieces(create, streamFrame(payload), {});
        QCOMPARE(int(none.frames.size()), 0);
        QCOMPARE(none.counters.lengthMismatches, 1u);
    }

    void finishScansWhatAStray19Held()
    {
        // A stray 19 claims 48 bytes; the two frames behind it are fewer, so
        // feeding alone holds them. At the end of the input they come out.
        StreamParser parser(profile(ProfileId::Create2));
        Bytes input{7, 19, 48};
        for (int i = 0; i < 2; ++i) {
            const Bytes frame = frameFor(537 + i, 0, 15000);
            input.insert(input.end(), frame.begin(), frame.end());
        }
        input.push_back(19); // and a lone header at the very end
        Run run = feedInPieces(parser, input, {});
        QCOMPARE(int(run.frames.size()), 0);
        QVERIFY(parser.pendingBytes() > 0);
        parser.finish();
        QCOMPARE(parser.pendingBytes(), std::size_t(0));
        QCOMPARE(parser.counters().framesGood, 2u);
        QCOMPARE(parser.counters().bytesDiscarded, 1u + 2u + 1u); // 7, the stray 19 48, the lone 19
        QCOMPARE(int(run.frames.size()), 2);
        QCOMPARE(run.frames[1], (Values{{13, 0}, {22, 15000}, {29, 538}}));

        // An unfinished reply is not a stray 19: it stays pending.
        StreamParser replies(profile(ProfileId::Create2));
        const std::uint8_t ids[] = {22};
        QVERIFY(replies.expectReply(ids));
        replies.feed(bytesFrom("19"));
        replies.finish();
        QCOMPARE(replies.pendingBytes(), std::size_t(1));
        QCOMPARE(replies.pendingReplies(), std::size_t(1));
    }

    void resetForgetsEverything()
    {
        StreamParser parser(profile(ProfileId::Create2));
        parser.feed(bytesFrom("1 2 19 5 29"));
        QVERIFY(parser.pendingBytes() > 0);
        parser.reset();
        QCOMPARE(parser.pendingBytes(), std::size_t(0));
        QCOMPARE(parser.counters(), ParserCounters{});
    }

    // A docked Roomba prints its charging status between frames: the lines
    // come out as text, every frame still decodes, whatever the split, and
    // no byte counts as discarded. A stray 19 or junk byte ends a line.
    void textBetweenFramesIsTheRobotsWords()
    {
        const std::string line = "bat:   min 0  sec 12  mV 16421  mA 1183  tenths-deg 254  mAH 2580  state 2  mode 1";
        Bytes input;
        for (int i = 0; i < 6; ++i) {
            const Bytes f = frameFor(100 + i, 0, 16000);
            input.insert(input.end(), f.begin(), f.end());
            if (i % 2 == 0) {
                input.insert(input.end(), line.begin(), line.end());
                input.insert(input.end(), {'\r', '\n'});
            }
        }
        for (bool expectStream : {false, true}) {
            for (const std::vector<std::size_t> &splits : {std::vector<std::size_t>{}, {1}, {7}, {30}}) {
                StreamParser parser(profile(ProfileId::Create2));
                if (expectStream)
                    parser.setExpectedStream(kStreamIds);
                std::vector<std::string> lines;
                parser.setTextHandler([&](std::string_view l) { lines.emplace_back(l); });
                const Run run = feedInPieces(parser, input, splits);
                QCOMPARE(int(run.frames.size()), 6);
                QCOMPARE(lines, std::vector<std::string>(3, line));
                QCOMPARE(run.counters.bytesDiscarded, 0u);
                QCOMPARE(run.counters.textLines, 3u);
                QCOMPARE(run.counters.textBytes, 3 * (line.size() + 2));
            }
        }
        // Too short to be a line, cut by a junk byte, or by a frame: discarded.
        StreamParser parser(profile(ProfileId::Create2));
        std::vector<std::string> lines;
        parser.setTextHandler([&](std::string_view l) { lines.emplace_back(l); });
        Bytes junk{'o', 'k', '\n', 'b', 'a', 't', 0x01, ':', '\n', 'b', 'a', 't', ':'};
        const Bytes f = frameFor(100, 0, 16000);
        junk.insert(junk.end(), f.begin(), f.end());
        junk.insert(junk.end(), {' ', 'm', 'V', '\r', '\n'});
        const Run run = feedInPieces(parser, junk, {});
        QCOMPARE(int(run.frames.size()), 1);
        QVERIFY(lines.empty());
        QCOMPARE(run.counters.textBytes, 0u);
        QCOMPARE(run.counters.bytesDiscarded, std::uint64_t(junk.size() - f.size()));
        QCOMPARE(parser.pendingTextBytes(), std::size_t(0));
    }

    // A reader waiting for an unframed reply takes the robot's lines out.
    void withoutTextLinesLeavesTheReply()
    {
        const std::string text = "bat:   min 0  sec 1  mV 16000\r\n";
        Bytes received(text.begin(), text.end());
        received.insert(received.end(), {1, 0});
        received.insert(received.end(), text.begin(), text.end());
        QCOMPARE(withoutTextLines(received), (Bytes{1, 0}));
        // Printable reply bytes with no line end stay.
        QCOMPARE(withoutTextLines(Bytes{'a', 'b', 'c', 'd', 'e', 3}), (Bytes{'a', 'b', 'c', 'd', 'e', 3}));
    }

    // A reply is read only whole and consistent: lines of text before it or
    // among its bytes are the robot's words, whatever the split, and bytes
    // that make a mode no robot has are not read as one.
    void aReplyAmongTextIsReadWhole()
    {
        const std::string text = "bat:   min 0  sec 1  mV 16000  mA 1500  state 2  mode 1\r\n";
        const Bytes ids{35, 7};
        Bytes received(text.begin(), text.end());
        received.push_back(2); // Safe
        received.insert(received.end(), text.begin(), text.end());
        received.push_back(oi::bit::BumpLeft);
        const auto feed = [](StreamParser &parser, const Bytes &bytes, std::size_t piece) {
            std::vector<SensorSnapshot> replies;
            parser.setSnapshotHandler([&](const SensorSnapshot &r, FrameKind k) {
                if (k == FrameKind::Reply)
                    replies.push_back(r);
            });
            for (std::size_t at = 0; at < bytes.size(); at += piece)
                parser.feed(std::span(bytes).subspan(at, std::min(piece, bytes.size() - at)));
            return replies;
        };
        for (std::size_t piece : {received.size(), std::size_t(1), std::size_t(5), text.size(), text.size() + 1}) {
            StreamParser parser(profile(ProfileId::Create2));
            std::vector<std::string> lines;
            parser.setTextHandler([&](std::string_view l) { lines.emplace_back(l); });
            QVERIFY(parser.expectReply(ids));
            const std::vector<SensorSnapshot> replies = feed(parser, received, piece);
            QCOMPARE(int(replies.size()), 1);
            QCOMPARE(replies[0].oiMode(), oi::OiMode::Safe);
            QVERIFY(replies[0].bumpLeft());
            QCOMPARE(int(lines.size()), 2);
            QCOMPARE(parser.pendingReplies(), std::size_t(0));
        }
        // A line still coming holds the reply back; junk is not read as a mode.
        StreamParser parser(profile(ProfileId::Create2));
        QVERIFY(parser.expectReply(Bytes{35}));
        QVERIFY(feed(parser, Bytes{'b', 'a', 't', ':'}, 4).empty());
        const std::vector<SensorSnapshot> rest = feed(parser, Bytes{' ', 'x', '\r', '\n', 0xC8, 3}, 6);
        QCOMPARE(int(rest.size()), 1);
        QCOMPARE(rest[0].oiMode(), oi::OiMode::Full);
    }
};

QTEST_GUILESS_MAIN(TestStreamParser)
#include "tst_stream_parser.moc"
