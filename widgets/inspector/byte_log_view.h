// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QListView>

class ByteLogModel;

// The byte log on screen: one row per entry, one line each, in a fixed-pitch
// font, every row the same height, so drawing costs the rows in sight
// however long the log. Each part of a row has its colour (time dim, the
// direction bold, the meaning by what the entry is), every other entry on a
// tinted band. A line wider than the view is elided; its tooltip shows it
// whole, and a copy takes it whole.
//
// Rows can be selected (click, Shift, Ctrl, Ctrl+A); Ctrl+C copies them as
// the log shows them, one line each.
class ByteLogView : public QListView {
    Q_OBJECT
public:
    explicit ByteLogView(QWidget *parent = nullptr);
    void setLogModel(ByteLogModel *model);
    // Shows the model's pending entries: follows the newest if the reader
    // was at the end, else keeps the rows they were reading in place.
    void showPending();
    // The selected rows as the log shows them, one line each, oldest first.
    QString selectedText() const;

protected:
    void keyPressEvent(QKeyEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void updateRowHeight();
    ByteLogModel *m_log = nullptr;
};
