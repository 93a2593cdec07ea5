// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "battery_health.h"
#include "display_palette.h"

#include <QAbstractButton>
#include <QFontMetrics>
#include <QString>
#include <QStringList>
#include <QTime>

#include <optional>
#include <utility>

// The few values a fleet tile shows; a tile repaints only when one changes.
struct FleetTileValues {
    QString name;
    bool online = false;
    bool brokerReachable = true;       // false: what follows is the last known, the robot not heard since
    QString mode;                      // "Safe"; empty when not known
    QString modeReason;                // "cliff (front left)": why it is in Passive; empty: nothing to say
    std::optional<int> batteryPercent; // not known until the bridge says
    BatteryCondition packCondition = BatteryCondition::Unknown; // the pack's health
    std::optional<int> packCapacityMah; // measured
    bool bumpLeft = false;
    bool bumpRight = false;
    bool wheelDrop = false;
    int cliffs = 0;                    // how many cliff sensors see a drop
    QString link;                      // "streaming", "stale", ...
    bool linkHealthy = false;          // fresh data at the bridge
    std::optional<int> framesPerSecond;
    QString controller;                // empty: nobody
    QString program;                   // the controller's program, empty: none said (a console)
    // Its bridge went offline while the broker was fine (its last will), at
    // this time; null: not seen going (online, or offline before the console came).
    QTime bridgeLostAt;
    QString cutOffController;          // who drove it then, cut off; empty: nobody
    QString cutOffProgram;             // their program, empty: none said
    bool mayBeMoving = false;          // it was asked to move then: a real robot keeps its last drive
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
    // The same said shorter and shorter: without the word "battery", the
    // pack's capacity, then the pack's health (the charge alone at last).
    QStringList batteryTexts() const;
    // The lines below the name as painted at the tile's size: mode and
    // battery, hazards, link, control. The battery always whole (said
    // shorter when the mode would not fit beside it), the mode and why
    // shortened before it.
    QStringList shownLines() const;
    QString shownModeLine() const;
    // The height of its smallest type, in pixels.
    int smallestTextPixels() const;
    QString hazardText() const;
    QString linkText() const;
    QString controlText() const;
    // What a tile whose bridge went offline says at length (its tooltip, the
    // status bar): what was cut off, whether the robot may still be moving,
    // how to stop it and what to check. Empty while its bridge is not lost.
    static QString bridgeLostText(const FleetTileValues &values);

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
    // A line below the name: its texts, the longest first, of which the
    // first that fits is shown; kept whole at its right end, the first of
    // `rights` that leaves room (none: nothing there); its colour, if any
    // (then bold).
    struct Line {
        QStringList lefts;
        QStringList rights;
        std::optional<display::State> state;
    };
    QList<Line> lines() const;
    QFont fontOf(const Line &line) const;
    // The left and right parts as painted at the tile's size.
    std::pair<QString, QString> shown(const Line &line) const;
    // `left` shortened so that it and `right` share a line `width` wide.
    static QString leftPartShown(const QFontMetrics &metrics, int width, const QString &left, const QString &right);

    FleetTileValues m_values;
    int m_paints = 0;
};
