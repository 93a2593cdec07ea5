// SPDX-License-Identifier: GPL-3.0-or-later
// Runs a block program on a Robot (robot.js): the block that runs is
// highlighted, and whatever ends the program (a stop of the bridge's, the
// Stop button, a value out of range) is shown on that block in the library's
// words, as Python prints it ("Stopped: Stop all: your teacher ...").

import { StopButton } from './errors.js';
import { BlockError, Interpreter, knows } from './interpreter.js';

// How many steps run before the page is given time to draw and hear the hub.
const STEPS_PER_BREATH = 25;

// A block's bubble does not wrap its text: lines of a readable length.
function wrapped(words, width = 56) {
    const lines = [''];
    for (const word of words.split(' ')) {
        if (lines.at(-1) && lines.at(-1).length + word.length + 1 > width)
            lines.push('');
        lines[lines.length - 1] += (lines.at(-1) ? ' ' : '') + word;
    }
    return lines.join('\n');
}

const breath = () => new Promise(resolve => setTimeout(resolve, 0));

export class Runner {
    constructor(workspace) {
        this.workspace = workspace;
        this.running = false;
        this.blockId = null;
    }

    // Runs the workspace's program on robot; returns null when it finished, or
    // { words, blockId } for what ended it.
    async run(robot) {
        let steps = 0;
        const step = async block => {
            this.blockId = block.id;
            this.workspace.highlightBlock(block.id);
            robot.checkPending();
            if (++steps % STEPS_PER_BREATH === 0)
                await breath();
        };
        this.running = true;
        this.blockId = null;
        this.clearWords();
        try {
            const unknown = this.workspace.getAllBlocks(false).find(b => !knows(b.type));
            if (unknown) {
                this.blockId = unknown.id;
                throw new BlockError(`the page cannot run a "${unknown.type}" block`);
            }
            await robot.start();
            await new Interpreter(robot, step).runWorkspace(this.workspace);
            return null;
        } catch (e) {
            // As Python prints them: Ctrl-C's words alone, an exception's after its name.
            const words = e instanceof StopButton ? e.message : `${e.name}: ${e.message}`;
            this.showWords(this.blockId, words);
            return { words, blockId: this.blockId };
        } finally {
            robot.close();
            this.running = false;
            this.workspace.highlightBlock(null);
        }
    }

    showWords(blockId, words) {
        const block = blockId && this.workspace.getBlockById(blockId);
        if (!block)
            return;
        block.setWarningText(wrapped(words), 'run');
        block.select();
        const icon = block.getIcon?.(window.Blockly.icons.IconType.WARNING);
        icon?.setBubbleVisible?.(true);
        this.shownOn = block;
    }

    clearWords() {
        if (this.shownOn && !this.shownOn.isDisposed())
            this.shownOn.setWarningText(null, 'run');
        this.shownOn = null;
    }
}
