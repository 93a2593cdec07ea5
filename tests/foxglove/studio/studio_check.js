// SPDX-License-Identifier: GPL-3.0-or-later
// Foxglove Studio 1.48, the app @foxglove/studio-base ships prebuilt, in
// Debian's Chromium (playwright-core), against the live data server of a
// bridge or of the dashboard, and on an MCAP export over HTTP:
//   node studio_check.js SCENARIO DIR key=value...
// SCENARIO: bridge (live, then the same recording's MCAP) or dashboard.
// With STUDIO_DEBUG=1 in the environment, the page's console is printed too.
// Keys: layout, artefacts (where the screenshots go), bridge, dashboard,
// ctl, mosquitto (the programs). Everything listens on 127.0.0.1 only.
// Prints what it found as JSON, each failure on standard error; exits 1 on any.
"use strict";
const { chromium } = require("playwright-core");
const kLeastRate = 30; // telemetry messages a second per robot, as Studio counts them
const { spawn, execFileSync } = require("child_process");
const fs = require("fs");
const http = require("http");
const net = require("net");
const path = require("path");

const [scenario, dir, ...pairs] = process.argv.slice(2);
const arg = Object.fromEntries(pairs.map((p) => [p.slice(0, p.indexOf("=")), p.slice(p.indexOf("=") + 1)]));
const failures = [];
function check(ok, what) {
  if (!ok) failures.push(what);
  return ok;
}
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const started = Date.now();
const elapsed = () => ((Date.now() - started) / 1000).toFixed(1);

async function until(condition, ms, what, pollMs = 100) {
  const end = Date.now() + ms;
  for (;;) {
    const value = await condition();
    if (value) return value;
    if (Date.now() > end) throw new Error(`${what} did not happen within ${ms} ms`);
    await sleep(pollMs);
  }
}

function freePort() {
  return new Promise((resolve, reject) => {
    const s = net.createServer();
    s.on("error", reject);
    s.listen(0, "127.0.0.1", () => {
      const { port } = s.address();
      s.close(() => resolve(port));
    });
  });
}

// Whether something accepts connections on the port.
function accepts(port) {
  return new Promise((resolve) => {
    const socket = net.connect(port, "127.0.0.1");
    socket.on("connect", () => (socket.end(), resolve(true)));
    socket.on("error", () => resolve(false));
  });
}

// A program of ours, its output kept; ended with the test.
const children = [];
function start(program, args, env = {}) {
  const child = spawn(program, args, { env: { ...process.env, ...env }, stdio: ["ignore", "pipe", "pipe"] });
  const run = { child, log: "", exited: null };
  child.stdout.on("data", (d) => (run.log += d));
  child.stderr.on("data", (d) => (run.log += d));
  run.done = new Promise((resolve) => child.on("exit", (code, signal) => resolve((run.exited = { code, signal }))));
  children.push(run);
  return run;
}
async function stop(run) {
  if (run.exited) return run.exited;
  run.child.kill("SIGCONT");
  run.child.kill("SIGTERM");
  const timer = setTimeout(() => run.child.kill("SIGKILL"), 15000);
  const exited = await run.done;
  clearTimeout(timer);
  return exited;
}
process.on("exit", () => children.forEach((c) => c.exited || c.child.kill("SIGKILL")));

// The page, the app's files, the layout and the recordings, over HTTP on
// loopback. Ranges are served: Studio's remote file source reads an MCAP
// by its summary and chunks.
const here = __dirname;
const served = new Map(); // URL path -> file
let layoutJson = "{}"; // the layout of the next page opened
function serveFiles() {
  const types = { ".js": "text/javascript", ".html": "text/html", ".json": "application/json", ".wasm": "application/wasm",
    ".css": "text/css", ".png": "image/png", ".ttf": "font/ttf", ".woff2": "font/woff2", ".svg": "image/svg+xml" };
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, "http://127.0.0.1");
    if (url.pathname === "/layout.json") {
      res.writeHead(200, { "content-type": "application/json" });
      return res.end(layoutJson);
    }
    let file = served.get(url.pathname);
    if (!file && url.pathname === "/") file = path.join(here, "index.html");
    if (!file && url.pathname === "/studio_page.js") file = path.join(here, "studio_page.js");
    if (!file && /^\/node_modules\/(react|react-dom|@foxglove\/studio-base)\//.test(url.pathname) && !url.pathname.includes(".."))
      file = path.join(here, decodeURIComponent(url.pathname));
    let stat;
    try {
      stat = fs.statSync(file);
    } catch {
      res.writeHead(404);
      return res.end();
    }
    const headers = { "content-type": types[path.extname(file)] ?? "application/octet-stream", "accept-ranges": "bytes" };
    const range = /^bytes=(\d+)-(\d*)$/.exec(req.headers.range ?? "");
    if (range) {
      const from = Number(range[1]), to = range[2] ? Math.min(Number(range[2]), stat.size - 1) : stat.size - 1;
      res.writeHead(206, { ...headers, "content-range": `bytes ${from}-${to}/${stat.size}`, "content-length": to - from + 1 });
      fs.createReadStream(file, { start: from, end: to }).pipe(res);
    } else {
      res.writeHead(200, { ...headers, "content-length": stat.size });
      fs.createReadStream(file).pipe(res);
    }
  });
  return new Promise((resolve) => server.listen(0, "127.0.0.1", () => resolve({ server, origin: `http://127.0.0.1:${server.address().port}` })));
}

// The shipped layout as Studio gets it live, with more lines in the battery
// plot: the ROS 2 twin's voltage, decoded by Studio from CDR.
// plot: the ROS 2 twin's voltage, decoded by Studio from CDR, and each other
// robot's voltage, so that Studio subscribes to its telemetry.
function layoutForStudio(robots) {
  const layout = JSON.parse(fs.readFileSync(arg.layout, "utf8"));
  const battery = layout.configById["Plot!battery"];
  const voltage = battery.paths.find((p) => p.value === "/r1/telemetry.voltage");
  battery.paths.push({ ...voltage, value: "/r1/telemetry_ros2.voltage", label: "voltage (ROS 2)" });
  for (const r of robots.slice(1)) battery.paths.push({ ...voltage, value: `/${r}/telemetry.voltage`, label: `${r} voltage` });
  return JSON.stringify(layout);
}

let browser;
async function launchBrowser() {
  browser = await chromium.launch({
    executablePath: "/usr/bin/chromium",
    headless: true,
    args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
      "--disable-component-update", "--disable-sync"],
  });
  return browser;
}

// A page of Studio on `query` (its deep link: the data source and layout).
// Nothing leaves loopback: any other request is refused and counted.
async function openStudio(origin, query) {
  const context = await browser.newContext({ viewport: { width: 1280, height: 720 } });
  const page = await context.newPage();
  const seen = { pageErrors: [], outside: [] };
  await context.route((url) => !/^(http|ws):\/\/127\.0\.0\.1[:/]/.test(url.href) && !url.href.startsWith("blob:") && !url.href.startsWith("data:"),
    (route) => {
      seen.outside.push(route.request().url());
      return route.abort();
    });
  page.on("pageerror", (e) => seen.pageErrors.push(String(e).slice(0, 300)));
  if (process.env.STUDIO_DEBUG) {
    page.on("console", (m) => console.error("console", m.type(), m.text().slice(0, 200)));
    page.on("response", (r) => r.status() >= 400 && console.error("status", r.status(), r.url()));
  }
  await page.goto(`${origin}/?${query}&layoutId=roomba-r1`);
  await until(() => page.evaluate(() => window.studioPageError ?? document.querySelector('[data-testid="ErrorIcon"], .MuiTabs-root, [data-topic]') !== null),
    120000, "Studio's first render");
  const pageError = await page.evaluate(() => window.studioPageError);
  if (pageError) throw new Error(`the page did not render Studio: ${pageError}`);
  return { page, seen };
}

// The channels the server advertises, as a plain WebSocket client in the
// browser hears them: until none is added for 1.5 s.
async function advertisedTopics(page, url) {
  return page.evaluate(async (url) => {
    const topics = new Set();
    let last = Date.now();
    const ws = new WebSocket(url, ["foxglove.websocket.v1"]);
    ws.onmessage = (e) => {
      if (typeof e.data !== "string") return;
      const m = JSON.parse(e.data);
      if (m.op === "advertise") for (const c of m.channels) topics.add(c.topic), (last = Date.now());
    };
    await new Promise((resolve, reject) => ((ws.onopen = resolve), (ws.onerror = () => reject(new Error(`cannot connect to ${url}`)))));
    while (topics.size === 0 || Date.now() - last < 1500) await new Promise((r) => setTimeout(r, 100));
    ws.close();
    return [...topics].sort();
  }, url);
}

// What Studio shows: the topic list (name, count, rate) of the data source
// sidebar, the battery plot's legend (label and value), its start time and
// duration. Read in one go, so they belong together.
function readStudio(page) {
  return page.evaluate(() => {
    const topics = {};
    for (const el of document.querySelectorAll("[data-topic][data-topic-stat]")) {
      topics[el.dataset.topic] ??= {};
      topics[el.dataset.topic][el.dataset.topicStat] = el.innerText;
    }
    // The legend rows of the battery plot: a label, then its value.
    const legend = {};
    const panel = document.querySelector('[data-testid="panel-mouseenter-container Plot!battery"]');
    for (const name of panel ? panel.querySelectorAll('[class*="-plotName"]') : []) {
      const value = name.nextElementSibling;
      if (value && value.className.includes("-plotValue")) legend[name.innerText.trim()] = value.innerText.trim();
    }
    const overline = (text) => {
      const el = [...document.querySelectorAll(".MuiTypography-overline")].find((e) => e.textContent === text);
      return el?.parentElement?.innerText.slice(text.length).trim().split(/\s+/).at(-1);
    };
    // A file: the playback time, and how much of the file is loaded (the
    // ranges on the timeline, as fractions of it).
    const playback = document.querySelector('[data-testid="PlaybackTime-text"] input')?.value;
    const loaded = [...document.querySelectorAll('[class*="-range"]')].filter((el) => el.style.left && el.style.width)
      .map((el) => [parseFloat(el.style.left) / 100, (parseFloat(el.style.left) + parseFloat(el.style.width)) / 100]);
    return { topics, legend, start: overline("Start time"), duration: overline("Duration"), end: overline("End time"), playback, loaded };
  });
}

// The recording's CSV (roomba-ctl csv) with each row's wall time in ms:
// the header's `started` plus the row's time_s.
function readRecording(oirec) {
  const bytes = fs.readFileSync(oirec);
  const header = JSON.parse(bytes.subarray(14, 14 + bytes.readUInt32LE(10)).toString("utf8"));
  const startedMs = Date.parse(header.started);
  const text = execFileSync(arg.ctl, ["csv", oirec], { maxBuffer: 1 << 28 }).toString();
  const [first, ...lines] = text.trim().split("\n");
  const columns = first.split(",").map((c) => c.replace(/\[.*\]$/, ""));
  const rows = lines.map((line) => {
    const cells = line.split(",");
    const row = Object.fromEntries(columns.map((c, i) => [c, cells[i]]));
    row.wallMs = startedMs + Number(row.time_s) * 1000;
    return row;
  });
  return { startedMs, rows: rows.filter((r) => r.voltage !== undefined && r.voltage !== "") };
}

// Studio's time as it shows it: the start time (seconds, to the
// nanosecond) plus the duration (h:mm:ss.mmm), in ms.
function studioTimeMs(shown) {
  const [h, m, s] = (shown.duration ?? "").split(":").map(Number);
  return Number(shown.start) * 1000 + ((h * 60 + m) * 60 + s) * 1000;
}

// Reads until two readings a second apart agree (the data has stopped).
async function settledReading(page) {
  let before = await readStudio(page);
  for (let i = 0; i < 20; i++) {
    await sleep(1000);
    const now = await readStudio(page);
    if (JSON.stringify(now.legend) === JSON.stringify(before.legend) && now.duration === before.duration) return now;
    before = now;
  }
  throw new Error(`Studio's legend did not settle: ${JSON.stringify(before.legend)}`);
}

// No panel in error: the panels' own error screen, an error icon in a plot
// legend or in any panel's settings, the data source's problems, an uncaught
// error on the page. Leaves the topic list showing.
async function panelErrors(page, seen) {
  const errors = [...seen.pageErrors.map((e) => `page error: ${e}`)];
  const crashed = await page.getByText("This panel encountered an unexpected error").count();
  if (crashed) errors.push(`${crashed} panel(s) show "This panel encountered an unexpected error"`);
  const panels = page.locator('[data-testid^="panel-mouseenter-container "]');
  for (let i = 0; i < (await panels.count()); i++) {
    const panel = panels.nth(i);
    const title = (await panel.getAttribute("data-testid")).replace("panel-mouseenter-container ", "");
    await panel.hover();
    await panel.locator('button:has([data-testid="SettingsIcon"])').first().click();
    await sleep(300);
    // Each error in its settings, by its tooltip.
    const icons = page.locator('[data-testid="ErrorIcon"]');
    for (let j = 0; j < (await icons.count()); j++) {
      await icons.nth(j).hover();
      const tip = await page.getByRole("tooltip").last().innerText({ timeout: 3000 }).catch(() => "(no tooltip)");
      errors.push(`${title}: ${tip}`);
    }
  }
  // Back to the data source sidebar, its problems tab.
  await page.locator('[data-sidebar-key="connection"]').click();
  await page.getByRole("tab", { name: /Problems/ }).click();
  const problems = await page.locator(".MuiList-root .MuiListItemText-primary").allInnerTexts();
  if (!(await page.getByText("No problems found").count())) errors.push(`the data source's problems: ${JSON.stringify(problems)}`);
  await page.getByRole("tab", { name: "Topics" }).click();
  return errors;
}

// The row nearest `atMs`, within `withinMs`, with the legend's values.
function findRow(rows, legend, atMs, withinMs) {
  const same = rows.filter((r) => Math.abs(r.wallMs - atMs) <= withinMs && r.voltage === legend.voltage
    && r.battery_charge === legend.battery_charge && r.current === legend.current);
  return same.sort((a, b) => Math.abs(a.wallMs - atMs) - Math.abs(b.wallMs - atMs))[0];
}

async function live(kind, origin) {
  const oirec = path.join(dir, `${kind}.oirec`);
  fs.chmodSync(dir, 0o755); // mosquitto, run as root, reads its config as its own user
  let program, url;
  const robots = kind === "bridge" ? ["r1"] : ["r1", "r2"];
  if (kind === "bridge") {
    const brokerPort = await freePort();
    const conf = path.join(dir, "mosquitto.conf");
    fs.writeFileSync(conf, `listener ${brokerPort} 127.0.0.1\nallow_anonymous true\npersistence false\n`, { mode: 0o644 });
    const broker = start(arg.mosquitto, ["-c", conf]);
    await until(() => accepts(brokerPort), 10000, `mosquitto on port ${brokerPort} (${broker.log})`);
    program = start(arg.bridge, ["--broker", `mqtt://127.0.0.1:${brokerPort}`, "--name", "r1", "--sim",
      "--foxglove", "127.0.0.1:0", "--record", oirec]);
    url = await until(() => /live data server on (ws:\/\/127\.0\.0\.1:\d+)/.exec(program.log)?.[1], 20000, "the bridge's live data server");
  } else {
    const port = await freePort();
    program = start(arg.dashboard, ["--sim", "2", "--foxglove", `127.0.0.1:${port}`, "--record", oirec],
      { QT_QPA_PLATFORM: "offscreen", XDG_CONFIG_HOME: path.join(dir, "config") });
    url = `ws://127.0.0.1:${port}`;
    await until(() => accepts(port), 30000, `the dashboard's live data server on ${port}`);
  }
  const summary = { url };
  layoutJson = layoutForStudio(robots);
  const { page, seen } = await openStudio(origin, `ds=foxglove-websocket&ds.url=${encodeURIComponent(url)}`);
  summary.studioOpenS = Number(elapsed());
  // Every channel advertised is listed.
  const advertised = await advertisedTopics(page, url);
  summary.advertised = advertised.length;
  for (const r of robots)
    for (const t of ["telemetry", "telemetry_ros2", "pose", "tf", "events", "markers"])
      check(advertised.includes(`/${r}/${t}`), `/${r}/${t} is not advertised: ${advertised}`);
  await until(async () => {
    const listed = (await readStudio(page)).topics;
    return advertised.every((t) => t in listed);
  }, 30000,
    `Studio listing every channel advertised (${advertised})`).catch((e) => check(false, e.message));
  // The telemetry's rate as Studio's topic list shows it: its message count,
  // watched for 12 s once it has a few seconds of it. Studio redraws the
  // count every few frames, so the rate is taken between the first and the
  // last time the count changed. Its figure in Hz, read each second
  // meanwhile, is printed beside it: a running estimate that swings with
  // Studio's own rendering.
  const telemetry = robots.map((r) => `/${r}/telemetry`);
  const countOf = (topics, t) => Number((topics[t]?.count ?? "").replace(/\D/g, "")); // "1,234"
  const changes = Object.fromEntries(telemetry.map((t) => [t, []]));
  summary.hz = Object.fromEntries(telemetry.map((t) => [t, []]));
  // Once Studio redraws the counts (three changes each; a busy machine
  // delays its first redraws), for 12 s.
  const redraws = Object.fromEntries(telemetry.map((t) => [t, new Set()]));
  await until(async () => {
    const listed = (await readStudio(page)).topics;
    telemetry.forEach((t) => redraws[t].add(countOf(listed, t)));
    return telemetry.every((t) => redraws[t].size >= 3);
  }, 30000, "Studio redrawing the telemetry's counts", 50).catch((e) => check(false, e.message));
  for (let from = Date.now(), second = 1; Date.now() - from < 12000; await sleep(50)) {
    const listed = (await readStudio(page)).topics, at = Date.now();
    for (const t of telemetry) {
      if (changes[t].at(-1)?.count !== countOf(listed, t)) changes[t].push({ at, count: countOf(listed, t) });
      if (at - from >= second * 1000) summary.hz[t].push(parseFloat(listed[t]?.frequency) || 0);
    }
    if (at - from >= second * 1000) second++;
  }
  summary.rates = {};
  for (const t of telemetry) {
    const [a, b] = [changes[t][1] ?? changes[t][0], changes[t].at(-1)]; // the first reading may be an old count
    summary.rates[t] = Number((((b.count - a.count) * 1000) / Math.max(b.at - a.at, 1)).toFixed(2));
    // 45 a second is the aim, and a quiet machine gives it (47.5 to 47.9
    // seen); a busy one, such as CI with a sanitizer build beside it, slows
    // the robot itself (the recording says how many frames it read: 55 of
    // 66.7) and the window's thread (38.8 seen), so the test holds the rate
    // to 30, well above the 10 to 21 a second that data paced by the
    // display gave here.
    check(summary.rates[t] >= kLeastRate, `Studio counted ${b.count - a.count} messages on ${t} in ${(b.at - a.at) / 1000} s, ${summary.rates[t]} a second (its Hz: ${summary.hz[t].join(", ")}): not >= ${kLeastRate}`);
  }
  // The data stopped where it is (the server's process paused): the legend
  // holds the last message Studio got, at Studio's time.
  program.child.kill("SIGSTOP");
  const shown = await settledReading(page);
  summary.legend = shown.legend;
  summary.studioTime = { start: shown.start, duration: shown.duration };
  await page.screenshot({ path: path.join(arg.artefacts, `studio-${kind}.png`) });
  summary.panelErrors = await panelErrors(page, seen);
  check(summary.panelErrors.length === 0, `panels in error: ${summary.panelErrors.join("; ")}`);
  check(seen.outside.length === 0, `Studio asked for something off this machine: ${seen.outside.slice(0, 5)}`);
  program.child.kill("SIGCONT");
  await sleep(1500); // the recording is written at least once a second
  const exited = await stop(program);
  check(exited.code === 128 + 15 || exited.code === 0, `${kind} ended with ${JSON.stringify(exited)}: ${program.log.slice(-500)}`);
  await page.context().close();

  // The legend equals the recording's CSV at Studio's time: the row read
  // within 100 ms of it (a message goes at most one rate interval after its
  // frame was read, and the time with it) has the same voltage, current and
  // charge; the ROS 2 twin's voltage is the same.
  const recording = readRecording(oirec);
  const atMs = studioTimeMs(shown);
  const row = findRow(recording.rows, shown.legend, atMs, 100);
  summary.csvRows = recording.rows.length;
  // The frames the robot's link read a second (66.7 when the machine keeps up).
  summary.recordedFramesPerSecond = Number((recording.rows.length / (Number(recording.rows.at(-1).time_s) - Number(recording.rows[0].time_s))).toFixed(1));
  check(/^\d+$/.test(shown.legend.voltage ?? "") && Number(shown.legend.voltage) > 10000,
    `the legend's voltage: ${JSON.stringify(shown.legend)}`);
  if (check(row, `no CSV row within 100 ms of Studio's ${new Date(atMs).toISOString()} has the legend's ${JSON.stringify(shown.legend)}; near it: ${JSON.stringify(recording.rows.filter((r) => Math.abs(r.wallMs - atMs) < 100).map((r) => [r.time_s, r.voltage, r.current, r.battery_charge]))}`))
    summary.csvRow = { time_s: row.time_s, msFromStudioTime: Math.round(row.wallMs - atMs), voltage: row.voltage, current: row.current, battery_charge: row.battery_charge };
  check(shown.legend["voltage (ROS 2)"] === shown.legend.voltage, `the ROS 2 twin's voltage ${shown.legend["voltage (ROS 2)"]} is not the telemetry's ${shown.legend.voltage}`);
  return { summary, oirec, recording };
}

// Studio's remote file source on the recording's MCAP export, at an instant
// in the middle of the recording: its legend is the CSV's row at that time.
async function mcap(origin, oirec, recording) {
  const file = path.join(dir, "recording.mcap");
  execFileSync(arg.ctl, ["mcap", oirec, "-o", file]);
  served.set("/files/recording.mcap", file);
  const rows = recording.rows;
  // The last row, a second or more before the end, whose values differ from
  // the row before, so that the instant matters; else the row 2 s before the
  // end. Near the end, Studio has little to load after it.
  const endS = Number(rows.at(-1).time_s);
  const differs = (i) => ["voltage", "current", "battery_charge"].some((c) => rows[i][c] !== rows[i - 1][c]);
  let k = rows.findLastIndex((r, i) => i > 0 && Number(r.time_s) <= endS - 1 && differs(i));
  if (k < 0) k = rows.findLastIndex((r) => Number(r.time_s) <= endS - 2);
  // Halfway to the next row (a frame every 15 ms): Studio shows the last
  // message at or before its time, row k. (At 1 ms after it, the legend of
  // Studio 1.48 still shows the row before, the seek's own boundary.)
  const us = Math.round(((Number(rows[k].time_s) + Number(rows[k + 1].time_s)) / 2) * 1e6);
  const ns = BigInt(recording.startedMs) * 1000000n + BigInt(us) * 1000n;
  const iso = new Date(Number(ns / 1000000000n) * 1000).toISOString().replace(/\.\d+Z$/, "") + "." + String(ns % 1000000000n).padStart(9, "0") + "Z";
  const seconds = `${ns / 1000000000n}.${String(ns % 1000000000n).padStart(9, "0")}`;
  layoutJson = JSON.stringify(JSON.parse(fs.readFileSync(arg.layout, "utf8")));
  const { page, seen } = await openStudio(origin, `ds=remote-file&ds.url=${encodeURIComponent(`${origin}/files/recording.mcap`)}&time=${iso}`);
  // At the asked time, the file loaded from it on and no more coming for 3 s
  // (Studio 1.48 loads from the time sought).
  let last, sameFor = 0;
  await until(async () => {
    const s = await readStudio(page);
    const at = (Number(seconds) - Number(s.start)) / (Number(s.end) - Number(s.start));
    sameFor = last && JSON.stringify(s.loaded) === JSON.stringify(last.loaded) ? sameFor + 1 : 0;
    last = s;
    return s.playback === seconds && s.loaded.some(([from, to]) => from <= at + 0.001 && to > at) && sameFor >= 6;
  }, 120000, `Studio at ${seconds} with the file loaded after it`, 500).catch((e) => {
    throw new Error(`${e.message}: ${JSON.stringify({ ...last, topics: undefined })}`);
  });
  // Studio 1.48's plots take in what is loaded a while after: the legend may
  // first show the frame before. It must come to the CSV's row and stay.
  const want = rows.filter((r) => r.wallMs <= Number(ns) / 1e6).at(-1);
  const equal = (legend) => ["voltage", "current", "battery_charge"].every((c) => legend[c] === want[c]);
  const loadedAt = Date.now();
  let shown = await readStudio(page);
  for (; !equal(shown.legend) && Date.now() - loadedAt < 60000; shown = await readStudio(page)) await sleep(250);
  const summary = { time: seconds, secondsToShow: (Date.now() - loadedAt) / 1000 };
  await sleep(1000);
  shown = await readStudio(page);
  await page.screenshot({ path: path.join(arg.artefacts, "studio-mcap.png") });
  const errors = await panelErrors(page, seen);
  check(errors.length === 0, `MCAP: panels in error: ${errors.join("; ")}`);
  check(seen.outside.length === 0, `MCAP: Studio asked for something off this machine: ${seen.outside.slice(0, 5)}`);
  await page.context().close();
  Object.assign(summary, { legend: shown.legend, csvRow: { time_s: want.time_s, voltage: want.voltage, current: want.current, battery_charge: want.battery_charge } });
  check(equal(shown.legend), `MCAP at ${seconds}: the legend's ${JSON.stringify(shown.legend)} is not the CSV's ${JSON.stringify(summary.csvRow)}`);
  return summary;
}

async function main() {
  fs.mkdirSync(arg.artefacts, { recursive: true });
  const { server, origin } = await serveFiles();
  await launchBrowser();
  const summary = { scenario };
  try {
    const run = await live(scenario, origin);
    summary.live = run.summary;
    if (scenario === "bridge") summary.mcap = await mcap(origin, run.oirec, run.recording);
  } finally {
    summary.seconds = Number(elapsed());
    await browser.close();
    server.close();
    for (const c of children) await stop(c);
  }
  summary.screenshots = arg.artefacts;
  console.log(JSON.stringify(summary));
  for (const f of failures) console.error("FAIL: " + f);
  process.exit(failures.length ? 1 : 0);
}

main().catch((e) => {
  console.error("FAIL: " + (e?.stack ?? e));
  process.exit(1);
});
