// SPDX-License-Identifier: GPL-3.0-or-later
// What the robot senses, read from the latest telemetry, and song text, as
// python/roomba/sensors.py and song.py read them.

import { ValueError } from './errors.js';

export const LIGHT_BUMPERS = ['left', 'front_left', 'center_left', 'center_right', 'front_right', 'right'];
// Packet 21: 1 reconditioning, 2 full, 3 trickle charging.
const CHARGING_STATES = [1, 2, 3];

export function bumper(p) {
    const bits = p.bumps_wheel_drops || 0;
    const left = Boolean(bits & 2), right = Boolean(bits & 1);
    return { left, right, any: left || right };
}

export function wheelDrop(p) {
    const bits = p.bumps_wheel_drops || 0;
    const left = Boolean(bits & 8), right = Boolean(bits & 4), caster = Boolean(bits & 16);
    return { left, right, caster, any: left || right || caster };
}

export function cliff(p) {
    const c = Object.fromEntries(['left', 'front_left', 'front_right', 'right'].map(s => [s, Boolean(p['cliff_' + s])]));
    return { ...c, any: c.left || c.front_left || c.front_right || c.right };
}

export function lightBumper(p) {
    if (!('light_bumper' in p))
        return null; // a Roomba 500 or a Create has none
    const bits = p.light_bumper;
    const seen = Object.fromEntries(LIGHT_BUMPERS.map((s, i) => [s, Boolean(bits & (1 << i))]));
    const signals = LIGHT_BUMPERS.map(s => Math.trunc(p[`light_bump_${s}_signal`] || 0));
    return { ...seen, signals, any: Object.values(seen).some(Boolean) };
}

export function battery(p, statePercent) {
    let percent = statePercent ?? null;
    const charge = p.battery_charge, capacity = p.battery_capacity;
    if (charge != null && capacity)
        percent = Math.round(1000 * charge / capacity) / 10;
    return { percent, voltage_mv: p.voltage ?? null, current_ma: p.current ?? null,
             charging: CHARGING_STATES.includes(p.charging_state) };
}

// The robot's own distance and angle, summed over the telemetry.
export class OdometrySum {
    constructor() { this.x = this.y = this.heading = 0; }

    add(distanceMm, angleDeg) {
        if (!distanceMm && !angleDeg)
            return;
        const middle = this.heading + angleDeg * Math.PI / 360;
        this.x += distanceMm * Math.cos(middle);
        this.y += distanceMm * Math.sin(middle);
        this.heading += angleDeg * Math.PI / 180;
    }

    value() {
        const heading = Math.atan2(Math.sin(this.heading), Math.cos(this.heading)) * 180 / Math.PI;
        return { x_mm: Math.round(this.x * 10) / 10, y_mm: Math.round(this.y * 10) / 10,
                 heading_deg: Math.round(heading * 100) / 100 };
    }
}

const NOTE = /^([A-Ga-g])([#b]?)(-?\d)$/;
const SEMITONES = { c: 0, d: 2, e: 4, f: 5, g: 7, a: 9, b: 11 };
const MAX_NOTES = 16; // one song slot

function noteNumber(text) {
    if (['rest', 'r'].includes(text.toLowerCase()))
        return 0;
    if (/^\d+$/.test(text)) {
        const n = parseInt(text, 10);
        return n <= 255 ? n : null;
    }
    const m = NOTE.exec(text);
    if (!m)
        return null;
    const n = 12 * (parseInt(m[3], 10) + 1) + SEMITONES[m[1].toLowerCase()] + ({ '#': 1, b: -1, '': 0 })[m[2]];
    return n >= 0 && n <= 127 ? n : null;
}

const repr = s => `'${s}'`;

// [note, duration, ...]; a ValueError names the note at fault, in song.py's words.
export function parseSong(text) {
    if (typeof text !== 'string')
        throw new ValueError('play() takes the song as text, like "C4:16 E4:16 G4:32"');
    const words = text.trim().split(/[\s,]+/).filter(Boolean);
    if (!words.length)
        throw new ValueError('play() needs at least one note, like "C4:16"');
    if (words.length > MAX_NOTES)
        throw new ValueError(`a song holds at most ${MAX_NOTES} notes, not ${words.length}: play it in parts`);
    const data = [];
    words.forEach((word, i) => {
        const colon = word.indexOf(':');
        const note = colon < 0 ? word : word.slice(0, colon), duration = colon < 0 ? '' : word.slice(colon + 1);
        const n = noteNumber(note);
        if (n === null)
            throw new ValueError(`note ${i + 1}, ${repr(word)}: ${repr(note)} is not a note (write C4, C#4, Db4, a number or rest)`);
        if (!/^\d+$/.test(duration) || parseInt(duration, 10) < 1 || parseInt(duration, 10) > 255)
            throw new ValueError(`note ${i + 1}, ${repr(word)}: the duration must be a number from 1 to 255 (64 is one second), like C4:16`);
        data.push(n, parseInt(duration, 10));
    });
    return data;
}
