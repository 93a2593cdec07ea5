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
    // Measured with the font, not QLabel::sizeHint(): a selectable label lays
    // out a whole text document for its hint. Two pixels for the text cursor.
    const QMargins margins = label->contentsMargins();
    const int width = label->fontMetrics().horizontalAdvance(text) + margins.left() + margins.right() +
                      2 * (label->margin() + label->frameWidth() + std::max(0, label->indent())) + 2;
    const bool fixed = label->minimumSize() == label->maximumSize();
    if (fixed && width <= label->minimumWidth())
        return;
    const int height = fixed ? label->minimumHeight() : label->sizeHint().height();
    label->setFixedSize(std::max(width, fixed ? label->minimumWidth() : 0), height);
}
