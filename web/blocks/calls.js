// SPDX-License-Identifier: GPL-3.0-or-later
// Which library call each block is, in one place: the Python generator
// writes it as Python (robot.straight(500, speed=200)) and the page's
// interpreter makes the same call on its Robot (robot.js), so a block does
// in the browser what its line of Python does.

const value = (input, keyword = null) => ({ value: input, keyword });
const flag = (field, keyword) => ({ flag: field, keyword });

// A statement block: the call and its arguments, in the library's order.
export const STATEMENTS = {
    roomba_straight: () => ['straight', [value('DISTANCE'), value('SPEED', 'speed')]],
    roomba_turn: () => ['turn', [value('ANGLE'), value('RATE', 'rate')]],
    roomba_turn_side: block => ['turn_' + block.getFieldValue('SIDE'), [value('ANGLE'), value('RATE', 'rate')]],
    roomba_arc: () => ['arc', [value('RADIUS'), value('ANGLE'), value('SPEED', 'speed')]],
    roomba_drive: () => ['drive', [value('SPEED'), value('TURN', 'turn_rate')]],
    roomba_stop: () => ['stop', []],
    roomba_wait: () => ['wait', [value('SECONDS')]],
    roomba_wait_until: () => ['wait_until', [{ condition: 'CONDITION' }, value('TIMEOUT', 'timeout')]],
    roomba_reset_odometry: () => ['reset_odometry', []],
    roomba_play: () => ['play', [{ text: 'SONG' }]],
    roomba_digits: () => ['digits', [value('TEXT')]],
    roomba_leds: () => ['leds', [flag('DEBRIS', 'debris'), flag('SPOT', 'spot'), flag('DOCK', 'dock'),
                                 flag('CHECK_ROBOT', 'check_robot'), value('COLOUR', 'power_colour'),
                                 value('INTENSITY', 'power_intensity')]],
};

// A sensor block: the robot's property and the member read.
export const SENSORS = {
    roomba_bumper: block => ['bumper', block.getFieldValue('SIDE'), 'Boolean'],
    roomba_cliff: block => ['cliff', block.getFieldValue('SIDE'), 'Boolean'],
    roomba_wheel_drop: block => ['wheel_drop', block.getFieldValue('SIDE'), 'Boolean'],
    roomba_light_bumper: block => ['light_bumper', block.getFieldValue('SIDE'), 'Boolean'],
    roomba_wall: () => ['wall', null, 'Boolean'],
    roomba_battery: block => ['battery', block.getFieldValue('WHAT'), null],
    roomba_odometry: block => ['odometry', block.getFieldValue('WHAT'), 'Number'],
};
