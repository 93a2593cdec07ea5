// SPDX-License-Identifier: GPL-3.0-or-later
// The blocks page in Debian's Chromium, driven by playwright-core:
//   node page_check.js SCENARIO URL key=value...
// SCENARIO: "square" (sign in from the link, load programs/square.json, run
// it, print the pose the page read at its end as JSON), "stop-all" (run a
// long program; the test sends Stop all once this prints "running"; print
// the words on the block and the status line), "stop-button" (the same,
// the page's own Stop button pressed), "toolbox" (the categories shown),
// "screenshots" (out=DIR).
'use strict';
const { chromium } = require('playwright-core');
const fs = require('fs');
const path = require('path');

const [scenario, url, ...rest] = process.argv.slice(2);
const options = Object.fromEntries(rest.map(a => [a.slice(0, a.indexOf('=')), a.slice(a.indexOf('=') + 1)]));
const say = object => process.stdout.write(JSON.stringify(object) + '\n');

async function signIn(page) {
    await page.goto(`${url}/#user=${options.user}`);
    await page.fill('#password', options.password);
    await page.click('#sign-in button[type=submit]');
    await page.waitForSelector('#work:not([hidden])', { timeout: 30000 });
    await page.waitForFunction(() => window.blocksPage.robot?.keyFrameSeen, null, { timeout: 30000 });
}

async function load(page, file) {
    const program = JSON.parse(fs.readFileSync(file, 'utf8'));
    await page.evaluate(p => window.Blockly.serialization.workspaces.load(p, window.blocksPage.workspace), program);
}

async function runToEnd(page, timeout) {
    const before = await page.evaluate(() => window.blocksPage.runs || 0);
    await page.click('#run');
    await page.waitForFunction(n => (window.blocksPage.runs || 0) > n, before, { timeout });
    return page.evaluate(() => window.blocksPage.lastEnd);
}

async function main() {
    const browser = await chromium.launch({ executablePath: '/usr/bin/chromium',
        args: ['--no-sandbox', '--headless=new', '--disable-gpu'] });
    const size = { width: 1366, height: 768 };
    const context = await browser.newContext({ viewport: size, ignoreHTTPSErrors: true });
    const page = await context.newPage();
    const problems = [];
    page.on('pageerror', e => problems.push(e.message));
    page.on('console', m => m.type() === 'error' && problems.push(m.text()));
    try {
        if (scenario === 'square') {
            await signIn(page);
            await load(page, options.program);
            const python = await page.textContent('#python');
            const ended = await runToEnd(page, 50000);
            const pose = await page.evaluate(() => window.blocksPage.robot.odometrySum.value());
            say({ ended, pose, python, problems });
        } else if (scenario === 'stop-all' || scenario === 'stop-button') {
            await signIn(page);
            await load(page, options.program);
            await page.click('#run');
            // Moving: the robot holds control for this program.
            await page.waitForFunction(() => window.blocksPage.robot.moving, null, { timeout: 30000 });
            say({ running: true });
            if (scenario === 'stop-button')
                await page.click('#stop');
            await page.waitForFunction(() => !window.blocksPage.runner.running, null, { timeout: 30000 });
            const shown = await page.evaluate(() => {
                const { lastEnd, workspace } = window.blocksPage;
                const block = lastEnd && workspace.getBlockById(lastEnd.blockId);
                // A bubble's lines, joined as the words were before they were wrapped.
                const bubbles = [...document.querySelectorAll('.blocklyBubble')].map(b => {
                    const lines = [...b.querySelectorAll('text')].map(t => t.textContent);
                    return lines.length ? lines.join(' ') : b.textContent;
                });
                return { lastEnd, blockType: block?.type, bubbles,
                         status: document.getElementById('status').textContent };
            });
            if (options.out && scenario === 'stop-all')
                await page.screenshot({ path: path.join(options.out, 'blocks-stopped.png') });
            say({ ...shown, problems });
        } else if (scenario === 'toolbox') {
            await signIn(page);
            const categories = await page.evaluate(() =>
                window.blocksPage.workspace.getToolbox().getToolboxItems().map(item => item.getName?.()).filter(Boolean));
            say({ categories, problems });
        } else if (scenario === 'screenshots') {
            // A page opened at each size, as a laptop and a projector open it.
            for (const [width, height] of [[1280, 720], [1920, 1080]]) {
                const sized = await context.newPage();
                sized.on('pageerror', e => problems.push(e.message));
                await sized.setViewportSize({ width, height });
                await signIn(sized);
                await load(sized, options.program);
                await sized.waitForTimeout(300); // the sensors view draws at the next frame
                await sized.screenshot({ path: path.join(options.out, `blocks-${width}x${height}.png`) });
                await sized.close();
            }
            say({ problems });
        } else {
            throw new Error(`no scenario ${scenario}`);
        }
    } catch (e) {
        const status = await page.textContent('#status').catch(() => '(no page)');
        throw new Error(`${e.message}\nthe page said: ${status}\nerrors: ${problems.join('; ')}`);
    } finally {
        await browser.close();
    }
}

main().catch(e => {
    process.stderr.write(`${e.stack || e}\n`);
    process.exit(1);
});
