// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_runner.h"

#include "ir_character.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace {

double wrapped(double rad)
{
    while (rad > std::numbers::pi)
        rad -= 2 * std::numbers::pi;
    while (rad <= -std::numbers::pi)
        rad += 2 * std::numbers::pi;
    return rad;
}

} // namespace

LessonRunner::LessonRunner(QObject *parent) : QObject(parent) {}

void LessonRunner::Track::add(const oi::Pose &pose)
{
    if (last) {
        drivenMm += std::hypot(pose.xMm - last->xMm, pose.yMm - last->yMm);
        turnedDeg += wrapped(pose.thetaRad - last->thetaRad) * 180 / std::numbers::pi;
    }
    last = pose;
}

void LessonRunner::start(const Lesson &lesson, const oi::RobotProfile &profile)
{
    m_lesson = lesson;
    m_profile = &profile;
    m_running = true;
    m_last = oi::SensorSnapshot(profile);
    m_step = 0;
    resetStep();
    emit stepChanged(m_step);
}

void LessonRunner::stop()
{
    m_running = false;
    m_lesson = Lesson();
    m_step = 0;
    resetStep();
}

void LessonRunner::goToStep(int step)
{
    if (!m_running)
        return;
    m_step = std::clamp(step, 0, int(m_lesson.steps.size()));
    resetStep();
    emit stepChanged(m_step);
}

void LessonRunner::resetStep()
{
    m_progress = 0;
    m_odometry.reset();
    m_truePose.reset();
    m_hasTruePose = false;
    m_heldSince.clear();
    m_stepShownAt.reset();
    m_goalMet = false;
    m_secondsToRead = 0;
}

std::optional<double> LessonRunner::trueDrivenMm() const
{
    return m_hasTruePose ? std::optional(m_truePose.drivenMm) : std::nullopt;
}

std::optional<double> LessonRunner::trueTurnedDegrees() const
{
    return m_hasTruePose ? std::optional(m_truePose.turnedDeg) : std::nullopt;
}

std::optional<double> LessonRunner::readout(const QString &key) const
{
    if (key == QLatin1String(lesson::kDrivenMm))
        return drivenMm();
    if (key == QLatin1String(lesson::kTurnedDeg))
        return turnedDegrees();
    if (key == QLatin1String(lesson::kTrueDrivenMm))
        return trueDrivenMm();
    if (key == QLatin1String(lesson::kTrueTurnedDeg))
        return trueTurnedDegrees();
    const oi::PacketInfo *p = lesson::packetByKey(*m_profile, key);
    if (!p || !m_last.has(p->id))
        return std::nullopt;
    return m_last.raw(p->id);
}

void LessonRunner::update(const LessonFrame &frame)
{
    if (!m_running || isFinished())
        return;
    m_last.merge(frame.snapshot);
    m_odometry.add(frame.odometry);
    if (frame.truePose) {
        m_truePose.add(*frame.truePose);
        m_hasTruePose = true;
    }
    if (!m_stepShownAt)
        m_stepShownAt = frame.seconds;
    double progress = 0;
    const LessonGoal &goal = m_lesson.steps[m_step].goal;
    // Met once is met: a bump that came and went still counts while the text is read.
    m_goalMet = met(goal, frame.seconds, progress) || m_goalMet;
    m_progress = m_goalMet ? 1.0 : std::clamp(progress, 0.0, 1.0);
    if (!m_goalMet)
        return;
    m_secondsToRead = std::max(0.0, kReadSeconds - (frame.seconds - *m_stepShownAt));
    if (m_secondsToRead > 0)
        return;
    const int finishedStep = m_step++;
    resetStep();
    emit stepDone(finishedStep);
    emit stepChanged(m_step);
    if (isFinished())
        emit finished();
}

bool LessonRunner::met(const LessonGoal &goal, double seconds, double &progress)
{
    bool holds = false;
    switch (goal.kind) {
    case LessonGoal::Kind::Any:
    case LessonGoal::Kind::All: {
        // Every part is checked, so each keeps its own hold running.
        const bool any = goal.kind == LessonGoal::Kind::Any;
        holds = !any;
        double least = 1;
        for (const LessonGoal &g : goal.goals) {
            double p = 0;
            const bool partMet = met(g, seconds, p);
            holds = any ? (holds || partMet) : (holds && partMet);
            progress = std::max(progress, p);
            least = std::min(least, partMet ? 1.0 : p);
        }
        if (!any)
            progress = least;
        break;
    }
    case LessonGoal::Kind::Drive:
        progress = m_odometry.drivenMm / goal.distanceMm;
        holds = m_odometry.drivenMm >= goal.distanceMm;
        break;
    case LessonGoal::Kind::Turn:
        progress = std::abs(m_odometry.turnedDeg) / goal.degrees;
        holds = std::abs(m_odometry.turnedDeg) >= goal.degrees;
        break;
    case LessonGoal::Kind::Packet:
        holds = conditionHolds(goal);
        break;
    }
    if (goal.holdSeconds <= 0) {
        if (holds)
            progress = 1;
        return holds;
    }
    if (!holds) {
        m_heldSince.remove(&goal);
        if (goal.kind == LessonGoal::Kind::Packet)
            progress = 0;
        return false;
    }
    const double since = m_heldSince.value(&goal, seconds);
    m_heldSince.insert(&goal, since);
    progress = (seconds - since) / goal.holdSeconds;
    return seconds - since >= goal.holdSeconds;
}

bool LessonRunner::conditionHolds(const LessonGoal &goal) const
{
    const oi::PacketInfo *p = lesson::packetByKey(*m_profile, goal.packet);
    if (!p || !m_last.has(p->id))
        return false;
    const std::int32_t value = m_last.raw(p->id);
    for (const QString &bit : goal.bits) {
        const std::uint8_t mask = lesson::bitMask(*m_profile, p->id, bit);
        if (!mask || !(value & mask))
            return false;
    }
    if (goal.above && !(value > *goal.above))
        return false;
    if (goal.below && !(value < *goal.below))
        return false;
    if (goal.equals && value != *goal.equals)
        return false;
    if (!goal.ir.isEmpty()) {
        const oi::IrCharacter ir = oi::decodeIrCharacter(*m_profile, std::uint8_t(value));
        if (goal.ir == QLatin1String("dock"))
            return ir.kind == oi::IrCharacter::Kind::DockBeams;
        if (goal.ir == QLatin1String("virtual_wall"))
            return ir.kind == oi::IrCharacter::Kind::VirtualWall || ir.kind == oi::IrCharacter::Kind::Lighthouse;
        return ir.kind != oi::IrCharacter::Kind::None;
    }
    return true;
}

#include "moc_lesson_runner.cpp"
