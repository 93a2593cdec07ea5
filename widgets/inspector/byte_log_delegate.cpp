// SPDX-License-Identifier: GPL-3.0-or-later
// How the byte log draws a row: its parts in their colours on one line,
// each row made ready once and drawn from a cache while it stays in sight.
#include "byte_log_delegate.h"

#include "byte_log_model.h"
#include "display_palette.h"

#include <QGlyphRun>
#include <QPainter>
#include <QRawFont>
#include <QStyledItemDelegate>
#include <QTextLayout>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <unordered_map>

int byteLogRowHeight(const QFontMetrics &metrics)
{
    return metrics.lineSpacing() + 2;
}

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

// Draws a row part by part, each in its colour, on one line. A row is made
// ready once, when its entry first comes into sight, and drawn from that
// while it stays there: each new render tick prepares only the new rows,
// never the whole log. Each part is a run of the fixed-pitch font's glyphs,
// one advance apart: a character lookup each, and no shaping, which a fixed
// pitch does not need (a third of the cost of laying the row out as text).
// A row with a character the font lacks is laid out as text, so that Qt
// finds it another font.
class ByteLogDelegate : public QStyledItemDelegate {
public:
    ByteLogDelegate(const ByteLogModel *log, QObject *parent) : QStyledItemDelegate(parent), m_log(log) {}

    // Every row alike: one line of the font.
    QSize sizeHint(const QStyleOptionViewItem &option, const QModelIndex &) const override
    {
        return {0, byteLogRowHeight(option.fontMetrics)};
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

        Row uncached;
        const Row *row = nullptr;
        if (selected) {
            uncached = prepare(index.row(), option, width, true);
            row = &uncached;
        } else {
            // Made again only when what it shows changed.
            if (m_cacheFormat != m_log->formatVersion() || m_cacheWidth != width || m_cacheFont != option.font
                || m_cachePalette != option.palette.cacheKey() || m_cache.size() > kMaxCachedRows) {
                m_cache.clear();
                m_cacheFormat = m_log->formatVersion();
                m_cacheWidth = width;
                m_cacheFont = option.font;
                m_cachePalette = option.palette.cacheKey();
            }
            auto cached = m_cache.find(entry);
            if (cached == m_cache.end())
                cached = m_cache.emplace(entry, prepare(index.row(), option, width, false)).first;
            row = &cached->second;
        }
        const QFontMetricsF metrics(option.font);
        const qreal top = option.rect.top() + std::floor((option.rect.height() - metrics.height()) / 2);
        const QPointF origin(option.rect.left() + kTextMargin, top);
        if (row->layout) {
            row->layout->draw(painter, origin);
        } else {
            const QPen pen = painter->pen();
            for (const auto &[glyphs, colour] : row->runs) {
                painter->setPen(colour);
                painter->drawGlyphRun(origin + QPointF(0, metrics.ascent()), glyphs);
            }
            painter->setPen(pen);
        }

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
    // Characters of a long run of bytes kept in sight: a frame's header and first packets.
    static constexpr int kMinBytesShown = 24;

    // A row ready to draw: its parts' glyph runs, or, where the font lacks a
    // character, its text laid out.
    struct Row {
        std::vector<std::pair<QGlyphRun, QColor>> runs;
        std::unique_ptr<QTextLayout> layout;
    };
    struct Part {
        int start;
        int length;
        QColor colour;
        bool bold = false;
    };

    const LogColours &mutableColours(const QPalette &palette) const
    {
        m_colours.update(palette);
        return m_colours;
    }

    // The fixed-pitch font's glyphs, regular and bold, for `font`.
    const QRawFont &rawFont(const QFont &font, bool bold) const
    {
        if (m_rawFontOf != font) {
            m_rawFontOf = font;
            m_raw = QRawFont::fromFont(font);
            QFont boldFont = font;
            boldFont.setBold(true);
            m_rawBold = QRawFont::fromFont(boldFont);
        }
        return bold ? m_rawBold : m_raw;
    }

    Row prepare(int row, const QStyleOptionViewItem &option, int width, bool selected) const
    {
        const ByteLogModel::Parts parts = m_log->parts(row);
        const LogColours &c = mutableColours(option.palette);
        const QString tag = parts.tag();
        const QString gap = ByteLogModel::kGap;
        // Too long for the view: cut with "…"; the tooltip and a copy have
        // it whole. Counted in characters of the fixed-pitch font, not
        // measured: a frame's meaning runs to a thousand characters, and
        // measuring them would cost more than drawing the row.
        const qreal advance = QFontMetricsF(option.font).horizontalAdvance(QLatin1Char('0'));
        const int fits = std::max(1, int(width / std::max(1.0, advance)));
        QString bytes = parts.bytes;
        const int head = int(parts.time.size() + gap.size() + tag.size() + gap.size());
        if (head + bytes.size() + gap.size() + parts.meaning.size() > fits) {
            // A frame's 80 bytes would fill the row: they give up room first,
            // so that what they mean starts in sight.
            const int bytesRoom = std::max(kMinBytesShown, (fits - head) / 3);
            if (bytes.size() > bytesRoom)
                bytes = bytes.left(bytesRoom - 1) + QChar(0x2026);
        }
        QString line = parts.time + gap + tag + gap + bytes + gap + parts.meaning;
        if (line.size() > fits)
            line = line.left(fits - 1) + QChar(0x2026);

        const auto part = [&](int start, int length, const QColor &colour, bool bold = false) {
            return Part{start, std::clamp(length, 0, std::max(0, int(line.size()) - start)),
                        selected ? option.palette.color(QPalette::HighlightedText) : colour, bold};
        };
        const int tagAt = int(parts.time.size() + gap.size());
        const int bytesAt = tagAt + int(tag.size());
        const int meaningAt = bytesAt + int(gap.size() + bytes.size() + gap.size());
        const std::array<Part, 4> partsOfLine = {
            part(0, tagAt, c.dim),
            part(tagAt, int(tag.size()), parts.direction == ByteLogModel::Direction::Tx ? c.tx : c.rx, true),
            part(bytesAt, meaningAt - bytesAt, c.text),
            part(meaningAt, int(line.size()) - meaningAt, c.meaning(parts)),
        };

        Row ready;
        for (const Part &p : partsOfLine) {
            if (p.length == 0)
                continue;
            const QRawFont &font = rawFont(option.font, p.bold);
            const QList<quint32> glyphs = font.glyphIndexesForString(line.mid(p.start, p.length));
            if (!font.isValid() || glyphs.size() != p.length || glyphs.contains(0u))
                return {{}, layOut(line, partsOfLine, option.font)};
            QList<QPointF> positions;
            positions.reserve(glyphs.size());
            for (int i = 0; i < glyphs.size(); ++i)
                positions.append(QPointF((p.start + i) * advance, 0));
            QGlyphRun run;
            run.setRawFont(font);
            run.setGlyphIndexes(glyphs);
            run.setPositions(positions);
            ready.runs.emplace_back(std::move(run), p.colour);
        }
        return ready;
    }

    static std::unique_ptr<QTextLayout> layOut(const QString &line, const std::array<Part, 4> &parts,
                                               const QFont &font)
    {
        QList<QTextLayout::FormatRange> formats;
        for (const Part &p : parts) {
            QTextLayout::FormatRange r;
            r.start = p.start;
            r.length = p.length;
            r.format.setForeground(p.colour);
            if (p.bold)
                r.format.setFontWeight(QFont::Bold);
            formats.append(r);
        }
        auto layout = std::make_unique<QTextLayout>(line, font);
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
    mutable std::unordered_map<quint64, Row> m_cache;
    mutable QFont m_rawFontOf;
    mutable QRawFont m_raw;
    mutable QRawFont m_rawBold;
    mutable quint64 m_cacheFormat = 0;
    mutable int m_cacheWidth = -1;
    mutable QFont m_cacheFont;
    mutable qint64 m_cachePalette = -1;
};

} // namespace

QStyledItemDelegate *makeByteLogDelegate(const ByteLogModel *log, QObject *parent)
{
    return new ByteLogDelegate(log, parent);
}
