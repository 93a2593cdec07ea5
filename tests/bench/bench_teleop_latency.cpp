// SPDX-License-Identifier: GPL-3.0-or-later
// Input to wire: the time from a mouse move on the drive pad, or a drive key,
// to its bytes being written to the transport (on the link's thread). Each
// event waits out the 15 ms rate limit first, so this measures the path
// through the window, the teleop rules, the session and the link, not the
// limiter's deliberate hold.
//
//   bench_teleop_latency [--events N]    (N per input kind, default 1000)
//
// Runs on the offscreen platform unless QT_QPA_PLATFORM says otherwise.
#include "../app/recording_transport.h"
#include "drive_pad.h"
#include "main_window.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QSettings>
#include <QStandardPaths>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

using Clock = Recording::Clock;

void spin(int ms)
{
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
}

// Sends one event and returns microseconds until the transport saw a write,
// or -1 if none came within a second.
double timeToWire(Recording &recording, QWidget *target, QEvent &event)
{
    recording.take();
    const Clock::time_point sent = Clock::now();
    QApplication::sendEvent(target, &event);
    QElapsedTimer waited;
    waited.start();
    while (recording.count() == 0) {
        if (waited.elapsed() > 1000)
            return -1;
        QCoreApplication::processEvents();
    }
    const auto writes = recording.takeTimed();
    return std::chrono::duration<double, std::micro>(writes.first().second - sent).count();
}

void report(const char *what, std::vector<double> samples, int lost)
{
    std::sort(samples.begin(), samples.end());
    const auto at = [&samples](double q) {
        return samples.empty() ? 0.0 : samples[std::min(samples.size() - 1, std::size_t(q * samples.size()))];
    };
    std::printf("%-26s events %5zu  p50 %7.3f ms  p99 %7.3f ms  max %7.3f ms  lost %d\n", what, samples.size(),
                at(0.50) / 1000, at(0.99) / 1000, samples.empty() ? 0.0 : samples.back() / 1000, lost);
}

} // namespace

int main(int argc, char **argv)
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
    int events = 1000;
    const QStringList args = app.arguments();
    if (const qsizetype i = args.indexOf("--events"); i >= 0 && i + 1 < args.size())
        events = std::max(1, args[i + 1].toInt());

    Recording recording;
    recording.mode = int(oi::OiMode::Safe);
    MainWindow window;
    window.fleet().setTransportFactory(
        [&recording](const oilink::LinkSettings &) { return new RecordingTransport(&recording); });
    window.resize(1280, 860);
    window.show();
    window.activateWindow();
    window.start(oilink::LinkSettings::serial("/dev/recording", oi::ProfileId::Create2));
    QElapsedTimer ready;
    ready.start();
    while (window.session().state() != oilink::LinkState::Streaming
           || window.session().latest().oiMode() != oi::OiMode::Safe) {
        if (ready.elapsed() > 10000) {
            std::fprintf(stderr, "the recording link did not stream\n");
            return 1;
        }
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    }
    window.refreshDisplay();
    QWidget *area = window.drivePad()->padArea();
    area->setFocus();
    spin(50);

    // The pad: a press, then moves between two positions, each a new command.
    std::vector<double> mouse;
    int mouseLost = 0;
    const QPoint a = window.drivePad()->areaPointFor({0, 0.5});
    const QPoint b = window.drivePad()->areaPointFor({0.3, 0.5});
    {
        QMouseEvent press(QEvent::MouseButtonPress, QPointF(a), area->mapToGlobal(QPointF(a)), Qt::LeftButton,
                          Qt::LeftButton, Qt::NoModifier);
        if (timeToWire(recording, area, press) < 0)
            ++mouseLost;
    }
    for (int i = 0; i < events; ++i) {
        spin(TeleopController::kMinIntervalMs + 1);
        const QPointF p(i % 2 ? a : b);
        QMouseEvent move(QEvent::MouseMove, p, area->mapToGlobal(p), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        const double us = timeToWire(recording, area, move);
        us < 0 ? void(++mouseLost) : mouse.push_back(us);
    }
    {
        QMouseEvent release(QEvent::MouseButtonRelease, QPointF(a), area->mapToGlobal(QPointF(a)), Qt::LeftButton,
                            Qt::NoButton, Qt::NoModifier);
        timeToWire(recording, area, release);
    }

    // The keys: Up pressed (Drive) and released (stop), in turn.
    std::vector<double> keys;
    int keysLost = 0;
    for (int i = 0; i < events; ++i) {
        spin(TeleopController::kMinIntervalMs + 1);
        QKeyEvent key(i % 2 ? QEvent::KeyRelease : QEvent::KeyPress, Qt::Key_Up, Qt::NoModifier);
        const double us = timeToWire(recording, area, key);
        us < 0 ? void(++keysLost) : keys.push_back(us);
    }

    std::printf("input event to transport write, %d events each, target p99 <= 2 ms\n", events);
    report("drive pad (mouse move)", mouse, mouseLost);
    report("keyboard (press/release)", keys, keysLost);
    std::vector<double> all = mouse;
    all.insert(all.end(), keys.begin(), keys.end());
    report("all", all, mouseLost + keysLost);
    window.close();
    return 0;
}
