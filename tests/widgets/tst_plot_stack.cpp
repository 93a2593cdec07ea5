// SPDX-License-Identifier: GPL-3.0-or-later
#include "channel_chooser.h"
#include "plot_stack.h"
#include "plot_samples.h"
#include "sensor_history.h"
#include "trace_columns.h"
#include "value_axes.h"

#include <QAction>
#include <QApplication>
#include <QLabel>
#include <QMenu>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTest>

#include "custom_plot.h"

#include <algorithm>
#include <cmath>

using oi::ProfileId;
using oi::SensorSnapshot;

namespace {

// Points of a graph whose time lies within the plot's visible range.
int visiblePoints(QCustomPlot *plot, int graph)
{
    const QCPRange r = plot->xAxis->range();
    auto data = plot->graph(graph)->data();
    return int(data->findEnd(r.upper, false) - data->findBegin(r.lower, false));
}

int heldPoints(const SensorHistory &h, int id, const QCPRange &r)
{
    return int(h.upperBound(id, r.upper) - h.lowerBound(id, r.lower));
}

// A plot draws only while it is shown; wide enough that 10 samples a
// second never share a pixel column.
void showWide(PlotStack &plots)
{
    plots.resize(900, 500);
    plots.show();
    QVERIFY(QTest::qWaitForWindowExposed(&plots));
}

// A shown panel of one plot of `channels`, reading its own history, on a
// clock the test moves.
struct Scene {
    SensorHistory history;
    PlotStack plots;
    qint64 nowMs = 0;
    explicit Scene(std::vector<int> channels)
    {
        plots.setClock([this] { return nowMs; });
        showWide(plots);
        plots.setHistory(&history);
        QVERIFY(plots.setChannels(0, std::move(channels)));
    }
    // A display timer's tick later.
    void refresh()
    {
        nowMs += 33;
        plots.refresh();
    }
};

// The tracer's value label, if it is showing.
QLabel *visibleReadout(QCustomPlot *plot)
{
    auto *label = plot->findChild<QLabel *>(QStringLiteral("tracerReadout"));
    return label && !label->isHidden() ? label : nullptr;
}

int visibleTracers(QCustomPlot *plot)
{
    int n = 0;
    for (int i = 0; i < plot->itemCount(); ++i)
        if (auto *tracer = qobject_cast<QCPItemTracer *>(plot->item(i)))
            n += tracer->visible() ? 1 : 0;
    return n;
}

} // namespace

class TestPlotStack : public QObject {
    Q_OBJECT
private slots:
    void followsTheNewestSample()
    {
        Scene scene({22});
        SensorHistory &h = scene.history;
        PlotStack &plots = scene.plots;
        plots.setWindowSeconds(10);
        feed(h, 0, 1000); // 0 .. 99.9 s
        plots.refresh();
        // The right edge is the next step (half a second here) at or after the newest sample.
        QCOMPARE(plots.timeRange().upper, 100.0);
        QCOMPARE(plots.timeRange().lower, 90.0);
        QCustomPlot *plot = plots.plot(0);
        QCOMPARE(plot->xAxis->range().upper, 100.0);
        QCOMPARE(plot->graphCount(), 1);
        QCOMPARE(visiblePoints(plot, 0), heldPoints(h, 22, plot->xAxis->range()));
        QCOMPARE(visiblePoints(plot, 0), 100);
        QCOMPARE((plot->graph(0)->data()->constEnd() - 1)->key, 99.9);

        feed(h, 1000, 50); // appended, not reloaded
        plots.refresh();
        QCOMPARE(plot->xAxis->range().upper, 105.0);
        QCOMPARE(visiblePoints(plot, 0), heldPoints(h, 22, plot->xAxis->range()));
        QCOMPARE((plot->graph(0)->data()->constEnd() - 1)->value, 14000.0 + 1049);
        // The value axis spans what is visible, and at least the voltage's
        // smallest span (500 mV) about it.
        QVERIFY(plot->yAxis->range().contains(14000 + 1049));
        QVERIFY(plot->yAxis->range().contains(14000 + 949));
        QVERIFY(plot->yAxis->range().size() >= 500);
        QVERIFY(!plot->yAxis->range().contains(14000 + 600));
    }

    void fillsTheWindowFromTheLeftAtFirst()
    {
        Scene scene({22});
        SensorHistory &h = scene.history;
        PlotStack &plots = scene.plots;
        plots.setWindowSeconds(10);
        feed(h, 20, 20); // 2.0 .. 3.9 s
        plots.refresh();
        QCOMPARE(plots.timeRange().lower, 2.0);
        QCOMPARE(plots.timeRange().upper, 12.0);
        QCOMPARE(visiblePoints(plots.plot(0), 0), 20);
    }

    void redrawsOnlyWhenSomethingChanged()
    {
        Scene scene({22});
        SensorHistory &h = scene.history;
        PlotStack &plots = scene.plots;
        plots.addPlot({23});
        feed(h, 0, 100); // 0 .. 9.9 s in a 60 s window
        scene.refresh();
        const PlotStack::DrawCounts first = plots.drawCounts(0), second = plots.drawCounts(1);
        QVERIFY(first.full > 0);
        scene.refresh();
        scene.refresh();
        QCOMPARE(plots.drawCounts(0).full, first.full);
        QCOMPARE(plots.drawCounts(0).traces, first.traces);
        QCOMPARE(plots.drawCounts(1).full, second.full);
        QCOMPARE(plots.drawCounts(1).traces, second.traces);

        // A sample in a new column, inside both axes: the traces alone.
        feed(h, 100, 1);
        scene.refresh();
        QCOMPARE(plots.drawCounts(0).full, first.full);
        QCOMPARE(plots.drawCounts(0).traces, first.traces + 1);
        QCOMPARE(plots.drawCounts(1).full, second.full);
        QCOMPARE(plots.drawCounts(1).traces, second.traces + 1);
        QCOMPARE((plots.plot(0)->graph(0)->data()->constEnd() - 1)->value, 14100.0);

        // A sample in the same column that is no new extreme: nothing.
        SensorSnapshot same(oi::profile(ProfileId::Create2));
        same.set(22, 14100);
        same.set(23, -100);
        QVERIFY(h.append(10.001, same));
        scene.refresh();
        QCOMPARE(plots.drawCounts(0).traces, first.traces + 1);
        QCOMPARE(plots.drawCounts(1).traces, second.traces + 1);

        // A value beyond the value axis: that plot is drawn whole.
        SensorSnapshot high(oi::profile(ProfileId::Create2));
        high.set(22, 20000);
        high.set(23, -100);
        QVERIFY(h.append(10.2, high));
        scene.refresh();
        QCOMPARE(plots.drawCounts(0).full, first.full + 1);
        QVERIFY(plots.plot(0)->yAxis->range().contains(20000));
        QCOMPARE(plots.drawCounts(1).full, second.full);
        QCOMPARE(plots.drawCounts(1).traces, second.traces + 2);
    }

    // New samples redraw the traces only where they changed; what is on the
    // screen then is what a whole redraw would show, line and steps alike.
    void tracesDrawnInPartLookAsDrawnWhole()
    {
        Scene scene({22, 8});
        auto sample = [&](int k) {
            SensorSnapshot s(oi::profile(ProfileId::Create2));
            s.set(22, 14000 + (k * 37) % 100); // within the value axis once it is set
            s.set(8, (k / 7) % 2);
            QVERIFY(scene.history.append(k / 10.0, s));
        };
        for (int k = 0; k < 100; ++k)
            sample(k);
        scene.refresh();
        QCustomPlot *plot = scene.plots.plot(0);
        const QImage before = plot->grab().toImage();
        const PlotStack::DrawCounts drawn = scene.plots.drawCounts(0);
        for (int k = 100; k < 140; ++k) {
            sample(k);
            scene.refresh();
        }
        QCOMPARE(scene.plots.drawCounts(0).full, drawn.full);
        QVERIFY(scene.plots.drawCounts(0).traces >= drawn.traces + 30);
        const QImage inPart = plot->grab().toImage();
        QVERIFY(inPart != before);
        plot->replot();
        const QImage whole = plot->grab().toImage();
        int differing = 0;
        for (int y = 0; y < whole.height(); ++y)
            for (int x = 0; x < whole.width(); ++x)
                differing += inPart.pixel(x, y) != whole.pixel(x, y);
        QCOMPARE(differing, 0);
    }

    void hiddenPlotsCostNothingAndCatchUp()
    {
        Scene scene({22});
        SensorHistory &h = scene.history;
        PlotStack &plots = scene.plots;
        feed(h, 0, 100);
        scene.refresh();
        const PlotStack::DrawCounts before = plots.drawCounts(0);
        plots.hide();
        feed(h, 100, 100);
        scene.refresh();
        QCOMPARE(plots.drawCounts(0).full, before.full);
        QCOMPARE(plots.drawCounts(0).traces, before.traces);
        QCOMPARE((plots.plot(0)->graph(0)->data()->constEnd() - 1)->key, 9.9);
        scene.nowMs += 1000;
        plots.show();
        QTRY_COMPARE((plots.plot(0)->graph(0)->data()->constEnd() - 1)->key, 19.9);
        QVERIFY(plots.drawCounts(0).full + plots.drawCounts(0).traces > before.full + before.traces);
    }

    void redrawsAtMostOncePerScreenRefresh()
    {
        Scene scene({22});
        feed(scene.history, 0, 100);
        scene.refresh();
        const PlotStack::DrawCounts before = scene.plots.drawCounts(0);
        // Called again within the same millisecond: the data is taken, the
        // drawing waits.
        feed(scene.history, 100, 1);
        scene.plots.refresh();
        QCOMPARE(scene.plots.drawCounts(0).traces, before.traces);
        QCOMPARE((scene.plots.plot(0)->graph(0)->data()->constEnd() - 1)->key, 10.0);
        scene.nowMs += 5;
        scene.plots.refresh();
        QCOMPARE(scene.plots.drawCounts(0).traces, before.traces);
        // A screen refresh later it is drawn, with no further refresh called.
        scene.nowMs += 20;
        QTRY_COMPARE(scene.plots.drawCounts(0).traces, before.traces + 1);
        scene.refresh();
        QCOMPARE(scene.plots.drawCounts(0).traces, before.traces + 1);
    }

    void liveAxisMovesInSteps()
    {
        Scene scene({22});
        SensorHistory &h = scene.history;
        PlotStack &plots = scene.plots;
        plots.setWindowSeconds(20); // steps of one second
        feed(h, 0, 301);            // 0 .. 30 s
        scene.refresh();
        QCOMPARE(plots.timeRange(), QCPRange(10.0, 30.0));
        const PlotStack::DrawCounts before = plots.drawCounts(0);
        feed(h, 301, 9); // to 30.9 s: the axis moves one step, once
        for (int i = 0; i < 3; ++i)
            scene.refresh();
        QCOMPARE(plots.timeRange(), QCPRange(11.0, 31.0));
        QCOMPARE(plots.drawCounts(0).full, before.full + 1);
        feed(h, 310, 1); // 31.0 s: still inside the step
        scene.refresh();
        QCOMPARE(plots.timeRange(), QCPRange(11.0, 31.0));
        QCOMPARE(plots.drawCounts(0).full, before.full + 1);
    }

    void tracesHoldTwoPointsAColumnAndKeepTheirExtremes()
    {
        // A second of 1 kHz samples in columns of 10 ms: a spike one sample
        // wide and a dip survive.
        TraceColumns columns(0.010);
        for (int k = 0; k < 1000; ++k) {
            int value = k % 7;
            if (k == 333)
                value = 900;
            if (k == 777)
                value = -50;
            columns.add({k * 0.001 + 0.0005, value});
        }
        QCOMPARE(columns.columns().size(), std::size_t(100));
        QCOMPARE(columns.pointCount(), std::size_t(200));
        int highest = 0, lowest = 0;
        double highestAt = 0;
        columns.pointsFrom(0, [&](const SensorHistory::Sample &s) {
            if (s.value > highest) {
                highest = s.value;
                highestAt = s.time;
            }
            lowest = std::min(lowest, s.value);
        });
        QCOMPARE(highest, 900);
        QCOMPARE(highestAt, 0.3335);
        QCOMPARE(lowest, -50);
        // Points come in time order.
        double last = -1;
        columns.pointsFrom(0, [&](const SensorHistory::Sample &s) {
            QVERIFY(s.time >= last);
            last = s.time;
        });
        // Only a new column or a new extreme changes the points.
        columns.takeChanged();
        QVERIFY(!columns.add({0.9999, 3}));
        QCOMPARE(columns.takeChanged(), columns.columns().size());
        QVERIFY(columns.add({0.99995, 100}));
        QCOMPARE(columns.takeChanged(), std::size_t(99));
        QVERIFY(columns.add({1.0001, 1}));
        QCOMPARE(columns.takeChanged(), std::size_t(100));
        columns.dropBefore(0.5);
        QCOMPARE(columns.columns().front().index, 50);
        QCOMPARE(columns.columns().size(), std::size_t(51));
    }

    void pauseStopsFollowingAndAllowsPanning()
    {
        Scene scene({22});
        SensorHistory &h = scene.history;
        PlotStack &plots = scene.plots;
        plots.setWindowSeconds(10);
        feed(h, 0, 300);
        plots.refresh();
        const QCPRange before = plots.timeRange();
        QCOMPARE(plots.plot(0)->interactions(), QCP::Interactions());

        QSignalSpy paused(&plots, &PlotStack::pausedChanged);
        plots.setPaused(true);
        QCOMPARE(paused.count(), 1);
        QVERIFY(plots.plot(0)->interactions().testFlag(QCP::iRangeDrag));
        QVERIFY(plots.plot(0)->interactions().testFlag(QCP::iRangeZoom));
        QCOMPARE(plots.plot(0)->axisRect()->rangeDrag(), Qt::Horizontal);
        feed(h, 300, 100);
        plots.refresh();
        QCOMPARE(plots.timeRange(), before);
        QCOMPARE(plots.plot(0)->xAxis->range(), before);

        // Panning back to where the plot holds no data loads it.
        plots.setTimeRange(5.0, 10.0);
        plots.refresh();
        QCOMPARE(plots.plot(0)->xAxis->range(), QCPRange(5.0, 10.0));
        QCOMPARE(visiblePoints(plots.plot(0), 0), heldPoints(h, 22, QCPRange(5.0, 10.0)));
        QCOMPARE(visiblePoints(plots.plot(0), 0), 51);

        plots.setPaused(false);
        plots.refresh();
        QCOMPARE(plots.timeRange().lower, 30.0);
        QCOMPARE(plots.timeRange().upper, 40.0);
        QCOMPARE(visiblePoints(plots.plot(0), 0), heldPoints(h, 22, plots.timeRange()));
        QCOMPARE(plots.plot(0)->interactions(), QCP::Interactions());
    }

    void dragOnOnePlotMovesTheOthers()
    {
        SensorHistory h;
        PlotStack plots;
        plots.setHistory(&h);
        plots.setChannels(0, {22});
        plots.addPlot({23});
        feed(h, 0, 600);
        plots.refresh();
        plots.setPaused(true);
        plots.plot(0)->xAxis->setRange(12.0, 20.0); // what a drag does
        QCOMPARE(plots.plot(1)->xAxis->range(), QCPRange(12.0, 20.0));
        QCOMPARE(plots.timeRange(), QCPRange(12.0, 20.0));
    }

    void windowChoices()
    {
        Scene scene({22});
        SensorHistory &h = scene.history;
        PlotStack &plots = scene.plots;
        feed(h, 0, 7000); // 700 s
        QSignalSpy changed(&plots, &PlotStack::windowSecondsChanged);
        plots.setWindowSeconds(30);
        plots.refresh();
        QCOMPARE(plots.timeRange().size(), 30.0);
        QCOMPARE(plots.timeRange().upper, 700.5); // steps of 1.5 s
        QCOMPARE(visiblePoints(plots.plot(0), 0), heldPoints(h, 22, plots.timeRange()));
        plots.setWindowSeconds(600);
        plots.refresh();
        QCOMPARE(plots.timeRange().size(), 600.0);
        // 6000 samples on fewer pixel columns: at most two points a column,
        // and the first and last values still drawn.
        QCustomPlot *plot = plots.plot(0);
        const int columns = int(plot->axisRect()->width());
        QVERIFY(heldPoints(h, 22, plots.timeRange()) > 2 * columns);
        QVERIFY(visiblePoints(plot, 0) <= 2 * columns + 2);
        QVERIFY(visiblePoints(plot, 0) > columns / 2);
        bool found = false;
        const QCPRange values = plot->graph(0)->getValueRange(found, QCP::sdBoth, plots.timeRange());
        QVERIFY(found);
        const auto shown = h.samples(22, plots.timeRange().lower, plots.timeRange().upper);
        // The voltage rises by one a sample: the view's first column may
        // start a few samples before it.
        const double perColumn = 600.0 / columns / 0.1;
        QVERIFY(std::abs(values.lower - shown.front().value) <= perColumn + 1);
        QCOMPARE(values.upper, double(shown.back().value));
        QCOMPARE(changed.count(), 2);

        plots.setWindowSeconds(1); // bounded
        QCOMPARE(plots.windowSeconds(), PlotStack::kMinWindowSeconds);
        plots.setWindowSeconds(100000);
        QCOMPARE(plots.windowSeconds(), PlotStack::kMaxWindowSeconds);
    }

    void channelsPerPlot()
    {
        PlotStack plots;
        QCOMPARE(plots.plotCount(), 1);
        QCOMPARE(plots.addPlot({22, 23}), 1);
        QCOMPARE(plots.plotCount(), 2);
        QCOMPARE(plots.channels(1), (std::vector<int>{22, 23}));
        QCOMPARE(plots.plot(1)->graphCount(), 2);
        QCOMPARE(plots.plot(1)->graph(1)->name(), QStringLiteral("Current [mA]"));
        // One unit per axis: mV on the left, mA on the right.
        QCOMPARE(plots.plot(1)->yAxis->label(), QStringLiteral("mV"));
        QCOMPARE(plots.plot(1)->yAxis2->label(), QStringLiteral("mA"));
        QVERIFY(plots.plot(1)->yAxis2->visible());
        QCOMPARE(plots.plot(1)->graph(0)->valueAxis(), plots.plot(1)->yAxis);
        QCOMPARE(plots.plot(1)->graph(1)->valueAxis(), plots.plot(1)->yAxis2);
        QVERIFY(!plots.setChannels(1, {22, 23, 24})); // a third unit (°C)
        QCOMPARE(plots.channels(1), (std::vector<int>{22, 23}));
        QVERIFY(!plots.plot(0)->yAxis2->visible());
        QVERIFY(plots.setChannels(0, {46, 47, 46}));
        QCOMPARE(plots.channels(0), (std::vector<int>{46, 47}));
        QCOMPARE(plots.plot(0)->yAxis->label(), QStringLiteral(""));
        QVERIFY(plots.setChannels(0, {54, 55}));
        QCOMPARE(plots.plot(0)->yAxis->label(), QStringLiteral("mA"));

        QVERIFY(!plots.setChannels(0, {100}));       // a group, not a packet
        QVERIFY(!plots.setChannels(2, {22}));        // no such plot
        QVERIFY(!plots.setChannels(0, {22, 23, 24, 25, 26, 27, 28, 29, 30}));
        QCOMPARE(plots.channels(0), (std::vector<int>{54, 55}));
        QCOMPARE(plots.plottedChannels(), (std::vector<int>{54, 55, 22, 23}));

        // Ticking a channel in the chooser adds it.
        QAction *voltage = plots.channelChooser(0)->actionFor(22);
        QVERIFY(voltage && !voltage->isChecked());
        voltage->trigger();
        QCOMPARE(plots.channels(0), (std::vector<int>{54, 55, 22}));
        QVERIFY(voltage->isChecked());
        // Two units shown: a third is offered in another plot, and says so.
        QAction *temperature = plots.channelChooser(0)->actionFor(24);
        QVERIFY(!temperature->isEnabled());
        QVERIFY2(temperature->toolTip().contains(QStringLiteral("add a plot for \u00b0C")), qPrintable(temperature->toolTip()));
        QVERIFY(plots.channelChooser(0)->actionFor(57)->isEnabled()); // mA, like the others
        auto *battery = qobject_cast<QMenu *>(voltage->parent());
        QVERIFY(battery);
        QCOMPARE(battery->title(), QStringLiteral("Battery (1)"));
        voltage->trigger();
        QCOMPARE(plots.channels(0), (std::vector<int>{54, 55}));

        QVERIFY(plots.removePlot(1));
        QCOMPARE(plots.plotCount(), 1);
        QVERIFY(!plots.removePlot(0)); // the last plot stays
        QCOMPARE(plots.plottedChannels(), (std::vector<int>{54, 55}));
    }

    // Noise of a milliamp or two is a thin line, not the whole plot.
    void aQuietCurrentKeepsItsSmallestSpan()
    {
        Scene scene({23});
        for (int k = 0; k < 100; ++k) {
            SensorSnapshot s(oi::profile(ProfileId::Create2));
            s.set(23, -380 + (k % 3) - 1); // 1.5 mA of noise
            QVERIFY(scene.history.append(k / 10.0, s));
        }
        scene.refresh();
        const QCPRange shown = scene.plots.plot(0)->yAxis->range();
        QVERIFY2(shown.size() >= 200, qPrintable(QString::number(shown.size())));
        QVERIFY(shown.contains(-381) && shown.contains(-379));
        QVERIFY(std::abs(shown.center() + 380) < 1);
    }

    void smallestSpansFollowTheCatalogue_data()
    {
        QTest::addColumn<int>("packet");
        QTest::addColumn<double>("span");
        QTest::newRow("voltage") << 22 << 500.0;
        QTest::newRow("current") << 23 << 200.0;
        QTest::newRow("motor current") << 54 << 200.0;
        QTest::newRow("angle") << 20 << 10.0;
        QTest::newRow("a flag, all of it") << 8 << 1.0;
        QTest::newRow("a state, all of it") << 21 << 5.0;
        QTest::newRow("a cliff signal, a fortieth") << 28 << 4095 / 40.0;
    }
    void smallestSpansFollowTheCatalogue()
    {
        QFETCH(int, packet);
        QFETCH(double, span);
        QCOMPARE(valueaxes::minimumSpan(*oi::profile(ProfileId::Create2).packet(packet)), span);
    }

    // Plots keep a readable height: when they do not fit, the stack scrolls.
    void plotsKeepTheirHeightAndTheStackScrolls()
    {
        PlotStack plots;
        plots.setChannels(0, {22});
        plots.addPlot({23});
        plots.addPlot({28});
        plots.resize(900, 300);
        plots.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plots));
        for (int i = 0; i < plots.plotCount(); ++i)
            QVERIFY2(plots.plot(i)->height() >= 110, qPrintable(QString::number(plots.plot(i)->height())));
        auto *scroll = plots.findChild<QScrollArea *>(QStringLiteral("plotScroll"));
        QVERIFY(scroll);
        QVERIFY(scroll->verticalScrollBar()->maximum() > 0);
        // Tall enough, nothing scrolls and the plots share the height.
        plots.resize(900, 800);
        QTRY_COMPARE(scroll->verticalScrollBar()->maximum(), 0);
        QVERIFY(plots.plot(2)->height() > 180);
    }

    void chooserGroupsCoverEveryPacketOnce()
    {
        for (ProfileId id : oi::allProfiles()) {
            const oi::RobotProfile &profile = oi::profile(id);
            std::vector<int> seen;
            const auto groups = ChannelChooser::groups(profile);
            // The SCI has no light bumpers and no cargo bay: five.
            QVERIFY(groups.size() >= (profile.polled() ? 5u : 6u));
            for (const auto &g : groups) {
                QVERIFY(!g.title.isEmpty());
                QVERIFY(!g.ids.empty());
                seen.insert(seen.end(), g.ids.begin(), g.ids.end());
            }
            std::sort(seen.begin(), seen.end());
            std::vector<int> all;
            for (const oi::PacketInfo &info : profile.packets())
                all.push_back(info.id);
            std::sort(all.begin(), all.end());
            QCOMPARE(seen, all);
        }
        const auto create2 = ChannelChooser::groups(oi::profile(ProfileId::Create2));
        QCOMPARE(create2.front().title, QStringLiteral("Bumps & cliffs"));
        QCOMPARE(create2[1].title, QStringLiteral("Battery"));
        QCOMPARE(create2[1].ids, (std::vector<int>{21, 22, 23, 24, 25, 26, 34}));
    }

    void profileChangeDropsMissingChannels()
    {
        PlotStack plots;
        QVERIFY(plots.setChannels(0, {22, 46}));
        plots.setProfile(oi::profile(ProfileId::Create1));
        QCOMPARE(plots.channels(0), (std::vector<int>{22}));
        QCOMPARE(plots.plot(0)->graphCount(), 1);
        QVERIFY(!plots.channelChooser(0)->actionFor(46));
        QVERIFY(plots.channelChooser(0)->actionFor(33));
    }

    // ERRATA 16: before 3.3.0 the distance is wrong. Its legend entry greys
    // and says why; the angle beside it, corrected, stays as it is.
    void unreliableDistanceIsGreyedInTheLegend()
    {
        PlotStack plots;
        QVERIFY(plots.setChannels(0, {19, 20}));
        auto *legend = plots.findChild<QLabel *>("plotLegend");
        QVERIFY(legend);
        QVERIFY(!legend->text().contains("unreliable"));
        QVERIFY(legend->toolTip().isEmpty());

        plots.setCorrections(oi::correctionsFor({3, 2, 9}));
        QVERIFY2(legend->text().contains("Distance [mm] (unreliable)"), qPrintable(legend->text()));
        QVERIFY(!legend->text().contains("Angle [degrees] (unreliable)"));
        QVERIFY2(legend->toolTip().contains("before 3.3.0") && legend->toolTip().contains("distance"),
                 qPrintable(legend->toolTip()));

        plots.setCorrections(oi::correctionsFor({3, 4, 0}));
        QVERIFY(!legend->text().contains("unreliable"));
        QVERIFY(legend->toolTip().isEmpty());
    }

    void tracerReadsValuesWhilePaused()
    {
        SensorHistory h;
        PlotStack plots;
        plots.resize(700, 400);
        plots.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plots));
        plots.setHistory(&h);
        plots.setWindowSeconds(10);
        plots.setChannels(0, {22, 23});
        feed(h, 0, 101);
        plots.refresh();
        QCustomPlot *plot = plots.plot(0);
        plot->replot();
        const QPointF at(plot->xAxis->coordToPixel(5.0), plot->yAxis->coordToPixel(plot->yAxis->range().center()));

        QMouseEvent live(QEvent::MouseMove, at, plot->mapToGlobal(at), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
        QCoreApplication::sendEvent(plot, &live);
        QVERIFY(!visibleReadout(plot)); // no tracer while following

        plots.setPaused(true);
        QMouseEvent paused(QEvent::MouseMove, at, plot->mapToGlobal(at), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
        QCoreApplication::sendEvent(plot, &paused);
        QLabel *readout = visibleReadout(plot);
        QVERIFY(readout);
        QVERIFY(readout->text().startsWith(QStringLiteral("t = 5 s<br>")));
        QVERIFY(readout->text().contains(QStringLiteral("Voltage: 14050 mV<br>")));
        QVERIFY(readout->text().endsWith(QStringLiteral("Current: -50 mA")));
        QCOMPARE(visibleTracers(plot), 2);
        // Inside the plot area.
        QVERIFY(plot->axisRect()->rect().contains(readout->geometry()));

        QEvent leave(QEvent::Leave);
        QCoreApplication::sendEvent(plot, &leave);
        QVERIFY(!visibleReadout(plot));
        QCOMPARE(visibleTracers(plot), 0);
    }

    void markersAreDrawnOnEveryPlot()
    {
        Scene scene({22});
        PlotStack &plots = scene.plots;
        plots.addPlot({23});
        plots.setWindowSeconds(10);
        feed(scene.history, 0, 100); // 0 .. 9.9 s
        plots.setPaused(true);
        plots.setTimeRange(0, 10);
        plots.setMarkers({{2.5, QStringLiteral("hit the table leg")}, {7.0, QString()}});
        scene.refresh();
        for (int i = 0; i < plots.plotCount(); ++i) {
            QCustomPlot *plot = plots.plot(i);
            QList<QCPItemLine *> lines;
            QStringList labels;
            for (int k = 0; k < plot->itemCount(); ++k) {
                if (auto *line = qobject_cast<QCPItemLine *>(plot->item(k)))
                    lines << line;
                if (auto *text = qobject_cast<QCPItemText *>(plot->item(k)); text && text->visible())
                    labels << text->text();
            }
            QCOMPARE(lines.size(), 2);
            QCOMPARE(labels, QStringList{QStringLiteral("hit the table leg")});
            // Vertical, at its time on the shared axis, across the data area.
            const double x = plot->xAxis->coordToPixel(2.5);
            QCOMPARE(lines[0]->start->pixelPosition().x(), x);
            QCOMPARE(lines[0]->end->pixelPosition().x(), x);
            QCOMPARE(lines[0]->start->pixelPosition().y(), double(plot->axisRect()->top()));
            QCOMPARE(lines[0]->end->pixelPosition().y(), double(plot->axisRect()->top() + plot->axisRect()->height()));
            // And it is painted there: a column of the line's colour where
            // the background would be.
            const QImage image = plot->grab().toImage();
            const QColor background = image.pixelColor(int(plot->xAxis->coordToPixel(5.2)),
                                                       plot->axisRect()->bottom() - 3);
            int marked = 0;
            for (int y = plot->axisRect()->top() + 30; y < plot->axisRect()->bottom() - 5; ++y)
                marked += image.pixelColor(int(std::round(x)), y) != background ? 1 : 0;
            QVERIFY2(marked > (plot->axisRect()->height() - 35) * 3 / 4, qPrintable(QString::number(marked)));
        }
        // A plot added later has them too; an empty list clears them.
        const int added = plots.addPlot({8});
        auto lineCount = [](QCustomPlot *plot) {
            int n = 0;
            for (int k = 0; k < plot->itemCount(); ++k)
                n += qobject_cast<QCPItemLine *>(plot->item(k)) ? 1 : 0;
            return n;
        };
        QCOMPARE(lineCount(plots.plot(added)), 2);
        plots.setMarkers({});
        for (int i = 0; i < plots.plotCount(); ++i)
            QCOMPARE(lineCount(plots.plot(i)), 0);
    }

    // Both wheels' encoders on a straight run read the same: the earlier
    // line still shows beside the one drawn over it.
    void linesThatReadTheSameBothShow()
    {
        Scene scene({43, 44});
        for (int k = 0; k < 100; ++k) {
            SensorSnapshot s(oi::profile(ProfileId::Create2));
            s.set(43, 100 * k);
            s.set(44, 100 * k);
            QVERIFY(scene.history.append(k / 10.0, s));
        }
        scene.plots.setPaused(true);
        scene.plots.setTimeRange(0, 10);
        scene.refresh();
        QCustomPlot *plot = scene.plots.plot(0);
        QCOMPARE(plot->graphCount(), 2);
        const QImage image = plot->toPixmap().toImage();
        const auto pixelsOf = [&](const QColor &colour) {
            int n = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) {
                    const QColor c = image.pixelColor(x, y);
                    n += std::abs(c.red() - colour.red()) + std::abs(c.green() - colour.green())
                             + std::abs(c.blue() - colour.blue()) < 30;
                }
            return n;
        };
        const int first = pixelsOf(plot->graph(0)->pen().color());
        const int second = pixelsOf(plot->graph(1)->pen().color());
        QVERIFY2(first > 200 && second > 200, qPrintable(QStringLiteral("%1 and %2 pixels").arg(first).arg(second)));
    }

    void comparisonRunIsDrawnShiftedAndDashed()
    {
        Scene scene({22, 23});
        PlotStack &plots = scene.plots;
        feed(scene.history, 0, 100); // 0 .. 9.9 s
        SensorHistory other;
        for (int k = 0; k < 100; ++k) {
            SensorSnapshot s(oi::profile(ProfileId::Create2));
            s.set(22, 15000 + k);
            s.set(23, -2000);
            QVERIFY(other.append(k / 10.0, s));
        }
        plots.setPaused(true);
        plots.setTimeRange(0, 10);
        plots.setComparison(&other, 1.5, QStringLiteral("second.oirec"), QStringLiteral("first.oirec"));
        scene.refresh();
        QCustomPlot *plot = plots.plot(0);
        // One line per packet from each run; this run's lines come first.
        QCOMPARE(plot->graphCount(), 4);
        QCOMPARE(plot->graph(0)->pen().style(), Qt::SolidLine);
        for (int g : {2, 3}) {
            const QCPGraph *graph = plot->graph(g);
            QCOMPARE(graph->pen().style(), Qt::CustomDashLine);
            QCOMPARE(graph->pen().color().rgb(), plot->graph(g - 2)->pen().color().rgb());
            QVERIFY(graph->pen().color().alpha() < 255);
        }
        // The other run's voltage, 1.5 s later: its first sample at 1.5 s.
        auto voltage = plot->graph(2)->data();
        QVERIFY(!voltage->isEmpty());
        QCOMPARE(voltage->constBegin()->key, 1.5);
        QCOMPARE(voltage->constBegin()->value, 15000.0);
        // Its current (-2000) is inside the current's axis, as this run's
        // is, and its voltage inside the voltage's.
        QVERIFY(plot->yAxis2->range().contains(-2000));
        QVERIFY(plot->yAxis2->range().contains(-99));
        QVERIFY(plot->yAxis->range().contains(15000));
        QCOMPARE(plot->graph(3)->valueAxis(), plot->yAxis2);
        const QString legend = plot->parentWidget()->findChild<QLabel *>(QStringLiteral("plotLegend"))->text();
        QVERIFY2(legend.contains(QStringLiteral("first.oirec")), qPrintable(legend));
        QVERIFY2(legend.contains(QStringLiteral("second.oirec (moved 1.50 s)")), qPrintable(legend));
        // Every plot overlays its packets, a new one too.
        const int added = plots.addPlot({8});
        scene.refresh();
        QCOMPARE(plots.plot(added)->graphCount(), 2);

        plots.setComparison(nullptr, 0, QString(), QString());
        scene.refresh();
        QCOMPARE(plot->graphCount(), 2);
        QVERIFY(!plot->parentWidget()->findChild<QLabel *>(QStringLiteral("plotLegend"))->text().contains(
            QStringLiteral("oirec")));
    }

    void clearedHistoryEmptiesThePlots()
    {
        Scene scene({22});
        SensorHistory &h = scene.history;
        PlotStack &plots = scene.plots;
        feed(h, 0, 50);
        plots.refresh();
        QCOMPARE(plots.plot(0)->graph(0)->dataCount(), 50);
        h.clear();
        plots.refresh();
        QCOMPARE(plots.plot(0)->graph(0)->dataCount(), 0);
        plots.setHistory(nullptr);
        plots.refresh();
        QCOMPARE(plots.plot(0)->graph(0)->dataCount(), 0);
    }
};

QTEST_MAIN(TestPlotStack)
#include "tst_plot_stack.moc"
