// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QColor>
#include <QFont>
#include <QPalette>

// Colours and fonts every widget uses for sensor states, so a cliff looks
// the same in the diagram, the gauges and the plots, and stays readable on a
// light or a dark palette and from the back of a classroom.
namespace display {

enum class State { Idle, Active, Warning, Alert, Stale };

// Fill colour for a sensor in this state, contrasting with `palette`'s window.
QColor stateColor(State state, const QPalette &palette);
// Text colour that reads on top of stateColor(state, palette).
QColor textOn(State state, const QPalette &palette);
// A font `factor` times the widget's base point size, bold for values.
QFont valueFont(const QFont &base, qreal factor = 1.6);

} // namespace display
