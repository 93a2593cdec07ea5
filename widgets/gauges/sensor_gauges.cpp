// SPDX-License-Identifier: GPL-3.0-or-later
// The sensor gauges: which gauges the robot has, their layout, titles and
// the stale banner.
#include "sensor_gauges.h"
#include "sensor_gauges_dash.h"

#include "display_palette.h"
#include "oi_text.h"
#include "value_gauge.h"

#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QScrollArea>
#include <QScrollBar>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <cstdlib>

using display::State;
using gauge_text::kDash;

namespace {

// Which packet a gauge shows, and what the packet must be called on the
// profile for the gauge to apply (packets 15, 32 and 33 mean different
// things on different robots).
struct GaugePacket {
    const char *key;
    int packetId;
    const char *packetKey;
};

constexpr GaugePacket kGaugePackets[] = {
    {"battery", 25, "battery_charge"},
    {"voltage", 22, "voltage"},
    {"current", 23, "current"},
    {"temperature", 24, "temperature"},
    {"charging_state", 21, "charging_state"},
    {"charging_sources", 34, "charging_sources"},
    {"requested_velocity", 39, "requested_velocity"},
    {"requested_radius", 40, "requested_radius"},
    {"left_motor_current", 54, "left_motor_current"},
    {"right_motor_current", 55, "right_motor_current"},
    {"main_brush_current", 56, "main_brush_current"},
    {"side_brush_current", 57, "side_brush_current"},
    {"dirt_detect", 15, "dirt_detect"},
    {"cargo_bay_analog", 33, "cargo_bay_analog_signal"},
    {"digital_input_0", 32, "cargo_bay_digital_inputs"},
    {"digital_input_1", 32, "cargo_bay_digital_inputs"},
    {"digital_input_2", 32, "cargo_bay_digital_inputs"},
    {"digital_input_3", 32, "cargo_bay_digital_inputs"},
    {"baud_rate_change", 32, "cargo_bay_digital_inputs"},
};

constexpr int kMinGaugeWidth = 135;
// Wider captions wrap rather than take a column from every section.
constexpr int kMaxCaptionChars = 24;

} // namespace

SensorGauges::SensorGauges(QWidget *parent) : QWidget(parent), m_snapshot(*m_profile)
{
    m_banner = new QLabel(this);
    m_banner->setObjectName("staleBanner");
    m_banner->setAlignment(Qt::AlignCenter);
    m_banner->setFont(display::valueFont(font(), 1.3));
    m_banner->setAutoFillBackground(true);
    m_banner->setMargin(6);
    m_banner->setWordWrap(true); // a narrow dock wraps it, never cuts it
    m_banner->hide();

    // The gauges scroll where the panel is short; the banner stays in view.
    m_scroll = new QScrollArea(this);
    m_scroll->setFrameShape(QFrame::NoFrame);
    m_scroll->setWidgetResizable(true);
    m_scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_content = new QWidget(m_scroll);
    m_content->setObjectName("gaugeArea");
    m_content->setAutoFillBackground(false);
    m_scroll->viewport()->setAutoFillBackground(false);
    m_grid = new QGridLayout;
    m_grid->setSpacing(8);
    auto *contentLayout = new QVBoxLayout(m_content);
    contentLayout->setContentsMargins(8, 4, 8, 8);
    contentLayout->addLayout(m_grid);
    contentLayout->addStretch(1);
    m_scroll->setWidget(m_content);
    m_scroll->viewport()->installEventFilter(this);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    layout->addWidget(m_banner);
    layout->addWidget(m_scroll, 1);

    auto section = [this](QStringList keys) {
        auto *label = new QLabel(m_content);
        label->setObjectName("heading");
        label->setFont(display::valueFont(font(), 1.15));
        m_sections.append({label, keys});
    };
    section({"battery", "voltage", "current", "temperature", "charging_state", "charging_sources", "battery_health"});
    section({"requested_velocity", "requested_radius"});
    section({"left_motor_current", "right_motor_current", "main_brush_current", "side_brush_current",
             "dirt_detect"});
    section({"cargo_bay_analog", "digital_input_0", "digital_input_1", "digital_input_2", "digital_input_3",
             "baud_rate_change"});

    for (const GaugePacket &g : kGaugePackets)
        addGauge(QString::fromLatin1(g.key));
    addGauge(QStringLiteral("battery_health"));
    m_gauges.value("battery")->setRange(0, 100);
    m_gauges.value("requested_velocity")->setRange(-500, 500);
    m_gauges.value("dirt_detect")->setRange(0, 255);
    m_gauges.value("cargo_bay_analog")->setRange(0, 1023);

    refreshBanner();
    setProfile(*m_profile);
    retranslateUi();
}

void SensorGauges::retranslateUi()
{
    showBannerText();
    const QString headings[] = {tr("Battery"), tr("Drive"), tr("Motors and dirt"), tr("Cargo bay")};
    for (qsizetype i = 0; i < m_sections.size(); ++i)
        m_sections[i].heading->setText(headings[i]);
    refreshTitles();
    refreshReliability();
    setSnapshot(m_snapshot); // values and details in the new language
    setBatteryHealth(m_health);
}

void SensorGauges::setBatteryHealth(const BatteryHealthReport &report)
{
    m_health = report;
    ValueGauge *health = m_gauges.value("battery_health");
    health->setValue(BatteryHealth::conditionWords(report.condition));
    health->setState(report.condition == BatteryCondition::Replace ? State::Alert
                     : report.condition == BatteryCondition::Worn  ? State::Warning
                     : report.condition == BatteryCondition::Good  ? State::Active
                                                                   : State::Idle);
    const BatteryMeasurement &m = report.measurement;
    QStringList figures;
    if (m.capacityMah)
        figures << tr("%1 of %2 mAh").arg(std::lround(*m.capacityMah)).arg(m.claimedCapacityMah);
    if (m.resistanceMohm)
        figures << tr("%1 mΩ").arg(std::lround(*m.resistanceMohm));
    health->setDetail(figures.join(tr(", ")));
    QStringList tip{report.reason, BatteryHealth::confidenceWords(m)};
    if (report.fromEarlierSession)
        tip << tr("Measured %1, on an earlier connection.").arg(m.at.toString(Qt::ISODate));
    if (!report.trend.isEmpty())
        tip << tr("Capacity measured so far: %1.").arg(report.trend);
    health->setToolTip(tip.join(QLatin1Char('\n')));
    showBattery(m_snapshot);
}

void SensorGauges::setCorrections(const oi::FirmwareCorrections &corrections)
{
    m_corrections = corrections;
    refreshReliability();
}

void SensorGauges::refreshReliability()
{
    for (const GaugePacket &g : kGaugePackets)
        m_gauges.value(QString::fromLatin1(g.key))->setUnreliable(oitext::unreliableReason(g.packetId, m_corrections));
}

void SensorGauges::refreshTitles()
{
    const std::pair<const char *, QString> titles[] = {
        {"battery", tr("Charge")},
        {"voltage", tr("Voltage")},
        {"current", tr("Current")},
        {"temperature", tr("Temperature")},
        {"charging_state", tr("Charging")},
        {"charging_sources", tr("Charging sources")},
        {"requested_velocity", tr("Requested velocity")},
        {"requested_radius", tr("Requested radius")},
        {"left_motor_current", tr("Left wheel motor")},
        {"right_motor_current", tr("Right wheel motor")},
        {"main_brush_current", tr("Main brush motor")},
        {"side_brush_current", tr("Side brush motor")},
        {"dirt_detect", tr("Dirt detect")},
        {"cargo_bay_analog", tr("Analog input")},
        {"baud_rate_change", tr("Baud rate change")},
        {"battery_health", tr("Pack health")}};
    for (const auto &[key, title] : titles)
        m_gauges.value(key)->setTitle(title);
    for (int i = 0; i < 4; ++i)
        m_gauges.value(QStringLiteral("digital_input_%1").arg(i))->setTitle(tr("Digital input %1").arg(i));
    // The cargo-bay inputs take the profile's names for their bits.
    const auto bits = m_profile->bits(32);
    for (std::size_t i = 0; i < bits.size() && i < 5; ++i) {
        const QString key = i < 4 ? QStringLiteral("digital_input_%1").arg(i)
                                  : QStringLiteral("baud_rate_change");
        m_gauges.value(key)->setTitle(oitext::bitName(bits[i]));
    }

    // Columns as wide as the widest title, and the longest detail, need;
    // past a limit (long translations) captions wrap instead.
    const ValueGauge *any = m_gauges.value("battery");
    int width = any->widthForCaption(batteryDetail(8888, 8888));
    for (const QString &key : shownGaugeKeys())
        width = std::max(width, m_gauges.value(key)->widthForCaption(m_gauges.value(key)->title()));
    m_captionWidth = std::min(width, fontMetrics().averageCharWidth() * kMaxCaptionChars);
    if (m_columns > 0 && columnsForWidth(m_scroll->width()) != m_columns)
        relayout();
}

QString SensorGauges::batteryDetail(int chargeMah, int capacityMah) const
{
    return tr("%1 of %2 mAh").arg(chargeMah).arg(capacityMah);
}

ValueGauge *SensorGauges::addGauge(const QString &key)
{
    auto *g = new ValueGauge(QString(), m_content);
    g->setObjectName(key);
    m_gauges.insert(key, g);
    return g;
}

QStringList SensorGauges::allGaugeKeys()
{
    QStringList keys;
    for (const GaugePacket &g : kGaugePackets)
        keys << QString::fromLatin1(g.key);
    keys << QStringLiteral("battery_health");
    return keys;
}

bool SensorGauges::gaugeApplies(const QString &key) const
{
    // Measured from the voltage and current, which every robot streams.
    if (key == QLatin1String("battery_health"))
        return m_profile->packet(22) && m_profile->packet(23);
    for (const GaugePacket &g : kGaugePackets) {
        if (key != QLatin1String(g.key))
            continue;
        const oi::PacketInfo *info = m_profile->packet(g.packetId);
        return info && info->key == g.packetKey;
    }
    return false;
}

QStringList SensorGauges::shownGaugeKeys() const
{
    QStringList keys;
    for (const Section &section : m_sections)
        for (const QString &key : section.keys)
            if (gaugeApplies(key))
                keys << key;
    return keys;
}

ValueGauge *SensorGauges::gauge(const QString &key) const { return m_gauges.value(key); }

QString SensorGauges::gaugeText(const QString &key) const
{
    const ValueGauge *g = gauge(key);
    return g ? g->text() : QString();
}

bool SensorGauges::isGaugeShown(const QString &key) const
{
    const ValueGauge *g = gauge(key);
    return g && !g->isHidden();
}

bool SensorGauges::isGaugeOutOfRange(const QString &key) const
{
    const ValueGauge *g = gauge(key);
    return g && g->isOutOfRange();
}

void SensorGauges::setProfile(const oi::RobotProfile &profile)
{
    m_profile = &profile;
    refreshTitles();
    // Gauges the profile lacks keep nothing from the previous robot.
    for (auto it = m_gauges.cbegin(); it != m_gauges.cend(); ++it) {
        if (gaugeApplies(it.key()))
            continue;
        ValueGauge *g = it.value();
        g->setValue(kDash);
        g->setDetail(QString());
        g->setBarValue(std::nullopt);
        g->setState(State::Idle);
        g->setOutOfRange(false);
    }
    relayout();
    setSnapshot(oi::SensorSnapshot(profile));
}

int SensorGauges::columnsForWidth(int w) const
{
    const int minWidth = std::max({kMinGaugeWidth, fontMetrics().averageCharWidth() * 16, m_captionWidth});
    const int spacing = m_grid->horizontalSpacing();
    const int usable = w - 16 - m_scroll->verticalScrollBar()->sizeHint().width();
    const int fit = std::clamp((usable + spacing) / (minWidth + spacing), 1, 6);
    // Sections hold six, five and two gauges: two, three or six columns
    // fill their rows best, and wider gauges show long values whole.
    return fit >= 6 ? 6 : fit >= 3 ? 3 : fit;
}

void SensorGauges::relayout()
{
    m_columns = columnsForWidth(m_scroll->width());
    while (m_grid->count() > 0)
        delete m_grid->takeAt(0); // the layout item, not the widget
    for (int c = 0; c < m_grid->columnCount(); ++c)
        m_grid->setColumnStretch(c, 0);

    int row = 0;
    for (const Section &section : m_sections) {
        QStringList shown;
        for (const QString &key : section.keys) {
            const bool applies = gaugeApplies(key);
            m_gauges.value(key)->setVisible(applies);
            if (applies)
                shown << key;
        }
        section.heading->setVisible(!shown.isEmpty());
        if (shown.isEmpty())
            continue;
        m_grid->addWidget(section.heading, row++, 0, 1, m_columns);
        for (int i = 0; i < shown.size(); ++i)
            m_grid->addWidget(m_gauges.value(shown[i]), row + i / m_columns, i % m_columns);
        row += int((shown.size() + m_columns - 1) / m_columns);
    }
    for (int c = 0; c < m_columns; ++c)
        m_grid->setColumnStretch(c, 1);
}

QSize SensorGauges::sizeHint() const { return {520, 480}; }

QSize SensorGauges::minimumSizeHint() const { return {kMinGaugeWidth + 40, 160}; }

bool SensorGauges::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_scroll->viewport() && event->type() == QEvent::Resize
        && columnsForWidth(m_scroll->width()) != m_columns)
        relayout();
    return QWidget::eventFilter(watched, event);
}

void SensorGauges::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    if (event->type() == QEvent::PaletteChange)
        refreshBanner();
}

void SensorGauges::refreshBanner()
{
    QPalette p = m_banner->palette();
    p.setColor(QPalette::Window, display::stateColor(State::Stale, palette()));
    p.setColor(QPalette::WindowText, display::textOn(State::Stale, palette()));
    m_banner->setPalette(p);
}

void SensorGauges::showBannerText()
{
    m_banner->setText(m_replayEnded ? tr("REPLAY FINISHED \u2014 the recording has ended")
                                    : tr("STALE \u2014 no fresh data from the robot"));
}

void SensorGauges::setStale(bool stale, bool replayEnded)
{
    replayEnded = stale && replayEnded;
    if (m_stale == stale && m_replayEnded == replayEnded)
        return;
    m_stale = stale;
    m_replayEnded = replayEnded;
    showBannerText();
    m_banner->setVisible(stale);
    for (ValueGauge *g : std::as_const(m_gauges))
        g->setStale(stale);
}

void SensorGauges::setSnapshot(const oi::SensorSnapshot &snapshot)
{
    m_snapshot = snapshot;
    showBattery(snapshot);
    showDrive(snapshot);
    if (gaugeApplies("left_motor_current"))
        showMotors(snapshot);
    if (gaugeApplies("cargo_bay_analog"))
        showCargoBay(snapshot);
}

#include "moc_sensor_gauges.cpp"
