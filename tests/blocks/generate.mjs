// SPDX-License-Identifier: GPL-3.0-or-later
// The page's generators in node, with Blockly's headless workspace:
//   node generate.mjs WEB_DIR OUT_DIR PROGRAM.json...
// writes OUT_DIR/PROGRAM.py, the Python the page shows for each block
// program, and checks that the page's interpreter knows each of its blocks.

import { createRequire } from 'node:module';
import { readFileSync, writeFileSync } from 'node:fs';
import { basename, join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const [webDir, outDir, ...programs] = process.argv.slice(2).map(p => resolve(p));
const require = createRequire(join(webDir, 'package.json'));
const Blockly = require('blockly');
const python = require('blockly/python');
const load = name => import(pathToFileURL(join(webDir, name)).href);
const { defineBlocks } = await load('blocks.js');
const { makePythonGenerator, pythonProgram } = await load('python.js');
const { knows } = await load('interpreter.js');

defineBlocks(Blockly);
const toPython = makePythonGenerator(Blockly, python);
let failed = 0;
for (const program of programs) {
    const workspace = new Blockly.Workspace();
    try {
        Blockly.serialization.workspaces.load(JSON.parse(readFileSync(program, 'utf8')), workspace);
        const unknown = workspace.getAllBlocks(false).filter(b => !knows(b.type));
        if (unknown.length)
            throw new Error(`the page cannot run ${unknown.map(b => b.type).join(', ')}`);
        writeFileSync(join(outDir, basename(program, '.json') + '.py'), pythonProgram(toPython, workspace));
    } catch (e) {
        console.error(`${program}: ${e.message}`);
        failed++;
    }
    workspace.dispose();
}
process.exit(failed ? 1 : 0);
