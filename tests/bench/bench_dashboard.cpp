// SPDX-License-Identifier: GPL-3.0-or-later
// The dashboard under load: the default layout at 1600x1000, virtual robots
// streaming group 100 at 66.7 Hz. Prints start-up time to the first painted
// frame with live data (and the GUI thread's CPU time until then, which load
// from other programs skews less), process CPU time per second of wall time, and memory
// over time; the last line, starting "result:", sums the run up for scripts
// (tests/bench/perf_table.sh).
//
//   bench_dashboard [--seconds N] [--history-seconds S] [--hide DOCK]...
//                   [--robots N] [--every-dock] [--fleet] [--paints] [--xvfb]
//
// --hide closes a dock by object name (plotsDock, inspectorDock, ...), to
// see what each view costs.
// --history-seconds shrinks the history so it fills within the run (the
// default keeps an hour, which a 10-minute run never fills); memory should
// then stay flat once it is full.
// --robots N: N virtual robots in one room, saved in the settings and
// restored at start as a user's list would be; the first is selected.
// --every-dock: every dock open and visible; a dock tabbed behind another
// floats beside the window.
// --fleet: a classroom in one window, 30 robots, each one's card in the robot
// list, and the selected robot with every dock open (--robots 30
// --every-dock). The MQTT fleet console is not measured here.
// --paints: at the end, which widgets were painted how often and over how
// many pixels a second, and which timers and queued calls woke the GUI
// thread how often: where drawing time and wake-ups go.
// --xvfb: runs itself again under xvfb-run on a 1600x1000 screen with the xcb
// platform; otherwise set QT_QPA_PLATFORM (offscreen) yourself.
#include "main_window.h"
#include "custom_plot.h"
#include "plot_stack.h"
#include "robot_diagram.h"
#include "saved_robots.h"
#include "x11_images.h"

#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QPaintEvent>
#include <QSettings>
#include <QStandardPaths>
#include <QStyleFactory>
#include <QTimer>

#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <algorithm>
#include <map>
#include <vector>

namespace {

double cpuSeconds()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

// VmRSS or VmHWM from /proc/self/status, in MiB.
double statusMiB(const char *field)
{
    QFile f("/proc/self/status");
    if (!f.open(QIODevice::ReadOnly))
        return -1;
    for (const QByteArray &line : f.readAll().split('\n'))
        if (line.startsWith(field))
            return line.mid(qsizetype(qstrlen(field))).trimmed().split(' ').first().toDouble() / 1024.0;
    return -1;
}

// CPU time of the calling thread, in ms: what start-up cost the GUI thread,
// which other programs on the machine skew less than the wall clock.
double threadCpuMs()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

// Notes the first paint of the diagram after live data arrived.
class FirstLivePaint : public QObject {
public:
    FirstLivePaint(MainWindow *window, QElapsedTimer *clock) : m_window(window), m_clock(clock) {}
    qint64 ms = -1;
    double cpuMs = -1; // the GUI thread's CPU time until then

protected:
    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (ms < 0 && event->type() == QEvent::Paint && m_window->session().snapshotCount() > 0) {
            ms = m_clock->elapsed();
            cpuMs = threadCpuMs();
        }
        return QObject::eventFilter(watched, event);
    }

private:
    MainWindow *m_window;
    QElapsedTimer *m_clock;
};

// Counts paint events by widget class (and object name, where it has one).
class PaintCounter : public QObject {
public:
    struct Count {
        std::uint64_t paints = 0;
        double pixels = 0;
    };
    std::map<QString, Count> counts;
    std::map<QString, std::uint64_t> timers; // by the timer's owner and interval
    std::map<QString, std::uint64_t> calls;  // queued calls, by receiver

protected:
    static QString nameOf(const QObject *object)
    {
        if (!object)
            return QStringLiteral("(none)");
        QString name = QString::fromLatin1(object->metaObject()->className());
        if (!object->objectName().isEmpty())
            name += QLatin1Char(' ') + object->objectName();
        return name;
    }

    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (event->type() == QEvent::Timer) {
            const auto *timer = qobject_cast<const QTimer *>(watched);
            const QString owner = timer ? nameOf(timer->parent()) + QStringLiteral(" (%1 ms)").arg(timer->interval())
                                        : nameOf(watched) + QStringLiteral(" (startTimer)");
            ++timers[owner];
        } else if (event->type() == QEvent::MetaCall) {
            ++calls[nameOf(watched)];
        }
        if (event->type() == QEvent::Paint && watched->isWidgetType()) {
            QString name = QString::fromLatin1(watched->metaObject()->className());
            if (!watched->objectName().isEmpty())
                name += QLatin1Char(' ') + watched->objectName();
            Count &c = counts[name];
            ++c.paints;
            for (const QRect &r : static_cast<QPaintEvent *>(event)->region())
                c.pixels += double(r.width()) * r.height();
        }
        return QObject::eventFilter(watched, event);
    }
};

void printPaints(const PaintCounter &counter, double seconds)
{
    std::vector<std::pair<QString, PaintCounter::Count>> rows(counter.counts.begin(), counter.counts.end());
    std::sort(rows.begin(), rows.end(), [](const auto &a, const auto &b) { return a.second.pixels > b.second.pixels; });
    std::printf("paints per second, by widget (most pixels first):\n");
    for (std::size_t i = 0; i < rows.size() && i < 25; ++i)
        std::printf("  %8.2f paints/s %10.0f px/s  %s\n", rows[i].second.paints / seconds,
                    rows[i].second.pixels / seconds, qPrintable(rows[i].first));
    const auto printRates = [seconds](const char *title, const std::map<QString, std::uint64_t> &counts) {
        std::vector<std::pair<QString, std::uint64_t>> byRate(counts.begin(), counts.end());
        std::sort(byRate.begin(), byRate.end(), [](const auto &a, const auto &b) { return a.second > b.second; });
        std::printf("%s per second on the GUI thread:\n", title);
        for (std::size_t i = 0; i < byRate.size() && i < 15; ++i)
            std::printf("  %8.2f /s  %s\n", double(byRate[i].second) / seconds, qPrintable(byRate[i].first));
    };
    printRates("timer events, by the timer's owner", counter.timers);
    printRates("queued calls, by receiver", counter.calls);
}

// How often each plot was drawn whole and in part, beside how long one of its
// pixel columns lasts.
void printPlotDraws(const QWidget &window, double seconds)
{
    std::printf("plot draws per second (whole, traces only), by plot:\n");
    for (const PlotStack *stack : window.findChildren<PlotStack *>()) {
        for (int i = 0; i < stack->plotCount(); ++i) {
            const PlotStack::DrawCounts draws = stack->drawCounts(i);
            const QCPAxis *axis = stack->plot(i)->xAxis;
            const int width = axis->axisRect()->width();
            std::printf("  %8.2f %8.2f  plot %d, %d px, column %.1f ms\n", double(draws.full) / seconds,
                        double(draws.traces) / seconds, i, width,
                        width > 0 ? 1000.0 * axis->range().size() / width : 0.0);
        }
    }
}

// Runs this benchmark again under xvfb-run, without --xvfb. Returns only on failure.
int runUnderXvfb(int argc, char **argv)
{
    std::vector<char *> args{const_cast<char *>("xvfb-run"), const_cast<char *>("-a"), const_cast<char *>("-s"),
                             const_cast<char *>("-screen 0 1600x1000x24"), argv[0]};
    for (int i = 1; i < argc; ++i)
        if (std::strcmp(argv[i], "--xvfb") != 0)
            args.push_back(argv[i]);
    args.push_back(nullptr);
    setenv("QT_QPA_PLATFORM", "xcb", 1);
    execvp(args[0], args.data());
    std::perror("bench_dashboard: xvfb-run");
    return 2;
}

// Every dock shown; those tabbed behind another float in a cascade beside the window.
void showEveryDock(MainWindow &window)
{
    int floated = 0;
    for (QDockWidget *dock : window.findChildren<QDockWidget *>()) {
        dock->show();
        if (!window.tabifiedDockWidgets(dock).isEmpty() && dock->visibleRegion().isEmpty()) {
            dock->setFloating(true);
            dock->setGeometry(40 + 30 * floated, 60 + 30 * floated, 480, 360);
            ++floated;
        }
    }
}

} // namespace

int main(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i)
        if (std::strcmp(argv[i], "--xvfb") == 0)
            return runUnderXvfb(argc, argv);

    QElapsedTimer clock;
    clock.start();
    sendX11ImagesThroughTheSocket(); // as roomba-dashboard's main() does
    QApplication app(argc, argv);
    QApplication::setStyle(QStyleFactory::create("Fusion"));
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear(); // no layout or connection from earlier runs

    int seconds = 600;
    int robots = 1;
    bool everyDock = false;
    bool paints = false;
    double historySeconds = 0;
    QStringList hidden;
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i < args.size(); ++i) {
        const bool hasValue = i + 1 < args.size();
        if (args[i] == "--every-dock") {
            everyDock = true;
        } else if (args[i] == "--paints") {
            paints = true;
        } else if (args[i] == "--fleet") {
            everyDock = true;
            robots = 30;
        } else if (hasValue && args[i] == "--seconds") {
            seconds = args[++i].toInt();
        } else if (hasValue && args[i] == "--robots") {
            robots = args[++i].toInt();
        } else if (hasValue && args[i] == "--history-seconds") {
            historySeconds = args[++i].toDouble();
        } else if (hasValue && args[i] == "--hide") {
            hidden << args[++i];
        } else {
            std::fprintf(stderr, "bench_dashboard: unknown or incomplete argument %s\n", qPrintable(args[i]));
            return 2;
        }
    }
    if (seconds <= 0 || robots <= 0) {
        std::fprintf(stderr, "bench_dashboard: --seconds and --robots need positive numbers\n");
        return 2;
    }

    // The robots as a user's saved list, so that start-up restores them.
    {
        QSettings settings;
        QList<SavedRobot> saved;
        for (int i = 0; i < robots; ++i) {
            oilink::LinkSettings link = oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, std::nullopt);
            link.virtualSeed = std::uint32_t(i + 1);
            saved << SavedRobot{QString("Robot %1").arg(i + 1), QColor::fromHsv((i * 37) % 360, 200, 220), link, true};
        }
        saveRobots(settings, saved);
    }

    MainWindow window;
    if (historySeconds > 0)
        window.setHistoryCapacity(std::size_t(historySeconds * 1000.0 / 15.0));
    FirstLivePaint firstPaint(&window, &clock);
    window.robotDiagram()->installEventFilter(&firstPaint);
    window.resize(1600, 1000);
    window.show();
    for (const QString &name : hidden) {
        auto *dock = window.findChild<QDockWidget *>(name);
        if (!dock) {
            std::fprintf(stderr, "bench_dashboard: no dock called %s\n", qPrintable(name));
            return 2;
        }
        dock->close();
    }
    window.start();
    if (everyDock)
        showEveryDock(window);

    const QString docks = everyDock ? QString("every dock open") : QString("default docks");
    std::printf("bench_dashboard: platform %s, %d s, %s, %d virtual Create 2 streaming group 100\n",
                qPrintable(QApplication::platformName()), seconds,
                qPrintable(hidden.isEmpty() ? docks : docks + ", hidden: " + hidden.join(", ")),
                int(window.fleet().count()));
    std::printf("history: %zu samples per channel (%s)\n", window.history().capacity(),
                historySeconds > 0 ? qPrintable(QString("full after %1 s").arg(historySeconds))
                                   : "one hour at 66.7 Hz");
    std::fflush(stdout);

    double cpuStart = 0;
    qint64 wallStart = 0;
    int minute = 0;
    double cpuPercent = 0;
    QTimer sampler;
    sampler.setInterval(1000);
    QObject::connect(&sampler, &QTimer::timeout, [&] {
        const qint64 now = clock.elapsed();
        if (firstPaint.ms >= 0 && wallStart == 0) {
            std::printf("start-up to the first painted frame with live data: %lld ms (target <= 250 ms), "
                        "GUI thread CPU %.0f ms\n",
                        static_cast<long long>(firstPaint.ms), firstPaint.cpuMs);
            wallStart = now;
            cpuStart = cpuSeconds();
        }
        if (wallStart == 0)
            return;
        const qint64 elapsed = now - wallStart;
        if (elapsed >= (minute + 1) * 60000LL || elapsed >= seconds * 1000LL) {
            ++minute;
            const double cpu = cpuSeconds() - cpuStart;
            cpuPercent = 100.0 * cpu / (elapsed / 1000.0);
            std::printf("%4lld s: CPU %.2f %% of one core, RSS %.1f MiB, history %.1f MiB, snapshots %llu\n",
                        static_cast<long long>(elapsed / 1000), 100.0 * cpu / (elapsed / 1000.0),
                        statusMiB("VmRSS:"), window.history().memoryBytes() / 1048576.0,
                        static_cast<unsigned long long>(window.session().snapshotCount()));
            std::fflush(stdout);
        }
        if (elapsed >= seconds * 1000LL) {
            std::printf("peak RSS %.1f MiB; link %s, %.1f frames/s\n", statusMiB("VmHWM:"),
                        qPrintable(oilink::linkStateName(window.session().state())),
                        window.session().statistics().framesPerSecond);
            std::printf("result: robots %d, %s, platform %s, %d s, cpu %.2f %%, rss %.1f MiB, first live frame %lld ms\n",
                        int(window.fleet().count()), qPrintable(docks), qPrintable(QApplication::platformName()),
                        seconds, cpuPercent, statusMiB("VmRSS:"), static_cast<long long>(firstPaint.ms));
            app.quit();
        }
    });
    PaintCounter paintCounter;
    if (paints)
        app.installEventFilter(&paintCounter);
    sampler.start();
    const int status = app.exec();
    window.session().closeAndWait();
    if (paints) {
        printPaints(paintCounter, clock.elapsed() / 1000.0);
        printPlotDraws(window, clock.elapsed() / 1000.0);
    }
    return status;
}
