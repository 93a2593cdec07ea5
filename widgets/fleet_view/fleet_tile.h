// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QAbstractButton>
#include <QFontMetrics>
#include <QString>

#include <optional>

// The few values a fleet tile shows; a tile repaints only when one changes.
struct FleetTileValues {
    QString name;
    bool online = false;
    bool brokerReachable = true;       // false: what follows is the last known, the robot not heard since
    QString mode;                      // "Safe"; empty when not known
    QString modeReason;                // "cliff (front left)": why it is in Passive; empty: nothing to say
    std::optional<int> batteryPercent; // not known until the bridge says
    bool bumpLeft = false;
    bool bumpRight = false;
    bool wheelDrop = false;
    int cliffs = 0;                    // how many cliff sensors see a drop
    QString link;                      // "streaming", "stale", ...
    bool linkHealthy = false;          // fresh data at the bridge
    std::optional<int> framesPerSecond;
    QString controller;                // empty: nobody
    QString program;                   // the controller's program, empty: none said (a console)
    friend bool operator==(const FleetTileValues &, const FleetTileValues &) = default;
};

// One robot of the fleet view, large enough to read on a projector: its
// name and whether it is online, its mode and battery, bumps and cliffs,
// its link and who is in control. Click to select it; checked when it is
// the selected robot.
class FleetTile : public QAbstractButton {
    Q_OBJECT
public:
    explicit FleetTile(QWidget *parent = nullptr);

    void setValues(const FleetTileValues &values);
    const FleetTileValues &values() const { return m_values; }

    // The texts of the lines below the name, as painted.
    QString statusText() const;
    QString modeText() const; // the mode, why, and the battery
    QString modeOnlyText() const;
    QString batteryText() const; // empty while not known
    // The mode line as painted at the tile's size: the battery always whole,
    // the mode and why shortened before it.
    QString shownModeLine() const;
    // The height of its smallest type, in pixels.
    int smallestTextPixels() const;
    QString hazardText() const;
    QString linkText() const;
    QString controlText() const;

    // How often it was painted: a test sees a repaint skipped.
    int paintCount() const { return m_paints; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override { return sizeHint(); }

protected:
    void paintEvent(QPaintEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void updateAccessibleText();
    QFont lineFont() const;
    int lineWidth() const;
    // `left` shortened so that it and `right` share a line `width` wide.
    static QString leftPartShown(const QFontMetrics &metrics, int width, const QString &left, const QString &right);

    FleetTileValues m_values;
    int m_paints = 0;
};
