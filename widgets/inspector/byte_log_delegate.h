// SPDX-License-Identifier: GPL-3.0-or-later
// The byte log's row drawing, for ByteLogView.
#pragma once

#include <QFontMetrics>

class ByteLogModel;
class QObject;
class QStyledItemDelegate;

// Every row alike: one line of the font.
int byteLogRowHeight(const QFontMetrics &metrics);

// The delegate that draws `log`'s rows, owned by `parent`.
QStyledItemDelegate *makeByteLogDelegate(const ByteLogModel *log, QObject *parent);
