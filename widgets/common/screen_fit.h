// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QRect>
#include <QSize>

class QWidget;

// Sizes that follow the screen a window is on, from a 1280×720 projector up.
namespace screenfit {

// The screen area `w` may use (its own screen, else the primary one).
QRect available(const QWidget *w);

// `wanted`, made no larger than `room` less a window frame's margin.
QSize fitted(QSize wanted, QSize room);

// How much larger than the desktop's type a view of `size` can set its type
// so that `reference` (what fits at scale 1) fills it: the smaller of the
// width and height ratios, kept within [low, high].
qreal scaleFor(QSize size, QSize reference, qreal low, qreal high);

} // namespace screenfit
