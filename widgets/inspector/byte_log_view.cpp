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
#include <QTextLayout>

#include <algorithm>
#include <memory>
#include <unordered_map>

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

// Draws a row part by part, each in its colour, on one line. A row's text is
// laid out once, when its entry first comes into sight, and drawn from that
// layout while it stays there: each new render tick lays out only the new
// rows, as a text document would, and never the whole log.
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
        const bool selected = option.state & QStyle::State_Selected;
        const int width = option.rect.width() - 2 * kTextMargin;
        const quint64 entry = m_log->entryNumber(index.row());
        if (selected)
            painter->fillRect(option.rect, option.palette.brush(QPalette::Highlight));
        else if (entry % 2 == 1) // every other entry on a tinted band
            painter->fillRect(option.rect, mutableColours(option.palette).band);

        std::unique_ptr<QTextLayout> uncached;
        const QTextLayout *layout = nullptr;
        if (selected) {
            uncached = layOut(index.row(), option, width, true);
            layout = uncached.get();
        } else {
            // Laid out again only when what it shows changed.
            if (m_cacheFormat != m_log->formatVersion() || m_cacheWidth != width || m_cacheFont != option.font
                || m_cachePalette != option.palette.cacheKey() || m_cache.size() > kMaxCachedRows) {
                m_cache.clear();
                m_cacheFormat = m_log->formatVersion();
                m_cacheWidth = width;
                m_cacheFont = option.font;
                m_cachePalette = option.palette.cacheKey();
            }
            std::unique_ptr<QTextLayout> &cached = m_cache[entry];
            if (!cached)
                cached = layOut(index.row(), option, width, false);
            layout = cached.get();
        }
        const int top = option.rect.top() + (option.rect.height() - int(layout->boundingRect().height())) / 2;
        layout->draw(painter, QPointF(option.rect.left() + kTextMargin, top));

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
    // More rows than any screen shows: past it, the rows out of sight go.
    static constexpr std::size_t kMaxCachedRows = 400;

    const LogColours &mutableColours(const QPalette &palette) const
    {
        m_colours.update(palette);
        return m_colours;
    }

    std::unique_ptr<QTextLayout> layOut(int row, const QStyleOptionViewItem &option, int width, bool selected) const
    {
        const ByteLogModel::Parts parts = m_log->parts(row);
        const LogColours &c = mutableColours(option.palette);
        const QString tag = parts.tag();
        const QString gap = ByteLogModel::kGap;
        QString line = parts.line();
        // Too long for the view: cut with "…"; the tooltip and a copy have it
        // whole. Counted in characters of the fixed-pitch font, not measured:
        // a frame's meaning runs to a thousand characters, and measuring
        // them would cost more than drawing the row.
        const int fits = std::max(1, width / std::max(1, QFontMetrics(option.font).horizontalAdvance(QLatin1Char('0'))));
        if (line.size() > fits)
            line = line.left(fits - 1) + QChar(0x2026);

        const auto range = [&](int start, int length, const QColor &colour, bool bold = false) {
            QTextLayout::FormatRange r;
            r.start = start;
            r.length = std::clamp(length, 0, std::max(0, int(line.size()) - start));
            r.format.setForeground(selected ? option.palette.color(QPalette::HighlightedText) : colour);
            if (bold)
                r.format.setFontWeight(QFont::Bold);
            return r;
        };
        const int tagAt = int(parts.time.size() + gap.size());
        const int bytesAt = tagAt + int(tag.size());
        const int meaningAt = bytesAt + int(gap.size() + parts.bytes.size() + gap.size());
        const QList<QTextLayout::FormatRange> formats = {
            range(0, tagAt, c.dim),
            range(tagAt, int(tag.size()), parts.direction == ByteLogModel::Direction::Tx ? c.tx : c.rx, true),
            range(bytesAt, meaningAt - bytesAt, c.text),
            range(meaningAt, int(line.size()) - meaningAt, c.meaning(parts)),
        };

        auto layout = std::make_unique<QTextLayout>(line, option.font);
        QTextOption textOption;
        textOption.setWrapMode(QTextOption::NoWrap);
        layout->setTextOption(textOption);
        layout->setFormats(formats);
        layout->setCacheEnabled(true);
        layout->beginLayout();
        layout->createLine();
        layout->endLayout();
        return layout;
    }

    const ByteLogModel *m_log;
    mutable LogColours m_colours;
    mutable std::unordered_map<quint64, std::unique_ptr<QTextLayout>> m_cache;
    mutable quint64 m_cacheFormat = 0;
    mutable int m_cacheWidth = -1;
    mutable QFont m_cacheFont;
    mutable qint64 m_cachePalette = -1;
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
