// SPDX-License-Identifier: GPL-3.0-or-later
// The robot diagram's scene: where each part of the robot stands and its
// colours, shared by robot_diagram*.cpp alone.
#pragma once

#include "sensor_snapshot.h"

#include <QColor>
#include <QPainterPath>
#include <QPalette>
#include <QPointF>
#include <QRectF>
#include <QSizeF>
#include <QString>

#include <array>
#include <cmath>
#include <numbers>

namespace diagram_scene {

// The scene is 1000 units wide with the robot's centre at the origin; y
// grows towards the back of the robot. The body's radius of 250 units stands
// for the real 170 mm. The status chips fill whatever height is left below.
inline constexpr qreal kSceneWidthLightBumps = 1000;
inline constexpr qreal kSceneWidthPlain = 900;
inline constexpr qreal kSceneTopLightBumps = -470; // room for the light-bump bars
inline constexpr qreal kSceneTopPlain = -320;
inline constexpr qreal kBodyRadius = 250;
inline constexpr qreal kBumperInner = 252;
inline constexpr qreal kBumperOuter = 282;
inline constexpr qreal kBumperOuterBumped = 298;
inline constexpr qreal kBumperGapDegrees = 1.5;
inline constexpr qreal kBumperRightStart = -12; // degrees, 0 = robot's right, 90 = front
inline constexpr qreal kBumperLeftEnd = 192;
inline constexpr qreal kLightBumpBase = 306;
inline constexpr qreal kLightBumpLength = 122;
inline constexpr qreal kLightBumpLabelRadius = 452;
inline constexpr qreal kLightBumpHalfWidthDegrees = 7;
inline constexpr qreal kCliffLampRadius = 26;
inline constexpr QSizeF kCliffLabelSize(98, 58);
inline constexpr qreal kChipTop = 272;
inline constexpr qreal kChipMinHeight = 80;
inline constexpr qreal kChipMaxHeight = 118;
inline constexpr qreal kChipGap = 10;
inline constexpr qreal kChipRows = 3;
inline constexpr qreal kChipBottomMargin = 8;
inline constexpr qreal kSceneBottom = kChipTop + kChipRows * (kChipMinHeight + kChipGap);
inline constexpr qreal kSignalMax = 4095;

// Left to right across the front, as bits 0..5 of packet 45 run.
inline constexpr std::array<qreal, 6> kLightBumperAngles = {168, 136, 104, 76, 44, 12};

inline QPointF polar(qreal radius, qreal degrees)
{
    const qreal a = degrees * std::numbers::pi / 180.0;
    return {radius * std::cos(a), -radius * std::sin(a)};
}

inline QRectF circleRect(qreal radius) { return {-radius, -radius, 2 * radius, 2 * radius}; }

// A ring segment between two radii, from `startDegrees` counter-clockwise
// through `sweepDegrees`.
inline QPainterPath ringSegment(qreal inner, qreal outer, qreal startDegrees, qreal sweepDegrees)
{
    QPainterPath path;
    path.arcMoveTo(circleRect(outer), startDegrees);
    path.arcTo(circleRect(outer), startDegrees, sweepDegrees);
    path.arcTo(circleRect(inner), startDegrees + sweepDegrees, -sweepDegrees);
    path.closeSubpath();
    return path;
}

inline QPointF cliffLampPoint(oi::CliffSensor sensor)
{
    switch (sensor) {
    case oi::CliffSensor::Left: return {-195, -80};
    case oi::CliffSensor::FrontLeft: return {-80, -205};
    case oi::CliffSensor::FrontRight: return {80, -205};
    case oi::CliffSensor::Right: return {195, -80};
    }
    return {};
}

// The number and bar sit beside the lamp, towards the middle of the robot.
inline QRectF cliffLabelRect(oi::CliffSensor sensor)
{
    QPointF centre;
    switch (sensor) {
    case oi::CliffSensor::Left: centre = {-115, -80}; break;
    case oi::CliffSensor::FrontLeft: centre = {-80, -145}; break;
    case oi::CliffSensor::FrontRight: centre = {80, -145}; break;
    case oi::CliffSensor::Right: centre = {115, -80}; break;
    }
    return {centre - QPointF(kCliffLabelSize.width() / 2, kCliffLabelSize.height() / 2),
            kCliffLabelSize};
}

inline constexpr std::array<oi::CliffSensor, 4> kCliffs = {
    oi::CliffSensor::Left, oi::CliffSensor::FrontLeft, oi::CliffSensor::FrontRight,
    oi::CliffSensor::Right};

inline constexpr QRectF kWheelLeft(-195, -30, 44, 110);
inline constexpr QRectF kWheelRight(151, -30, 44, 110);
inline constexpr QPointF kCaster(0, -18); // Create 1, drawn between the cliff labels
inline constexpr qreal kCasterRadius = 24;
inline constexpr QPointF kOmniReceiver(0, -228);
inline constexpr QRectF kWall(316, -10, 18, 160);
inline constexpr QRectF kCargoBay(-125, 62, 250, 146);

inline bool isDark(const QPalette &palette) { return palette.color(QPalette::Window).lightness() < 128; }

// The colour of signal strengths, matching the bars in SignalBars.
inline QColor cliffSignalColour(const QPalette &palette)
{
    return isDark(palette) ? QColor(70, 200, 200) : QColor(0, 130, 140);
}
inline QColor lightBumpSignalColour(const QPalette &palette)
{
    return isDark(palette) ? QColor(110, 160, 245) : QColor(40, 100, 200);
}

inline QString signalText(const oi::SensorSnapshot &s, int packetId)
{
    return s.has(packetId) ? QString::number(s.raw(packetId)) : QStringLiteral("\u2014");
}

} // namespace diagram_scene
