// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "display_palette.h"

#include <QFrame>
#include <QString>

#include <optional>

class QLabel;
class GaugeBar;
class ValueLine;

// One reading: a caption, a big value with its unit, a detail line and an
// optional bar between a minimum and a maximum. A value outside what the
// specification allows gets a red border and says OUT OF RANGE, so a bad
// reading is never mistaken for a good one.
class ValueGauge : public QFrame {
    Q_OBJECT
public:
    explicit ValueGauge(const QString &title, QWidget *parent = nullptr);

    void setTitle(const QString &title);
    void setValue(const QString &value, const QString &unit = QString());
    void setDetail(const QString &detail);
    // The bar runs from `min` to `max`; where the range spans zero it grows
    // from zero, so negative values go left.
    void setRange(double min, double max);
    void clearRange();
    // Where the bar stands; nullopt leaves it empty.
    void setBarValue(std::optional<double> value);
    // Colours the stripe down the gauge's left edge and the bar.
    void setState(display::State state);
    void setOutOfRange(bool outOfRange);
    void setStale(bool stale);
    // A value the robot is known to report wrongly: greyed, with `why` as its
    // tooltip. Empty makes it a good value again.
    void setUnreliable(const QString &why);
    // A readout among several (a lesson's step, the projector): no room kept
    // for an empty detail or a bar it has not got, so that a few of them fit
    // beside the step's views with every title and value whole.
    void setCompact(bool compact);
    QString unreliableReason() const { return m_unreliable; }
    // Stale or unreliable: shown grey.
    bool isGreyed() const { return m_stale || !m_unreliable.isEmpty(); }

    QString title() const;
    // The width at which `caption` fits on one line as the title or detail.
    int widthForCaption(const QString &caption) const;
    QString valueText() const;
    QString unitText() const;
    QString detailText() const;
    // The value and its unit as shown, e.g. "14.52 V" or "straight".
    QString text() const;
    bool isOutOfRange() const { return m_outOfRange; }
    bool hasBar() const;
    // The bar's filled share, 0..1 (from zero for ranges that span it).
    double barFraction() const;
    display::State state() const { return m_state; }

protected:
    void paintEvent(QPaintEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    // The value, detail and flags in words, for screen readers.
    void updateDescription();
    void refreshToolTip();
    void refreshColours();
    void showCompactRows();

    QLabel *m_title = nullptr;
    ValueLine *m_value = nullptr;
    QLabel *m_detail = nullptr;
    QLabel *m_flag = nullptr;
    GaugeBar *m_bar = nullptr;
    display::State m_state = display::State::Idle;
    bool m_outOfRange = false;
    bool m_stale = false;
    QString m_unreliable;
    bool m_compact = false;
};
