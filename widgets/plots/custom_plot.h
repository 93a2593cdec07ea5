// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// QCustomPlot's header, without what it does not use. It includes the whole
// of Qt Print Support, and through it every Qt Widgets, Gui and Core header,
// though none of its declarations needs them: that doubled the compile time
// of every unit that draws a plot. Its umbrella header's guard is set while
// qcustomplot.h is read, so the umbrella is skipped, and cleared after, so a
// file that does print can still include it.
#ifndef QT_QTPRINTSUPPORT_MODULE_H
#define QT_QTPRINTSUPPORT_MODULE_H
#define ROOMBA_PRINT_SUPPORT_SKIPPED
#endif
#include <qcustomplot.h>
#ifdef ROOMBA_PRINT_SUPPORT_SKIPPED
#undef QT_QTPRINTSUPPORT_MODULE_H
#undef ROOMBA_PRINT_SUPPORT_SKIPPED
#endif
