// SPDX-License-Identifier: GPL-3.0-or-later
// The dashboard under load: every dock visible, the virtual robot streaming
// group 100 at 66.7 Hz. Prints start-up time to the first painted frame with
// live data, process CPU time per second of wall time, and memory over time.
//
//   bench_dashboard [--seconds N] [--history-seconds S] [--hide DOCK]...
//
// --hide closes a dock by object name (plotsDock, inspectorDock, ...), to
// see what each view costs.
// --history-seconds shrinks the history so it fills within the run (the
// default keeps an hour, which a 10-minute run never fills); memory should
// then stay flat once it is full. Run with QT_QPA_PLATFORM=offscreen, or under
// xvfb-run for the xcb platform.
#include "main_window.h"
#include "robot_diagram.h"

#include <QApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QSettings>
#include <QStandardPaths>
#include <QStyleFactory>
#include <QTimer>

#include <sys/resource.h>

#include <cstdio>

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

// Notes the first paint of the diagram after live data arrived.
class FirstLivePaint : public QObject {
public:
    FirstLivePaint(MainWindow *window, QElapsedTimer *clock) : m_window(window), m_clock(clock) {}
    qint64 ms = -1;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override
    {
        if (ms < 0 && event->type() == QEvent::Paint && m_window->session().snapshotCount() > 0)
            ms = m_clock->elapsed();
        return QObject::eventFilter(watched, event);
    }

private:
    MainWindow *m_window;
    QElapsedTimer *m_clock;
};

} // namespace

int main(int argc, char **argv)
{
    QElapsedTimer clock;
    clock.start();
    QApplication app(argc, argv);
    QApplication::setStyle(QStyleFactory::create("Fusion"));
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear(); // no layout or connection from earlier runs

    int seconds = 600;
    double historySeconds = 0;
    QStringList hidden;
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i + 1 < args.size(); ++i) {
        if (args[i] == "--seconds")
            seconds = args[i + 1].toInt();
        else if (args[i] == "--history-seconds")
            historySeconds = args[i + 1].toDouble();
        else if (args[i] == "--hide")
            hidden << args[i + 1];
    }
    if (seconds <= 0) {
        std::fprintf(stderr, "bench_dashboard: --seconds needs a positive number\n");
        return 2;
    }

    MainWindow window;
    if (historySeconds > 0)
        window.setHistoryCapacity(std::size_t(historySeconds * 1000.0 / 15.0));
    FirstLivePaint firstPaint(&window, &clock);
    window.robotDiagram()->installEventFilter(&firstPaint);
    window.resize(1400, 900);
    window.show();
    for (const QString &name : hidden) {
        auto *dock = window.findChild<QDockWidget *>(name);
        if (!dock) {
            std::fprintf(stderr, "bench_dashboard: no dock called %s\n", qPrintable(name));
            return 2;
        }
        dock->close();
    }
    window.start(oilink::LinkSettings::virtualRobotOf(oi::ProfileId::Create2, std::nullopt));

    std::printf("bench_dashboard: platform %s, %d s, %s, virtual Create 2 streaming group 100\n",
                qPrintable(QApplication::platformName()), seconds,
                hidden.isEmpty() ? "every dock visible" : qPrintable("hidden: " + hidden.join(", ")));
    std::printf("history: %zu samples per channel (%s)\n", window.history().capacity(),
                historySeconds > 0 ? qPrintable(QString("full after %1 s").arg(historySeconds))
                                   : "one hour at 66.7 Hz");
    std::fflush(stdout);

    double cpuStart = 0;
    qint64 wallStart = 0;
    int minute = 0;
    QTimer sampler;
    sampler.setInterval(1000);
    QObject::connect(&sampler, &QTimer::timeout, [&] {
        const qint64 now = clock.elapsed();
        if (firstPaint.ms >= 0 && wallStart == 0) {
            std::printf("start-up to the first painted frame with live data: %lld ms (target < 1000 ms)\n",
                        static_cast<long long>(firstPaint.ms));
            wallStart = now;
            cpuStart = cpuSeconds();
        }
        if (wallStart == 0)
            return;
        const qint64 elapsed = now - wallStart;
        if (elapsed >= (minute + 1) * 60000LL || elapsed >= seconds * 1000LL) {
            ++minute;
            const double cpu = cpuSeconds() - cpuStart;
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
            app.quit();
        }
    });
    sampler.start();
    const int status = app.exec();
    window.session().closeAndWait();
    return status;
}
