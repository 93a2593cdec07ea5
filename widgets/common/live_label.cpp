// SPDX-License-Identifier: GPL-3.0-or-later
#include "live_label.h"

#include <QLabel>

#include <algorithm>

void setLiveText(QLabel *label, const QString &text)
{
    if (label->text() == text)
        return;
    // Fixed in both directions, QWidget::updateGeometry() leaves the layouts
    // alone: the label only repaints.
    label->setText(text);
    const QSize fits = label->sizeHint();
    const bool fixed = label->minimumSize() == label->maximumSize();
    if (fixed && fits.width() <= label->minimumWidth() && fits.height() == label->minimumHeight())
        return;
    label->setFixedSize(std::max(fits.width(), fixed ? label->minimumWidth() : 0), fits.height());
}
