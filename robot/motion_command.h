// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "command_encoder.h"

#include <QMetaType>

// What an input device (drive pad, keyboard, gamepad) asks the robot to do,
// before the session's sending rules turn it into bytes.
struct MotionCommand {
    enum class Kind { Drive, DriveDirect, DrivePwm };
    Kind kind = Kind::Drive;
    int velocity = 0; // Drive: mm/s
    int radius = oi::kRadiusStraight; // Drive: mm, or the special values
    int right = 0;    // DriveDirect: mm/s; DrivePwm: -255..255
    int left = 0;

    bool isStop() const { return kind == Kind::Drive ? velocity == 0 : right == 0 && left == 0; }
    static MotionCommand stop(Kind kind = Kind::Drive) { return MotionCommand{kind}; }
    // The bytes for this command on a profile (validated by the encoder).
    oi::EncodeResult encode(const oi::CommandEncoder &encoder) const
    {
        switch (kind) {
        case Kind::DriveDirect: return encoder.driveDirect(right, left);
        case Kind::DrivePwm: return encoder.drivePwm(right, left);
        case Kind::Drive: break;
        }
        return encoder.drive(velocity, radius);
    }
    friend bool operator==(const MotionCommand &, const MotionCommand &) = default;
};

Q_DECLARE_METATYPE(MotionCommand)
