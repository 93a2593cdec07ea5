// SPDX-License-Identifier: GPL-3.0-or-later
// The byte log's view: one row per entry, scrolled, selected and copied.
#include "byte_log_view.h"

#include "byte_log_delegate.h"
#include "byte_log_model.h"

#include <QClipboard>
#include <QFontDatabase>
#include <QGuiApplication>
#include <QKeyEvent>
#include <QPainter>
#include <QScrollBar>
#include <QStyledItemDelegate>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <unordered_map>

ByteLogView::ByteLogView(QWidget *parent) : QAbstractItemView(parent)
{
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff); // long lines are elided
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setTabKeyNavigation(false); // a log: Tab moves on to the next control
    setTextElideMode(Qt::ElideRight);
    // Arrows move the selection here, as in a text: they drive no robot.
    setProperty("readsArrowKeys", true);
}

void ByteLogView::setLogModel(ByteLogModel *model)
{
    m_log = model;
    setItemDelegate(makeByteLogDelegate(model, this));
    setModel(model);
    // The oldest rows going keep the ones in sight where they are.
    connect(model, &QAbstractItemModel::rowsRemoved, this, &ByteLogView::keepRowsInPlace);
}

int ByteLogView::rowHeight() const
{
    return byteLogRowHeight(fontMetrics());
}

int ByteLogView::rowsInSight() const
{
    return std::max(1, viewport()->height() / rowHeight());
}

int ByteLogView::firstRowInSight() const
{
    return verticalScrollBar()->value();
}

void ByteLogView::showPending()
{
    if (!m_log || m_log->pendingCount() == 0)
        return;
    QScrollBar *scroll = verticalScrollBar();
    // Rows, one scroll step each: near the end means within two rows of it.
    const bool atBottom = scroll->value() >= scroll->maximum() - 2;
    m_log->showPending();
    if (atBottom)
        scroll->setValue(scroll->maximum());
}

void ByteLogView::keepRowsInPlace(const QModelIndex &, int first, int last)
{
    QScrollBar *scroll = verticalScrollBar();
    const int gone = last - first + 1;
    if (first == 0 && scroll->value() >= gone) {
        // The rows in sight are the same entries at smaller row numbers:
        // the scroll value follows them and no pixel changes.
        m_keepPixels = true;
        scroll->setValue(scroll->value() - gone);
        m_keepPixels = false;
    } else {
        viewport()->update();
    }
    updateGeometries();
}

QRect ByteLogView::visualRect(const QModelIndex &index) const
{
    if (!index.isValid())
        return {};
    const int h = rowHeight();
    return {0, (index.row() - firstRowInSight()) * h, viewport()->width(), h};
}

void ByteLogView::scrollTo(const QModelIndex &index, ScrollHint hint)
{
    if (!index.isValid())
        return;
    const int row = index.row(), first = firstRowInSight(), sight = rowsInSight();
    int value = first;
    switch (hint) {
    case EnsureVisible:
        if (row < first)
            value = row;
        else if (row >= first + sight)
            value = row - sight + 1;
        break;
    case PositionAtTop:
        value = row;
        break;
    case PositionAtBottom:
        value = row - sight + 1;
        break;
    case PositionAtCenter:
        value = row - sight / 2;
        break;
    }
    verticalScrollBar()->setValue(value);
}

QModelIndex ByteLogView::indexAt(const QPoint &point) const
{
    if (!model() || point.y() < 0)
        return {};
    const int row = firstRowInSight() + point.y() / rowHeight();
    return row < model()->rowCount() ? model()->index(row, 0) : QModelIndex();
}

QModelIndex ByteLogView::moveCursor(CursorAction action, Qt::KeyboardModifiers)
{
    const int rows = model() ? model()->rowCount() : 0;
    if (rows == 0)
        return {};
    const QModelIndex current = currentIndex();
    int row = current.isValid() ? current.row() : firstRowInSight();
    switch (action) {
    case MoveUp:
    case MovePrevious:
        --row;
        break;
    case MoveDown:
    case MoveNext:
        ++row;
        break;
    case MovePageUp:
        row -= rowsInSight();
        break;
    case MovePageDown:
        row += rowsInSight();
        break;
    case MoveHome:
        row = 0;
        break;
    case MoveEnd:
        row = rows - 1;
        break;
    case MoveLeft:
    case MoveRight:
        break;
    }
    return model()->index(std::clamp(row, 0, rows - 1), 0);
}

int ByteLogView::verticalOffset() const
{
    return firstRowInSight() * rowHeight();
}

void ByteLogView::setSelection(const QRect &rect, QItemSelectionModel::SelectionFlags command)
{
    if (!model() || model()->rowCount() == 0)
        return;
    const int last = model()->rowCount() - 1, h = rowHeight();
    const QRect r = rect.normalized();
    const int top = std::clamp(firstRowInSight() + r.top() / h, 0, last);
    const int bottom = std::clamp(firstRowInSight() + r.bottom() / h, 0, last);
    selectionModel()->select(QItemSelection(model()->index(top, 0), model()->index(bottom, 0)), command);
}

QRegion ByteLogView::visualRegionForSelection(const QItemSelection &selection) const
{
    QRegion region;
    const int h = rowHeight();
    for (const QItemSelectionRange &range : selection)
        region += QRect(0, (range.top() - firstRowInSight()) * h, viewport()->width(),
                        (range.bottom() - range.top() + 1) * h)
                      .intersected(viewport()->rect());
    return region;
}

void ByteLogView::paintEvent(QPaintEvent *event)
{
    if (!model())
        return;
    QPainter painter(viewport());
    const int h = rowHeight(), rows = model()->rowCount();
    const QRect area = event->rect();
    const int first = firstRowInSight() + std::max(0, area.top()) / h;
    const int last = std::min(rows - 1, firstRowInSight() + area.bottom() / h);
    QStyleOptionViewItem option;
    initViewItemOption(&option);
    const QStyle::State state = option.state;
    const QModelIndex current = currentIndex();
    const bool focus = hasFocus() && current.isValid();
    QAbstractItemDelegate *delegate = itemDelegate();
    for (int row = first; row <= last; ++row) {
        const QModelIndex index = model()->index(row, 0);
        option.rect = QRect(0, (row - firstRowInSight()) * h, viewport()->width(), h);
        option.state = state;
        if (selectionModel() && selectionModel()->isSelected(index))
            option.state |= QStyle::State_Selected;
        if (focus && current.row() == row)
            option.state |= QStyle::State_HasFocus;
        delegate->paint(&painter, option, index);
    }
}

void ByteLogView::updateGeometries()
{
    QScrollBar *scroll = verticalScrollBar();
    const int rows = model() ? model()->rowCount() : 0;
    // At the end, it stays there as rows come or the view shrinks.
    const bool atEnd = scroll->value() == scroll->maximum();
    scroll->setSingleStep(1);
    scroll->setPageStep(rowsInSight());
    scroll->setRange(0, std::max(0, rows - rowsInSight()));
    if (atEnd)
        scroll->setValue(scroll->maximum());
    QAbstractItemView::updateGeometries();
}

void ByteLogView::scrollContentsBy(int, int dy)
{
    // Moves what is drawn and paints only the rows that came into sight.
    if (!m_keepPixels)
        viewport()->scroll(0, dy * rowHeight());
}

void ByteLogView::rowsInserted(const QModelIndex &parent, int start, int end)
{
    QAbstractItemView::rowsInserted(parent, start, end);
    updateGeometries();
    // Only where the new rows land, if that is in sight.
    const int h = rowHeight();
    viewport()->update(QRect(0, (start - firstRowInSight()) * h, viewport()->width(), (end - start + 1) * h));
}

QString ByteLogView::selectedText() const
{
    QModelIndexList rows = selectionModel() ? selectionModel()->selectedRows() : QModelIndexList();
    std::sort(rows.begin(), rows.end(), [](const QModelIndex &a, const QModelIndex &b) { return a.row() < b.row(); });
    QStringList lines;
    lines.reserve(rows.size());
    for (const QModelIndex &row : std::as_const(rows))
        lines << row.data(Qt::DisplayRole).toString();
    return lines.join(QLatin1Char('\n'));
}

void ByteLogView::keyPressEvent(QKeyEvent *event)
{
    // Every selected row, not only the current one as an item view copies.
    if (event == QKeySequence::Copy) {
        if (const QString text = selectedText(); !text.isEmpty())
            QGuiApplication::clipboard()->setText(text);
        event->accept();
        return;
    }
    QAbstractItemView::keyPressEvent(event);
}

void ByteLogView::changeEvent(QEvent *event)
{
    QAbstractItemView::changeEvent(event);
    // A new font changes the row height; colours follow the palette as rows are drawn.
    if (event->type() == QEvent::FontChange || event->type() == QEvent::StyleChange) {
        updateGeometries();
        viewport()->update();
    }
}

#include "moc_byte_log_view.cpp"
