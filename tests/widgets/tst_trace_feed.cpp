// SPDX-License-Identifier: GPL-3.0-or-later
#include "plot_samples.h"
#include "sensor_history.h"
#include "trace_feed.h"

#include <QTest>

#include "custom_plot.h"

#include <cmath>

namespace {

QList<double> keys(const QCPGraph *graph)
{
    QList<double> out;
    for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it)
        out << it->key;
    return out;
}

} // namespace

class TestTraceFeed : public QObject {
    Q_OBJECT
    QCustomPlot m_plot;

private slots:
    void liveAppendsOnlyTheNewSamples()
    {
        SensorHistory h;
        feed(h, 0, 100); // 0 .. 9.9 s
        TraceFeed trace(22, m_plot.addGraph());
        // Columns narrower than a sample: every sample is a point.
        QVERIFY(trace.update(&h, 0, 10, 0.01, true));
        QCOMPARE(trace.graph()->dataCount(), 100);
        QCOMPARE(trace.changedFrom(), -std::numeric_limits<double>::infinity()); // drawn whole
        trace.takeChanged();
        QVERIFY(!trace.update(&h, 0, 10, 0.01, true)); // nothing new
        QCOMPARE(trace.changedFrom(), TraceFeed::kUnchanged);

        feed(h, 100, 1);
        QVERIFY(trace.update(&h, 0, 10, 0.01, true));
        QCOMPARE(trace.graph()->dataCount(), 101);
        QCOMPARE(keys(trace.graph()).last(), 10.0);
        // Only the line on from the last sample that stayed is drawn anew.
        QCOMPARE(trace.changedFrom(), 9.9);
    }

    void pausedLoadsASpanEitherSideOfTheView()
    {
        SensorHistory h;
        feed(h, 0, 1000); // 0 .. 99.9 s
        TraceFeed trace(22, m_plot.addGraph());
        QVERIFY(trace.update(&h, 40, 50, 0.01, false));
        // 30 .. 60 s, and one sample either side so lines reach the edges.
        QCOMPARE(keys(trace.graph()).first(), 29.9);
        QCOMPARE(keys(trace.graph()).last(), 60.1);
        QVERIFY(!trace.update(&h, 35, 45, 0.01, false)); // a small pan: nothing to load
        QVERIFY(trace.update(&h, 70, 80, 0.01, false));  // out of what is loaded
        QCOMPARE(keys(trace.graph()).first(), 59.9);
        // New samples do not move a paused view's line.
        feed(h, 1000, 10);
        QVERIFY(!trace.update(&h, 70, 80, 0.01, false));
    }

    void aMissingChannelEmptiesTheGraph()
    {
        SensorHistory h;
        feed(h, 0, 10);
        TraceFeed trace(22, m_plot.addGraph());
        QVERIFY(trace.update(&h, 0, 10, 0.01, true));
        QVERIFY(trace.update(nullptr, 0, 10, 0.01, true)); // it had points
        QCOMPARE(trace.graph()->dataCount(), 0);
        QVERIFY(!trace.update(nullptr, 0, 10, 0.01, true));
    }

    void comparisonIsShiftedAndLoadedOnce()
    {
        SensorHistory other;
        feed(other, 0, 100); // 0 .. 9.9 s
        ComparisonFeed comparison(22, m_plot.addGraph());
        QVERIFY(comparison.update(other, 2.5, 0, 20, 0.01));
        QCOMPARE(comparison.graph()->dataCount(), 100);
        QCOMPARE(keys(comparison.graph()).first(), 2.5);
        QCOMPARE(comparison.graph()->data()->constBegin()->value, 14000.0);
        QVERIFY(!comparison.update(other, 2.5, 0, 20, 0.01)); // unchanged
        QVERIFY(!comparison.update(other, 2.5, 5, 25, 0.01)); // inside what is loaded
        QVERIFY(comparison.update(other, 1.0, 5, 25, 0.01));  // moved
        QCOMPARE(keys(comparison.graph()).first(), 1.0);
        feed(other, 100, 5);                                  // the other run changed
        QVERIFY(comparison.update(other, 1.0, 5, 25, 0.01));
        QCOMPARE(comparison.graph()->dataCount(), 105);
        // Wider columns: at most two points a column.
        QVERIFY(comparison.update(other, 1.0, 5, 25, 1.0));
        QVERIFY(comparison.graph()->dataCount() <= 2 * 11);
    }
};

QTEST_MAIN(TestTraceFeed)
#include "tst_trace_feed.moc"
