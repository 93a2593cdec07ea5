// SPDX-License-Identifier: GPL-3.0-or-later
// Written by resources/lessons/lesson_texts.py from the shipped lessons: do not edit.
#include "shipped_lessons.h"

#include <QtGlobal>

QStringList lesson::shippedTexts()
{
    static const char *const texts[] = {
        QT_TRANSLATE_NOOP("Lesson", "Battery and current while driving"),
        QT_TRANSLATE_NOOP("Lesson", "Where the energy goes: the battery's voltage, charge and current, standing and driving."),
        QT_TRANSLATE_NOOP("Lesson", "The battery reports its voltage, its charge and the current flowing in or out of it. A negative current flows out of the battery. Keep the robot still, off the dock: the current stays small, above -400 mA, for two seconds."),
        QT_TRANSLATE_NOOP("Lesson", "Now drive. The wheel motors draw current from the battery, so the current goes further below zero. Keep driving until the current stays under -400 mA for two seconds."),
        QT_TRANSLATE_NOOP("Lesson", "Stop the robot. The motors stop drawing and the current comes back to what the robot needs to stand still: above -400 mA for two seconds. The voltage rises a little too."),
        QT_TRANSLATE_NOOP("Lesson", "Bumpers and wheel drops"),
        QT_TRANSLATE_NOOP("Lesson", "The switches that tell the robot it has hit something or lost the floor."),
        QT_TRANSLATE_NOOP("Lesson", "The bumper is one piece, but behind it sit two switches, one on the left and one on the right. Press the left half of the bumper gently. On the virtual robot, put its left front by a wall with the button below, then drive forward (Up arrow) until it touches."),
        QT_TRANSLATE_NOOP("Lesson", "Now press the right half of the bumper. On the virtual robot, put its right front by the wall with the button below and drive forward. Watch packet 7: the left bumper is one bit, the right bumper another."),
        QT_TRANSLATE_NOOP("Lesson", "Press the middle of the bumper, or drive straight into a wall: both switches close at once, and the robot knows the obstacle is straight ahead. On the virtual robot, face the wall with the button below, then drive forward."),
        QT_TRANSLATE_NOOP("Lesson", "Lift the robot a little off the floor. Each drive wheel drops down on its spring and closes a switch. Lift it until both wheels hang. In Safe mode the robot drops to Passive when its wheels drop: that is expected here. On the virtual robot, lift it with the button below."),
        QT_TRANSLATE_NOOP("Lesson", "Put the robot back down, away from any wall. Every switch opens again: packet 7 reads 0 for a whole second."),
        QT_TRANSLATE_NOOP("Lesson", "Put its left front by a wall"),
        QT_TRANSLATE_NOOP("Lesson", "Put its right front by the wall"),
        QT_TRANSLATE_NOOP("Lesson", "Face the wall head on"),
        QT_TRANSLATE_NOOP("Lesson", "Lift it off the floor"),
        QT_TRANSLATE_NOOP("Lesson", "Put it down in the open"),
        QT_TRANSLATE_NOOP("Lesson", "Cliff sensors"),
        QT_TRANSLATE_NOOP("Lesson", "Four infrared eyes under the bumper that keep the robot from falling down the stairs."),
        QT_TRANSLATE_NOOP("Lesson", "Under the front of the robot, four cliff sensors shine infrared light at the floor and measure how much comes back. On the floor each signal is high. Keep the robot on the floor and watch the front signals stay above 1000 for two seconds."),
        QT_TRANSLATE_NOOP("Lesson", "Drive slowly towards the edge of a table or a step, in Safe mode, or lift the front of the robot a little. On the virtual robot, carry it to the stage edge with the button below, then drive forward (Up arrow). When a front sensor loses the floor, the robot sets its cliff flag and, in Safe mode, stops and drops to Passive. A dark rug does the same, though the floor is there: then the signals stay low but well above 0 and no wheel drops. Either way, carry the robot back onto a light floor before you drive again."),
        QT_TRANSLATE_NOOP("Lesson", "Look at the signal behind the flag: over the edge almost no light comes back. The robot stopped, as the yellow line says; leave it in Passive for now and hold it a little further over the edge, so that a front signal stays under 500 for half a second. On the virtual robot, use the button below."),
        QT_TRANSLATE_NOOP("Lesson", "Carry the robot back onto the floor, away from the edge. The flags clear and the signals rise again: both front signals above 1000 for one second. On the virtual robot, use the button below."),
        QT_TRANSLATE_NOOP("Lesson", "Carry it to face the stage edge"),
        QT_TRANSLATE_NOOP("Lesson", "Hold it further over the edge"),
        QT_TRANSLATE_NOOP("Lesson", "Carry it back onto the floor"),
        QT_TRANSLATE_NOOP("Lesson", "Encoders, distance and angle"),
        QT_TRANSLATE_NOOP("Lesson", "How the robot knows how far it drove and which way it points, and how wrong it gets."),
        QT_TRANSLATE_NOOP("Lesson", "Each drive wheel turns an encoder that counts its steps. The dashboard adds up the steps of both wheels to work out how far the robot went: odometry. Drive straight ahead for one metre."),
        QT_TRANSLATE_NOOP("Lesson", "Now turn on the spot, a quarter turn: 90 degrees. When one wheel goes forward and the other back, the difference between them is the angle. On the virtual robot, compare odometry with the way the robot truly points."),
        QT_TRANSLATE_NOOP("Lesson", "Turn a whole circle, 360 degrees. Small errors add up: watch how far the odometry and the true turn drift apart."),
        QT_TRANSLATE_NOOP("Lesson", "IR from the dock and the virtual wall"),
        QT_TRANSLATE_NOOP("Lesson", "Invisible beams that lead the robot home and keep it out."),
        QT_TRANSLATE_NOOP("Lesson", "The IR receiver at the front of the robot picks up infrared beams. The dock sends out two buoys, red and green, and a short force field. Place the robot a metre in front of the dock, facing it, until the receiver sees the dock. On the virtual robot, use the button below."),
        QT_TRANSLATE_NOOP("Lesson", "A virtual wall sends a beam that the robot will not cross. Bring the robot into the beam of the virtual wall: the virtual wall flag, packet 13, turns on. In the virtual classroom, the virtual wall stands on the front wall; the button below carries the robot into its beam."),
        QT_TRANSLATE_NOOP("Lesson", "Drive the robot onto the dock, nose first, following the buoys. When its contacts touch the dock, the home base shows up as a charging source. On the virtual robot, put it in front of the dock with the button below, then drive forward (Up arrow)."),
        QT_TRANSLATE_NOOP("Lesson", "Put it a metre from the dock, facing it"),
        QT_TRANSLATE_NOOP("Lesson", "Carry it into the virtual wall's beam"),
        QT_TRANSLATE_NOOP("Lesson", "Put it in front of the dock"),
        QT_TRANSLATE_NOOP("Lesson", "Light bumpers and wall following"),
        QT_TRANSLATE_NOOP("Lesson", "Seeing a wall before touching it, and keeping beside it."),
        QT_TRANSLATE_NOOP("Lesson", "Six light bumpers look out through the window of the bumper. Each one shines infrared light and measures what a wall sends back. Move the robot slowly towards a wall, facing it, until the centre left signal is above 1000. On the virtual robot, face a wall with the button below, then drive forward (Up arrow)."),
        QT_TRANSLATE_NOOP("Lesson", "Each light bumper also has an on/off flag in packet 45, set when its signal is strong. Come close enough that the centre left and centre right flags are on together."),
        QT_TRANSLATE_NOOP("Lesson", "The wall sensor on the right side looks sideways. Turn the robot so that the wall is on its right and drive along it, a few centimetres away. Keep the wall signal above 30 for three seconds. On the virtual robot, put it beside the wall with the button below, then drive forward."),
        QT_TRANSLATE_NOOP("Lesson", "Come closer to the wall, about four centimetres: the robot decides that a wall is there and sets the wall flag, packet 8. Keep it on for one second. On the virtual robot, use the button below."),
        QT_TRANSLATE_NOOP("Lesson", "Face it to a wall"),
        QT_TRANSLATE_NOOP("Lesson", "Put it beside a wall, on its right"),
        QT_TRANSLATE_NOOP("Lesson", "Carry it 4 cm from the wall"),
    };
    QStringList out;
    for (const char *text : texts)
        out << QString::fromUtf8(text);
    return out;
}
