// SPDX-License-Identifier: GPL-3.0-or-later
#include "channel_chooser.h"
#include "pseudo_translation.h"
#include "plot_samples.h"
#include "sensor_history.h"
#include "plot_stack.h"
#include "sensor_plots.h"
#include "trace_columns.h"

#include <QAction>
#include <QApplication>
#include <QPushButton>
#include <QToolButton>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "custom_plot.h"

#include <algorithm>
#include <cmath>

using oi::ProfileId;
using oi::SensorSnapshot;

namespace {


QByteArray readAll(const QString &path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

} // namespace

class TestSensorPlots : public QObject {
    Q_OBJECT
private slots:
    // The badge says "Live" only while fresh data comes: never beside a
    // STALE banner at the end of a replay.
    void theBadgeSaysLiveOnlyWhileDataIsFresh()
    {
        SensorPlots plots;
        QCOMPARE(plots.statusText(), QString("Live"));
        plots.setStale(true);
        QCOMPARE(plots.statusText(), QString("Not live: no fresh data"));
        plots.stack()->setPaused(true);
        QVERIFY(plots.statusText().startsWith("Paused"));
        plots.stack()->setPaused(false);
        QCOMPARE(plots.statusText(), QString("Not live: no fresh data"));
        plots.setStale(false);
        QCOMPARE(plots.statusText(), QString("Live"));
    }

    // The window box shows the stack's window, whoever set it.
    void windowBoxFollowsTheStack()
    {
        SensorPlots plots;
        auto *box = plots.findChild<QComboBox *>(QStringLiteral("window"));
        QVERIFY(box);
        QCOMPARE(box->currentData().toDouble(), plots.stack()->windowSeconds());
        plots.stack()->setWindowSeconds(600);
        QCOMPARE(box->currentData().toDouble(), 600.0);
        plots.stack()->setWindowSeconds(45); // between the choices: gets its own entry
        QCOMPARE(box->currentData().toDouble(), 45.0);
        QCOMPARE(box->currentText(), QStringLiteral("45 s"));
        // And a choice in the box sets the stack's.
        box->setCurrentIndex(box->findData(120.0));
        emit box->activated(box->currentIndex());
        QCOMPARE(plots.stack()->windowSeconds(), 120.0);
    }

    void exportsTheVisibleRange()
    {
        QTemporaryDir dir;
        SensorHistory h;
        SensorPlots plots;
        plots.setHistory(&h);
        plots.stack()->setWindowSeconds(10);
        plots.stack()->setChannels(0, {22});
        plots.stack()->addPlot({8, 22});
        feed(h, 0, 201); // 0 .. 20 s
        plots.refresh();
        QCOMPARE(plots.stack()->timeRange(), QCPRange(10.0, 20.0));

        QByteArray expected = "time_s,voltage[mV],wall\n";
        for (int k = 100; k <= 200; ++k) {
            expected += QByteArray::number(k / 10.0) + ',' + QByteArray::number(14000 + k) + ',';
            if (k % 10 == 0)
                expected += QByteArray::number((k / 10) % 2);
            expected += '\n';
        }
        const QString visible = dir.filePath(QStringLiteral("visible.csv"));
        QString error;
        QVERIFY2(plots.exportVisibleCsv(visible, &error), qPrintable(error));
        QCOMPARE(readAll(visible), expected);

        const QString all = dir.filePath(QStringLiteral("all.csv"));
        QVERIFY(plots.exportAllCsv(all, &error));
        QCOMPARE(readAll(all).count('\n'), 1 + 201);
        QVERIFY(readAll(all).startsWith("time_s,voltage[mV],wall\n0,14000,0\n0.1,14001,\n"));

        QVERIFY(!plots.exportVisibleCsv(dir.filePath(QStringLiteral("no/dir/x.csv")), &error));
        QVERIFY(error.contains(QStringLiteral("no/dir/x.csv")));
        SensorPlots empty;
        QVERIFY(!empty.exportAllCsv(all, &error));
        QVERIFY(!error.isEmpty());
    }

    // The markers drawn go into the export, each on the first row at or
    // after it; those outside the range exported stay out.
    void exportCarriesTheMarkers()
    {
        QTemporaryDir dir;
        SensorHistory h;
        SensorPlots plots;
        plots.setHistory(&h);
        plots.stack()->setWindowSeconds(10);
        plots.stack()->setChannels(0, {22});
        feed(h, 0, 201); // 0 .. 20 s
        plots.setMarkers({{12.05, "hit the table leg"}, {3.0, "early"}});
        plots.refresh();
        const QString visible = dir.filePath(QStringLiteral("visible.csv"));
        QString error;
        QVERIFY2(plots.exportVisibleCsv(visible, &error), qPrintable(error));
        const QList<QByteArray> lines = readAll(visible).split('\n');
        QCOMPARE(lines[0], QByteArray("time_s,voltage[mV],marker"));
        QCOMPARE(lines[1], QByteArray("10,14100,"));
        QCOMPARE(lines[22], QByteArray("12.1,14121,hit the table leg"));
        QCOMPARE(readAll(visible).count("early"), 0);
        const QString all = dir.filePath(QStringLiteral("all.csv"));
        QVERIFY(plots.exportAllCsv(all, &error));
        QVERIFY(readAll(all).contains("\n3,14030,early\n"));
    }

    void spaceTogglesPause()
    {
        SensorPlots plots;
        plots.resize(600, 400);
        plots.show();
        plots.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&plots));
        plots.setFocus();
        QSignalSpy spy(plots.stack(), &PlotStack::pausedChanged);
        QTest::keyClick(&plots, Qt::Key_Space);
        QVERIFY(plots.stack()->isPaused());
        QTest::keyClick(&plots, Qt::Key_Space);
        QVERIFY(!plots.stack()->isPaused());
        QTest::keyClick(&plots, Qt::Key_Space, Qt::ControlModifier);
        QVERIFY(plots.stack()->isPaused());
        QCOMPARE(spy.count(), 3);
        // From inside a plot too.
        plots.stack()->plot(0)->setFocus();
        QTest::keyClick(plots.stack()->plot(0), Qt::Key_Space);
        QVERIFY(!plots.stack()->isPaused());
    }

    // Renders three plots of a realistic drive to PNG, for a person to look at.
    void snapshot()
    {
        // Into ROOMBA_WIDGET_SNAPSHOT_DIR for a person to look at, else a scratch folder.
        QTemporaryDir scratch;
        QByteArray dir = qgetenv("ROOMBA_WIDGET_SNAPSHOT_DIR");
        if (dir.isEmpty())
            dir = scratch.path().toLocal8Bit();
        SensorHistory h;
        for (int k = 0; k < 66.7 * 180; ++k) {
            const double t = k * 0.015;
            SensorSnapshot s(oi::profile(ProfileId::Create2));
            const bool driving = std::fmod(t, 40.0) > 8.0;
            s.set(22, int(14900 - t * 1.8 + 6 * std::sin(k * 0.11) + (driving ? -120 : 0)));
            s.set(23, int((driving ? -1150 : -380) + 60 * std::sin(k * 0.9) + 35 * std::sin(k * 0.13)));
            s.set(54, int(driving ? 180 + 40 * std::sin(k * 0.05) : 0));
            s.set(55, int(driving ? 170 + 45 * std::sin(k * 0.07 + 1) : 0));
            const double wall = std::max(0.0, std::sin(t / 9.0));
            s.set(46, int(20 + 900 * wall * wall + 10 * std::sin(k * 1.3)));
            s.set(47, int(15 + 400 * std::pow(std::max(0.0, std::sin(t / 4.0 + 1)), 2)));
            s.set(48, int(30 + 1600 * std::pow(std::max(0.0, std::sin(t / 6.0 + 2)), 4)));
            QVERIFY(h.append(t, s));
        }
        SensorPlots plots;
        plots.setHistory(&h);
        plots.stack()->setWindowSeconds(60);
        plots.stack()->setChannels(0, {22, 23});
        plots.stack()->addPlot({54, 55});
        plots.stack()->addPlot({46, 47, 48});
        plots.resize(900, 600);
        plots.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plots));
        plots.refresh();
        QCoreApplication::processEvents();
        QVERIFY(plots.grab().save(QDir(QString::fromLocal8Bit(dir)).filePath(QStringLiteral("sensor_plots.png"))));

        plots.stack()->setPaused(true);
        plots.stack()->setTimeRange(120, 150);
        plots.refresh();
        QCustomPlot *plot = plots.stack()->plot(1);
        const QPointF at(plot->xAxis->coordToPixel(134.0), plot->height() / 2.0);
        QMouseEvent move(QEvent::MouseMove, at, plot->mapToGlobal(at), Qt::NoButton, Qt::NoButton, Qt::NoModifier);
        QCoreApplication::sendEvent(plot, &move);
        QCoreApplication::processEvents();
        plot->replot();
        QVERIFY(plots.grab().save(QDir(QString::fromLocal8Bit(dir)).filePath(QStringLiteral("sensor_plots_paused.png"))));

        // Markers, and the same run again 2 s later for comparison.
        QEvent leave(QEvent::Leave);
        QCoreApplication::sendEvent(plot, &leave);
        plots.setMarkers({{126.0, QStringLiteral("hit the table leg")}, {141.5, QStringLiteral("turned")}});
        plots.setComparison(&h, 2.0, QStringLiteral("second try.oirec"), QStringLiteral("first try.oirec"));
        plots.refresh();
        QCoreApplication::processEvents();
        QVERIFY(plots.grab().save(QDir(QString::fromLocal8Bit(dir)).filePath(QStringLiteral("sensor_plots_comparison.png"))));
        plots.setComparison(nullptr, 0, {}, {});
        plots.setMarkers({});

        // The channel menu and one of its groups.
        QMenu *menu = plots.stack()->channelChooser(1)->menu();
        menu->popup(plots.mapToGlobal(QPoint(10, 60)));
        QVERIFY(QTest::qWaitForWindowExposed(menu));
        QVERIFY(menu->grab().save(QDir(QString::fromLocal8Bit(dir)).filePath(QStringLiteral("channel_menu.png"))));
        QMenu *battery = menu->actions().at(1)->menu();
        QVERIFY(battery);
        battery->popup(plots.mapToGlobal(QPoint(200, 60)));
        QVERIFY(QTest::qWaitForWindowExposed(battery));
        QVERIFY(battery->grab().save(QDir(QString::fromLocal8Bit(dir)).filePath(QStringLiteral("channel_menu_battery.png"))));
        battery->hide();
        menu->hide();

        // Empty plots on a dark palette: the hints and axes must still read.
        QPalette dark;
        dark.setColor(QPalette::Window, QColor(45, 47, 52));
        dark.setColor(QPalette::Base, QColor(30, 32, 36));
        dark.setColor(QPalette::AlternateBase, QColor(40, 42, 46));
        dark.setColor(QPalette::Text, QColor(225, 225, 225));
        dark.setColor(QPalette::WindowText, QColor(225, 225, 225));
        dark.setColor(QPalette::Button, QColor(55, 57, 62));
        dark.setColor(QPalette::ButtonText, QColor(225, 225, 225));
        dark.setColor(QPalette::Mid, QColor(90, 92, 98));
        SensorHistory waiting;
        SensorPlots empty;
        empty.setPalette(dark);
        empty.setHistory(&waiting);
        empty.stack()->setChannels(0, {22});
        empty.stack()->addPlot();
        empty.resize(900, 400);
        empty.show();
        QVERIFY(QTest::qWaitForWindowExposed(&empty));
        empty.refresh();
        QCoreApplication::processEvents();
        QVERIFY(empty.grab().save(QDir(QString::fromLocal8Bit(dir)).filePath(QStringLiteral("sensor_plots_empty_dark.png"))));
    }

    void translatesOnTheSpot()
    {
        SensorHistory h;
        SensorPlots plots;
        plots.resize(800, 500);
        plots.setHistory(&h);
        plots.stack()->setChannels(0, {22, 23});
        plots.stack()->addPlot({}); // empty: shows its hint
        feed(h, 0, 50);
        plots.refresh();
        plots.stack()->setPaused(true);
        plots.show();
        {
            ScopedPseudoTranslation pseudo;
            QCoreApplication::processEvents();
            QStringList left = untranslatedTexts(&plots);
            // Texts QCustomPlot and the menus draw themselves.
            QStringList shown = {plots.stack()->plot(1)->xAxis->label(), plots.stack()->plot(0)->graph(0)->name(),
                                 plots.stack()->plot(0)->accessibleDescription()};
            for (QAction *a : plots.stack()->channelChooser(0)->menu()->actions())
                shown << a->text();
            for (QAction *a : plots.findChild<QPushButton *>("export")->menu()->actions())
                shown << a->text();
            for (int i = 0; i < plots.stack()->plot(1)->itemCount(); ++i)
                if (auto *text = qobject_cast<QCPItemText *>(plots.stack()->plot(1)->item(i)))
                    shown << text->text();
            for (const QString &text : shown)
                if (looksUntranslated(text))
                    left << text;
            QVERIFY2(left.isEmpty(), qPrintable(left.join('\n')));
            QCOMPARE(plots.stack()->channels(0), std::vector<int>({22, 23}));
            QVERIFY(plots.stack()->isPaused());
        }
        QCoreApplication::processEvents();
        QCOMPARE(plots.findChild<QPushButton *>("addPlot")->text(), QString("Add plot"));
        QCOMPARE(plots.findChild<QPushButton *>("pause")->text(), QString("Resume"));
        QCOMPARE(plots.stack()->channelChooser(0)->text(), QString("Channels (2)"));
        QCOMPARE(plots.stack()->plot(0)->graph(0)->name(), QString("Voltage [mV]"));
        QCOMPARE(plots.stack()->plot(0)->graph(0)->dataCount() > 0, true); // data loaded again
    }

    void keyboardReachesEveryControl()
    {
        SensorHistory h;
        SensorPlots plots;
        plots.resize(800, 500);
        plots.setHistory(&h);
        plots.stack()->setChannels(0, {22});
        plots.stack()->addPlot({23});
        feed(h, 0, 200);
        plots.refresh();
        plots.show();
        plots.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&plots));
        QList<QWidget *> expected = {plots.findChild<QWidget *>("pause"), plots.findChild<QWidget *>("window"),
                                     plots.findChild<QWidget *>("addPlot"), plots.findChild<QWidget *>("export")};
        for (int i = 0; i < plots.stack()->plotCount(); ++i) {
            QWidget *frame = plots.stack()->plot(i)->parentWidget();
            expected << plots.stack()->channelChooser(i) << frame->findChild<QToolButton *>() << plots.stack()->plot(i);
        }
        expected.first()->setFocus(Qt::TabFocusReason);
        QList<QWidget *> visited;
        while (QWidget *w = QApplication::focusWidget()) {
            if (visited.contains(w) || visited.size() > 30)
                break;
            visited << w;
            QTest::keyClick(w, Qt::Key_Tab);
        }
        auto names = [](const QList<QWidget *> &list) {
            QStringList out;
            for (QWidget *w : list)
                out << QString::fromLatin1(w->metaObject()->className()) + ' ' + w->objectName();
            return out.join(", ");
        };
        QVERIFY2(visited == expected, qPrintable(names(visited) + "\nexpected: " + names(expected))); // reading order
        for (int i = 0; i < plots.stack()->plotCount(); ++i) {
            QVERIFY(!plots.stack()->plot(i)->accessibleName().isEmpty());
            QVERIFY(!plots.stack()->plot(i)->accessibleDescription().isEmpty());
        }
        // Paused, the arrows pan and +/- zoom the shared time axis.
        QCustomPlot *plot = plots.stack()->plot(1);
        plot->setFocus();
        QTest::keyClick(plot, Qt::Key_Space);
        QVERIFY(plots.stack()->isPaused());
        const QCPRange before = plots.stack()->timeRange();
        QTest::keyClick(plot, Qt::Key_Left);
        QVERIFY(plots.stack()->timeRange().upper < before.upper);
        QCOMPARE(plots.stack()->plot(0)->xAxis->range().upper, plots.stack()->timeRange().upper);
        QTest::keyClick(plot, Qt::Key_Plus);
        QVERIFY(plots.stack()->timeRange().size() < before.size());
        QTest::keyClick(plot, Qt::Key_Minus);
        QVERIFY(qAbs(plots.stack()->timeRange().size() - before.size()) < 1e-9);
    }
};

QTEST_MAIN(TestSensorPlots)
#include "tst_sensor_plots.moc"
