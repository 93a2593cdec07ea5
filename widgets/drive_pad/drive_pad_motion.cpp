// SPDX-License-Identifier: GPL-3.0-or-later
// What the drive pad's knob means: the command a knob position asks for, the
// knob position a command stands at, and the command in words.
#include "drive_pad.h"

#include "command_encoder.h"

#include <algorithm>
#include <cmath>

MotionCommand DrivePad::commandAt(QPointF knob) const
{
    const auto kind = MotionCommand::Kind(int(mapping()));
    const double r = std::min(1.0, std::hypot(knob.x(), knob.y()));
    if (r < kDeadZone)
        return MotionCommand::stop(kind);
    const double x = knob.x() / std::max(1.0, std::hypot(knob.x(), knob.y()));
    const double y = knob.y() / std::max(1.0, std::hypot(knob.x(), knob.y()));
    const int limit = speedLimit();

    if (kind == MotionCommand::Kind::Drive) {
        MotionCommand c;
        const int speed = int(std::lround(limit * r));
        if (speed == 0)
            return c;
        const double angle = std::abs(std::atan2(x, y)) * 180.0 / M_PI; // 0 ahead, 180 behind
        if (angle <= kZoneDegrees) {
            c.velocity = speed;
        } else if (angle >= 180.0 - kZoneDegrees) {
            c.velocity = -speed;
        } else if (std::abs(angle - 90.0) <= kZoneDegrees) {
            // ERRATA 14: ±1 turns in place; the velocity sets how fast.
            c.velocity = speed;
            c.radius = x > 0 ? oi::kRadiusTurnInPlaceClockwise : oi::kRadiusTurnInPlaceCounterClockwise;
        } else {
            // Tighter circles towards the horizontal: 2000 mm at the edge of
            // the straight zone down to 40 mm at the turn-in-place zone.
            const bool forward = angle < 90.0;
            const double a = forward ? angle : 180.0 - angle;
            const double t = (a - kZoneDegrees) / (90.0 - 2 * kZoneDegrees);
            const int radius = int(std::lround(kMaxArcRadius * std::pow(double(kMinArcRadius) / kMaxArcRadius, t)));
            c.velocity = forward ? speed : -speed;
            c.radius = x < 0 ? radius : -radius; // positive turns left
        }
        return c;
    }

    // Each wheel: forward plus or minus the turn, scaled back into the limit.
    double right = limit * (y - x);
    double left = limit * (y + x);
    const double peak = std::max(std::abs(right), std::abs(left));
    if (peak > limit) {
        right *= limit / peak;
        left *= limit / peak;
    }
    MotionCommand c{kind};
    if (kind == MotionCommand::Kind::DrivePwm) {
        right = right * kMaxPwm / kMaxSpeedLimit;
        left = left * kMaxPwm / kMaxSpeedLimit;
    }
    c.right = int(std::lround(right));
    c.left = int(std::lround(left));
    return c;
}

QPointF DrivePad::knobFor(const MotionCommand &c) const
{
    if (c.isStop())
        return {};
    const double limit = c.kind == MotionCommand::Kind::DrivePwm ? kMaxPwm : std::max(1, speedLimit());
    double ahead = 0, left = 0;
    if (c.kind == MotionCommand::Kind::Drive) {
        if (c.radius == oi::kRadiusTurnInPlaceCounterClockwise)
            left = std::abs(c.velocity);
        else if (c.radius == oi::kRadiusTurnInPlaceClockwise)
            left = -std::abs(c.velocity);
        else if (c.radius == oi::kRadiusStraight || c.radius == oi::kRadiusStraightAlt)
            ahead = c.velocity;
        else {
            // Half way between straight and turning in place, to the side it turns.
            ahead = c.velocity * std::sqrt(0.5);
            left = std::abs(c.velocity) * std::sqrt(0.5) * (c.radius > 0 ? 1 : -1);
        }
    } else {
        ahead = (c.right + c.left) / 2.0;
        left = (c.right - c.left) / 2.0;
    }
    QPointF knob(-left / limit, ahead / limit);
    const double length = std::hypot(knob.x(), knob.y());
    return length > 1 ? knob / length : knob;
}

QString DrivePad::describe(const MotionCommand &c)
{
    return words(c, Wording::Shown);
}

QString DrivePad::spokenDescription(const MotionCommand &c)
{
    return words(c, Wording::Spoken);
}

QString DrivePad::words(const MotionCommand &c, Wording wording)
{
    const bool spoken = wording == Wording::Spoken;
    if (c.isStop())
        return tr("Stopped");
    switch (c.kind) {
    case MotionCommand::Kind::DriveDirect:
        return (spoken ? tr("Right wheel %1 mm/s, left wheel %2 mm/s") : tr("Drive Direct: right %1, left %2 mm/s"))
            .arg(c.right)
            .arg(c.left);
    case MotionCommand::Kind::DrivePwm:
        return (spoken ? tr("Right wheel power %1, left wheel power %2") : tr("Drive PWM: right %1, left %2"))
            .arg(c.right)
            .arg(c.left);
    case MotionCommand::Kind::Drive:
        break;
    }
    const bool straight = c.radius == oi::kRadiusStraight || c.radius == oi::kRadiusStraightAlt;
    if (!spoken) {
        const QString radius = straight ? tr("straight")
                               : c.radius == oi::kRadiusTurnInPlaceClockwise ? tr("turn in place, clockwise")
                               : c.radius == oi::kRadiusTurnInPlaceCounterClockwise ? tr("turn in place, anticlockwise")
                                                                                     : tr("radius %1 mm").arg(c.radius);
        return tr("Drive %1 mm/s, %2").arg(c.velocity).arg(radius);
    }
    if (c.radius == oi::kRadiusTurnInPlaceClockwise)
        return tr("Turning in place clockwise, %1 mm/s").arg(c.velocity);
    if (c.radius == oi::kRadiusTurnInPlaceCounterClockwise)
        return tr("Turning in place anticlockwise, %1 mm/s").arg(c.velocity);
    const QString way = c.velocity > 0 ? tr("Forward %1 mm/s").arg(c.velocity)
                                       : tr("Backward %1 mm/s").arg(-c.velocity);
    if (straight)
        return tr("%1, straight").arg(way);
    // A positive radius puts the turn's centre on the robot's left.
    return (c.radius > 0 ? tr("%1, turning left (radius %2 mm)") : tr("%1, turning right (radius %2 mm)"))
        .arg(way)
        .arg(std::abs(c.radius));
}
