// SPDX-License-Identifier: GPL-3.0-or-later
// DESIGN: the parser allocates nothing per byte. Every allocation in this
// executable is counted, so feeding can be checked to make none.
#include "oi_test_support.h"
#include "stream_parser.h"

#include <QTest>

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> g_allocations{0};
}

void *operator new(std::size_t size)
{
    ++g_allocations;
    if (void *p = std::malloc(size ? size : 1))
        return p;
    throw std::bad_alloc();
}
void operator delete(void *p) noexcept { std::free(p); }
void operator delete(void *p, std::size_t) noexcept { std::free(p); }

using namespace oi;
using namespace oi_test;

class TestParserAllocations : public QObject {
    Q_OBJECT
private slots:
    void feedingAllocatesNothing_data()
    {
        QTest::addColumn<int>("chunk");
        QTest::newRow("byte by byte") << 1;
        QTest::newRow("serial-sized chunks") << 64;
        QTest::newRow("large chunks") << 4096;
    }
    void feedingAllocatesNothing()
    {
        QFETCH(int, chunk);
        // Group 100 frames with junk, stray 19s and a corrupted frame mixed in.
        Bytes payload{100};
        for (int i = 0; i < 80; ++i)
            payload.push_back(std::uint8_t(i * 7));
        const Bytes frame = streamFrame(payload);
        Bytes input;
        for (int i = 0; i < 2000; ++i) {
            if (i % 10 == 0)
                input.push_back(19);
            if (i % 17 == 0)
                input.insert(input.end(), {1, 2, 3});
            input.insert(input.end(), frame.begin(), frame.end());
            if (i % 50 == 0)
                input[input.size() - 5] ^= 0x40;
        }
        StreamParser parser(profile(ProfileId::Create2));
        const std::uint8_t ids[] = {100};
        QVERIFY(parser.setExpectedStream(ids));
        long frames = 0;
        parser.setSnapshotHandler([&frames](const SensorSnapshot &s, FrameKind) { frames += s.has(58); });

        const long before = g_allocations.load();
        for (std::size_t at = 0; at < input.size(); at += std::size_t(chunk))
            parser.feed(std::span(input).subspan(at, std::min(std::size_t(chunk), input.size() - at)));
        const long during = g_allocations.load() - before;

        QCOMPARE(during, 0L);
        QCOMPARE(frames, 2000L - 40L);
        QCOMPARE(parser.counters().checksumFailures, 40u);
    }
};

QTEST_GUILESS_MAIN(TestParserAllocations)
#include "tst_parser_allocations.moc"
