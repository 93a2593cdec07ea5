// SPDX-License-Identifier: GPL-3.0-or-later
// The same blocks as JavaScript for the page's runtime (robot.js): each
// block's call awaited, and before each statement a step that shows the
// block running and raises a stop waiting for the program.

import { SENSORS, STATEMENTS } from './calls.js';

// javascript: Blockly's javascript generator module ({ JavascriptGenerator, javascriptGenerator, Order }).
export function makeJavascriptGenerator(javascript) {
    const { Order } = javascript;
    const generator = new javascript.JavascriptGenerator('JavaScript');
    Object.assign(generator.forBlock, javascript.javascriptGenerator.forBlock);
    generator.addReservedWords('robot,step,tick');
    generator.STATEMENT_PREFIX = 'await step(%1);\n';
    // A loop of the student's own lets the page breathe (and a stop in) each time round.
    generator.INFINITE_LOOP_TRAP = 'await tick();\n';

    const argument = (block, arg) => {
        if (arg.value)
            return generator.valueToCode(block, arg.value, Order.NONE) || '0';
        if (arg.flag)
            return block.getFieldValue(arg.flag) === 'TRUE' ? 'true' : 'false';
        if (arg.text)
            return generator.quote_(block.getFieldValue(arg.text));
        return `async () => (${generator.valueToCode(block, arg.condition, Order.NONE) || 'false'})`;
    };
    for (const [type, call] of Object.entries(STATEMENTS)) {
        generator.forBlock[type] = block => {
            const [name, args] = call(block);
            return `await robot.${name}(${args.map(a => argument(block, a)).join(', ')});\n`;
        };
    }
    for (const [type, sensor] of Object.entries(SENSORS)) {
        generator.forBlock[type] = block => {
            const [property, member] = sensor(block);
            return [member ? `(await robot.${property}()).${member}` : `(await robot.${property}())`, Order.MEMBER];
        };
    }
    return generator;
}
