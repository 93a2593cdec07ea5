// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "sensor_snapshot.h"

#include <QChartView>
#include <QList>
#include <QStringList>

class QBarCategoryAxis;
class QBarSet;
class QStackedBarSeries;
class QValueAxis;

// A live bar chart of the four cliff signals and, on the Roomba 500 / 600,
// the six light-bump signals, on a fixed 0..4095 axis. Cliff and light-bump
// bars have their own colours. The two kinds are two sets of one stacked
// series, each zero where the other has its bars, so every bar is centred on
// its own category.
class SignalBars : public QChartView {
    Q_OBJECT
public:
    explicit SignalBars(QWidget *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile);
    const oi::RobotProfile &profile() const { return *m_profile; }
    // Shows the snapshot's signals; call it from a display timer.
    void setSnapshot(const oi::SensorSnapshot &snapshot);
    // Stale bars turn grey and the title says so.
    void setStale(bool stale);
    bool isStale() const { return m_stale; }

    // The categories shown, left to right: "Cliff L", "Cliff FL", ...,
    // then "Light L" .. "Light R" (the light bumpers) on the Roomba 500 / 600.
    QStringList categories() const;
    // The bar heights, one per category, in the same order.
    QList<qreal> barValues() const;
    // The height of one category's bar, or -1 for an unknown category.
    qreal barValue(const QString &category) const;
    QColor cliffColour() const;
    QColor lightBumpColour() const;
    QValueAxis *valueAxis() const { return m_axisY; }

    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

protected:
    void changeEvent(QEvent *event) override;

private:
    // The value axis labelled every 1000, or more sparsely where that does not fit.
    void fitValueLabels(const QRectF &plotArea);
    bool hasLightBumpers() const { return m_profile->caps.lightBumpers; }
    void retranslateUi();
    void refreshCategories();
    void showBars();
    // The signals in words, for screen readers.
    void updateDescription();
    void applyPalette();
    void applyFonts();

    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    QStackedBarSeries *m_series = nullptr;
    QBarSet *m_cliffs = nullptr;
    QBarSet *m_lightBumps = nullptr;
    QBarCategoryAxis *m_axisX = nullptr;
    QValueAxis *m_axisY = nullptr;
    QStringList m_categories; // plain names; the axis shows them on two lines
    bool m_stale = false;
};
