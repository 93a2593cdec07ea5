// SPDX-License-Identifier: GPL-3.0-or-later
// The classroom protocol's table as the hub sends it (signed-in.protocol),
// read as python/roomba/protocol.py reads classroom_protocol.json: a table
// that is missing or wrong is an error, never a default.

export class TableError extends Error {}

export class ProtocolTable {
    constructor(table) {
        try {
            this.figures = Object.fromEntries(
                Object.entries(table.figures).map(([key, row]) => [key, number(row.value, key)]));
            this.goals = Object.fromEntries(table.goal_commands.map(row => [row.command, Object.fromEntries(
                row.fields.map(f => [f.field, [number(f.min, f.field), number(f.max, f.field), String(f.unit)]]))]));
            this.controlLost = new Set(table.stop_reasons.filter(row => row.frees_control).map(row => row.stop));
        } catch (e) {
            throw new TableError(`the classroom protocol's table from the hub cannot be read: ${e.message}`);
        }
    }

    figure(key) {
        if (!(key in this.figures))
            throw new TableError(`the classroom protocol's table has no figure "${key}"`);
        return this.figures[key];
    }

    // [low, high, unit] of a goal command's field.
    goalRange(command, field) {
        const range = this.goals[command]?.[field];
        if (!range)
            throw new TableError(`the classroom protocol's table has no ${command} field "${field}"`);
        return range;
    }
}

function number(value, what) {
    const n = Number(value);
    if (typeof value !== 'number' || !Number.isFinite(n))
        throw new Error(`${what} is not a number`);
    return n;
}
