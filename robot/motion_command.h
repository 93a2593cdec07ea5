// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "command_encoder.h"
#include "oi_command.h"

#include <QMetaType>

#include <cmath>
#include <cstdlib>
#include <optional>

// What an input device (drive pad, keyboard, gamepad) asks the robot to do,
// before the session's sending rules turn it into a typed command.
struct MotionCommand {
    enum class Kind { Drive, DriveDirect, DrivePwm };
    Kind kind = Kind::Drive;
    int velocity = 0; // Drive: mm/s
    int radius = oi::kRadiusStraight; // Drive: mm, or the special values
    int right = 0;    // DriveDirect: mm/s; DrivePwm: -255..255
    int left = 0;

    bool isStop() const { return kind == Kind::Drive ? velocity == 0 : right == 0 && left == 0; }
    static MotionCommand stop(Kind kind = Kind::Drive) { return MotionCommand{kind}; }
    // A typed Drive, Drive Direct or Drive PWM as a motion command, so that
    // the sending rules apply to it wherever it came from; nothing for
    // other commands. Fields in the document's order (commandFieldNames):
    // velocity, radius; right, left.
    static std::optional<MotionCommand> fromCommand(const oi::OiCommand &command)
    {
        if (command.fields.size() != 2)
            return std::nullopt;
        MotionCommand m;
        switch (command.command) {
        case oi::Command::Drive:
            m.velocity = command.fields[0];
            m.radius = command.fields[1];
            return m;
        case oi::Command::DriveDirect: m.kind = Kind::DriveDirect; break;
        case oi::Command::DrivePwm: m.kind = Kind::DrivePwm; break;
        default: return std::nullopt;
        }
        m.right = command.fields[0];
        m.left = command.fields[1];
        return m;
    }
    // The typed Drive, Drive Direct or Drive PWM; the link encodes it.
    oi::OiCommand toCommand() const
    {
        switch (kind) {
        case Kind::DriveDirect: return {oi::Command::DriveDirect, {right, left}, {}};
        case Kind::DrivePwm: return {oi::Command::DrivePwm, {right, left}, {}};
        case Kind::Drive: break;
        }
        return {oi::Command::Drive, {velocity, radius}, {}};
    }
    // Drive Direct as a Drive of the same wheel speeds, for a robot without
    // Drive Direct (the SCI): the mean speed, and the turning radius its
    // wheels `wheelBaseMm` apart make.
    MotionCommand asDrive(double wheelBaseMm) const
    {
        if (kind != Kind::DriveDirect)
            return *this;
        constexpr int kMaxRadius = 2000;
        MotionCommand m;
        if (right == left) {
            m.velocity = right;
            return m;
        }
        if (right == -left) {
            m.velocity = std::abs(right - left) / 2;
            m.radius = right > left ? oi::kRadiusTurnInPlaceCounterClockwise : oi::kRadiusTurnInPlaceClockwise;
            return m;
        }
        const double radius = wheelBaseMm / 2 * (right + left) / (right - left);
        m.velocity = (right + left) / 2;
        m.radius = std::abs(radius) > kMaxRadius ? oi::kRadiusStraight
                   : std::abs(radius) < 1       ? (radius > 0 ? 1 : -1)
                                                : int(std::lround(radius));
        return m;
    }
    friend bool operator==(const MotionCommand &, const MotionCommand &) = default;
};

Q_DECLARE_METATYPE(MotionCommand)
