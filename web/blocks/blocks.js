// SPDX-License-Identifier: GPL-3.0-or-later
// The robot's blocks: each one call of the roomba library (docs/python.md),
// grouped in the sets a teacher may show (move, sensors, sound, lights,
// control). The allowed values come from the protocol's table the hub sends.

const COLOURS = { move: 210, sensors: 160, sound: 290, lights: 45, control: 120 };

const number = (name, value) => ({ type: 'input_value', name, check: 'Number' });
const side = (name, sides) => ({ type: 'field_dropdown', name, options: sides.map(([label, value]) => [label, value]) });
const SIDES_BUMPER = [['left', 'left'], ['right', 'right'], ['either side', 'any']];
const SIDES_CLIFF = [['left', 'left'], ['front left', 'front_left'], ['front right', 'front_right'], ['right', 'right'],
                     ['any', 'any']];
const SIDES_WHEEL = [['left', 'left'], ['right', 'right'], ['front (caster)', 'caster'], ['any', 'any']];
const SIDES_LIGHT = [['left', 'left'], ['front left', 'front_left'], ['centre left', 'center_left'],
                     ['centre right', 'center_right'], ['front right', 'front_right'], ['right', 'right'], ['any', 'any']];

// Which goal field each number input is, for its range (the protocol's table).
export const GOAL_INPUTS = {
    roomba_straight: { DISTANCE: ['straight', 'distance'], SPEED: ['straight', 'speed'] },
    roomba_turn: { ANGLE: ['turn', 'angle'], RATE: ['turn', 'rate'] },
    roomba_turn_side: { ANGLE: ['turn', 'angle'], RATE: ['turn', 'rate'] },
    roomba_arc: { RADIUS: ['arc', 'radius'], ANGLE: ['arc', 'angle'], SPEED: ['arc', 'speed'] },
};

// Block definitions, as Blockly's JSON, by set.
const DEFINITIONS = {
    move: [
        { type: 'roomba_straight', message0: 'drive straight %1 mm at %2 mm/s', args0: [number('DISTANCE'), number('SPEED')],
          previousStatement: null, nextStatement: null, inputsInline: true,
          tooltip: 'robot.straight(mm, speed): ahead, back if negative; waits until the robot is there' },
        { type: 'roomba_turn_side', message0: 'turn %1 %2 degrees at %3 degrees/s',
          args0: [side('SIDE', [['left', 'left'], ['right', 'right']]), number('ANGLE'), number('RATE')],
          previousStatement: null, nextStatement: null, inputsInline: true,
          tooltip: 'robot.turn_left(degrees, rate) or robot.turn_right(...): on the spot' },
        { type: 'roomba_turn', message0: 'turn by %1 degrees at %2 degrees/s',
          args0: [number('ANGLE'), number('RATE')], previousStatement: null, nextStatement: null, inputsInline: true,
          tooltip: 'robot.turn(degrees, rate): on the spot, left (counter-clockwise) if more than 0, right if less' },
        { type: 'roomba_arc', message0: 'drive an arc of radius %1 mm turning %2 degrees at %3 mm/s',
          args0: [number('RADIUS'), number('ANGLE'), number('SPEED')], previousStatement: null, nextStatement: null,
          inputsInline: true, tooltip: 'robot.arc(radius, angle, speed): along a circle, left if the angle is positive' },
        { type: 'roomba_drive', message0: 'drive at %1 mm/s turning %2 degrees/s', args0: [number('SPEED'), number('TURN')],
          previousStatement: null, nextStatement: null, inputsInline: true,
          tooltip: 'robot.drive(speed, turn_rate): returns at once and lasts until the next move or stop' },
        { type: 'roomba_stop', message0: 'stop', previousStatement: null, nextStatement: null,
          tooltip: 'robot.stop(): stops the wheels and brushes' },
    ],
    sensors: [
        { type: 'roomba_bumper', message0: 'bumper pressed on %1', args0: [side('SIDE', SIDES_BUMPER)], output: 'Boolean',
          tooltip: 'robot.bumper' },
        { type: 'roomba_cliff', message0: 'cliff under %1', args0: [side('SIDE', SIDES_CLIFF)], output: 'Boolean',
          tooltip: 'robot.cliff: no floor under a cliff sensor' },
        { type: 'roomba_wheel_drop', message0: 'wheel dropped: %1', args0: [side('SIDE', SIDES_WHEEL)], output: 'Boolean',
          tooltip: 'robot.wheel_drop: a wheel hanging down' },
        { type: 'roomba_wall', message0: 'wall seen on the right', output: 'Boolean',
          tooltip: 'robot.wall: the wall sensor on the right' },
        { type: 'roomba_light_bumper', message0: 'light bumper sees something %1', args0: [side('SIDE', SIDES_LIGHT)],
          output: 'Boolean', tooltip: 'robot.light_bumper (Roomba 600, Create 2)' },
        { type: 'roomba_battery', message0: 'battery %1',
          args0: [side('WHAT', [['percent', 'percent'], ['voltage (mV)', 'voltage_mv'], ['current (mA)', 'current_ma'],
                                ['charging', 'charging']])],
          output: null, tooltip: 'robot.battery' },
        { type: 'roomba_odometry', message0: 'position %1',
          args0: [side('WHAT', [['x (mm ahead)', 'x_mm'], ['y (mm left)', 'y_mm'], ['heading (degrees)', 'heading_deg']])],
          output: 'Number', tooltip: 'robot.odometry: where the robot thinks it is, from its own wheels' },
        { type: 'roomba_reset_odometry', message0: 'set position to 0', previousStatement: null, nextStatement: null,
          tooltip: 'robot.reset_odometry(): from here, x 0, y 0, heading 0' },
        { type: 'roomba_wait_until', message0: 'wait until %1 at most %2 seconds',
          args0: [{ type: 'input_value', name: 'CONDITION', check: 'Boolean' }, number('TIMEOUT')],
          previousStatement: null, nextStatement: null, inputsInline: true,
          tooltip: 'robot.wait_until(condition, timeout)' },
    ],
    sound: [
        { type: 'roomba_play', message0: 'play notes %1', args0: [{ type: 'field_input', name: 'SONG', text: 'C4:16 E4:16 G4:32' }],
          previousStatement: null, nextStatement: null,
          tooltip: 'robot.play(song): NOTE:DURATION, like C4:16 (C4, C#4, Db4, a number or rest; 64 is one second)' },
    ],
    lights: [
        { type: 'roomba_digits', message0: 'show %1 on the display', args0: [{ type: 'input_value', name: 'TEXT' }],
          previousStatement: null, nextStatement: null, inputsInline: true,
          tooltip: 'robot.digits(text): up to 4 characters (Roomba 600, Create 2)' },
        { type: 'roomba_leds', message0: 'lights: debris %1 spot %2 dock %3 check robot %4 %5 power colour %6 brightness %7',
          args0: [{ type: 'field_checkbox', name: 'DEBRIS', checked: false },
                  { type: 'field_checkbox', name: 'SPOT', checked: false },
                  { type: 'field_checkbox', name: 'DOCK', checked: false },
                  { type: 'field_checkbox', name: 'CHECK_ROBOT', checked: false },
                  { type: 'input_dummy' }, number('COLOUR'), number('INTENSITY')],
          previousStatement: null, nextStatement: null,
          tooltip: 'robot.leds(...): power colour 0 green to 255 red, brightness 0 off to 255' },
    ],
    control: [
        { type: 'roomba_wait', message0: 'wait %1 seconds', args0: [number('SECONDS')],
          previousStatement: null, nextStatement: null, inputsInline: true, tooltip: 'robot.wait(seconds)' },
    ],
};

const shadow = value => ({ shadow: { type: 'math_number', fields: { NUM: value } } });
const text = value => ({ shadow: { type: 'text', fields: { TEXT: value } } });

// The toolbox's blocks, with the values a new block starts with.
const TOOLBOX = {
    move: [
        { type: 'roomba_straight', inputs: { DISTANCE: shadow(500), SPEED: shadow(200) } },
        { type: 'roomba_turn_side', inputs: { ANGLE: shadow(90), RATE: shadow(90) } },
        { type: 'roomba_turn', inputs: { ANGLE: shadow(90), RATE: shadow(90) } },
        { type: 'roomba_arc', inputs: { RADIUS: shadow(300), ANGLE: shadow(90), SPEED: shadow(200) } },
        { type: 'roomba_drive', inputs: { SPEED: shadow(200), TURN: shadow(0) } },
        { type: 'roomba_stop' },
    ],
    sensors: [
        { type: 'roomba_wait_until', inputs: { TIMEOUT: shadow(10) } },
        { type: 'roomba_bumper' }, { type: 'roomba_cliff' }, { type: 'roomba_wheel_drop' }, { type: 'roomba_wall' },
        { type: 'roomba_light_bumper' }, { type: 'roomba_battery' }, { type: 'roomba_odometry' },
        { type: 'roomba_reset_odometry' },
    ],
    sound: [{ type: 'roomba_play' }],
    lights: [
        { type: 'roomba_digits', inputs: { TEXT: text('HI') } },
        { type: 'roomba_leds', inputs: { COLOUR: shadow(0), INTENSITY: shadow(255) } },
    ],
    control: [
        { type: 'roomba_wait', inputs: { SECONDS: shadow(1) } },
        { type: 'controls_repeat_ext', inputs: { TIMES: shadow(4) } },
        { type: 'controls_whileUntil' }, { type: 'controls_if' }, { type: 'controls_if', extraState: { hasElse: true } },
        { type: 'logic_compare' }, { type: 'logic_operation' }, { type: 'logic_negate' }, { type: 'logic_boolean' },
    ],
};

const NAMES = { move: 'Move', sensors: 'Sensors', sound: 'Sound', lights: 'Lights', control: 'Control' };
export const SETS = Object.keys(DEFINITIONS);

export function defineBlocks(Blockly) {
    for (const [set, blocks] of Object.entries(DEFINITIONS))
        Blockly.defineBlocksWithJsonArray(blocks.map(b => ({ colour: COLOURS[set], ...b })));
}

// The toolbox for the sets the teacher chose; numbers, text and variables always.
export function toolbox(sets) {
    const contents = SETS.filter(s => sets.includes(s)).map(s => ({
        kind: 'category', name: NAMES[s], colour: String(COLOURS[s]),
        contents: TOOLBOX[s].map(b => ({ kind: 'block', ...b })),
    }));
    contents.push({ kind: 'category', name: 'Numbers', colour: '230', contents: [
        { kind: 'block', type: 'math_number', fields: { NUM: 0 } },
        { kind: 'block', type: 'math_arithmetic' },
        { kind: 'block', type: 'math_round' },
        { kind: 'block', type: 'math_random_int', inputs: { FROM: shadow(1), TO: shadow(10) } },
        { kind: 'block', type: 'text' },
        { kind: 'block', type: 'text_join' },
    ] });
    contents.push({ kind: 'category', name: 'Variables', colour: '330', custom: 'VARIABLE' });
    return { kind: 'categoryToolbox', contents };
}

// The range of each number typed into a move, from the protocol's table:
// a number outside it gets a warning on its block before anything runs.
export function rangeWarnings(workspace, table) {
    for (const block of workspace.getAllBlocks(false)) {
        const inputs = GOAL_INPUTS[block.type];
        if (!inputs || block.isInFlyout)
            continue;
        const problems = [];
        for (const [input, [command, field]] of Object.entries(inputs)) {
            const target = block.getInputTargetBlock(input);
            if (target?.type !== 'math_number')
                continue;
            const value = Number(target.getFieldValue('NUM'));
            const [low, high, unit] = table.goalRange(command, field);
            if (value < low || value > high)
                problems.push(`${field} must be from ${low} to ${high} ${unit}, not ${value}`);
        }
        block.setWarningText(problems.length ? problems.join('\n') : null, 'range');
    }
}

// What each input takes, for a block's tooltip: "distance: -10000 to 10000 mm".
export function rangeTooltips(Blockly, table) {
    for (const [type, inputs] of Object.entries(GOAL_INPUTS)) {
        const base = DEFINITIONS.move.find(b => b.type === type).tooltip;
        const ranges = Object.values(inputs).map(([command, field]) => {
            const [low, high, unit] = table.goalRange(command, field);
            return `${field}: ${low} to ${high} ${unit}`;
        });
        Blockly.Blocks[type].init = ((init) => function () {
            init.call(this);
            this.setTooltip(`${base}\n${ranges.join(', ')}`);
        })(Blockly.Blocks[type].init);
    }
}
