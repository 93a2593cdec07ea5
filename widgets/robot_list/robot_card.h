// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QAbstractButton>
#include <QColor>
#include <QString>

#include <optional>

// What the robot list shows of one robot, at a glance.
struct RobotCardValues {
    QString name;
    QColor colour;
    QString profile;                    // "Create 2"
    QString mode;                       // "Safe"; empty when unknown
    std::optional<int> batteryPercent;  // unknown until the robot says
    QString link;                       // "streaming", "lost", "not connected"
    bool live = false;                  // fresh data is arriving
    friend bool operator==(const RobotCardValues &, const RobotCardValues &) = default;
};

// One robot in the robot list: a colour bar, its name, and below it the
// profile, mode, battery and link. Checked when it is the selected robot.
class RobotCard : public QAbstractButton {
    Q_OBJECT
public:
    explicit RobotCard(QWidget *parent = nullptr);

    void setValues(const RobotCardValues &values);
    const RobotCardValues &values() const { return m_values; }
    // "Create 2 · Safe · 87 %"
    QString detailText() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    void renameRequested();

protected:
    void paintEvent(QPaintEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;

private:
    void updateAccessibleText();

    RobotCardValues m_values;
};
