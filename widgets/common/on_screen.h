// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

// Whether any of `widget` is on screen. A widget in a dock tabbed behind
// another stays visible to Qt (isVisible()) with nothing of it on screen; a
// view that draws or lays out text only for the screen asks this instead.
inline bool isOnScreen(const QWidget *widget)
{
    return widget->isVisible() && !widget->visibleRegion().isEmpty();
}
