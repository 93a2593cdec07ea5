// SPDX-License-Identifier: GPL-3.0-or-later
// What each gauge reads from a sensor frame: the battery, the drive, the
// motors and the cargo bay.
#include "sensor_gauges.h"
#include "sensor_gauges_dash.h"

#include "display_palette.h"
#include "oi_text.h"
#include "value_gauge.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

using display::State;
using gauge_text::kDash;

namespace {

// Units are printed as the specification writes them, untranslated.
QString unitOf(const oi::SensorSnapshot &s, int packetId) { return oitext::fromView(s.value(packetId).unit()); }

// Cargo-bay connector pins of digital inputs 0..3 and the baud-rate-change pin.
constexpr int kCargoBayPins[] = {17, 5, 18, 6, 15};

} // namespace

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
    QString detail = s.has(25) && s.has(26) ? batteryDetail(s.batteryChargeMah(), s.batteryCapacityMah()) : QString();
    if (m_health.estimatedFromVoltage && !detail.isEmpty())
        detail = tr("%1, estimated from voltage").arg(detail);
    battery->setDetail(detail);
    battery->setToolTip(m_health.estimatedFromVoltage
                            ? tr("The robot guessed this charge from its voltage as it booted: until a full charge it "
                                 "is an estimate, and a worn pack's voltage sags under load, so it reads low.")
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
    charging->setToolTip(QString());
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
            charging->setToolTip(BatteryHealth::chargingFaultWords());
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
