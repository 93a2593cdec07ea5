// SPDX-License-Identifier: GPL-3.0-or-later
#include "stream_parser.h"

#include <QTest>

using namespace oi;

class TestStreamParser : public QObject {
    Q_OBJECT
private slots:
    void create2Example()
    {
        // ERRATA 1: the Create 2 document's example, header included in the sum.
        StreamParser parser(profile(ProfileId::Create2));
        int frames = 0;
        SensorSnapshot last;
        parser.setSnapshotHandler([&](const SensorSnapshot &s, FrameKind) { ++frames; last = s; });
        const std::uint8_t bytes[] = {19, 5, 29, 2, 25, 13, 0, 163};
        parser.feed(bytes);
        QCOMPARE(frames, 1);
        // The document calls this 549 (0x0225), reading "25" as hex; the bytes are
        // decimal (the checksum only balances with 25), so the value is 2*256+25.
        QCOMPARE(last.raw(29), 537);
        QVERIFY(last.has(13));
        QCOMPARE(last.raw(13), 0);
    }
};

QTEST_GUILESS_MAIN(TestStreamParser)
#include "tst_stream_parser.moc"
