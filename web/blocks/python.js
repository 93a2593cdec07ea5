// SPDX-License-Identifier: GPL-3.0-or-later
// The Python a block program is: a file that runs unchanged with
// `python3 -m roomba.practice FILE.py` at home or as it is in class.

import { SENSORS, STATEMENTS } from './calls.js';

export const HEADER = '# Made with blocks. At home: python3 -m roomba.practice FILE.py\n'
    + 'from roomba import Robot\n';

// A Python generator for the blocks: Blockly's own for the standard blocks.
// python: Blockly's python generator module ({ PythonGenerator, pythonGenerator, Order }).
export function makePythonGenerator(Blockly, python) {
    const { Order } = python;

    class ProgramPython extends python.PythonGenerator {
        constructor() {
            super('Python');
            Object.assign(this.forBlock, python.pythonGenerator.forBlock);
            this.INDENT = '    ';
            this.addReservedWords('robot,Robot,roomba');
        }

        // The whole file: imports, variables, then the program inside
        // `with Robot() as robot:`, so that the robot stops at its end.
        finish(code) {
            const imports = [], definitions = [];
            for (const d of Object.values(this.definitions_).filter(d => d.trim()))
                (/^(from\s+\S+\s+)?import\s+\S+/.test(d) ? imports : definitions).push(d);
            Blockly.CodeGenerator.prototype.finish.call(this, code);
            this.isInitialized = false;
            this.nameDB_.reset();
            const body = code.trim() ? this.prefixLines(code.replace(/\n+$/, ''), this.INDENT) : this.INDENT + 'pass';
            const variables = definitions.length ? definitions.join('\n') + '\n\n' : '';
            return `${HEADER}${imports.map(i => i + '\n').join('')}\n${variables}with Robot() as robot:\n${body}\n`;
        }
    }

    const generator = new ProgramPython();
    const argument = (block, arg) => {
        let code;
        if (arg.value)
            code = generator.valueToCode(block, arg.value, Order.NONE) || '0';
        else if (arg.flag)
            code = block.getFieldValue(arg.flag) === 'TRUE' ? 'True' : 'False';
        else if (arg.text)
            code = generator.quote_(block.getFieldValue(arg.text));
        else
            code = 'lambda: ' + (generator.valueToCode(block, arg.condition, Order.LAMBDA) || 'False');
        return arg.keyword ? `${arg.keyword}=${code}` : code;
    };
    for (const [type, call] of Object.entries(STATEMENTS)) {
        generator.forBlock[type] = block => {
            const [name, args] = call(block);
            return `robot.${name}(${args.map(a => argument(block, a)).join(', ')})\n`;
        };
    }
    for (const [type, sensor] of Object.entries(SENSORS)) {
        generator.forBlock[type] = block => {
            const [property, member] = sensor(block);
            return [member ? `robot.${property}.${member}` : `robot.${property}`, Order.MEMBER];
        };
    }
    return generator;
}

// The file for a workspace, ending in a newline.
export function pythonProgram(generator, workspace) {
    return generator.workspaceToCode(workspace).replace(/\n*$/, '\n');
}
