// SPDX-License-Identifier: GPL-3.0-or-later
#include "display_palette.h"

namespace display {
namespace {
bool isDark(const QPalette &palette) { return palette.color(QPalette::Window).lightness() < 128; }
} // namespace

QColor stateColor(State state, const QPalette &palette)
{
    const bool dark = isDark(palette);
    switch (state) {
    case State::Idle:
        return dark ? QColor(70, 74, 80) : QColor(205, 210, 216);
    case State::Active:
        return dark ? QColor(60, 170, 90) : QColor(30, 140, 60);
    case State::Warning:
        return dark ? QColor(235, 170, 40) : QColor(210, 130, 0);
    case State::Alert:
        return dark ? QColor(240, 80, 70) : QColor(200, 30, 30);
    case State::Stale:
        return dark ? QColor(150, 110, 200) : QColor(120, 70, 170);
    }
    return palette.color(QPalette::Mid);
}

QColor textOn(State state, const QPalette &palette)
{
    const QColor fill = stateColor(state, palette);
    return fill.lightness() > 140 ? QColor(20, 20, 20) : QColor(250, 250, 250);
}

QFont valueFont(const QFont &base, qreal factor)
{
    QFont f = base;
    const qreal size = base.pointSizeF() > 0 ? base.pointSizeF() : 10.0;
    f.setPointSizeF(size * factor);
    f.setBold(true);
    return f;
}

} // namespace display
