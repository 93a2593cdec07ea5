// SPDX-License-Identifier: GPL-3.0-or-later
#include "value_gauge.h"

#include <QEvent>
#include <QFontMetrics>
#include <QFontMetricsF>
#include <QtMath>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPainterPath>
#include <QVBoxLayout>

#include <algorithm>

using display::State;

namespace {
constexpr int kStripeWidth = 7;
constexpr int kRadius = 8;
} // namespace

// The bar under a gauge's value.
class GaugeBar : public QWidget {
public:
    explicit GaugeBar(QWidget *parent) : QWidget(parent)
    {
        setFixedHeight(10);
        setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    }

    // The filled span as fractions of the width, start <= end.
    std::pair<double, double> span() const
    {
        if (!m_value || m_max <= m_min)
            return {0, 0};
        const auto at = [this](double v) { return std::clamp((v - m_min) / (m_max - m_min), 0.0, 1.0); };
        const double origin = m_min < 0 && m_max > 0 ? at(0) : 0.0;
        const double end = at(*m_value);
        return {std::min(origin, end), std::max(origin, end)};
    }

    bool spansZero() const { return m_min < 0 && m_max > 0; }

    // A gauge without a bar keeps the room for one, so gauges line up.
    bool m_visible = true;
    double m_min = 0;
    double m_max = 1;
    std::optional<double> m_value;
    QColor m_fill;
    QColor m_track;

protected:
    void paintEvent(QPaintEvent *) override
    {
        if (!m_visible)
            return;
        QPainter p(this);
        p.setRenderHint(QPainter::Antialiasing);
        const QRectF r = QRectF(rect()).adjusted(0.5, 0.5, -0.5, -0.5);
        p.setPen(Qt::NoPen);
        p.setBrush(m_track);
        p.drawRoundedRect(r, 4, 4);
        const auto [start, end] = span();
        if (end > start) {
            p.setBrush(m_fill);
            p.drawRoundedRect(QRectF(r.left() + r.width() * start, r.top(), r.width() * (end - start),
                                     r.height()),
                              4, 4);
        }
        if (spansZero()) {
            // A tick at zero, so the direction of a signed value is plain.
            const double x = r.left() + r.width() * (0 - m_min) / (m_max - m_min);
            p.setPen(QPen(palette().color(QPalette::WindowText), 2));
            p.drawLine(QPointF(x, r.top() - 1), QPointF(x, r.bottom() + 1));
        }
    }
};

// The big value and its unit on one line. Rather than push the gauge wider,
// both shrink together, to a point, so "Trickle charging" fits a narrow
// column; past that point the value is elided.
class ValueLine : public QWidget {
public:
    explicit ValueLine(QWidget *parent) : QWidget(parent)
    {
        setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
        refreshFonts();
    }

    void set(const QString &value, const QString &unit)
    {
        if (value == m_value && unit == m_unit)
            return;
        const bool wider = naturalWidth() < naturalWidth(value, unit);
        m_value = value;
        m_unit = unit;
        if (wider)
            updateGeometry();
        update();
    }

    void refreshFonts()
    {
        m_valueFont = display::valueFont(font(), 1.9);
        m_unitFont = font();
        m_unitFont.setPointSizeF(m_unitFont.pointSizeF() * 1.15);
        updateGeometry();
        update();
    }

    QSize sizeHint() const override
    {
        return {qCeil(naturalWidth()), QFontMetrics(m_valueFont).height()};
    }
    QSize minimumSizeHint() const override
    {
        const qreal digits = QFontMetricsF(m_valueFont).horizontalAdvance(QStringLiteral("0000"));
        return {qCeil(std::min(digits, naturalWidth())), QFontMetrics(m_valueFont).height()};
    }

    QString m_value = QStringLiteral("\u2014");
    QString m_unit;
    QColor m_valueColour;
    QColor m_unitColour;

protected:
    void paintEvent(QPaintEvent *) override
    {
        QPainter p(this);
        p.setRenderHint(QPainter::TextAntialiasing);
        const qreal natural = naturalWidth();
        qreal factor = natural > width() ? std::max(kMinFactor, width() / natural) : 1.0;
        QFont valueFont = m_valueFont;
        QFont unitFont = m_unitFont;
        // Text does not scale exactly with its point size (sizes round to
        // whole pixels): shrink a little more until it fits.
        for (;;) {
            valueFont.setPointSizeF(m_valueFont.pointSizeF() * factor);
            unitFont.setPointSizeF(m_unitFont.pointSizeF() * factor);
            if (factor <= kMinFactor || scaledWidth(valueFont, unitFont) <= width())
                break;
            factor = std::max(kMinFactor, factor - 0.03);
        }
        const QFontMetricsF vm(valueFont);
        const QFontMetricsF um(unitFont);
        // Both sit on the baseline of the full-size value.
        const qreal baseline = QFontMetricsF(m_valueFont).ascent();
        const qreal unitWidth = m_unit.isEmpty() ? 0 : um.horizontalAdvance(m_unit) + gap(um);
        const QString value = vm.elidedText(m_value, Qt::ElideRight, width() - unitWidth);
        p.setFont(valueFont);
        p.setPen(m_valueColour);
        p.drawText(QPointF(0, baseline), value);
        if (!m_unit.isEmpty()) {
            p.setFont(unitFont);
            p.setPen(m_unitColour);
            p.drawText(QPointF(vm.horizontalAdvance(value) + gap(um), baseline), m_unit);
        }
    }

private:
    static constexpr qreal kMinFactor = 0.55;
    static qreal gap(const QFontMetricsF &unitMetrics) { return unitMetrics.horizontalAdvance(' '); }

    qreal scaledWidth(const QFont &valueFont, const QFont &unitFont) const
    {
        const QFontMetricsF um(unitFont);
        const qreal unitWidth = m_unit.isEmpty() ? 0 : um.horizontalAdvance(m_unit) + gap(um);
        return QFontMetricsF(valueFont).horizontalAdvance(m_value) + unitWidth;
    }

    qreal naturalWidth() const { return naturalWidth(m_value, m_unit); }
    qreal naturalWidth(const QString &value, const QString &unit) const
    {
        const QFontMetricsF um(m_unitFont);
        const qreal unitWidth = unit.isEmpty() ? 0 : um.horizontalAdvance(unit) + gap(um);
        return QFontMetricsF(m_valueFont).horizontalAdvance(value) + unitWidth + 1;
    }

    QFont m_valueFont;
    QFont m_unitFont;
};

namespace {
// Captions wrap onto a second line rather than being cut off in a narrow
// gauge.
QLabel *captionLabel(QWidget *parent)
{
    auto *label = new QLabel(parent);
    label->setWordWrap(true);
    label->setTextFormat(Qt::PlainText);
    return label;
}
} // namespace

ValueGauge::ValueGauge(const QString &title, QWidget *parent) : QFrame(parent)
{
    setObjectName("gauge");
    // As tall as a wrapped caption needs, not only as the size hint says.
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Minimum);
    setMinimumWidth(120);

    m_title = captionLabel(this);
    m_title->setObjectName("title");
    m_value = new ValueLine(this);
    m_value->setObjectName("value");
    m_detail = captionLabel(this);
    m_detail->setObjectName("detail");
    m_flag = new QLabel(this);
    m_flag->setObjectName("outOfRange");
    m_flag->setFont(display::valueFont(font(), 1.0));
    m_flag->hide();
    m_bar = new GaugeBar(this);
    m_bar->m_visible = false;

    // The detail and the flag share a row, so the flag never moves the
    // gauges around.
    auto *detailRow = new QHBoxLayout;
    detailRow->addWidget(m_detail, 1);
    detailRow->addWidget(m_flag, 1);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(kStripeWidth + 8, 6, 10, 8);
    layout->setSpacing(2);
    layout->addWidget(m_title);
    layout->addWidget(m_value);
    layout->addLayout(detailRow);
    layout->addWidget(m_bar);

    // Keeps the detail row's height when it is empty.
    m_detail->setMinimumHeight(m_flag->sizeHint().height());
    refreshColours();
    setTitle(title);
    retranslateUi();
}

void ValueGauge::retranslateUi()
{
    m_flag->setText(tr("OUT OF RANGE"));
    updateDescription();
    update();
}

void ValueGauge::updateDescription()
{
    QString text = this->text();
    if (!detailText().isEmpty())
        text = tr("%1, %2").arg(text, detailText());
    if (m_outOfRange)
        text = tr("%1, out of range").arg(text);
    if (m_stale)
        text = tr("%1, stale").arg(text);
    if (!m_unreliable.isEmpty())
        text = tr("%1, unreliable: %2").arg(text, m_unreliable);
    if (accessibleDescription() != text)
        setAccessibleDescription(text);
}

void ValueGauge::setValue(const QString &value, const QString &unit)
{
    m_value->set(value, unit);
    updateDescription();
}

void ValueGauge::setDetail(const QString &detail)
{
    m_detail->setText(detail);
    showCompactRows();
    refreshToolTip();
    updateDescription();
}

void ValueGauge::setRange(double min, double max)
{
    m_bar->m_min = min;
    m_bar->m_max = max;
    m_bar->m_visible = true;
    showCompactRows();
    m_bar->update();
}

void ValueGauge::clearRange()
{
    m_bar->m_visible = false;
    showCompactRows();
    m_bar->update();
}

void ValueGauge::setBarValue(std::optional<double> value)
{
    m_bar->m_value = value;
    m_bar->update();
}

void ValueGauge::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    refreshColours();
}

void ValueGauge::setOutOfRange(bool outOfRange)
{
    if (m_outOfRange == outOfRange)
        return;
    m_outOfRange = outOfRange;
    m_flag->setVisible(outOfRange);
    m_detail->setVisible(!outOfRange);
    updateDescription();
    update();
}

void ValueGauge::setStale(bool stale)
{
    if (m_stale == stale)
        return;
    m_stale = stale;
    updateDescription();
    refreshColours();
}

void ValueGauge::setUnreliable(const QString &why)
{
    if (m_unreliable == why)
        return;
    m_unreliable = why;
    refreshToolTip();
    updateDescription();
    refreshColours();
}

void ValueGauge::refreshToolTip()
{
    // The detail may be elided on screen; why a value is unreliable comes after it.
    const QString detail = detailText();
    if (m_unreliable.isEmpty() || detail.isEmpty())
        setToolTip(detail + m_unreliable);
    else
        setToolTip(detail + QLatin1Char('\n') + m_unreliable);
}

void ValueGauge::setTitle(const QString &title)
{
    m_title->setText(title);
    m_title->setToolTip(title);
    setAccessibleName(title);
}

QString ValueGauge::title() const { return m_title->text(); }

void ValueGauge::setCompact(bool compact)
{
    m_compact = compact;
    m_detail->setMinimumHeight(compact ? 0 : m_flag->sizeHint().height());
    showCompactRows();
}

void ValueGauge::showCompactRows()
{
    m_detail->setVisible(!m_compact || !m_detail->text().isEmpty());
    m_bar->setVisible(!m_compact || m_bar->m_visible);
}


int ValueGauge::widthForCaption(const QString &caption) const
{
    const QMargins m = layout()->contentsMargins();
    return m.left() + m_title->fontMetrics().horizontalAdvance(caption) + m.right() + 2;
}
QString ValueGauge::valueText() const { return m_value->m_value; }
QString ValueGauge::unitText() const { return m_value->m_unit; }
QString ValueGauge::detailText() const { return m_detail->text(); }

QString ValueGauge::text() const
{
    return unitText().isEmpty() ? valueText() : valueText() + ' ' + unitText();
}

bool ValueGauge::hasBar() const { return m_bar->m_visible; }

double ValueGauge::barFraction() const
{
    const auto [start, end] = m_bar->span();
    return end - start;
}

void ValueGauge::refreshColours()
{
    const QPalette pal = palette();
    const State shown = isGreyed() ? State::Stale : m_state;
    QColor text = pal.color(QPalette::WindowText);
    QColor soft = text;
    soft.setAlphaF(0.72);
    if (isGreyed()) {
        text.setAlphaF(0.45);
        soft.setAlphaF(0.4);
    }
    auto colour = [](QLabel *label, const QColor &c) {
        QPalette p = label->palette();
        p.setColor(QPalette::WindowText, c);
        label->setPalette(p);
    };
    colour(m_title, soft);
    m_value->m_valueColour = text;
    m_value->m_unitColour = soft;
    m_value->update();
    colour(m_detail, soft);
    colour(m_flag, display::stateColor(State::Alert, pal));

    m_bar->m_fill = display::stateColor(shown == State::Idle ? State::Active : shown, pal);
    if (isGreyed())
        m_bar->m_fill = soft;
    QColor track = pal.color(QPalette::WindowText);
    track.setAlphaF(0.12);
    m_bar->m_track = track;
    m_bar->update();
    update();
}

void ValueGauge::changeEvent(QEvent *event)
{
    QFrame::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    if (event->type() == QEvent::PaletteChange)
        refreshColours();
    if (event->type() == QEvent::FontChange) {
        m_value->refreshFonts();
        m_flag->setFont(display::valueFont(font(), 1.0));
    }
}

void ValueGauge::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QPalette pal = palette();
    const QColor alert = display::stateColor(State::Alert, pal);
    const qreal border = m_outOfRange ? 3.0 : 1.0;
    const QRectF r = QRectF(rect()).adjusted(border / 2, border / 2, -border / 2, -border / 2);

    QColor background = pal.color(QPalette::Base);
    if (m_outOfRange && !isGreyed())
        background = QColor::fromRgbF(background.redF() * 0.85 + alert.redF() * 0.15,
                                      background.greenF() * 0.85 + alert.greenF() * 0.15,
                                      background.blueF() * 0.85 + alert.blueF() * 0.15);
    QColor edge = pal.color(QPalette::Mid);
    if (m_outOfRange)
        edge = alert;
    p.setPen(QPen(edge, border));
    p.setBrush(background);
    p.drawRoundedRect(r, kRadius, kRadius);

    // The stripe: the state at a glance, grey when stale.
    const State shown = isGreyed() ? State::Idle : m_state;
    QPainterPath clip;
    clip.addRoundedRect(r, kRadius, kRadius);
    p.setClipPath(clip);
    p.setPen(Qt::NoPen);
    p.setBrush(display::stateColor(shown, pal));
    p.drawRect(QRectF(r.left(), r.top(), kStripeWidth, r.height()));
}

#include "moc_value_gauge.cpp"
