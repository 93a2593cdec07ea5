// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class QWidget;
class SignalBars;

// Makes the signal bars for a window that includes no Qt Charts header
// (signal_bars.h brings them, and they are slow to compile): returns them
// as a widget for a dock and sets `bars` to the same object, typed.
QWidget *makeSignalBars(QWidget *parent, SignalBars **bars);
