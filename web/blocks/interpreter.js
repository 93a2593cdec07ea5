// SPDX-License-Identifier: GPL-3.0-or-later
// Runs a block program on the page's Robot (robot.js) by walking its blocks,
// as the Python they make runs them: each statement block is the same call
// (calls.js), numbers and text behave as Python's. The hub's page allows no
// code made at run time (its Content-Security-Policy), so nothing is eval'd.

import { SENSORS, STATEMENTS } from './calls.js';
import { ValueError } from './errors.js';

// What the interpreter knows besides the robot's blocks: the toolbox's own.
const STANDARD = new Set(['controls_repeat_ext', 'controls_whileUntil', 'controls_if', 'logic_compare',
    'logic_operation', 'logic_negate', 'logic_boolean', 'math_number', 'math_arithmetic', 'math_round',
    'math_random_int', 'text', 'text_join', 'variables_get', 'variables_set', 'math_change']);

export const knows = type => type in STATEMENTS || type in SENSORS || STANDARD.has(type);

// Python's str() of a value the blocks make.
function pyStr(v) {
    if (v === null || v === undefined)
        return 'None';
    if (typeof v === 'boolean')
        return v ? 'True' : 'False';
    return String(v);
}

// Python's round(): halves to even.
function pyRound(x) {
    const r = Math.round(x);
    return Math.abs(x % 1) === 0.5 && r % 2 !== 0 ? r - 1 : r;
}

const isNumber = v => typeof v === 'number';

export class BlockError extends Error {
    get name() { return 'TypeError'; }
}

function arithmetic(op, a, b) {
    if (!isNumber(a) || !isNumber(b)) {
        if (op === 'ADD' && typeof a === 'string' && typeof b === 'string')
            return a + b;
        throw new BlockError(`unsupported operand for ${op.toLowerCase()}: ${pyStr(a)} and ${pyStr(b)}`);
    }
    switch (op) {
    case 'ADD': return a + b;
    case 'MINUS': return a - b;
    case 'MULTIPLY': return a * b;
    case 'DIVIDE':
        if (b === 0)
            throw new ValueError('division by zero');
        return a / b;
    default: return a ** b;
    }
}

function compare(op, a, b) {
    switch (op) {
    case 'EQ': return a === b;
    case 'NEQ': return a !== b;
    case 'LT': return a < b;
    case 'LTE': return a <= b;
    case 'GT': return a > b;
    default: return a >= b;
    }
}

export class Interpreter {
    // robot: a Robot; step(block) is awaited before each statement and each
    // time round a loop (it shows the block and raises a stop waiting).
    constructor(robot, step) {
        this.robot = robot;
        this.step = step;
        this.variables = new Map();
    }

    async runWorkspace(workspace) {
        for (const block of workspace.getTopBlocks(true)) {
            if (block.outputConnection)
                await this.value(block);
            else
                await this.statements(block);
        }
    }

    async statements(block) {
        for (; block; block = block.getNextBlock())
            if (block.isEnabled())
                await this.statement(block);
    }

    async input(block, name, otherwise) {
        const target = block.getInputTargetBlock(name);
        return target ? this.value(target) : otherwise;
    }

    async argument(block, arg) {
        if (arg.value)
            return this.input(block, arg.value, 0);
        if (arg.flag)
            return block.getFieldValue(arg.flag) === 'TRUE';
        if (arg.text)
            return block.getFieldValue(arg.text);
        return () => this.input(block, arg.condition, false);
    }

    async statement(block) {
        await this.step(block);
        const type = block.type;
        if (type in STATEMENTS) {
            const [name, spec] = STATEMENTS[type](block);
            const args = [];
            for (const arg of spec)
                args.push(await this.argument(block, arg));
            return this.robot[name](...args);
        }
        switch (type) {
        case 'controls_repeat_ext': {
            const times = Math.trunc(await this.input(block, 'TIMES', 0));
            for (let i = 0; i < times; i++) {
                await this.statements(block.getInputTargetBlock('DO'));
                await this.step(block);
            }
            return;
        }
        case 'controls_whileUntil': {
            const until = block.getFieldValue('MODE') === 'UNTIL';
            while (Boolean(await this.input(block, 'BOOL', false)) !== until) {
                await this.statements(block.getInputTargetBlock('DO'));
                await this.step(block);
            }
            return;
        }
        case 'controls_if': {
            for (let n = 0; block.getInput('IF' + n); n++)
                if (await this.input(block, 'IF' + n, false))
                    return this.statements(block.getInputTargetBlock('DO' + n));
            return this.statements(block.getInputTargetBlock('ELSE'));
        }
        case 'variables_set':
            this.variables.set(block.getFieldValue('VAR'), await this.input(block, 'VALUE', null));
            return;
        case 'math_change': {
            const id = block.getFieldValue('VAR'), now = this.variables.get(id);
            this.variables.set(id, (isNumber(now) ? now : 0) + await this.input(block, 'DELTA', 0));
            return;
        }
        default:
            if (block.outputConnection)
                return this.value(block);
            throw new BlockError(`the page cannot run a "${type}" block`);
        }
    }

    async value(block) {
        const type = block.type;
        if (type in SENSORS) {
            const [property, member] = SENSORS[type](block);
            const reading = await this.robot[property]();
            return member ? reading[member] : reading;
        }
        switch (type) {
        case 'math_number': return Number(block.getFieldValue('NUM'));
        case 'text': return block.getFieldValue('TEXT');
        case 'logic_boolean': return block.getFieldValue('BOOL') === 'TRUE';
        case 'logic_negate': return !(await this.input(block, 'BOOL', false));
        case 'logic_operation': {
            const a = await this.input(block, 'A', false);
            if (block.getFieldValue('OP') === 'AND')
                return a ? this.input(block, 'B', false) : a;
            return a ? a : this.input(block, 'B', false);
        }
        case 'logic_compare':
            return compare(block.getFieldValue('OP'), await this.input(block, 'A', 0), await this.input(block, 'B', 0));
        case 'math_arithmetic':
            return arithmetic(block.getFieldValue('OP'), await this.input(block, 'A', 0), await this.input(block, 'B', 0));
        case 'math_round': {
            const x = await this.input(block, 'NUM', 0);
            const op = block.getFieldValue('OP');
            return op === 'ROUND' ? pyRound(x) : op === 'ROUNDUP' ? Math.ceil(x) : Math.floor(x);
        }
        case 'math_random_int': {
            const low = Math.trunc(await this.input(block, 'FROM', 0)), high = Math.trunc(await this.input(block, 'TO', 0));
            return low + Math.floor(Math.random() * (high - low + 1));
        }
        case 'text_join': {
            let text = '';
            for (let n = 0; block.getInput('ADD' + n); n++)
                text += pyStr(await this.input(block, 'ADD' + n, ''));
            return text;
        }
        case 'variables_get': {
            const v = this.variables.get(block.getFieldValue('VAR'));
            return v === undefined ? null : v;
        }
        default:
            throw new BlockError(`the page cannot run a "${type}" block`);
        }
    }
}
