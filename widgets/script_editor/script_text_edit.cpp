// SPDX-License-Identifier: GPL-3.0-or-later
#include "script_text_edit.h"

#include <QPainter>
#include <QTextBlock>

namespace {

constexpr int kGutterPadding = 6; // space either side of the numbers

// The gutter is a child widget that asks the editor to paint it, because only
// the editor knows where each block is on screen.
class Gutter : public QWidget {
public:
    explicit Gutter(ScriptTextEdit *editor) : QWidget(editor), m_editor(editor) {}
    QSize sizeHint() const override { return {m_editor->gutterWidth(), 0}; }

protected:
    void paintEvent(QPaintEvent *event) override { m_editor->paintGutter(event); }

private:
    ScriptTextEdit *m_editor;
};

} // namespace

ScriptTextEdit::ScriptTextEdit(QWidget *parent) : QPlainTextEdit(parent), m_gutter(new Gutter(this))
{
    m_gutter->setObjectName("lineNumbers");
    connect(this, &QPlainTextEdit::blockCountChanged, this, &ScriptTextEdit::updateGutterWidth);
    connect(this, &QPlainTextEdit::updateRequest, this, &ScriptTextEdit::updateGutter);
    updateGutterWidth();
}

int ScriptTextEdit::gutterWidth() const
{
    int digits = 1;
    for (int n = qMax(1, blockCount()); n >= 10; n /= 10)
        ++digits;
    // At least two digits wide so the text does not shift at line 10.
    return 2 * kGutterPadding + fontMetrics().horizontalAdvance(u'9') * qMax(2, digits);
}

void ScriptTextEdit::updateGutterWidth() { setViewportMargins(gutterWidth(), 0, 0, 0); }

void ScriptTextEdit::updateGutter(const QRect &rect, int dy)
{
    if (dy)
        m_gutter->scroll(0, dy);
    else
        m_gutter->update(0, rect.y(), m_gutter->width(), rect.height());
    if (rect.contains(viewport()->rect()))
        updateGutterWidth();
}

void ScriptTextEdit::resizeEvent(QResizeEvent *event)
{
    QPlainTextEdit::resizeEvent(event);
    const QRect cr = contentsRect();
    m_gutter->setGeometry(QRect(cr.left(), cr.top(), gutterWidth(), cr.height()));
}

void ScriptTextEdit::paintGutter(QPaintEvent *event)
{
    QPainter painter(m_gutter);
    painter.fillRect(event->rect(), palette().color(QPalette::AlternateBase));
    painter.setPen(palette().color(QPalette::PlaceholderText));
    painter.setFont(font());
    QTextBlock block = firstVisibleBlock();
    int top = qRound(blockBoundingGeometry(block).translated(contentOffset()).top());
    while (block.isValid() && top <= event->rect().bottom()) {
        const int height = qRound(blockBoundingRect(block).height());
        if (block.isVisible() && top + height >= event->rect().top())
            painter.drawText(0, top, m_gutter->width() - kGutterPadding, fontMetrics().height(), Qt::AlignRight,
                             QString::number(block.blockNumber() + 1));
        top += height;
        block = block.next();
    }
}

#include "moc_script_text_edit.cpp"
