// SPDX-License-Identifier: GPL-3.0-or-later
#include "signal_bars.h"

#include "display_palette.h"
#include "signal_bars_factory.h"

#include <QBarCategoryAxis>
#include <QBarSet>
#include <QChart>
#include <QEvent>
#include <QLegend>
#include <QLegendMarker>
#include <QStackedBarSeries>

#include <cmath>
#include <QValueAxis>

namespace {

constexpr int kCliffCount = 4;
constexpr int kLightBumpCount = 6;
constexpr qreal kSignalMax = 4095;
constexpr int kCliffSignalFirst = 28;     // packets 28..31
constexpr int kLightBumpSignalFirst = 46; // packets 46..51

// Short positions under the bars: Left, Front Left, Center Left, ...
const char *const kCliffPositions[kCliffCount] = {
    QT_TRANSLATE_NOOP("SignalBars", "L"), QT_TRANSLATE_NOOP("SignalBars", "FL"),
    QT_TRANSLATE_NOOP("SignalBars", "FR"), QT_TRANSLATE_NOOP("SignalBars", "R")};
const char *const kLightBumpPositions[kLightBumpCount] = {
    QT_TRANSLATE_NOOP("SignalBars", "L"),  QT_TRANSLATE_NOOP("SignalBars", "FL"),
    QT_TRANSLATE_NOOP("SignalBars", "CL"), QT_TRANSLATE_NOOP("SignalBars", "CR"),
    QT_TRANSLATE_NOOP("SignalBars", "FR"), QT_TRANSLATE_NOOP("SignalBars", "R")};

bool isDark(const QPalette &palette) { return palette.color(QPalette::Window).lightness() < 128; }

// A grey `share` of the way from `from` to `to`.
QColor greyBetween(const QColor &from, const QColor &to, qreal share)
{
    const int level = qRound(qGray(from.rgb()) * (1 - share) + qGray(to.rgb()) * share);
    return QColor(level, level, level);
}

QColor withAlpha(QColor c, qreal alpha)
{
    c.setAlphaF(alpha);
    return c;
}

} // namespace

SignalBars::SignalBars(QWidget *parent) : QChartView(parent)
{
    auto *chart = new QChart;
    chart->setAnimationOptions(QChart::NoAnimation); // values change at display rate
    chart->setBackgroundRoundness(0);
    chart->setMargins(QMargins(4, 4, 4, 4));

    m_cliffs = new QBarSet(QString());
    m_lightBumps = new QBarSet(QString());
    m_series = new QStackedBarSeries;
    m_series->append(m_cliffs);
    m_series->append(m_lightBumps);
    m_series->setBarWidth(0.7);
    chart->addSeries(m_series);

    m_axisX = new QBarCategoryAxis;
    m_axisY = new QValueAxis;
    m_axisY->setRange(0, kSignalMax);
    m_axisY->setTickType(QValueAxis::TicksDynamic);
    m_axisY->setTickAnchor(0);
    m_axisY->setTickInterval(1000);
    m_axisY->setMinorTickCount(1);
    m_axisY->setLabelFormat("%d");
    chart->addAxis(m_axisX, Qt::AlignBottom);
    chart->addAxis(m_axisY, Qt::AlignLeft);
    m_series->attachAxis(m_axisX);
    m_series->attachAxis(m_axisY);

    chart->legend()->setAlignment(Qt::AlignBottom);
    // Squeezed, Qt Charts shows every value label as "…": as many as fit.
    connect(chart, &QChart::plotAreaChanged, this, &SignalBars::fitValueLabels);
    setChart(chart);
    setRenderHint(QPainter::Antialiasing);

    applyFonts();
    applyPalette();
    retranslateUi(); // the categories: laying out the axis's labels is dear, once is enough
    showBars();
}

void SignalBars::retranslateUi()
{
    m_cliffs->setLabel(tr("Cliff"));
    m_lightBumps->setLabel(tr("Light bump"));
    refreshCategories();
    applyPalette(); // the title
    setAccessibleName(tr("Signal bars"));
    updateDescription();
}

void SignalBars::refreshCategories()
{
    // The position, with the kind in small type under it, fits ten bars in a
    // narrow chart; the colours and the legend tell the kinds apart too.
    m_categories.clear();
    QStringList labels;
    auto add = [&](const QString &kind, const QString &smallKind, const char *position) {
        const QString shortPosition = tr(position);
        m_categories << kind + ' ' + shortPosition;
        labels << QStringLiteral("<center><b>%1</b><br><small>%2</small></center>").arg(shortPosition, smallKind);
    };
    for (const char *position : kCliffPositions)
        add(tr("Cliff"), tr("cliff", "under a bar"), position);
    if (hasLightBumpers())
        for (const char *position : kLightBumpPositions)
            add(tr("Light"), tr("light", "under a bar"), position);
    m_axisX->setCategories(labels);
}

void SignalBars::updateDescription()
{
    // The signals as a list a screen reader can read out: "Cliff L 2610, ...".
    QStringList parts;
    const QList<qreal> values = barValues();
    for (qsizetype i = 0; i < m_categories.size(); ++i)
        parts << tr("%1: %2").arg(m_categories.at(i)).arg(values.at(i));
    QString text = parts.join(tr(", "));
    if (m_stale)
        text = tr("Stale: %1").arg(text);
    if (accessibleDescription() != text)
        setAccessibleDescription(text);
}

QSize SignalBars::minimumSizeHint() const
{
    // Narrower, and the category labels under ten bars are cut short.
    return hasLightBumpers() ? QSize(460, 280) : QSize(300, 280);
}
QSize SignalBars::sizeHint() const { return {560, 360}; }

void SignalBars::setProfile(const oi::RobotProfile &profile)
{
    // The same robot kind again (another robot selected, a dock made late
    // catching up): the categories stay, and their labels are dear to lay out.
    if (&profile == m_profile)
        return;
    m_profile = &profile;
    refreshCategories();
    showBars();
}

// A bar at zero for each category, the legend and title for the profile.
void SignalBars::showBars()
{
    const QStringList &names = m_categories;

    // Each set is zero where the other has its bars.
    m_cliffs->remove(0, m_cliffs->count());
    m_lightBumps->remove(0, m_lightBumps->count());
    for (int i = 0; i < names.size(); ++i) {
        m_cliffs->append(0);
        m_lightBumps->append(0);
    }
    const QList<QLegendMarker *> markers = chart()->legend()->markers(m_series);
    if (markers.size() == 2)
        markers.at(1)->setVisible(hasLightBumpers());
    applyPalette(); // the title names what is shown
    updateDescription();
    updateGeometry();
}

void SignalBars::setSnapshot(const oi::SensorSnapshot &snapshot)
{
    auto show = [](QBarSet *set, int index, qreal value) {
        if (set->at(index) != value)
            set->replace(index, value);
    };
    for (int i = 0; i < kCliffCount; ++i)
        show(m_cliffs, i, snapshot.has(kCliffSignalFirst + i) ? snapshot.raw(kCliffSignalFirst + i) : 0);
    for (int i = 0; hasLightBumpers() && i < kLightBumpCount; ++i) {
        const int id = kLightBumpSignalFirst + i;
        show(m_lightBumps, kCliffCount + i, snapshot.has(id) ? snapshot.raw(id) : 0);
    }
    updateDescription();
}

void SignalBars::setStale(bool stale)
{
    if (m_stale == stale)
        return;
    m_stale = stale;
    applyPalette();
    updateDescription();
}

QStringList SignalBars::categories() const { return m_categories; }

QList<qreal> SignalBars::barValues() const
{
    QList<qreal> out;
    for (int i = 0; i < m_categories.size(); ++i)
        out << m_cliffs->at(i) + m_lightBumps->at(i);
    return out;
}

qreal SignalBars::barValue(const QString &category) const
{
    const qsizetype index = categories().indexOf(category);
    return index < 0 ? -1 : barValues().at(index);
}

QColor SignalBars::cliffColour() const
{
    // The same colours as the signal bars in the robot diagram.
    return isDark(palette()) ? QColor(70, 200, 200) : QColor(0, 130, 140);
}

QColor SignalBars::lightBumpColour() const
{
    return isDark(palette()) ? QColor(110, 160, 245) : QColor(40, 100, 200);
}

void SignalBars::fitValueLabels(const QRectF &plotArea)
{
    const qreal pitch = QFontMetricsF(m_axisY->labelsFont()).height() * 1.2;
    qreal interval = 1000;
    while (interval < kSignalMax && (std::floor(kSignalMax / interval) + 1) * pitch > plotArea.height())
        interval *= 2;
    if (m_axisY->tickInterval() != interval)
        m_axisY->setTickInterval(interval);
}

void SignalBars::applyFonts()
{
    QFont labels = font();
    labels.setPointSizeF(labels.pointSizeF() * 1.1);
    // The category labels keep the base size: ten must fit side by side.
    m_axisX->setLabelsFont(font());
    m_axisY->setLabelsFont(labels);
    chart()->legend()->setFont(labels);
    chart()->setTitleFont(display::valueFont(font(), 1.3));
}

void SignalBars::applyPalette()
{
    const QPalette pal = palette();
    const QColor window = pal.color(QPalette::Window);
    const QColor text = pal.color(QPalette::WindowText);
    setBackgroundBrush(window);
    chart()->setBackgroundBrush(window);
    chart()->setPlotAreaBackgroundVisible(false);
    chart()->legend()->setLabelColor(text);

    for (QAbstractAxis *axis : {static_cast<QAbstractAxis *>(m_axisX), static_cast<QAbstractAxis *>(m_axisY)}) {
        axis->setLabelsColor(text);
        axis->setLinePen(QPen(withAlpha(text, 0.6), 1));
        axis->setGridLineColor(withAlpha(text, 0.18));
    }
    m_axisY->setMinorGridLineColor(withAlpha(text, 0.08));
    m_axisX->setGridLineVisible(false);

    const QString title = hasLightBumpers() ? tr("Cliff and light-bump signals") : tr("Cliff signals");
    if (m_stale) {
        chart()->setTitle(tr("STALE \u2014 %1").arg(title));
        chart()->setTitleBrush(display::stateColor(display::State::Stale, pal));
        // Opaque greys, a shade apart, so the two kinds still read apart.
        m_cliffs->setColor(greyBetween(window, text, 0.4));
        m_lightBumps->setColor(greyBetween(window, text, 0.28));
    } else {
        chart()->setTitle(title);
        chart()->setTitleBrush(text);
        m_cliffs->setColor(cliffColour());
        m_lightBumps->setColor(lightBumpColour());
    }
    m_cliffs->setBorderColor(m_cliffs->color());
    m_lightBumps->setBorderColor(m_lightBumps->color());
}

void SignalBars::changeEvent(QEvent *event)
{
    QChartView::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    else if (event->type() == QEvent::PaletteChange)
        applyPalette();
    else if (event->type() == QEvent::FontChange)
        applyFonts();
}

QWidget *makeSignalBars(QWidget *parent, SignalBars **bars)
{
    *bars = new SignalBars(parent);
    return *bars;
}

#include "moc_signal_bars.cpp"
