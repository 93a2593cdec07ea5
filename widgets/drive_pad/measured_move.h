// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "motion_goal.h"

#include <QWidget>

class QComboBox;
class QGridLayout;
class QLabel;
class QPushButton;
class QSpinBox;

// "Move exactly": a straight move or a turn on the spot by a measured
// amount, which the robot's model closes on the robot's own odometry (the
// moves a student's program makes through a bridge). The row only asks:
// goalRequested() carries the move; setResult() shows how it ended.
class MeasuredMove : public QWidget {
    Q_OBJECT
public:
    enum class Direction { Forward, Backward, TurnLeft, TurnRight };

    explicit MeasuredMove(QWidget *parent = nullptr);

    // The drive pad's speed limit (mm/s), which the move keeps to.
    void setSpeedLimit(int mmPerSecond);
    void setDirection(Direction direction);
    Direction direction() const;
    void setAmount(int amount); // mm, or degrees for a turn
    int amount() const;
    // The move Go asks for now.
    MotionGoal goal() const;
    // What happened to the last move, in words; empty hides it.
    void setResult(const QString &text);
    QString result() const;
    QPushButton *goButton() const { return m_go; }
    // One control under the other, for beside the pad; else in a row.
    void setColumn(bool column);

signals:
    void goalRequested(const MotionGoal &goal);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    void updateUnit();
    void arrange();

    QLabel *m_title = nullptr;
    QComboBox *m_direction = nullptr;
    QSpinBox *m_amount = nullptr;
    QPushButton *m_go = nullptr;
    QLabel *m_result = nullptr;
    QGridLayout *m_grid = nullptr;
    bool m_column = false;
    int m_speedLimit = 200;
    int m_distance = 500, m_angle = 90; // each kind keeps its own amount
};
