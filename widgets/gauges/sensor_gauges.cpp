// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensor_gauges.h"

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
#include <cstdlib>

using display::State;

namespace {

const QString kDash = QStringLiteral("\u2014");

// Units are printed as the specification writes them, untranslated.
QString unitOf(const oi::SensorSnapshot &s, int packetId) { return oitext::fromView(s.value(packetId).unit()); }

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

// Cargo-bay connector pins of digital inputs 0..3 and the baud-rate-change pin.
constexpr int kCargoBayPins[] = {17, 5, 18, 6, 15};

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
    section({"battery", "voltage", "current", "temperature", "charging_state", "charging_sources"});
    section({"requested_velocity", "requested_radius"});
    section({"left_motor_current", "right_motor_current", "main_brush_current", "side_brush_current",
             "dirt_detect"});
    section({"cargo_bay_analog", "digital_input_0", "digital_input_1", "digital_input_2", "digital_input_3",
             "baud_rate_change"});

    for (const GaugePacket &g : kGaugePackets)
        addGauge(QString::fromLatin1(g.key));
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
        {"baud_rate_change", tr("Baud rate change")}};
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
    return keys;
}

bool SensorGauges::gaugeApplies(const QString &key) const
{
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

void SensorGauges::showBattery(const oi::SensorSnapshot &s)
{
    ValueGauge *battery = m_gauges.value("battery");
    if (const std::optional<double> percent = s.batteryPercent()) {
        battery->setValue(QString::number(*percent, 'f', 0), "%");
        battery->setBarValue(*percent);
        battery->setState(*percent < 15 ? State::Alert : *percent < 30 ? State::Warning : State::Active);
    } else {
        battery->setValue(kDash, "%");
        battery->setBarValue(std::nullopt);
        battery->setState(State::Idle);
    }
    battery->setDetail(s.has(25) && s.has(26) ? batteryDetail(s.batteryChargeMah(), s.batteryCapacityMah())
                                              : QString());
    battery->setOutOfRange(s.value(25).outOfRange() || s.value(26).outOfRange());

    ValueGauge *voltage = m_gauges.value("voltage");
    voltage->setValue(s.has(22) ? QString::number(s.voltageMv() / 1000.0, 'f', 2) : kDash, "V");
    voltage->setOutOfRange(s.value(22).outOfRange());

    ValueGauge *current = m_gauges.value("current");
    current->setValue(s.has(23) ? QString::number(s.currentMa()) : kDash, unitOf(s, 23));
    current->setDetail(!s.has(23)            ? QString()
                       : s.currentMa() < 0   ? tr("discharging")
                       : s.currentMa() > 0   ? tr("charging")
                                             : tr("no current"));
    current->setOutOfRange(s.value(23).outOfRange());

    ValueGauge *temperature = m_gauges.value("temperature");
    temperature->setValue(s.has(24) ? QString::number(s.temperatureC()) : kDash, unitOf(s, 24));
    temperature->setOutOfRange(s.value(24).outOfRange());

    ValueGauge *charging = m_gauges.value("charging_state");
    charging->setOutOfRange(s.value(21).outOfRange());
    if (!s.has(21)) {
        charging->setValue(kDash);
        charging->setState(State::Idle);
    } else {
        switch (s.raw(21)) {
        case int(oi::ChargingState::NotCharging):
            charging->setValue(tr("Not charging"));
            charging->setState(State::Idle);
            break;
        case int(oi::ChargingState::Reconditioning):
            charging->setValue(tr("Reconditioning"));
            charging->setState(State::Active);
            break;
        case int(oi::ChargingState::FullCharging):
            charging->setValue(tr("Full charging"));
            charging->setState(State::Active);
            break;
        case int(oi::ChargingState::Trickle):
            charging->setValue(tr("Trickle charging"));
            charging->setState(State::Active);
            break;
        case int(oi::ChargingState::Waiting):
            charging->setValue(tr("Waiting"));
            charging->setState(State::Warning);
            break;
        case int(oi::ChargingState::Fault):
            charging->setValue(tr("Charging fault"));
            charging->setState(State::Alert);
            break;
        default:
            charging->setValue(tr("Unknown (%1)").arg(s.raw(21)));
            charging->setState(State::Alert);
            break;
        }
    }

    ValueGauge *sources = m_gauges.value("charging_sources");
    QStringList available;
    for (const oi::BitMeaning &b : m_profile->bits(34))
        if (s.raw(34) & b.mask)
            available << oitext::bitName(b);
    sources->setValue(!s.has(34) ? kDash : available.isEmpty() ? tr("none") : available.join(tr(" + ")));
    sources->setState(available.isEmpty() ? State::Idle : State::Active);
    sources->setOutOfRange(s.value(34).outOfRange());
}

void SensorGauges::showDrive(const oi::SensorSnapshot &s)
{
    ValueGauge *velocity = m_gauges.value("requested_velocity");
    if (s.has(39)) {
        velocity->setValue(QString::number(s.requestedVelocity()), unitOf(s, 39));
        velocity->setBarValue(s.requestedVelocity());
        velocity->setState(s.requestedVelocity() != 0 ? State::Active : State::Idle);
        velocity->setDetail(s.requestedVelocity() > 0   ? tr("forward")
                            : s.requestedVelocity() < 0 ? tr("backward")
                                                        : tr("stopped"));
    } else {
        velocity->setValue(kDash, unitOf(s, 39));
        velocity->setBarValue(std::nullopt);
        velocity->setState(State::Idle);
        velocity->setDetail(QString());
    }
    velocity->setOutOfRange(s.value(39).outOfRange());

    // ERRATA 14: 32767 and 32768 (-32768 as a signed word) mean straight,
    // -1 and 1 turn in place; any other radius lies within +-2000 mm.
    ValueGauge *radius = m_gauges.value("requested_radius");
    bool outOfRange = s.value(40).outOfRange();
    if (!s.has(40)) {
        radius->setValue(kDash, unitOf(s, 40));
        radius->setDetail(QString());
        radius->setState(State::Idle);
    } else {
        const int r = s.requestedRadius();
        radius->setState(State::Active);
        if (r == 32767 || r == 32768 || r == -32768) {
            radius->setValue(tr("straight"));
            radius->setDetail(tr("radius %1").arg(r));
            radius->setState(State::Idle);
        } else if (r == -1) {
            radius->setValue(tr("turn in place cw"));
            radius->setDetail(tr("radius -1"));
        } else if (r == 1) {
            radius->setValue(tr("turn in place ccw"));
            radius->setDetail(tr("radius 1"));
        } else {
            radius->setValue(QString::number(r), unitOf(s, 40));
            radius->setDetail(r > 0 ? tr("turning left") : r < 0 ? tr("turning right") : QString());
            outOfRange = outOfRange || std::abs(r) > 2000;
        }
    }
    radius->setOutOfRange(outOfRange);
}

void SensorGauges::showMotors(const oi::SensorSnapshot &s)
{
    const std::pair<const char *, int> currents[] = {{"left_motor_current", 54},
                                                     {"right_motor_current", 55},
                                                     {"main_brush_current", 56},
                                                     {"side_brush_current", 57}};
    for (const auto &[key, id] : currents) {
        ValueGauge *g = m_gauges.value(key);
        g->setValue(s.has(id) ? QString::number(s.raw(id)) : kDash, unitOf(s, id));
        g->setOutOfRange(s.value(id).outOfRange());
    }

    ValueGauge *dirt = m_gauges.value("dirt_detect");
    dirt->setValue(s.has(15) ? QString::number(s.dirtDetect()) : kDash);
    dirt->setBarValue(s.has(15) ? std::optional<double>(s.dirtDetect()) : std::nullopt);
    dirt->setState(s.has(15) && s.dirtDetect() > 0 ? State::Warning : State::Idle);
    dirt->setOutOfRange(s.value(15).outOfRange());
}

void SensorGauges::showCargoBay(const oi::SensorSnapshot &s)
{
    ValueGauge *analog = m_gauges.value("cargo_bay_analog");
    if (s.has(33)) {
        analog->setValue(QString::number(s.cargoBayAnalog()));
        analog->setBarValue(s.cargoBayAnalog());
        // 0 is 0 V and 1023 is 5 V.
        analog->setDetail(tr("%1 V on pin 4").arg(s.cargoBayAnalog() * 5.0 / 1023.0, 0, 'f', 2));
    } else {
        analog->setValue(kDash);
        analog->setBarValue(std::nullopt);
        analog->setDetail(QString());
    }
    analog->setState(State::Idle);
    analog->setOutOfRange(s.value(33).outOfRange());

    const bool outOfRange = s.value(32).outOfRange();
    for (int i = 0; i < 4; ++i) {
        ValueGauge *g = m_gauges.value(QStringLiteral("digital_input_%1").arg(i));
        const bool high = s.cargoBayDigitalInput(i);
        g->setValue(!s.has(32) ? kDash : high ? tr("high") : tr("low"));
        g->setDetail(tr("pin %1").arg(kCargoBayPins[i]));
        g->setState(s.has(32) && high ? State::Active : State::Idle);
        g->setOutOfRange(outOfRange);
    }
    // ERRATA 6: active low; it idles high.
    ValueGauge *baud = m_gauges.value("baud_rate_change");
    const bool asserted = s.baudRateChangeAsserted();
    baud->setValue(!s.has(32) ? kDash : asserted ? tr("asserted (low)") : tr("idle (high)"));
    baud->setDetail(tr("pin %1").arg(kCargoBayPins[4]));
    baud->setState(asserted ? State::Warning : State::Idle);
    baud->setOutOfRange(outOfRange);
}

#include "moc_sensor_gauges.cpp"
