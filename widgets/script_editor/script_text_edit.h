// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPlainTextEdit>

// A plain text editor with line numbers in a gutter on the left, so the line
// named in an error message is easy to find.
class ScriptTextEdit : public QPlainTextEdit {
    Q_OBJECT
public:
    explicit ScriptTextEdit(QWidget *parent = nullptr);

    int gutterWidth() const;
    void paintGutter(QPaintEvent *event);

protected:
    void resizeEvent(QResizeEvent *event) override;

private:
    void updateGutterWidth();
    void updateGutter(const QRect &rect, int dy);

    QWidget *m_gutter = nullptr;
};
