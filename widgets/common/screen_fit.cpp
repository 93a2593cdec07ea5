// SPDX-License-Identifier: GPL-3.0-or-later
#include "screen_fit.h"

#include <QGuiApplication>
#include <QScreen>
#include <QWidget>

#include <algorithm>

namespace screenfit {

namespace {
// A title bar and borders, which the available area does not leave out.
constexpr int kFrameWidth = 16;
constexpr int kFrameHeight = 40;
} // namespace

QRect available(const QWidget *w)
{
    const QScreen *screen = w && w->screen() ? w->screen() : QGuiApplication::primaryScreen();
    return screen ? screen->availableGeometry() : QRect(0, 0, 1280, 720);
}

QSize fitted(QSize wanted, QSize room)
{
    return wanted.boundedTo(QSize(std::max(1, room.width() - kFrameWidth), std::max(1, room.height() - kFrameHeight)));
}

qreal scaleFor(QSize size, QSize reference, qreal low, qreal high)
{
    if (reference.isEmpty())
        return low;
    const qreal ratio = std::min(qreal(size.width()) / reference.width(), qreal(size.height()) / reference.height());
    return std::clamp(ratio, low, high);
}

} // namespace screenfit
