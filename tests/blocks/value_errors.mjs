// SPDX-License-Identifier: GPL-3.0-or-later
// The page's Robot (web/blocks/robot.js) on values the library refuses,
// and its moves' planned times: one line each, as value_errors.py prints
// them for the library's Robot.   node value_errors.mjs WEB_DIR PROTOCOL_JSON
import { readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const [webDir, protocol] = process.argv.slice(2).map(p => resolve(p));
const load = name => import(pathToFileURL(join(webDir, name)).href);
const { parseSong } = await load('sensors.js');
const { Robot } = await load('robot.js');
const { ProtocolTable } = await load('table.js');
const json = JSON.parse(readFileSync(protocol, 'utf8'));
const table = new ProtocolTable(json);
// Nothing is sent: each value is refused before the robot is asked.
const hub = { signedIn: true, listen: () => () => {}, subscribe() {}, publish() {} };
const robot = new Robot(hub, 'r1', 'alice', table);
const calls = [() => parseSong('C4:16 X9:3'), () => parseSong('C4'), () => parseSong(''), () => robot.straight(20000),
    () => robot.straight(100, 600), () => robot.turn(90, 5), () => robot.arc(100, 90, 400), () => robot.arc(20, 90),
    () => robot.drive(400, 100), () => robot.drive(600), () => robot.digits('HELLO'),
    () => robot.leds(false, false, false, false, 300, 0), () => robot.wait(-1)];
for (const call of calls) {
    try {
        await call();
        console.log('accepted');
    } catch (e) {
        console.log(`${e.name}: ${e.message}`);
    }
}
for (const example of json.move_time_examples)
    console.log(`${example.command} ${robot.kinematicSeconds(example.command, example.fields).toFixed(4)}`);
