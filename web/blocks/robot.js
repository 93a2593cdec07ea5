// SPDX-License-Identifier: GPL-3.0-or-later
// The roomba library's Robot (python/roomba/robot.py) over the hub's
// WebSocket: the same calls, control and heartbeat, goal commands, answers
// and stops, and the same words, so that a block program does in the
// browser what its Python does. Keep the two in step.

import { BatteryLow, ConnectionLost, MotionTimeout, RobotError, SafetyStop, StopButton, Stopped, ValueError, g }
    from './errors.js';
import * as sensors from './sensors.js';

// The bridge sends telemetry at least every 45 ms: data older than this is stale.
const STALE_AFTER_MS = 500;
const CONNECT_TIMEOUT_MS = 10000;
const ANSWER_TIMEOUT_MS = 3000;
const SAFE_TIMEOUT_MS = 2000;
// The bridge tells the distance and angle at most 100 ms late.
const ODOMETRY_LAG_MS = 120;
// A move's answer may come this much after the bridge's own time limit.
const MOVE_MARGIN_MS = 3000;
const MODE_SAFE = 2, MODE_FULL = 3;

const CAUSE_WORDS = {
    cliff_left: 'a cliff under its left side',
    cliff_front_left: 'a cliff ahead on the left',
    cliff_front_right: 'a cliff ahead on the right',
    cliff_right: 'a cliff under its right side',
    wheel_drop_left: 'its left wheel dropped',
    wheel_drop_right: 'its right wheel dropped',
    wheel_drop_caster: 'its front wheel dropped',
    charger: 'it is on its charger',
    battery_low: 'its battery is nearly flat',
};

const now = () => performance.now();

function number(name, value) {
    if (typeof value !== 'number' || !Number.isFinite(value))
        throw new ValueError(`${name} must be a number, not ${typeof value === 'string' ? `'${value}'` : value}`);
    return value;
}

function checkRange(name, value, low, high, unit) {
    const v = number(name, value);
    if (!(low <= v && v <= high))
        throw new ValueError(`${name} must be from ${g(low)} to ${g(high)} ${unit}, not ${g(v)}`);
    return v;
}

function safetyWords(cause) {
    const words = cause.filter(c => c !== 'safety').map(c => CAUSE_WORDS[c] || c.replaceAll('_', ' '));
    return words.length ? words.join(' and ') : 'a safety sensor';
}

function safetyFix(cause) {
    if (cause.some(c => c.startsWith('cliff')))
        return 'Carry it back from the edge, then run your program again.';
    if (cause.some(c => c.startsWith('wheel_drop')))
        return 'Put it back flat on the floor, then run your program again.';
    if (cause.includes('charger'))
        return 'Lift it off its dock, then run your program again.';
    if (cause.includes('battery_low'))
        return 'Put it on its dock to charge, then run your program again.';
    return 'Check the robot, then run your program again.';
}

export class Robot {
    // hub: the page's Hub (subscribe, publish, listen); user: the account,
    // which the broker makes the client id; table: a ProtocolTable.
    constructor(hub, name, user, table) {
        this.hub = hub;
        this.name = name;
        this.clientName = user;
        this.table = table;
        this.heartbeatMs = table.figure('heartbeat_ms');
        this.leaseS = table.figure('lease_ms') / 1000;
        this.willGraceMs = table.figure('will_grace_ms');
        this.wheelBase = table.figure('wheel_base_mm');
        this.maxWheelSpeed = table.figure('max_wheel_speed_mm_per_s');
        this.state = null;
        this.packets = {};
        this.telemetryAt = null;
        this.keyFrameSeen = false;
        this.odometrySum = new sensors.OdometrySum();
        this.settledAt = 0;
        this.control = false;
        this.takeAnswer = null;
        this.replies = new Map();
        this.swallow = new Set();
        this.ids = 1;
        this.pending = null;
        this.busy = false;
        this.moving = false;
        this.connected = hub.signedIn;
        this.closed = false;
        this.waiters = new Set();
        this.onChange = null; // the page's sensor view
        this.unlisten = hub.listen(this);
        const base = `roomba/${name}/`;
        this.topics = [base + 'state', base + 'telemetry', base + 'reply/' + this.clientName];
        this.topics.forEach(t => hub.subscribe(t));
    }

    // ----- the page's side: a program's start and end -----

    // What new Robot() does: connected, the robot online and a key frame seen.
    async start() {
        const deadline = now() + CONNECT_TIMEOUT_MS;
        this.pending = null;
        this.closed = false;
        this.odometrySum = new sensors.OdometrySum();
        await this._wait(() => this.state?.online, deadline,
            `robot ${this.name} is not on the broker: is its bridge running, and is the name right?`, false);
        await this._wait(() => this.keyFrameSeen, deadline,
            `robot ${this.name} sends no data: is it switched on and connected to its bridge?`, false);
    }

    // What the end of a Python program does (close()): stops the robot if it
    // moves, gives control back. The robot stays watched for the sensor view.
    close() {
        if (this.closed)
            return;
        if (this.connected && this.control === true) {
            if (this.moving)
                this._publishCommand('stop', null);
            this._release();
        }
        this.closed = true;
    }

    // The Stop button, as Ctrl-C: the robot stops at once, the program ends.
    stopButton() {
        this._publishCommand('stop', null);
        this._deliver(new StopButton('Stopped with the Stop button: the robot was stopped.'), false);
    }

    // The page goes to another robot.
    forget() {
        this.close();
        this.unlisten();
        this.topics.forEach(t => this.hub.unsubscribe(t));
    }

    // A stop waiting for the program, taken where it stands (the statement
    // prefix calls it): the browser's SIGUSR1.
    checkPending() {
        const exc = this.pending;
        if (exc && !this.busy) {
            this.pending = null;
            throw exc;
        }
    }

    // ----- which part failed -----

    _failedPart() {
        if (!this.connected)
            return 'broker';
        const state = this.state || {};
        if (state.online === false)
            return 'bridge';
        if (![undefined, null, 'streaming'].includes(state.link))
            return 'robot';
        return 'network';
    }

    _lost(part = null) {
        part = part || this._failedPart();
        const name = this.name;
        let message;
        if (part === 'broker')
            message = `The classroom broker is not answering: is it running on the teacher's machine, and is this `
                + `computer on the classroom network? Your program stopped; ${name} stops within ${g(this.leaseS)} s `
                + `without its heartbeat. Run your program again once the broker is back.`;
        else if (part === 'bridge' && this.moving)
            message = `Robot ${name}'s bridge went offline while you drove it: a real robot keeps its last drive when `
                + `its bridge dies. Pick it up and hold its power button to switch it off, then ask your teacher to `
                + `restart its bridge and run your program again.`;
        else if (part === 'bridge')
            message = `Robot ${name}'s bridge went offline (the broker is fine): ask your teacher to check the bridge `
                + `on the computer beside the robot, then run your program again.`;
        else if (part === 'robot')
            message = `Robot ${name} does not answer its bridge (its link is ${(this.state || {}).link}): is it `
                + `switched on and charged, and is its cable plugged in? Its bridge stopped it; run your program `
                + `again once it answers.`;
        else
            message = `Robot ${name} sent no data for more than ${g(STALE_AFTER_MS / 1000)} s while the broker and its `
                + `bridge still count as up: the network is slow, or the bridge's computer lost it. Check the `
                + `network, then run your program again.`;
        return new ConnectionLost(message, name, null, part);
    }

    // ----- what the hub brings -----

    brokerLost() {
        const was = this.connected;
        this.connected = false;
        this._notify();
        if (was && !this.closed)
            this._deliver(this._lost('broker'));
    }

    message(topic, text) {
        let payload;
        try {
            payload = JSON.parse(text);
        } catch {
            return;
        }
        if (!payload || typeof payload !== 'object' || Array.isArray(payload))
            return;
        const parts = topic.split('/');
        if (parts.length < 3 || parts[1] !== this.name)
            return;
        if (parts[2] === 'state')
            this._onState(payload);
        else if (parts[2] === 'telemetry')
            this._onTelemetry(payload);
        else if (parts[2] === 'reply' && parts[3] === this.clientName)
            this._onReply(payload);
        this.onChange?.(this);
    }

    _onState(state) {
        this.state = state;
        this._notify();
        if (!state.online) {
            setTimeout(() => this._judgeOffline(), this.willGraceMs);
        } else if (this.moving && state.mode === 'passive' && (state.mode_cause || [null])[0] === 'safety') {
            const cause = state.mode_cause;
            this._deliver(new SafetyStop(`${this.name} stopped itself: ${safetyWords(cause)}. ${safetyFix(cause)}`,
                this.name, 'drive', cause));
        }
    }

    _judgeOffline() {
        if (this.connected && !(this.state || {}).online)
            this._deliver(this._lost('bridge'), false);
    }

    _onTelemetry(packets) {
        if (packets.key_frame) {
            this.packets = {};
            this.keyFrameSeen = true;
        }
        this.odometrySum.add(packets.distance || 0, packets.angle || 0);
        Object.assign(this.packets, packets);
        this.telemetryAt = now();
        this._notify();
    }

    _onReply(reply) {
        const rid = reply.id;
        if (rid === 'control')
            return this._onControlReply(reply);
        if (rid === 'stopped') {
            if (this._swallowed('stopped'))
                return;
            const who = reply.by;
            return this._deliver(new Stopped(`${who} stopped ${this.name}: your program ends here. Run it again to go on.`,
                this.name, null, who));
        }
        if (rid === 'safety') {
            const text = reply.error || '';
            const Kind = text.includes('link') ? ConnectionLost : SafetyStop;
            return this._deliver(new Kind(`${this.name}: ${text}`, this.name));
        }
        this.replies.set(rid, reply);
        const stop = reply.stop;
        if (stop != null)
            this.moving = false;
        if (this.table.controlLost.has(stop))
            this.swallow.add('control');
        else if (stop === 'stopped' && reply.by && reply.by !== this.clientName)
            this.swallow.add('stopped');
        this._notify();
    }

    _swallowed(notice) {
        return this.swallow.delete(notice);
    }

    // Control gone, however it went: the worker stops keeping it.
    _loseControl() {
        if (this.control === true)
            this._keep(false);
        this.control = false;
    }

    _onControlReply(reply) {
        const answersTake = !reply.ok || reply.controller === this.clientName;
        if (this.takeAnswer === null && this.control === 'taking' && answersTake) {
            this.takeAnswer = reply;
            this._notify();
            return;
        }
        if (reply.ok || !this.control)
            return;
        this._loseControl();
        this.moving = false;
        this._notify();
        if (this._swallowed('control'))
            return;
        this._deliver(this._controlLost(reply.error || '', reply.controller), false);
    }

    _controlLost(error, controller, command = null) {
        if (error.startsWith('stop all'))
            return new Stopped(`Stop all: your teacher stopped every robot, ${this.name} too. Your program ends here; `
                + `run it again when your teacher says so.`, this.name, command, 'stop all');
        if (error.endsWith('took control'))
            return new Stopped(`${controller} took control of ${this.name}: your program ends here. Run it again when `
                + `the robot is free.`, this.name, command, controller);
        if (error.startsWith('no heartbeat'))
            return new ConnectionLost(`${this.name}'s bridge heard nothing from your program for ${g(this.leaseS)} s, so `
                + `it stopped the robot (a slow network, or a program that was stuck). Run it again.`, this.name, command);
        return new ConnectionLost(`${this.name}: ${error}`, this.name, command);
    }

    // ----- raising what happened, where the program is -----

    _deliver(exc, onlyInControl = true) {
        if (this.closed || this.pending !== null)
            return;
        if (onlyInControl && !this.control && !this.busy)
            return;
        this.pending = exc;
        this._notify();
    }

    _notify() {
        for (const wake of this.waiters)
            wake();
    }

    _changed(ms) {
        return new Promise(resolve => {
            const done = () => {
                clearTimeout(timer);
                this.waiters.delete(done);
                resolve();
            };
            const timer = setTimeout(done, ms);
            this.waiters.add(done);
        });
    }

    // Waits until done() holds, raising whatever happens meanwhile.
    async _wait(done, deadline, timeoutMessage, checkData = true) {
        for (;;) {
            if (this.pending !== null) {
                const exc = this.pending;
                this.pending = null;
                throw exc;
            }
            const result = await done();
            if (result)
                return result;
            if (checkData)
                this._checkFresh();
            const left = deadline - now();
            if (left <= 0) {
                if (timeoutMessage === null)
                    return result;
                throw new RobotError(timeoutMessage, this.name);
            }
            await this._changed(Math.min(left, 50));
        }
    }

    _checkFresh() {
        if (this.telemetryAt === null || now() - this.telemetryAt > STALE_AFTER_MS)
            throw this._lost();
    }

    // The library at work: a stop arriving now is raised by its wait.
    async _call(body) {
        if (this.closed)
            throw new RobotError(`${this.name} was closed: make a new Robot() to drive it again.`, this.name);
        this.busy = true;
        try {
            return await body();
        } finally {
            this.busy = false;
        }
    }

    async _callChecked(body) {
        const result = await this._call(body);
        const exc = this.pending;
        if (exc !== null) {
            this.pending = null;
            throw exc;
        }
        return result;
    }

    // ----- control, and the heartbeat -----

    // The hub's worker keeps control while this holds it (Python's heartbeat
    // thread); when the telemetry goes stale it stops keeping and says so.
    _keep(on) {
        this.hub.keep(on ? { robot: this.name, client: this.clientName, heartbeatMs: this.heartbeatMs,
                             staleMs: STALE_AFTER_MS } : null);
    }

    heartbeatStale() {
        if (this.closed || this.control !== true)
            return;
        const lost = this._lost(); // before the release forgets that it moved
        this._publishCommand('stop', null);
        this._release();
        this._deliver(lost, false);
    }

    _publishControl(action, qos) {
        // A clock that never goes back, from one page to the next of the same
        // account: the bridge counts the lease from it (docs/mqtt.md, "Control").
        const message = { action, sent_ms: Math.trunc(performance.timeOrigin + now()) }; // as hub_worker.js
        if (action === 'take')
            message.program = 'blocks';
        this.hub.publish(`roomba/${this.name}/control/${this.clientName}`, JSON.stringify(message), qos);
    }

    _publishCommand(command, fields, data = null, qos = 1) {
        const rid = String(this.ids++);
        const message = { v: 2, id: rid, command };
        if (fields !== null)
            message.fields = fields;
        if (data !== null)
            message.data = data;
        this.hub.publish(`roomba/${this.name}/command/${this.clientName}`, JSON.stringify(message), qos);
        return rid;
    }

    async _takeControl(command) {
        if (this.control === true)
            return;
        this.control = 'taking';
        this.takeAnswer = null;
        this._publishControl('take', 1);
        let answer;
        try {
            answer = await this._wait(() => this.takeAnswer, now() + ANSWER_TIMEOUT_MS, null);
        } finally {
            if (this.control === 'taking')
                this.control = Boolean(this.takeAnswer?.ok);
            this._keep(this.control === true);
        }
        if (!answer)
            throw new RobotError(`${this.name} did not answer when ${this.clientName} asked to drive it: your account may `
                + `not be allowed to drive this robot (ask your teacher), or its bridge is stuck.`, this.name, command);
        if (!answer.ok) {
            if (answer.controller)
                throw new RobotError(`${this.name} is being driven by ${answer.controller}: wait until they finish, or `
                    + `ask your teacher.`, this.name, command);
            throw new RobotError(`${this.name} would not give control: ${answer.error}. Try again in a moment.`,
                this.name, command);
        }
    }

    _release() {
        const had = this.control === true;
        this._loseControl();
        this.moving = false;
        if (had)
            this._publishControl('release', 1);
    }

    async _ask(command, fields = null, data = null, timeoutMs = ANSWER_TIMEOUT_MS) {
        const rid = this._publishCommand(command, fields, data);
        const reply = await this._wait(() => this.replies.get(rid), now() + timeoutMs,
            `${this.name} did not answer ${command} in ${g(timeoutMs / 1000)} s: is its bridge running?`);
        this.replies.delete(rid);
        return reply;
    }

    _refused(command, reply) {
        const error = reply.error || '';
        if (error.includes('has control') && reply.controller)
            return new Stopped(`${reply.controller} took control of ${this.name}: your program ends here.`,
                this.name, command, reply.controller);
        if (error.includes('nobody has control'))
            return this._controlLost('no heartbeat', null, command);
        return new RobotError(`${this.name} refused ${command}: ${error}`, this.name, command);
    }

    async _readyToDrive(command) {
        this._checkFresh();
        const low = (this.state || {}).battery_low;
        if (low)
            throw new BatteryLow(`${this.name} was not moved: ${low.replace(/\.+$/, '')}.`, this.name, command, low);
        await this._takeControl(command);
        if ([MODE_SAFE, MODE_FULL].includes(this.packets.oi_mode))
            return;
        const reply = await this._ask('safe');
        if (!reply.ok)
            throw this._refused('safe', reply);
        await this._wait(() => [MODE_SAFE, MODE_FULL].includes(this.packets.oi_mode), now() + SAFE_TIMEOUT_MS, null);
        if (![MODE_SAFE, MODE_FULL].includes(this.packets.oi_mode)) {
            const cause = (this.state || {}).mode_cause || [];
            throw new SafetyStop(`${this.name} would not enter Safe mode (${safetyWords(cause)}), so it cannot drive. `
                + safetyFix(cause), this.name, command, cause);
        }
    }

    // ----- a move's time, as the bridge plans it (robot/motion_goal.cpp) -----

    maxArcSpeed(radius) {
        return this.maxWheelSpeed * radius / (radius + this.wheelBase / 2);
    }

    kinematicSeconds(command, f) {
        const arm = this.wheelBase / 2, rad = Math.PI / 180;
        let length, top;
        if (command === 'straight')
            [length, top] = [Math.abs(f.distance), f.speed];
        else if (command === 'turn')
            [length, top] = [Math.abs(f.angle) * rad * arm, f.rate * rad * arm];
        else
            [length, top] = [Math.abs(f.angle) * rad * (f.radius + arm), f.speed * (f.radius + arm) / f.radius];
        const a = this.table.figure('acceleration_mm_per_s2'), creep = Math.min(this.table.figure('creep_mm_per_s'), top);
        const ramp = (top * top - creep * creep) / (2 * a);
        if (length >= 2 * ramp)
            return 2 * (top - creep) / a + (length - 2 * ramp) / top;
        return 2 * (Math.sqrt(creep * creep + a * length) - creep) / a;
    }

    timeLimitSeconds(command, fields) {
        return this.table.figure('time_limit_factor') * this.kinematicSeconds(command, fields)
            + this.table.figure('time_limit_extra_s');
    }

    // ----- moves -----

    _goalField(command, field, value) {
        const [low, high, unit] = this.table.goalRange(command, field);
        return checkRange(field, value, low, high, unit);
    }

    _move(command, fields, call) {
        const limitSeconds = this.timeLimitSeconds(command, fields);
        return this._callChecked(async () => {
            await this._readyToDrive(call);
            this.moving = true;
            let reply;
            try {
                reply = await this._ask(command, fields, null, limitSeconds * 1000 + MOVE_MARGIN_MS);
            } catch (e) {
                if (e.constructor === RobotError && e.message.includes('did not answer')) {
                    this._publishCommand('stop', null);
                    throw new MotionTimeout(`${this.name}: ${call} did not end in ${limitSeconds.toFixed(1)} s: the robot `
                        + `was stopped. Is it pushing against something?`, this.name, call);
                }
                throw e;
            } finally {
                this.moving = false;
                this._moved();
            }
            if (reply.ok)
                return reply;
            throw this._moveFailed(call, reply);
        });
    }

    _moveFailed(call, reply) {
        const { stop, by } = reply, error = reply.error || '';
        if (stop == null)
            return this._refused(call, reply);
        if (stop === 'safety') {
            const cause = reply.cause || [];
            return new SafetyStop(`${this.name}: ${call} stopped early, after ${this._measured(reply)}, because `
                + `${safetyWords(cause)}. ${safetyFix(cause)}`, this.name, call, cause);
        }
        if (stop === 'timeout')
            return new MotionTimeout(`${this.name}: ${call} did not end in time (it went ${this._measured(reply)}): the `
                + `robot was stopped. Is it pushing against a wall or stuck? Move it, then run your program again.`,
                this.name, call);
        if (this.table.controlLost.has(stop)) {
            this._loseControl();
            return this._controlLost(stop === 'stop-all' ? 'stop all' : error, by, call);
        }
        if (stop === 'stopped' && by)
            return new Stopped(`${by} stopped ${this.name} during ${call}: your program ends here. Run it again to go on.`,
                this.name, call, by);
        if (stop === 'no-data')
            return new ConnectionLost(`${this.name}: ${call} stopped: ${error}`, this.name, call);
        return new RobotError(`${this.name}: ${call} stopped: ${error}`, this.name, call);
    }

    _measured(reply) {
        return `${(reply.distance_mm || 0).toFixed(0)} mm and ${(reply.angle_deg || 0).toFixed(0)} degrees`;
    }

    async straight(distance, speed = 200) {
        distance = this._goalField('straight', 'distance', distance);
        speed = this._goalField('straight', 'speed', speed);
        return (await this._move('straight', { distance, speed }, `straight(${g(distance)})`)).distance_mm;
    }

    async turn(angle, rate = 90) {
        angle = this._goalField('turn', 'angle', angle);
        rate = this._goalField('turn', 'rate', rate);
        return (await this._move('turn', { angle, rate }, `turn(${g(angle)})`)).angle_deg;
    }

    turn_left(angle = 90, rate = 90) {
        return this.turn(Math.abs(number('angle', angle)), rate);
    }

    turn_right(angle = 90, rate = 90) {
        return this.turn(-Math.abs(number('angle', angle)), rate);
    }

    async arc(radius, angle, speed = 200) {
        radius = this._goalField('arc', 'radius', radius);
        angle = this._goalField('arc', 'angle', angle);
        const [low, , unit] = this.table.goalRange('arc', 'speed');
        const fastest = Math.floor(this.maxArcSpeed(radius));
        speed = checkRange('speed', speed, low, fastest, `${unit} on an arc of radius ${g(radius)} mm`);
        return (await this._move('arc', { radius, angle, speed }, `arc(${g(radius)}, ${g(angle)})`)).angle_deg;
    }

    drive(speed = 200, turnRate = 0) {
        const max = this.maxWheelSpeed, arm = this.wheelBase / 2;
        speed = checkRange('speed', speed, -max, max, 'mm/s');
        turnRate = number('turn_rate', turnRate);
        const spin = turnRate * Math.PI / 180 * arm;
        if (Math.abs(speed) + Math.abs(spin) > max) {
            const most = ((max - Math.abs(speed)) / arm * 180 / Math.PI).toFixed(0);
            throw new ValueError(`turn_rate must be from -${most} to ${most} degrees a second at speed ${g(speed)} mm/s `
                + `(no wheel goes faster than ${g(max)} mm/s), not ${g(turnRate)}`);
        }
        const fields = { 'right-velocity': Math.round(speed + spin), 'left-velocity': Math.round(speed - spin) };
        return this._callChecked(async () => {
            await this._readyToDrive('drive');
            const reply = await this._ask('drive-direct', fields);
            if (!reply.ok)
                throw this._refused('drive', reply);
            this.moving = speed !== 0 || turnRate !== 0;
        });
    }

    stop() {
        return this._callChecked(async () => {
            this.moving = false;
            const reply = await this._ask('stop');
            this._moved();
            if (!reply.ok)
                throw this._refused('stop', reply);
        });
    }

    wait(seconds) {
        seconds = number('seconds', seconds);
        if (seconds < 0)
            throw new ValueError(`seconds must be 0 or more, not ${g(seconds)}`);
        return this._callChecked(() => this._wait(() => false, now() + seconds * 1000, null));
    }

    // condition: an async function, as Python's lambda.
    async wait_until(condition, timeout = 10) {
        timeout = number('timeout', timeout);
        return Boolean(await this._callChecked(() => this._wait(condition, now() + timeout * 1000, null)));
    }

    // ----- sensors (async: a stop waiting is raised by reading one) -----

    _latest() {
        if (this.pending !== null && !this.busy) {
            const exc = this.pending;
            this.pending = null;
            throw exc;
        }
        this._checkFresh();
        return { ...this.packets };
    }

    async bumper() { return sensors.bumper(this._latest()); }
    async cliff() { return sensors.cliff(this._latest()); }
    async wheel_drop() { return sensors.wheelDrop(this._latest()); }
    async wall() { return Boolean(this._latest().wall); }
    async light_bumper() {
        const seen = sensors.lightBumper(this._latest());
        if (seen === null)
            throw new RobotError(`${this.name} has no light bumper (a Roomba 500 or a Create): in Python, `
                + `robot.light_bumper is None on it.`, this.name, 'light_bumper');
        return seen;
    }
    async battery() { return sensors.battery(this._latest(), (this.state || {}).battery_percent); }

    _moved() {
        this.settledAt = now() + ODOMETRY_LAG_MS;
    }

    async odometry() {
        await this._call(() => this._wait(() => now() >= this.settledAt, this.settledAt, null));
        this._latest();
        return this.odometrySum.value();
    }

    async reset_odometry() {
        await this._call(() => this._wait(() => now() >= this.settledAt, this.settledAt, null));
        this.odometrySum = new sensors.OdometrySum();
    }

    // ----- sound and lights -----

    play(song) {
        const data = sensors.parseSong(song);
        return this._callChecked(async () => {
            await this._readyToDrive('play');
            for (const [command, extra] of [['song', data], ['play', null]]) {
                const reply = await this._ask(command, { 'song-number': 0 }, extra);
                if (!reply.ok)
                    throw this._refused('play', reply);
            }
        });
    }

    digits(text) {
        if (typeof text !== 'string' || text.length > 4 || [...text].some(c => c.charCodeAt(0) < 32 || c.charCodeAt(0) > 126))
            throw new ValueError(`digits() shows 0 to 4 letters, digits or signs, like "HI", not ${
                typeof text === 'string' ? `'${text}'` : String(text)}`);
        const padded = text.toUpperCase().padEnd(4);
        const fields = Object.fromEntries([...padded].map((c, i) => [`digit-${3 - i}`, c.charCodeAt(0)]));
        return this._simple('digit-leds-ascii', fields, 'digits');
    }

    leds(debris = false, spot = false, dock = false, checkRobot = false, powerColour = 0, powerIntensity = 0) {
        checkRange('power_colour', powerColour, 0, 255, '');
        checkRange('power_intensity', powerIntensity, 0, 255, '');
        const bits = Number(Boolean(debris)) | Number(Boolean(spot)) << 1 | Number(Boolean(dock)) << 2
            | Number(Boolean(checkRobot)) << 3;
        return this._simple('leds', { 'led-bits': bits, 'power-led-colour': Math.trunc(powerColour),
                                      'power-led-intensity': Math.trunc(powerIntensity) }, 'leds');
    }

    _simple(command, fields, call) {
        return this._callChecked(async () => {
            await this._readyToDrive(call);
            const reply = await this._ask(command, fields);
            if (!reply.ok)
                throw this._refused(call, reply);
        });
    }
}
