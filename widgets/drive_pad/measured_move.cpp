// SPDX-License-Identifier: GPL-3.0-or-later
#include "measured_move.h"

#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>

#include <algorithm>
#include <numbers>

MeasuredMove::MeasuredMove(QWidget *parent) : QWidget(parent)
{
    m_title = new QLabel(this);
    m_direction = new QComboBox(this);
    m_direction->setObjectName("moveDirection");
    for (Direction d : {Direction::Forward, Direction::Backward, Direction::TurnLeft, Direction::TurnRight})
        m_direction->addItem(QString(), int(d));
    m_amount = new QSpinBox(this);
    m_amount->setObjectName("moveAmount");
    m_title->setBuddy(m_amount);
    m_go = new QPushButton(this);
    m_go->setObjectName("moveGo");
    m_result = new QLabel(this);
    m_result->setObjectName("moveResult");
    m_result->setWordWrap(true);
    m_result->hide();

    connect(m_direction, &QComboBox::currentIndexChanged, this, &MeasuredMove::updateUnit);
    connect(m_amount, &QSpinBox::valueChanged, this, [this](int value) {
        const bool turn = direction() == Direction::TurnLeft || direction() == Direction::TurnRight;
        (turn ? m_angle : m_distance) = value;
    });
    connect(m_go, &QPushButton::clicked, this, [this] { emit goalRequested(goal()); });
    // Enter in the amount goes, as a form's default button would.
    connect(m_amount, &QSpinBox::editingFinished, this, [this] {
        if (m_amount->hasFocus())
            m_go->click();
    });

    m_grid = new QGridLayout(this);
    m_grid->setContentsMargins(0, 0, 0, 0);
    arrange();
    retranslateUi();
    updateUnit();
}

void MeasuredMove::setColumn(bool column)
{
    if (column == m_column)
        return;
    m_column = column;
    arrange();
}

void MeasuredMove::arrange()
{
    for (QWidget *w : {static_cast<QWidget *>(m_title), static_cast<QWidget *>(m_direction),
                       static_cast<QWidget *>(m_amount), static_cast<QWidget *>(m_go), static_cast<QWidget *>(m_result)})
        m_grid->removeWidget(w);
    m_title->setWordWrap(m_column);
    if (m_column) {
        m_grid->addWidget(m_title, 0, 0, 1, 2);
        m_grid->addWidget(m_direction, 1, 0, 1, 2);
        m_grid->addWidget(m_amount, 2, 0);
        m_grid->addWidget(m_go, 2, 1);
        m_grid->addWidget(m_result, 4, 0, 1, 2, Qt::AlignTop);
        m_grid->setColumnStretch(0, 1);
        m_grid->setRowStretch(4, 1);
        setMaximumWidth(fontMetrics().averageCharWidth() * 26);
    } else {
        m_grid->addWidget(m_title, 0, 0, 1, 3);
        m_grid->addWidget(m_direction, 1, 0);
        m_grid->addWidget(m_amount, 1, 1);
        m_grid->addWidget(m_go, 1, 2);
        m_grid->addWidget(m_result, 2, 0, 1, 3);
        m_grid->setColumnStretch(0, 1);
        m_grid->setRowStretch(4, 0);
        setMaximumWidth(QWIDGETSIZE_MAX);
    }
}

void MeasuredMove::retranslateUi()
{
    m_title->setText(tr("Move exactly:"));
    m_title->setToolTip(tr("A move measured by the robot's own wheels, as a student's program makes it."));
    m_direction->setItemText(int(Direction::Forward), tr("Forward"));
    m_direction->setItemText(int(Direction::Backward), tr("Backward"));
    m_direction->setItemText(int(Direction::TurnLeft), tr("Turn left"));
    m_direction->setItemText(int(Direction::TurnRight), tr("Turn right"));
    m_go->setText(tr("Go"));
    m_go->setToolTip(tr("The robot drives until its wheels have measured the distance or the turn, "
                        "then stops. Space or Esc stops it sooner."));
    updateUnit();
}

void MeasuredMove::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void MeasuredMove::updateUnit()
{
    const bool turn = direction() == Direction::TurnLeft || direction() == Direction::TurnRight;
    const QSignalBlocker block(m_amount);
    if (turn) {
        m_amount->setRange(1, int(MotionGoal::kMaxAngleDeg));
        m_amount->setSuffix(tr(" °"));
        m_amount->setValue(m_angle);
    } else {
        m_amount->setRange(1, int(MotionGoal::kMaxDistanceMm));
        m_amount->setSuffix(tr(" mm"));
        m_amount->setValue(m_distance);
    }
}

void MeasuredMove::setSpeedLimit(int mmPerSecond) { m_speedLimit = mmPerSecond; }

void MeasuredMove::setDirection(Direction direction) { m_direction->setCurrentIndex(int(direction)); }

MeasuredMove::Direction MeasuredMove::direction() const { return Direction(m_direction->currentData().toInt()); }

void MeasuredMove::setAmount(int amount) { m_amount->setValue(amount); }

int MeasuredMove::amount() const { return m_amount->value(); }

MotionGoal MeasuredMove::goal() const
{
    // The pad's speed limit, within what a measured move can keep to.
    const double speed = std::clamp(double(m_speedLimit), MotionGoal::kMinSpeedMmPerS, MotionGoal::kMaxWheelSpeedMmPerS);
    MotionGoal g;
    switch (direction()) {
    case Direction::Forward:
    case Direction::Backward:
        g.kind = MotionGoal::Kind::Straight;
        g.distanceMm = direction() == Direction::Forward ? amount() : -amount();
        g.speedMmPerS = speed;
        break;
    case Direction::TurnLeft:
    case Direction::TurnRight:
        // Each wheel at the speed limit, on the spot.
        g.kind = MotionGoal::Kind::Turn;
        g.angleDeg = direction() == Direction::TurnLeft ? amount() : -amount();
        g.rateDegPerS = std::clamp(speed / (oi::kWheelBaseMm / 2) * 180 / std::numbers::pi,
                                   MotionGoal::kMinRateDegPerS, MotionGoal::kMaxRateDegPerS);
        break;
    }
    return g;
}

void MeasuredMove::setResult(const QString &text)
{
    m_result->setText(text);
    m_result->setVisible(!text.isEmpty());
}

QString MeasuredMove::result() const { return m_result->text(); }

#include "moc_measured_move.cpp"
