// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QAbstractItemView>

class ByteLogModel;

// The byte log on screen: one row per entry, one line each, in a fixed-pitch
// font, every row the same height, so drawing costs the rows in sight
// however long the log. Its own view rather than a list view, which lays
// out every row and repaints all it shows whenever one is added: here new
// rows at the end scroll what is drawn and paint only themselves. Each part of a row has its colour (time dim, the
// direction bold, the meaning by what the entry is), every other entry on a
// tinted band. A line wider than the view is elided; its tooltip shows it
// whole, and a copy takes it whole.
//
// Rows can be selected (click, Shift, Ctrl, Ctrl+A); Ctrl+C copies them as
// the log shows them, one line each.
class ByteLogView : public QAbstractItemView {
    Q_OBJECT
public:
    explicit ByteLogView(QWidget *parent = nullptr);
    void setLogModel(ByteLogModel *model);
    // Shows the model's pending entries: follows the newest if the reader
    // was at the end, else keeps the rows they were reading in place.
    void showPending();
    // The selected rows as the log shows them, one line each, oldest first.
    QString selectedText() const;

    QRect visualRect(const QModelIndex &index) const override;
    void scrollTo(const QModelIndex &index, ScrollHint hint = EnsureVisible) override;
    QModelIndex indexAt(const QPoint &point) const override;

protected:
    QModelIndex moveCursor(CursorAction action, Qt::KeyboardModifiers modifiers) override;
    int horizontalOffset() const override { return 0; }
    int verticalOffset() const override;
    bool isIndexHidden(const QModelIndex &) const override { return false; }
    void setSelection(const QRect &rect, QItemSelectionModel::SelectionFlags command) override;
    QRegion visualRegionForSelection(const QItemSelection &selection) const override;
    void paintEvent(QPaintEvent *event) override;
    void updateGeometries() override;
    void scrollContentsBy(int dx, int dy) override;
    void rowsInserted(const QModelIndex &parent, int start, int end) override;
    void keyPressEvent(QKeyEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    // The vertical scroll bar counts rows: its value is the first row in sight.
    int rowHeight() const;
    int rowsInSight() const;
    int firstRowInSight() const;
    void keepRowsInPlace(const QModelIndex &parent, int first, int last);

    ByteLogModel *m_log = nullptr;
    bool m_keepPixels = false;
};
