// SPDX-License-Identifier: GPL-3.0-or-later
// The blocks page: sign in to the classroom hub, choose a robot, program it
// with blocks, see the Python they make, run them and watch its sensors.

import { defineBlocks, rangeTooltips, rangeWarnings, toolbox } from './blocks.js';
import { Hub } from './hub.js';
import { makePythonGenerator, pythonProgram } from './python.js';
import { Robot } from './robot.js';
import { Runner } from './runner.js';
import { ProtocolTable } from './table.js';

const $ = id => document.getElementById(id);
const { Blockly, python } = window;
const page = { hub: null, user: null, robot: null, workspace: null, runner: null, table: null, toPython: null };
window.blocksPage = page; // for the page's own tests

function say(text, kind = '') {
    $('status').textContent = text;
    $('status').className = kind;
}

function start() {
    if (!Blockly || !python) {
        say('Blockly is missing: the page was built without it (npm could not fetch it). Ask your teacher to '
            + 'build the dashboard again with the network reachable.', 'problem');
        $('sign-in').hidden = true;
        return;
    }
    const fromLink = new URLSearchParams(location.hash.slice(1)).get('user');
    if (fromLink) {
        $('user').value = fromLink;
        $('password').focus();
    }
    const url = `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/hub`;
    page.hub = new Hub(url, { signedIn, refused, error: why => say(`The hub: ${why}`, 'problem'), closed });
    page.hub.open();
    $('sign-in').addEventListener('submit', event => {
        event.preventDefault();
        $('sign-in-error').textContent = '';
        page.user = $('user').value.trim();
        page.hub.signIn(page.user, $('password').value);
    });
    $('run').addEventListener('click', run);
    $('stop').addEventListener('click', () => page.robot?.stopButton());
    $('download').addEventListener('click', download);
    $('robot').addEventListener('change', () => chooseRobot($('robot').value));
}

function refused(why) {
    $('sign-in-error').textContent = `Not signed in: ${why}`;
}

function closed(why) {
    say(`${why[0].toUpperCase()}${why.slice(1)}. Reload the page to sign in again.`, 'problem');
    $('run').disabled = true;
}

function signedIn(m) {
    page.user = m.user;
    try {
        page.table = new ProtocolTable(m.protocol);
    } catch (e) {
        say(`The hub's protocol table: ${e.message}`, 'problem');
        return;
    }
    $('sign-in').hidden = true;
    $('work').hidden = false;
    $('who').textContent = `Signed in as ${m.user}`;
    if (!page.workspace)
        makeWorkspace(m.blocks || []);
    const robots = m.robots || [];
    $('robot').replaceChildren(...robots.map(name => new Option(name, name)));
    $('robot-label').hidden = false;
    if (!robots.length) {
        say('Your account drives no robot: ask your teacher.', 'problem');
        return;
    }
    chooseRobot(robots[0]);
    say('Signed in. Put blocks together, then press Run.');
}

function makeWorkspace(sets) {
    defineBlocks(Blockly);
    rangeTooltips(Blockly, page.table);
    page.workspace = Blockly.inject($('workspace'), {
        toolbox: toolbox(sets), media: 'node_modules/blockly/media/', trashcan: true, sounds: false,
        zoom: { controls: true, wheel: true, startScale: innerWidth >= 1800 ? 1.35 : 1.0 }, grid: { spacing: 24, length: 3, colour: '#ddd' },
        renderer: 'zelos',
    });
    page.toPython = makePythonGenerator(Blockly, python);
    page.runner = new Runner(page.workspace);
    const saved = localStorage.getItem(storageKey());
    if (saved) {
        try {
            Blockly.serialization.workspaces.load(JSON.parse(saved), page.workspace);
        } catch {
            say('Your saved blocks could not be read; you start with none.', 'problem');
        }
    }
    page.workspace.addChangeListener(event => {
        if (event.isUiEvent)
            return;
        showPython();
        rangeWarnings(page.workspace, page.table);
        localStorage.setItem(storageKey(), JSON.stringify(Blockly.serialization.workspaces.save(page.workspace)));
    });
    showPython();
    $('download').disabled = false;
}

const storageKey = () => `roomba-blocks:${page.user}`;

function showPython() {
    $('python').textContent = pythonProgram(page.toPython, page.workspace);
}

function chooseRobot(name) {
    if (page.robot?.name === name)
        return;
    page.robot?.forget();
    page.robot = new Robot(page.hub, name, page.user, page.table);
    page.robot.onChange = showSensorsSoon;
    $('robot').value = name;
    $('sensor-robot').textContent = name;
    $('run').disabled = false;
}

// Ten times a second is enough to read, and leaves the machine to the program.
const SENSOR_VIEW_MS = 100;
let drawing = false;
function showSensorsSoon(robot) {
    if (drawing)
        return;
    drawing = true;
    setTimeout(() => requestAnimationFrame(() => {
        drawing = false;
        showSensors(robot);
    }), SENSOR_VIEW_MS);
}

const yes = (on, word) => on ? `<span class="on">${word}</span>` : '';
const sides = (reading, names) => names.filter(([key]) => reading[key]).map(([, word]) => yes(true, word)).join(' ') || 'none';

function showSensors(robot) {
    const p = robot.packets, state = robot.state || {};
    const bits = p.bumps_wheel_drops || 0;
    $('s-bumper').innerHTML = sides({ l: bits & 2, r: bits & 1 }, [['l', 'left'], ['r', 'right']]);
    $('s-cliff').innerHTML = sides(p, [['cliff_left', 'left'], ['cliff_front_left', 'front left'],
                                       ['cliff_front_right', 'front right'], ['cliff_right', 'right']]);
    $('s-wheel').innerHTML = sides({ l: bits & 8, r: bits & 4, c: bits & 16 }, [['l', 'left'], ['r', 'right'], ['c', 'front']]);
    $('s-wall').innerHTML = p.wall ? yes(true, 'a wall on the right') : 'none';
    $('s-light').innerHTML = 'light_bumper' in p
        ? sides(Object.fromEntries([0, 1, 2, 3, 4, 5].map(i => [i, p.light_bumper & (1 << i)])),
                [[0, 'left'], [1, 'front left'], [2, 'centre left'], [3, 'centre right'], [4, 'front right'], [5, 'right']])
        : 'this robot has none';
    const percent = p.battery_charge != null && p.battery_capacity ? 100 * p.battery_charge / p.battery_capacity
        : state.battery_percent;
    $('s-battery').textContent = percent != null
        ? `${percent.toFixed(0)} %${p.voltage ? `, ${(p.voltage / 1000).toFixed(1)} V` : ''}` : 'unknown';
    const pose = robot.odometrySum.value();
    $('s-pose').textContent = `${pose.x_mm.toFixed(0)}, ${pose.y_mm.toFixed(0)} mm, ${pose.heading_deg.toFixed(0)}°`;
    $('s-state').textContent = !state.online ? 'offline'
        : `${state.mode || 'online'}${state.controller ? `, driven by ${state.controller}` : ''}`;
}

async function run() {
    const robot = page.robot;
    const program = pythonProgram(page.toPython, page.workspace);
    $('run').disabled = true;
    $('stop').disabled = false;
    $('robot').disabled = true;
    say(`Running on ${robot.name}…`, 'running');
    page.hub.send({ op: 'running', robot: robot.name, program });
    const ended = await page.runner.run(robot);
    page.hub.send({ op: 'ended', robot: robot.name, why: ended ? ended.words : 'finished' });
    page.lastEnd = ended;
    page.runs = (page.runs || 0) + 1;
    say(ended ? ended.words : `Your program finished on ${robot.name}.`, ended ? 'problem' : '');
    $('run').disabled = false;
    $('stop').disabled = true;
    $('robot').disabled = false;
}

function download() {
    const link = document.createElement('a');
    link.href = URL.createObjectURL(new Blob([pythonProgram(page.toPython, page.workspace)], { type: 'text/x-python' }));
    link.download = 'blocks.py';
    link.click();
    URL.revokeObjectURL(link.href);
}

start();
