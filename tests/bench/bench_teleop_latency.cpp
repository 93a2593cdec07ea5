// SPDX-License-Identifier: GPL-3.0-or-later
// Input to wire: the time from a mouse move on the drive pad, or a drive key,
// arriving for the window to its bytes being written to the transport (on
// the link's thread). The input comes from another thread, as the window
// system's does, at moments the window does not choose: one that arrives
// while the window draws a plot waits for it, and that wait counts. Each
// waits out the 15 ms rate limit first, so this measures the path through
// the window, the teleop rules, the session and the link, not the limiter's
// deliberate hold. The window runs its event loop meanwhile, sleeping when
// it has nothing to do.
//
//   bench_teleop_latency [--events N]    (N per input kind, default 1000)
//
// Runs on the offscreen platform unless QT_QPA_PLATFORM says otherwise.
#include "../common/recording_transport.h"
#include "drive_pad.h"
#include "main_window.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QInputDevice>
#include <QKeyEvent>
#include <QPointingDevice>
#include <QMouseEvent>
#include <QSettings>
#include <QStandardPaths>

#include <algorithm>
#include <cstdio>
#include <random>
#include <thread>
#include <vector>

namespace {

using Clock = Recording::Clock;

// Posts `event` to `target` and returns microseconds until the transport
// saw a write, or -1 if none came within a second. Called on the input's
// own thread, which sleeps while it waits.
double timeToWire(Recording &recording, QWidget *target, QEvent *event)
{
    recording.take();
    const Clock::time_point sent = Clock::now();
    QCoreApplication::postEvent(target, event);
    if (!recording.waitForWrite(1000))
        return -1;
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
    QWidget *area = window.dock<DrivePad>()->padArea();
    area->setFocus();

    // The input's thread: a press on the pad, moves between two positions
    // (each a new command), a release; then Up pressed (Drive) and released
    // (stop), in turn. Each after the rate limit and a random part of a
    // frame more, so the inputs fall on every phase of the window's work.
    std::vector<double> mouse;
    std::vector<double> keys;
    int mouseLost = 0;
    int keysLost = 0;
    const QPoint a = window.dock<DrivePad>()->areaPointFor({0, 0.5});
    const QPoint b = window.dock<DrivePad>()->areaPointFor({0.3, 0.5});
    const QPointF globalA = area->mapToGlobal(QPointF(a));
    const QPointF globalB = area->mapToGlobal(QPointF(b));
    // An event made without a device names the primary one, which is made
    // on first use as a child of the application: here, not on the input's thread.
    QInputDevice::primaryKeyboard();
    QPointingDevice::primaryPointingDevice();
    std::thread input([&] {
        std::mt19937 random(1);
        std::uniform_int_distribution<int> jitterUs(0, 5'000);
        // The input's pace, not a wait for something to happen: the rate
        // limit runs on the wall clock.
        const auto pause = [&] {
            std::this_thread::sleep_for(std::chrono::milliseconds(TeleopController::kMinIntervalMs + 1)
                                        + std::chrono::microseconds(jitterUs(random)));
        };
        const auto measure = [&](QEvent *event, std::vector<double> &into, int &lost) {
            pause();
            const double us = timeToWire(recording, area, event);
            us < 0 ? void(++lost) : into.push_back(us);
        };
        std::vector<double> ignored;
        int ignoredLost = 0;
        measure(new QMouseEvent(QEvent::MouseButtonPress, QPointF(a), globalA, Qt::LeftButton, Qt::LeftButton,
                                Qt::NoModifier),
                ignored, mouseLost);
        for (int i = 0; i < events; ++i) {
            const QPointF p(i % 2 ? a : b);
            measure(new QMouseEvent(QEvent::MouseMove, p, i % 2 ? globalA : globalB, Qt::NoButton, Qt::LeftButton,
                                    Qt::NoModifier),
                    mouse, mouseLost);
        }
        measure(new QMouseEvent(QEvent::MouseButtonRelease, QPointF(a), globalA, Qt::LeftButton, Qt::NoButton,
                                Qt::NoModifier),
                ignored, ignoredLost);
        for (int i = 0; i < events; ++i)
            measure(new QKeyEvent(i % 2 ? QEvent::KeyRelease : QEvent::KeyPress, Qt::Key_Up, Qt::NoModifier), keys,
                    keysLost);
        QMetaObject::invokeMethod(&app, "quit", Qt::QueuedConnection);
    });
    app.exec();
    input.join();

    std::printf("input event to transport write, %d events each, target p99 <= 1 ms\n", events);
    report("drive pad (mouse move)", mouse, mouseLost);
    report("keyboard (press/release)", keys, keysLost);
    std::vector<double> all = mouse;
    all.insert(all.end(), keys.begin(), keys.end());
    report("all", all, mouseLost + keysLost);
    window.close();
    return 0;
}
