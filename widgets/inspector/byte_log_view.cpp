// SPDX-License-Identifier: GPL-3.0-or-later
#include "byte_log_view.h"

#include "byte_log_model.h"
#include "display_palette.h"

#include <QApplication>
#include <QClipboard>
#include <QFontDatabase>
#include <QKeyEvent>
#include <QPainter>
#include <QScrollBar>
#include <QStyledItemDelegate>

#include <algorithm>

namespace {

constexpr int kTextMargin = 4; // as a text document's margin, so the log reads as it did

QColor mixColours(const QColor &a, const QColor &b, double bShare)
{
    return QColor::fromRgbF(float(a.redF() * (1 - bShare) + b.redF() * bShare),
                            float(a.greenF() * (1 - bShare) + b.greenF() * bShare),
                            float(a.blueF() * (1 - bShare) + b.blueF() * bShare));
}

// The log's colours for one palette; made again when the palette changes.
struct LogColours {
    qint64 paletteKey = -1;
    QColor text, dim, tx, rx, problem, textTone, other, band;

    void update(const QPalette &pal)
    {
        if (pal.cacheKey() == paletteKey)
            return;
        paletteKey = pal.cacheKey();
        text = pal.color(QPalette::Text);
        dim = text;
        dim.setAlpha(140);
        tx = display::stateColor(display::State::Active, pal);
        // A softer blue than the link colour, for lines that are mostly received.
        rx = mixColours(pal.color(QPalette::Highlight), text, 0.3);
        problem = display::stateColor(display::State::Alert, pal);
        textTone = display::stateColor(display::State::Stale, pal);
        other = display::stateColor(display::State::Warning, pal);
        band = mixColours(pal.color(QPalette::Base), text, 0.06);
    }

    QColor meaning(const ByteLogModel::Parts &p) const
    {
        switch (p.tone) {
        case ByteLogModel::Tone::Problem:
            return problem;
        case ByteLogModel::Tone::Text:
            return textTone;
        case ByteLogModel::Tone::Other:
            return other;
        case ByteLogModel::Tone::Command:
        case ByteLogModel::Tone::Frame:
            break;
        }
        return p.direction == ByteLogModel::Direction::Tx ? tx : rx;
    }
};

// Draws a row part by part, each in its colour, on one line: no layout, and
// nothing but the rows in sight.
class ByteLogDelegate : public QStyledItemDelegate {
public:
    ByteLogDelegate(const ByteLogModel *log, QObject *parent) : QStyledItemDelegate(parent), m_log(log) {}

    // Every row alike (the view asks once): one line of the font.
    QSize sizeHint(const QStyleOptionViewItem &option, const QModelIndex &) const override
    {
        return {0, option.fontMetrics.lineSpacing() + 2};
    }

    void paint(QPainter *painter, const QStyleOptionViewItem &option, const QModelIndex &index) const override
    {
        const ByteLogModel::Parts parts = m_log->parts(index.row());
        m_colours.update(option.palette);
        const bool selected = option.state & QStyle::State_Selected;
        if (selected)
            painter->fillRect(option.rect, option.palette.brush(QPalette::Highlight));
        else if (parts.tinted)
            painter->fillRect(option.rect, m_colours.band);

        QFont bold = option.font;
        bold.setBold(true);
        const QColor highlighted = option.palette.color(QPalette::HighlightedText);
        const auto colour = [&](const QColor &c) { return selected ? highlighted : c; };
        struct Piece {
            QString text;
            QColor colour;
            const QFont *font;
        };
        const Piece pieces[] = {
            {parts.time + ByteLogModel::kGap, colour(m_colours.dim), &option.font},
            {parts.tag(), colour(parts.direction == ByteLogModel::Direction::Tx ? m_colours.tx : m_colours.rx), &bold},
            {ByteLogModel::kGap + parts.bytes + ByteLogModel::kGap, colour(m_colours.text), &option.font},
            {parts.meaning, colour(m_colours.meaning(parts)), &option.font},
        };
        QRect line = option.rect.adjusted(kTextMargin, 0, -kTextMargin, 0);
        painter->save();
        for (const Piece &piece : pieces) {
            if (line.width() <= 0)
                break;
            const QFontMetrics metrics(*piece.font);
            const int width = metrics.horizontalAdvance(piece.text);
            painter->setFont(*piece.font);
            painter->setPen(piece.colour);
            // Too long for the view: cut with "…"; the tooltip has it whole.
            const QString text =
                width > line.width() ? metrics.elidedText(piece.text, Qt::ElideRight, line.width()) : piece.text;
            painter->drawText(line, Qt::AlignLeft | Qt::AlignVCenter | Qt::TextSingleLine, text);
            line.setLeft(line.left() + width);
        }
        painter->restore();
        if (option.state & QStyle::State_HasFocus) {
            QStyleOptionFocusRect focus;
            focus.QStyleOption::operator=(option);
            focus.backgroundColor = option.palette.color(selected ? QPalette::Highlight : QPalette::Base);
            const QWidget *widget = option.widget;
            QStyle *style = widget ? widget->style() : QApplication::style();
            style->drawPrimitive(QStyle::PE_FrameFocusRect, &focus, painter, widget);
        }
    }

private:
    const ByteLogModel *m_log;
    mutable LogColours m_colours;
};

} // namespace

ByteLogView::ByteLogView(QWidget *parent) : QListView(parent)
{
    setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    // One height for every row: the view lays out none of them to know it.
    setUniformItemSizes(true);
    setLayoutMode(QListView::SinglePass);
    setVerticalScrollMode(QAbstractItemView::ScrollPerItem);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff); // long lines are elided
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setTabKeyNavigation(false); // a log: Tab moves on to the next control
    setWordWrap(false);
    setTextElideMode(Qt::ElideRight);
}

void ByteLogView::setLogModel(ByteLogModel *model)
{
    m_log = model;
    setItemDelegate(new ByteLogDelegate(model, this));
    setModel(model);
}

void ByteLogView::showPending()
{
    if (!m_log || m_log->pendingCount() == 0)
        return;
    QScrollBar *scroll = verticalScrollBar();
    // Rows, one scroll step each: near the end means within two rows of it.
    const bool atBottom = scroll->value() >= scroll->maximum() - 2;
    const int value = scroll->value();
    const int rowsBefore = m_log->rowCount() + m_log->pendingCount();
    m_log->showPending();
    if (atBottom) {
        scrollToBottom();
    } else {
        // The oldest rows went: what the reader was looking at moved up by as many.
        const int dropped = rowsBefore - m_log->rowCount();
        scroll->setValue(std::max(0, value - dropped));
    }
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
    // Every selected row, not only the current one as a list view copies.
    if (event == QKeySequence::Copy) {
        if (const QString text = selectedText(); !text.isEmpty())
            QGuiApplication::clipboard()->setText(text);
        event->accept();
        return;
    }
    QListView::keyPressEvent(event);
}

void ByteLogView::changeEvent(QEvent *event)
{
    QListView::changeEvent(event);
    // Colours follow the palette at the next paint; a new font changes the row height.
    if (event->type() == QEvent::FontChange || event->type() == QEvent::StyleChange)
        scheduleDelayedItemsLayout();
}
