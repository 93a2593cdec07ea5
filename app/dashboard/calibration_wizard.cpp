// SPDX-License-Identifier: GPL-3.0-or-later
// The calibration wizard: its steps, the runs on the robot, and what the
// measurements make of the wheels.
#include "calibration_wizard.h"

#include "robot_fleet.h"
#include "robot_session.h"
#include "room_robots.h"

#include <QAction>
#include <QEvent>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QShortcut>
#include <QSlider>
#include <QSpinBox>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace {

constexpr double kPi = std::numbers::pi;

QString mm(double value, int decimals = 1)
{
    return QLocale().toString(value, 'f', decimals);
}

} // namespace

std::optional<double> CalibrationWizard::parseTyped(const QString &text)
{
    bool ok = false;
    const double value = QLocale().toDouble(text.trimmed(), &ok);
    if (ok)
        return value;
    const double c = QLocale::c().toDouble(text.trimmed(), &ok);
    return ok ? std::optional(c) : std::nullopt;
}

CalibrationWizard::CalibrationWizard(RobotSession &robot, TruePose truePose, QWidget *parent)
    : QDialog(parent), m_robot(robot), m_truePose(std::move(truePose)), m_drive(robot),
      m_assumed(robot.odometry().wheels())
{
    setObjectName("calibrationWizard");
    setWindowTitle(tr("Calibrate odometry: %1").arg(robot.name()));
    m_pages = new QStackedWidget(this);
    m_pages->addWidget(buildStraightPage());
    m_pages->addWidget(buildTurnPage());
    m_pages->addWidget(buildResultPage());

    m_stepTitle = new QLabel(this);
    QFont bold = m_stepTitle->font();
    bold.setBold(true);
    bold.setPointSizeF(bold.pointSizeF() * 1.2);
    m_stepTitle->setFont(bold);

    m_back = new QPushButton(tr("< &Back"), this);
    m_next = new QPushButton(tr("&Next >"), this);
    m_stop = new QPushButton(tr("&Stop"), this);
    m_stop->setObjectName("calibrationStop");
    m_stop->setToolTip(tr("Stop the robot (also Esc or Space)"));
    auto *close = new QPushButton(tr("&Close"), this);
    connect(m_back, &QPushButton::clicked, this, [this] { showStep(step() - 1); });
    connect(m_next, &QPushButton::clicked, this, [this] { showStep(step() + 1); });
    connect(m_stop, &QPushButton::clicked, this, &CalibrationWizard::stopRobot);
    connect(close, &QPushButton::clicked, this, &CalibrationWizard::reject);

    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_stop);
    buttons->addStretch();
    buttons->addWidget(m_back);
    buttons->addWidget(m_next);
    buttons->addWidget(close);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_stepTitle);
    layout->addWidget(m_pages, 1);
    layout->addLayout(buttons);

    // Space stops the robot whatever has the focus but a text field.
    auto *space = new QShortcut(QKeySequence(Qt::Key_Space), this);
    connect(space, &QShortcut::activated, this, &CalibrationWizard::stopRobot);

    connect(&m_drive, &CalibrationDrive::progressed, this, &CalibrationWizard::onProgress);
    connect(&m_drive, &CalibrationDrive::finished, this, &CalibrationWizard::onFinished);
    connect(&m_drive, &CalibrationDrive::aborted, this, &CalibrationWizard::onAborted);
    connect(&m_robot, &RobotSession::calibrationChanged, this, [this] { m_appliedText->setText(appliedText()); });
    showStep(0);
    resize(sizeHint().expandedTo(QSize(640, 480)));
}

int CalibrationWizard::step() const
{
    return m_pages->currentIndex();
}

void CalibrationWizard::showStep(int step)
{
    step = std::clamp(step, 0, m_pages->count() - 1);
    if (step != this->step())
        stopRobot();
    m_pages->setCurrentIndex(step);
    const QString titles[] = {tr("Step 1 of 3: straight line"), tr("Step 2 of 3: turn"), tr("Step 3 of 3: result")};
    m_stepTitle->setText(titles[step]);
    if (step == 2)
        computeResult();
    updateButtons();
}

void CalibrationWizard::updateButtons()
{
    const bool running = m_drive.isRunning();
    m_back->setEnabled(!running && step() > 0);
    m_next->setEnabled(!running && step() < m_pages->count() - 1);
    m_stop->setEnabled(running);
    m_driveStraight->setEnabled(!running);
    m_driveTurn->setEnabled(!running);
    m_distance->setEnabled(!running);
    m_turns->setEnabled(!running);
    // Nothing to type while the robot moves, so Space stops it wherever the focus is.
    for (QWidget *w : {static_cast<QWidget *>(m_measuredDistance), static_cast<QWidget *>(m_measuredDrift),
                       static_cast<QWidget *>(m_measuredAngle), static_cast<QWidget *>(m_angleSlider)})
        w->setEnabled(!running);
    if (running)
        m_stop->setFocus();
}

void CalibrationWizard::startRun(oi::EncoderRun::Kind kind)
{
    const bool straight = kind == oi::EncoderRun::Kind::Straight;
    QLabel *status = straight ? m_straightStatus : m_turnStatus;
    m_truthStart = m_truthLast = m_truePose ? m_truePose() : std::nullopt;
    m_truthTurnedRad = 0;
    const double target = straight ? m_distance->value() : m_turns->value() * 2 * kPi;
    if (!m_drive.start(kind, target))
        return; // aborted() said why
    status->setText(straight ? tr("Driving… Esc, Space or Stop stops it.") : tr("Spinning… Esc, Space or Stop stops it."));
    updateButtons();
}

void CalibrationWizard::onProgress(double progress)
{
    if (m_truthLast && m_truePose) {
        if (const auto now = m_truePose()) {
            m_truthTurnedRad += std::remainder(now->thetaRad - m_truthLast->thetaRad, 2 * kPi);
            m_truthLast = now;
        }
    }
    if (!m_drive.run())
        return;
    if (m_drive.run()->kind() == oi::EncoderRun::Kind::Straight)
        m_straightStatus->setText(tr("Driving… %1 of %2 mm by the encoders. Esc, Space or Stop stops it.")
                                      .arg(mm(progress, 0), mm(m_distance->value(), 0)));
    else
        m_turnStatus->setText(tr("Spinning… %1 of %2 degrees by the encoders. Esc, Space or Stop stops it.")
                                  .arg(mm(progress * 180 / kPi, 0), mm(m_turns->value() * 360.0, 0)));
}

void CalibrationWizard::onFinished()
{
    const oi::EncoderRun &run = *m_drive.run();
    const oi::PacketCheck packets = oi::checkPackets(run);
    if (run.kind() == oi::EncoderRun::Kind::Straight) {
        m_straight = run;
        QString text = tr("Stopped after %1 mm by the encoders. Now measure what it really drove.")
                           .arg(mm(packets.encoderDistanceMm));
        if (m_truthStart && m_truthLast) {
            // The room knows: the distance start to end, and how far off the line.
            const double dx = m_truthLast->xMm - m_truthStart->xMm, dy = m_truthLast->yMm - m_truthStart->yMm;
            const double along = dx * std::cos(m_truthStart->thetaRad) + dy * std::sin(m_truthStart->thetaRad);
            const double across = -dx * std::sin(m_truthStart->thetaRad) + dy * std::cos(m_truthStart->thetaRad);
            m_measuredDistance->setText(mm(std::hypot(along, across)));
            m_measuredDrift->setText(mm(across));
            text = tr("Stopped after %1 mm by the encoders. This is a virtual robot: the measurements below come "
                      "from its true position in the room, %2 mm from the start and %3 mm off the line.")
                       .arg(mm(packets.encoderDistanceMm), mm(std::hypot(along, across)), mm(across));
        }
        m_straightStatus->setText(text);
    } else {
        m_turn = run;
        QString text = tr("Stopped after %1 degrees by the encoders. Now read how far it really turned.")
                           .arg(mm(packets.encoderAngleDeg));
        if (m_truthStart) {
            const double degrees = m_truthTurnedRad * 180 / kPi;
            {
                const QSignalBlocker quiet(m_angleSlider); // the text keeps its decimals
                m_angleSlider->setValue(int(std::lround(degrees)));
            }
            m_measuredAngle->setText(mm(degrees));
            text = tr("Stopped after %1 degrees by the encoders. This is a virtual robot: the angle below comes from "
                      "its true heading in the room, %2 degrees.")
                       .arg(mm(packets.encoderAngleDeg), mm(degrees));
        }
        m_turnStatus->setText(text);
    }
    updateButtons();
}

void CalibrationWizard::onAborted(const QString &reason)
{
    QLabel *status = step() == 1 ? m_turnStatus : m_straightStatus;
    status->setText(tr("%1 Nothing was measured; run the step again.").arg(reason));
    updateButtons();
}

void CalibrationWizard::stopRobot()
{
    m_drive.stop();
}

void CalibrationWizard::changeEvent(QEvent *event)
{
    // Key releases go to whichever window has the focus now: stop.
    if (event->type() == QEvent::ActivationChange && !isActiveWindow())
        stopRobot();
    QDialog::changeEvent(event);
}

void CalibrationWizard::reject()
{
    // Esc stops a run first; pressed again, it closes.
    if (m_drive.isRunning()) {
        stopRobot();
        return;
    }
    QDialog::reject();
}

std::optional<double> CalibrationWizard::readMeasurement(QLineEdit *edit, double expected, const QString &what,
                                                         const QString &unit)
{
    const QString text = edit->text().trimmed();
    const std::optional<double> value = parseTyped(text);
    switch (oi::measurementFault(value.value_or(std::nan("")), expected)) {
    case oi::MeasurementFault::None:
        return value;
    case oi::MeasurementFault::NotANumber:
        m_resultText->setText(tr("%1: “%2” is not a number. Type what you measured, in %3.").arg(what, text, unit));
        break;
    case oi::MeasurementFault::NotPositive:
        m_resultText->setText(tr("%1: %2 %3 cannot be. Type what you measured, more than 0 %3.").arg(what, text, unit));
        break;
    case oi::MeasurementFault::FarOff:
        m_resultText->setText(tr("%1: %2 %3 is more than 50 % off the %4 %3 the encoders counted. Measure again: "
                                 "a typing slip, or a wheel that slipped?")
                                  .arg(what, text, unit, mm(expected, 0)));
        break;
    }
    return std::nullopt;
}

void CalibrationWizard::computeResult()
{
    m_result.reset();
    m_apply->setEnabled(false);
    if (!m_straight && !m_turn) {
        m_resultText->setText(tr("Drive the straight line, the turn or both first."));
        return;
    }
    std::optional<oi::StraightRun> straight;
    std::optional<oi::TurnRun> turn;
    QStringList packets;
    if (m_straight) {
        const oi::PacketCheck check = oi::checkPackets(*m_straight);
        const auto measured = readMeasurement(m_measuredDistance, oi::countedDistanceMm(m_assumed, m_straight->counts()),
                                              tr("Measured distance"), tr("mm"));
        if (!measured)
            return;
        // Off the line by d at the end of a run of length L: an arc that turned 2d/L.
        const std::optional<double> drift =
            m_measuredDrift->text().trimmed().isEmpty() ? std::optional(0.0) : parseTyped(m_measuredDrift->text());
        if (!drift || std::abs(*drift) > *measured / 2) {
            m_resultText->setText(tr("Off the line: “%1” is not a distance in mm less than half the run; leave it "
                                     "empty if you did not measure it.")
                                      .arg(m_measuredDrift->text()));
            return;
        }
        const double chord = std::hypot(*measured, *drift);
        straight = oi::StraightRun{m_straight->counts(), *measured, 2 * std::asin(*drift / chord)};
        packets << tr("Straight line: the distance packet (19) says %1 mm, the encoders %2 mm%3.")
                       .arg(mm(check.packetDistanceMm, 0), mm(check.encoderDistanceMm, 0),
                            check.distanceDisagrees ? tr(": they disagree") : QString());
    }
    if (m_turn) {
        const oi::PacketCheck check = oi::checkPackets(*m_turn);
        const auto measured = readMeasurement(m_measuredAngle, std::abs(check.encoderAngleDeg), tr("Measured angle"),
                                              tr("degrees"));
        if (!measured)
            return;
        turn = oi::TurnRun{m_turn->counts(), *measured * kPi / 180};
        packets << tr("Turn: the angle packet (20) says %1 degrees, the encoders %2 degrees%3.")
                       .arg(mm(check.packetAngleDeg, 0), mm(check.encoderAngleDeg, 0),
                            check.angleDisagrees ? tr(": they disagree") : QString());
    }
    const oi::Result<oi::Calibration> result = oi::calibrate(m_assumed, straight, turn);
    if (!result) {
        m_resultText->setText(tr("These runs cannot be right: %1").arg(QString::fromStdString(result.error().describe())));
        return;
    }
    m_result = *result;
    const oi::WheelGeometry &w = result->wheels;
    const bool disagree = (m_straight && oi::checkPackets(*m_straight).distanceDisagrees)
                          || (m_turn && oi::checkPackets(*m_turn).angleDisagrees);
    QString firmware;
    if (disagree)
        firmware = m_robot.firmwareRelease().isEmpty()
                       ? tr("This robot's firmware reports its own packets wrongly (Robot → Read firmware version… "
                            "names it). The map uses the encoders.")
                       : tr("Firmware %1 reports its own packets wrongly. The map uses the encoders.")
                             .arg(m_robot.firmwareRelease());
    QString text = tr("<p><b>Left wheel</b> %1 mm (%2 × the documented 72 mm), <b>right wheel</b> %3 mm (%4 ×)%5.<br>"
                      "<b>Wheel base</b> %6 mm (documented 235 mm).</p>"
                      "<p>A 1 m square driven by the encoders, predicted from these runs: <b>%7 mm</b> from its start "
                      "with the wheels counted now, <b>%8 mm</b> with these.</p>")
                       .arg(mm(w.leftDiameterMm, 2), QLocale().toString(w.leftDiameterMm / oi::kWheelDiameterMm, 'f', 3),
                            mm(w.rightDiameterMm, 2), QLocale().toString(w.rightDiameterMm / oi::kWheelDiameterMm, 'f', 3),
                            result->wheelsDiffer ? tr(": the two wheels differ") : QString(), mm(w.wheelBaseMm),
                            mm(result->squareErrorBeforeMm, 0), mm(result->squareErrorAfterMm, 0));
    text += QStringLiteral("<p>") + packets.join(QStringLiteral("<br>")) + QStringLiteral("</p>");
    if (!firmware.isEmpty())
        text += QStringLiteral("<p>") + firmware + QStringLiteral("</p>");
    m_resultText->setText(text);
    m_apply->setEnabled(true);
}

void CalibrationWizard::apply()
{
    if (!m_result || !m_robot.applyCalibration(m_result->wheels))
        return;
    // Runs counted with the old wheels cannot be measured against the new ones.
    m_assumed = m_result->wheels;
    m_straight.reset();
    m_turn.reset();
    m_apply->setEnabled(false);
}

void CalibrationWizard::resetToDocumented()
{
    m_robot.resetCalibration();
    m_assumed = oi::WheelGeometry{};
    m_straight.reset();
    m_turn.reset();
    computeResult();
}

QString CalibrationWizard::appliedText() const
{
    const auto &c = m_robot.calibration();
    if (!c)
        return tr("%1 is counted with the documented wheels: 72 mm, 235 mm apart.").arg(m_robot.name());
    return tr("%1 is counted with wheels of %2 mm (left) and %3 mm (right), %4 mm apart, measured on %5.")
        .arg(m_robot.name(), mm(c->wheels.leftDiameterMm, 2), mm(c->wheels.rightDiameterMm, 2),
             mm(c->wheels.wheelBaseMm), QLocale().toString(c->measuredAt, QLocale::ShortFormat));
}

CalibrationWizardAction::CalibrationWizardAction(RobotFleet &fleet, RoomRobots &room, QWidget *dialogParent)
    : QObject(dialogParent), m_fleet(fleet), m_room(room), m_dialogParent(dialogParent)
{
    m_action = new QAction(this);
    m_action->setObjectName("calibrateOdometryAction");
    connect(m_action, &QAction::triggered, this, &CalibrationWizardAction::open);
}

void CalibrationWizardAction::retranslate()
{
    m_action->setText(tr("&Calibrate odometry…"));
    m_action->setToolTip(tr("Measure the selected robot's real wheels, so that its map stops drifting"));
}

void CalibrationWizardAction::open()
{
    RobotSession *robot = m_fleet.selected();
    if (!robot)
        return;
    if (m_wizard)
        m_wizard->close();
    m_wizard = new CalibrationWizard(
        *robot, [this, robot]() -> std::optional<oi::Pose> { return m_room.truePose(robot); }, m_dialogParent);
    m_wizard->setAttribute(Qt::WA_DeleteOnClose);
    // The wizard holds the robot: it goes before the robot does.
    connect(&m_fleet, &RobotFleet::robotRemoved, m_wizard, [this, robot](RobotSession *removed) {
        if (removed == robot)
            delete m_wizard;
    });
    m_wizard->show();
}

#include "moc_calibration_wizard.cpp"
