// SPDX-License-Identifier: GPL-3.0-or-later
#include "stop_all_button.h"

#include "display_palette.h"

#include <QEvent>

StopAllButton::StopAllButton(QWidget *parent) : QPushButton(parent), m_base(font())
{
    // The alert red of the palette it is made in, white or black type on
    // it; padding in the type's size, so that it grows with its type.
    const display::State alert = display::State::Alert;
    const QPalette p = palette();
    setStyleSheet(QString("QPushButton { background: %1; color: %2; padding: 0.3em 0.9em; border-radius: 6px; }"
                          "QPushButton:pressed { background: %2; color: %1; }")
                      .arg(display::stateColor(alert, p).name(), display::textOn(alert, p).name()));
    setMinimumHeight(48);
    setTypeScale(1.3);
    retranslateUi();
}

void StopAllButton::setTypeScale(qreal factor)
{
    setFont(display::valueFont(m_base, factor));
}

void StopAllButton::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QPushButton::changeEvent(event);
}

void StopAllButton::retranslateUi()
{
    setText(tr("STOP ALL  (Shift+Esc)"));
    setToolTip(tr("Stop every robot at once, whichever is selected: the window's robots and every robot "
                  "on the broker.\nShift+Esc does the same from any window; Space or Esc stops the "
                  "selected robot."));
    setAccessibleName(tr("Stop all robots"));
}

#include "moc_stop_all_button.cpp"
