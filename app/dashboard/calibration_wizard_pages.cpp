// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration wizard's pages: the straight run, the turns, and the result.
#include "calibration_wizard.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>

namespace {

QLabel *wrappedLabel(const QString &text = {})
{
    auto *label = new QLabel(text);
    label->setWordWrap(true);
    return label;
}

} // namespace

QWidget *CalibrationWizard::buildStraightPage()
{
    auto *page = new QWidget;
    m_distance = new QSpinBox;
    m_distance->setObjectName("calibrationDistance");
    m_distance->setRange(300, 3000);
    m_distance->setSingleStep(100);
    m_distance->setValue(1000);
    m_distance->setSuffix(tr(" mm"));
    m_driveStraight = new QPushButton(tr("&Drive straight"));
    m_driveStraight->setObjectName("calibrationDriveStraight");
    connect(m_driveStraight, &QPushButton::clicked, this, [this] { startRun(oi::EncoderRun::Kind::Straight); });
    m_straightStatus = wrappedLabel();
    m_straightStatus->setObjectName("calibrationStraightStatus");
    m_measuredDistance = new QLineEdit;
    m_measuredDistance->setObjectName("calibrationMeasuredDistance");
    m_measuredDistance->setPlaceholderText(tr("from the tape, in mm"));
    m_measuredDrift = new QLineEdit;
    m_measuredDrift->setObjectName("calibrationMeasuredDrift");
    m_measuredDrift->setPlaceholderText(tr("optional: mm to the left (+) or right (-) of the line"));

    auto *drive = new QHBoxLayout;
    drive->addWidget(m_distance);
    drive->addWidget(m_driveStraight);
    drive->addStretch();
    auto *form = new QFormLayout;
    form->addRow(tr("Distance:"), drive);
    form->addRow(tr("It really drove:"), m_measuredDistance);
    form->addRow(tr("Off the line at the end:"), m_measuredDrift);
    auto *layout = new QVBoxLayout(page);
    layout->addWidget(wrappedLabel(
        tr("Put the robot on a hard, clear floor with room ahead, and mark the floor under the centre of its "
           "front edge. It enters Safe mode and drives ahead by its wheel encoders, slowly, then stops. Measure "
           "with a tape from the mark to where the front edge stopped and type it in. If it ended off the straight "
           "line, say how far: that tells a left wheel from a right one.")));
    layout->addLayout(form);
    layout->addWidget(m_straightStatus);
    layout->addStretch();
    return page;
}

QWidget *CalibrationWizard::buildTurnPage()
{
    auto *page = new QWidget;
    m_turns = new QSpinBox;
    m_turns->setObjectName("calibrationTurns");
    m_turns->setRange(1, 5);
    m_turns->setValue(2);
    m_turns->setSuffix(tr(" turns"));
    m_driveTurn = new QPushButton(tr("S&pin"));
    m_driveTurn->setObjectName("calibrationDriveTurn");
    connect(m_driveTurn, &QPushButton::clicked, this, [this] { startRun(oi::EncoderRun::Kind::Turn); });
    m_turnStatus = wrappedLabel();
    m_turnStatus->setObjectName("calibrationTurnStatus");
    m_measuredAngle = new QLineEdit;
    m_measuredAngle->setObjectName("calibrationMeasuredAngle");
    m_measuredAngle->setPlaceholderText(tr("in degrees, e.g. 715"));
    m_angleSlider = new QSlider(Qt::Horizontal);
    m_angleSlider->setObjectName("calibrationAngleSlider");
    // Typed and slid: each follows the other.
    const auto sliderRange = [this] {
        // Wheels 15 % off either way; a typed angle may go further.
        const int driven = m_turns->value() * 360;
        m_angleSlider->setRange(driven * 85 / 100, driven * 115 / 100);
    };
    sliderRange();
    m_angleSlider->setValue(m_turns->value() * 360);
    connect(m_turns, &QSpinBox::valueChanged, this, sliderRange);
    connect(m_angleSlider, &QSlider::valueChanged, this,
            [this](int value) { m_measuredAngle->setText(QLocale().toString(value)); });
    connect(m_measuredAngle, &QLineEdit::textEdited, this, [this](const QString &text) {
        if (const auto value = parseTyped(text)) {
            const QSignalBlocker quiet(m_angleSlider);
            m_angleSlider->setValue(int(std::lround(*value)));
        }
    });

    auto *drive = new QHBoxLayout;
    drive->addWidget(m_turns);
    drive->addWidget(m_driveTurn);
    drive->addStretch();
    auto *form = new QFormLayout;
    form->addRow(tr("Spin:"), drive);
    form->addRow(tr("It really turned:"), m_measuredAngle);
    form->addRow(QString(), m_angleSlider);
    auto *layout = new QVBoxLayout(page);
    layout->addWidget(wrappedLabel(
        tr("Mark the start heading: lay a strip of tape on the floor from the middle of the robot's front edge "
           "straight ahead, and put a piece of tape on the bumper above it. The robot spins whole turns "
           "counter-clockwise on the spot by its encoders and stops. Count the whole turns and read how far the "
           "bumper's mark is past the floor's: two turns that stop 5 degrees short are 715 degrees.")));
    layout->addLayout(form);
    layout->addWidget(m_turnStatus);
    layout->addStretch();
    return page;
}

QWidget *CalibrationWizard::buildResultPage()
{
    auto *page = new QWidget;
    m_resultText = wrappedLabel();
    m_resultText->setObjectName("calibrationResult");
    m_resultText->setTextFormat(Qt::RichText);
    m_apply = new QPushButton(tr("&Apply and keep"));
    m_apply->setObjectName("calibrationApply");
    m_reset = new QPushButton(tr("&Reset to the documented wheels"));
    m_reset->setObjectName("calibrationReset");
    m_appliedText = wrappedLabel(appliedText());
    m_appliedText->setObjectName("calibrationApplied");
    connect(m_apply, &QPushButton::clicked, this, &CalibrationWizard::apply);
    connect(m_reset, &QPushButton::clicked, this, &CalibrationWizard::resetToDocumented);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_apply);
    buttons->addWidget(m_reset);
    buttons->addStretch();
    auto *layout = new QVBoxLayout(page);
    layout->addWidget(m_resultText);
    layout->addLayout(buttons);
    layout->addWidget(m_appliedText);
    layout->addStretch();
    return page;
}
