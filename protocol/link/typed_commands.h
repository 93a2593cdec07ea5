// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "oi_command.h"

#include <QMetaType>

#include <vector>

// Typed commands as Qt values: what a widget asks a robot's session to send
// (RobotSession::send), and what the link sent (RobotLink::commandsSent),
// instead of bytes.
Q_DECLARE_METATYPE(oi::OiCommand)
Q_DECLARE_METATYPE(std::vector<oi::OiCommand>)
