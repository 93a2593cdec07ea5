// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QApplication>
#include <QList>
#include <QTest>
#include <QWidget>

// The widgets Tab visits, once round, starting at `first` (at most `limit`).
inline QList<QWidget *> tabCycle(QWidget *window, QWidget *first, int limit = 100)
{
    window->activateWindow();
    first->setFocus(Qt::TabFocusReason);
    QList<QWidget *> visited{QApplication::focusWidget()};
    for (int i = 0; i < limit; ++i) {
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_Tab);
        QWidget *focus = QApplication::focusWidget();
        if (!focus || focus == visited.first())
            break;
        visited << focus;
    }
    return visited;
}
