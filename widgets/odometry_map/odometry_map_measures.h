// SPDX-License-Identifier: GPL-3.0-or-later
// The odometry map's fixed measures, shared by its parts (odometry_map*.cpp).
#pragma once

namespace map_measures {

// A Roomba's or a Create's round body.
inline constexpr double kRobotDiameterMm = 340;
// One step of zoom: a button press, or a notch of the wheel.
inline constexpr double kZoomStep = 1.25;

} // namespace map_measures
