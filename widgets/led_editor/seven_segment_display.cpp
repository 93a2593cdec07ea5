// SPDX-License-Identifier: GPL-3.0-or-later
#include "seven_segment_display.h"

#include <QEvent>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QStringList>

#include <limits>

namespace {

constexpr int kDigits = 4;
constexpr int kSegments = 7;
constexpr qreal kAspect = 0.58; // digit width over height, like the robot's display
constexpr qreal kMargin = 8;

// A segment as a six-sided bar from `a` to `b`, `t` thick.
QPolygonF bar(QPointF a, QPointF b, qreal t)
{
    const qreal h = t / 2;
    if (qFuzzyCompare(a.y(), b.y()))
        return QPolygonF({a, {a.x() + h, a.y() - h}, {b.x() - h, b.y() - h}, b, {b.x() - h, b.y() + h},
                          {a.x() + h, a.y() + h}});
    return QPolygonF({a, {a.x() + h, a.y() + h}, {b.x() + h, b.y() - h}, b, {b.x() - h, b.y() - h},
                      {a.x() - h, a.y() + h}});
}

} // namespace

SevenSegmentDisplay::SevenSegmentDisplay(QWidget *parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);
    updateDescription();
}

void SevenSegmentDisplay::setEditable(bool editable)
{
    m_editable = editable;
    setCursor(editable ? Qt::PointingHandCursor : Qt::ArrowCursor);
    // Only an editor is something to operate; a preview stays out of the Tab chain.
    setFocusPolicy(editable ? Qt::StrongFocus : Qt::NoFocus);
    updateDescription();
}

void SevenSegmentDisplay::setMasks(const std::array<std::uint8_t, 4> &masks)
{
    if (masks == m_masks)
        return;
    m_masks = masks;
    updateDescription();
    update();
}

QString SevenSegmentDisplay::describeMasks() const
{
    static const char *const kLetters = "ABCDEFG";
    QStringList digits;
    for (int position = 0; position < kDigits; ++position) {
        QString lit;
        for (int s = 0; s < kSegments; ++s)
            if ((m_masks[position] >> s) & 1)
                lit += QLatin1Char(kLetters[s]);
        digits << (lit.isEmpty() ? tr("digit %1 dark").arg(position + 1)
                                 : tr("digit %1 segments %2").arg(position + 1).arg(lit));
    }
    return digits.join(QStringLiteral("; "));
}

void SevenSegmentDisplay::updateDescription()
{
    QString text = tr("Lit: %1.").arg(describeMasks());
    if (m_editable)
        text += QLatin1Char(' ') + tr("Arrow keys choose a segment, Space switches it.");
    setAccessibleDescription(text);
}

void SevenSegmentDisplay::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        updateDescription();
    QWidget::changeEvent(event);
}

// Scales with the font, so the digits stay in proportion on any screen.
QSize SevenSegmentDisplay::sizeHint() const
{
    const int h = fontMetrics().height() * 5;
    return {h * 220 / 84, h};
}
QSize SevenSegmentDisplay::minimumSizeHint() const
{
    const int h = fontMetrics().height() * 5;
    return {h * 160 / 84, h};
}

QRectF SevenSegmentDisplay::digitCell(int position) const
{
    const qreal height = this->height() - 2 * kMargin;
    const qreal gap = height * 0.22;
    const qreal width = qMin(height * kAspect, (this->width() - 2 * kMargin - 3 * gap) / kDigits);
    const qreal total = kDigits * width + (kDigits - 1) * gap;
    const qreal left = (this->width() - total) / 2;
    return {left + position * (width + gap), kMargin, width, height};
}

QPolygonF SevenSegmentDisplay::segmentShape(int position, int segmentBit) const
{
    const QRectF cell = digitCell(position);
    const qreal t = cell.width() * 0.2;
    const qreal g = t * 0.2; // a hair between segments, as on the real display
    const qreal l = cell.left() + t / 2, r = cell.right() - t / 2;
    const qreal top = cell.top() + t / 2, mid = cell.center().y(), bottom = cell.bottom() - t / 2;
    switch (segmentBit) {
    case 0: return bar({l + g, top}, {r - g, top}, t);       // A
    case 1: return bar({r, top + g}, {r, mid - g}, t);       // B
    case 2: return bar({r, mid + g}, {r, bottom - g}, t);    // C
    case 3: return bar({l + g, bottom}, {r - g, bottom}, t); // D
    case 4: return bar({l, mid + g}, {l, bottom - g}, t);    // E
    case 5: return bar({l, top + g}, {l, mid - g}, t);       // F
    default: return bar({l + g, mid}, {r - g, mid}, t);      // G
    }
}

QPoint SevenSegmentDisplay::segmentCentre(int position, int segmentBit) const
{
    return segmentShape(position, segmentBit).boundingRect().center().toPoint();
}

void SevenSegmentDisplay::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    // A dark panel like the robot's, so lit segments read on any palette.
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(28, 28, 28));
    p.drawRoundedRect(rect(), 6, 6);
    const QColor lit = isEnabled() ? QColor(255, 96, 48) : QColor(150, 90, 70);
    const QColor unlit(62, 62, 62);
    for (int position = 0; position < kDigits; ++position)
        for (int s = 0; s < kSegments; ++s) {
            p.setBrush((m_masks[position] >> s) & 1 ? lit : unlit);
            p.drawPolygon(segmentShape(position, s));
        }
    if (m_editable && hasFocus()) {
        // The keyboard's segment, framed around it so its own colour stays visible.
        const QRectF box = segmentShape(m_current / kSegments, m_current % kSegments).boundingRect();
        const qreal pad = qMin(box.width(), box.height()) * 0.35;
        p.setBrush(Qt::NoBrush);
        p.setPen(QPen(palette().color(QPalette::Highlight), 1.5, Qt::DashLine));
        p.drawRoundedRect(box.adjusted(-pad, -pad, pad, pad), 2, 2);
    }
}

void SevenSegmentDisplay::toggle(int position, int segmentBit)
{
    m_masks[position] ^= static_cast<std::uint8_t>(1u << segmentBit);
    updateDescription();
    update();
    emit segmentsChanged(m_masks);
}

void SevenSegmentDisplay::keyPressEvent(QKeyEvent *event)
{
    if (!m_editable) {
        QWidget::keyPressEvent(event);
        return;
    }
    constexpr int kAll = kDigits * kSegments;
    switch (event->key()) {
    case Qt::Key_Right: m_current = (m_current + 1) % kAll; break;
    case Qt::Key_Left: m_current = (m_current + kAll - 1) % kAll; break;
    // Up and Down jump a whole digit, keeping the segment.
    case Qt::Key_Down: m_current = (m_current + kSegments) % kAll; break;
    case Qt::Key_Up: m_current = (m_current + kAll - kSegments) % kAll; break;
    case Qt::Key_Space: toggle(m_current / kSegments, m_current % kSegments); return;
    default: QWidget::keyPressEvent(event); return;
    }
    update();
}

void SevenSegmentDisplay::mousePressEvent(QMouseEvent *event)
{
    if (!m_editable || event->button() != Qt::LeftButton) {
        QWidget::mousePressEvent(event);
        return;
    }
    // The nearest segment whose (slightly enlarged) box holds the click, so
    // thin segments are easy to hit.
    const QPointF at = event->position();
    int bestPosition = -1, bestSegment = -1;
    qreal bestDistance = std::numeric_limits<qreal>::max();
    for (int position = 0; position < kDigits; ++position)
        for (int s = 0; s < kSegments; ++s) {
            const QRectF box = segmentShape(position, s).boundingRect();
            const qreal grow = qMin(box.width(), box.height()) * 0.4;
            if (!box.adjusted(-grow, -grow, grow, grow).contains(at))
                continue;
            const QPointF d = box.center() - at;
            const qreal distance = QPointF::dotProduct(d, d);
            if (distance < bestDistance) {
                bestDistance = distance;
                bestPosition = position;
                bestSegment = s;
            }
        }
    if (bestPosition < 0)
        return;
    m_current = bestPosition * kSegments + bestSegment;
    toggle(bestPosition, bestSegment);
}

#include "moc_seven_segment_display.cpp"
