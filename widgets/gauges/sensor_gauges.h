// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "battery_health.h"
#include "firmware_banner.h"
#include "sensor_snapshot.h"

#include <QHash>
#include <QList>
#include <QStringList>
#include <QWidget>

class QGridLayout;
class QLabel;
class QScrollArea;
class ValueGauge;

// The robot's numbers as gauges, in sections: battery, drive, motors (Roomba
// 500 / 600) and cargo bay (Create 1). Gauges for packets the profile does
// not have are hidden. Gauges flow into as many columns as the width allows
// and scroll where the panel is short.
class SensorGauges : public QWidget {
    Q_OBJECT
public:
    explicit SensorGauges(QWidget *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile);
    const oi::RobotProfile &profile() const { return *m_profile; }
    // Shows the snapshot's values; call it from a display timer.
    void setSnapshot(const oi::SensorSnapshot &snapshot);
    // Packets this robot's firmware reports wrongly (requested radius before
    // 3.3.0) are greyed, with the reason as their tooltip.
    void setCorrections(const oi::FirmwareCorrections &corrections);
    // The pack's health (a gauge of the battery section), and the charge's
    // caveat: estimated from voltage after a boot that re-seeded it.
    void setBatteryHealth(const BatteryHealthReport &report);
    // Stale values are greyed under a STALE banner; at the end of a replay
    // the banner says the recording has ended.
    void setStale(bool stale, bool replayEnded = false);
    bool isStale() const { return m_stale; }

    // Gauge keys: "battery", "voltage", "current", "temperature",
    // "charging_state", "charging_sources", "requested_velocity",
    // "requested_radius", "left_motor_current", "right_motor_current",
    // "main_brush_current", "side_brush_current", "dirt_detect",
    // "cargo_bay_analog", "digital_input_0".."digital_input_3",
    // "baud_rate_change", "battery_health".
    static QStringList allGaugeKeys();
    // The keys of the gauges this profile shows, in order.
    QStringList shownGaugeKeys() const;
    ValueGauge *gauge(const QString &key) const;
    // The value and unit a gauge shows, e.g. "79 %", or an empty string for
    // an unknown key.
    QString gaugeText(const QString &key) const;
    bool isGaugeShown(const QString &key) const;
    bool isGaugeOutOfRange(const QString &key) const;
    int columnCount() const { return m_columns; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    struct Section {
        QLabel *heading = nullptr;
        QStringList keys;
    };

    void retranslateUi();
    void refreshTitles();
    QString batteryDetail(int chargeMah, int capacityMah) const;
    ValueGauge *addGauge(const QString &key);
    bool gaugeApplies(const QString &key) const;
    int columnsForWidth(int width) const;
    void relayout();
    void refreshBanner();
    void showBannerText();
    void refreshReliability();

    void showBattery(const oi::SensorSnapshot &s);
    void showDrive(const oi::SensorSnapshot &s);
    void showMotors(const oi::SensorSnapshot &s);
    void showCargoBay(const oi::SensorSnapshot &s);

    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    QHash<QString, ValueGauge *> m_gauges;
    QList<Section> m_sections;
    QScrollArea *m_scroll = nullptr;
    QWidget *m_content = nullptr;
    QGridLayout *m_grid = nullptr;
    QLabel *m_banner = nullptr;
    oi::SensorSnapshot m_snapshot; // the last shown, to show again in a new language
    BatteryHealthReport m_health;
    oi::FirmwareCorrections m_corrections;
    int m_columns = 0;
    int m_captionWidth = 0; // what the widest caption needs
    bool m_stale = false;
    bool m_replayEnded = false;
};
