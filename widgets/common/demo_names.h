// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

// The Create 1 demos (136), -1 (abort) through 9, as the document names them.
// Shared by the mode panel and the script editor so both list them alike.
namespace demos {

inline constexpr int kAbort = -1;
inline constexpr int kFirst = 0;
inline constexpr int kLast = 9;

inline constexpr const char *kNames[] = {
    QT_TRANSLATE_NOOP("Demos", "Abort demo"), QT_TRANSLATE_NOOP("Demos", "Cover"),
    QT_TRANSLATE_NOOP("Demos", "Cover and Dock"), QT_TRANSLATE_NOOP("Demos", "Spot Cover"),
    QT_TRANSLATE_NOOP("Demos", "Mouse"), QT_TRANSLATE_NOOP("Demos", "Drive Figure Eight"),
    QT_TRANSLATE_NOOP("Demos", "Wimp"), QT_TRANSLATE_NOOP("Demos", "Home"),
    QT_TRANSLATE_NOOP("Demos", "Tag"), QT_TRANSLATE_NOOP("Demos", "Pachelbel"),
    QT_TRANSLATE_NOOP("Demos", "Banjo")};

// The translated name of demo -1..9.
inline QString name(int demo)
{
    return QCoreApplication::translate("Demos", kNames[demo - kAbort]);
}

} // namespace demos
