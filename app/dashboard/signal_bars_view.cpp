// SPDX-License-Identifier: GPL-3.0-or-later
// Apart from robot_views.cpp: signal_bars.h brings Qt Charts, slow to compile.
#include "robot_view.h"
#include "robot_views.h"
#include "signal_bars.h"

namespace robot_views {
namespace {
class SignalBarsView : public QObject, public RobotView {
public:
    explicit SignalBarsView(SignalBars *bars) : QObject(bars), m_bars(bars) {}
    void showProfile(const oi::RobotProfile &p) override { m_bars->setProfile(p); }
    void showSnapshot(const oi::SensorSnapshot &s) override { m_bars->setSnapshot(s); }

private:
    SignalBars *m_bars;
};
} // namespace

RobotView *of(SignalBars *bars) { return new SignalBarsView(bars); }
} // namespace robot_views
