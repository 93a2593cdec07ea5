// SPDX-License-Identifier: GPL-3.0-or-later
// The live data server as clients we did not write see it: the protocol's own
// client (@foxglove/ws-protocol's FoxgloveClient) and ROS 2 message reader
// (@foxglove/rosmsg2-serialization), against live_rig (tests/foxglove).
//   node live_check.js SCENARIO RIG DIR
// Prints what it found, and each failure on standard error; exits 1 on any.
"use strict";
const { FoxgloveClient } = require("@foxglove/ws-protocol");
const { parse: parseRosmsg } = require("@foxglove/rosmsg");
const { MessageReader } = require("@foxglove/rosmsg2-serialization");
const WebSocket = require("ws");
const { spawn } = require("child_process");
const fs = require("fs");
const readline = require("readline");

const [scenario, rigPath, dir, layoutPath] = process.argv.slice(2);
const failures = [];
function check(ok, what) {
  if (!ok) failures.push(what);
  return ok;
}
function finish(summary) {
  console.log(JSON.stringify(summary, (k, v) => (typeof v === "bigint" ? v.toString() : v)));
  for (const f of failures) console.error("FAIL: " + f);
  process.exit(failures.length ? 1 : 0);
}
const text = new TextDecoder();
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// live_rig with its lines as a queue to wait on.
function startRig(args) {
  const rig = spawn(rigPath, args, { stdio: ["pipe", "pipe", "inherit"] });
  const lines = [];
  let wake = null;
  readline.createInterface({ input: rig.stdout }).on("line", (line) => {
    lines.push(line);
    if (wake) wake();
  });
  rig.on("exit", (code) => {
    lines.push(`exit ${code}`);
    if (wake) wake();
  });
  return {
    send: (command) => rig.stdin.write(command + "\n"),
    // The next line starting with `word`, within `ms`.
    async expect(word, ms = 60000) {
      const end = Date.now() + ms;
      for (;;) {
        const i = lines.findIndex((l) => l.startsWith(word + " ") || l === word || l.startsWith("error") || l.startsWith("exit"));
        if (i >= 0) {
          const line = lines.splice(i, 1)[0];
          if (!line.startsWith(word)) throw new Error(`live_rig said '${line}' while the test waited for '${word}'`);
          return line.slice(word.length).trim();
        }
        if (Date.now() > end) throw new Error(`live_rig did not say '${word}' within ${ms} ms`);
        await new Promise((r) => {
          wake = r;
          setTimeout(r, 100);
        });
      }
    },
    kill: () => rig.kill(),
  };
}

// A FoxgloveClient that keeps what it hears.
function connect(url, subprotocol) {
  const ws = new WebSocket(url, [subprotocol]);
  const client = new FoxgloveClient({ ws });
  const heard = { ws, client, serverInfo: [], channels: new Map(), withdrawn: [], messages: new Map(), times: [], closed: null, errors: [] };
  client.on("serverInfo", (info) => heard.serverInfo.push(info));
  client.on("advertise", (channels) => channels.forEach((c) => heard.channels.set(c.id, c)));
  client.on("unadvertise", (ids) => heard.withdrawn.push(...ids));
  client.on("time", (t) => heard.times.push({ wallMs: performance.now(), ns: t.timestamp }));
  client.on("error", (e) => heard.errors.push(String(e)));
  client.on("close", (e) => (heard.closed = e.code ?? true));
  heard.subscribe = (topic) => {
    const channel = [...heard.channels.values()].find((c) => c.topic === topic);
    if (!channel) return false;
    const id = client.subscribe(channel.id);
    heard.messages.set(id, { channel, list: [] });
    return true;
  };
  client.on("message", (m) => {
    const s = heard.messages.get(m.subscriptionId);
    if (s) s.list.push({ ns: m.timestamp, data: new Uint8Array(m.data.buffer, m.data.byteOffset, m.data.byteLength).slice() });
  });
  heard.on = (topic) => [...heard.messages.values()].find((s) => s.channel.topic === topic)?.list ?? [];
  heard.opened = new Promise((resolve, reject) => {
    ws.on("open", resolve);
    ws.on("error", reject);
  });
  return heard;
}

async function until(condition, ms, what) {
  const end = Date.now() + ms;
  while (!condition()) {
    if (Date.now() > end) throw new Error(`${what} did not happen within ${ms} ms`);
    await sleep(20);
  }
}

// Until nothing has arrived for `quietMs` on any of these clients.
async function untilQuiet(clients, quietMs) {
  let last = -1;
  let since = Date.now();
  for (;;) {
    const count = clients.reduce((n, c) => n + [...c.messages.values()].reduce((m, s) => m + s.list.length, 0), 0);
    if (count !== last) {
      last = count;
      since = Date.now();
    } else if (Date.now() - since > quietMs) return;
    await sleep(50);
  }
}

function readCsv(path) {
  const [header, ...rows] = fs.readFileSync(path, "utf8").trim().split("\n");
  const columns = header.split(",").map((c) => c.replace(/\[.*\]$/, ""));
  const byUs = new Map();
  for (const row of rows) {
    const cells = row.split(",");
    byUs.set(Math.round(Number(cells[0]) * 1e6), Object.fromEntries(columns.slice(1).map((c, i) => [c, cells[i + 1]])));
  }
  return { columns: columns.slice(1).filter((c) => c !== "marker"), byUs };
}

const kTopics = ["telemetry", "telemetry_ros2", "pose", "tf", "events", "markers"];

async function telemetry() {
  const rig = startRig(["telemetry", dir, "60"]);
  const url = await rig.expect("url");
  const clients = [connect(url, "foxglove.websocket.v1"), connect(url, "foxglove.sdk.v1")];
  const topics = [...kTopics, "true_pose"];
  for (const c of clients) {
    await c.opened;
    await until(() => c.channels.size >= topics.length, 10000, "the advertisement");
    for (const t of topics) check(c.subscribe(`/r1/${t}`), `/r1/${t} advertised to ${c.ws.protocol}`);
  }
  const summary = { subprotocols: clients.map((c) => c.ws.protocol) };
  check(summary.subprotocols.join() === "foxglove.websocket.v1,foxglove.sdk.v1", `each name accepted: ${summary.subprotocols}`);
  // The channels and their schemas.
  const channel = (topic) => [...clients[0].channels.values()].find((c) => c.topic === topic);
  const expect = {
    "/r1/telemetry": ["json", "roomba.Telemetry.create2", "jsonschema"],
    "/r1/telemetry_ros2": ["cdr", "roomba_msgs/msg/TelemetryCreate2", "ros2msg"],
    "/r1/pose": ["json", "foxglove.PoseInFrame", "jsonschema"],
    "/r1/tf": ["json", "foxglove.FrameTransform", "jsonschema"],
    "/r1/events": ["json", "foxglove.Log", "jsonschema"],
    "/r1/markers": ["json", "foxglove.Log", "jsonschema"],
    "/r1/true_pose": ["json", "foxglove.PoseInFrame", "jsonschema"],
  };
  for (const [topic, [encoding, schemaName, schemaEncoding]] of Object.entries(expect)) {
    const c = channel(topic);
    check(c && c.encoding === encoding && c.schemaName === schemaName && c.schemaEncoding === schemaEncoding,
      `${topic}: ${JSON.stringify(c && [c.encoding, c.schemaName, c.schemaEncoding])}`);
  }
  const schema = JSON.parse(channel("/r1/telemetry").schema);
  check(schema.properties.voltage?.title === "Voltage" && schema.properties.voltage?.description.includes("mV"),
    `the telemetry schema names each packet: ${JSON.stringify(schema.properties.voltage)}`);
  // The shipped layout asks only for what is served.
  const layout = JSON.stringify(JSON.parse(fs.readFileSync(layoutPath, "utf8")));
  check(layout.includes('"/r1/telemetry.voltage"') && layout.includes('"/r1/events"'), "the layout plots the battery and logs the events");
  for (const [, topic, field] of layout.matchAll(/"(\/r1\/[a-z_0-9]+)(?:\.([a-z_0-9]+))?"/g)) {
    check(channel(topic), `the layout's ${topic} is served`);
    if (field) check(topic === "/r1/telemetry" && schema.properties[field], `the layout's ${topic}.${field} is a field of the telemetry`);
  }
  check(clients[0].serverInfo[0]?.capabilities.includes("time") && clients[0].serverInfo[0]?.metadata["r1.profile"] === "create2",
    `serverInfo: ${JSON.stringify(clients[0].serverInfo[0])}`);

  rig.send("go");
  const csvPath = await rig.expect("done", 120000);
  await untilQuiet(clients, 500);
  rig.send("quit");
  const csv = readCsv(csvPath);
  // The recording's times are its writer's (the wall clock), the messages'
  // the robot's, which runs ten times faster here: each message is found in
  // the CSV by its values, in order, and its time checked against the rows'
  // place (a frame every 15 ms of the robot's time).
  const rows = [...csv.byUs.values()];
  const equal = (row, get) => csv.columns.every((column) => {
    const want = row[column] === "" ? undefined : Number(row[column]);
    const got = get(column);
    return got === want || (want === undefined && Number.isNaN(got));
  });
  const matchAll = (messages, decode, what) => {
    let cursor = 0, fields = 0, previous = null;
    for (const m of messages) {
      const value = decode(m.data);
      const get = (column) => value[column];
      let i = cursor;
      while (i < rows.length && !equal(rows[i], get)) i++;
      if (!check(i < rows.length, `${what}: the message at ${m.ns} ns (${JSON.stringify(value).slice(0, 300)}) equals no row of the recording's CSV after row ${cursor}`))
        return fields;
      fields += csv.columns.length;
      if (previous) {
        const rowsApart = i - previous.row, msApart = Number(m.ns - previous.ns) / 1e6;
        check(Math.abs(rowsApart * 15 - msApart) <= 1, `${what}: messages ${msApart} ms apart are ${rowsApart} frames apart in the recording`);
      }
      previous = { row: i, ns: m.ns };
      cursor = i + 1;
    }
    return fields;
  };
  const reader = new MessageReader(parseRosmsg(channel("/r1/telemetry_ros2").schema, { ros2: true }));
  summary.csvRows = rows.length;
  summary.clients = [];
  for (const c of clients) {
    const json = c.on("/r1/telemetry"), cdr = c.on("/r1/telemetry_ros2");
    let fields = matchAll(json, (data) => JSON.parse(text.decode(data)), `${c.ws.protocol} JSON`);
    fields += matchAll(cdr, (data) => reader.readMessage(data), `${c.ws.protocol} ROS 2`);
    const extra = new Set();
    for (const m of json.slice(0, 10))
      for (const key of Object.keys(JSON.parse(text.decode(m.data)))) if (!csv.columns.includes(key)) extra.add(key);
    check([...extra].every((k) => k.startsWith("unused_")), `JSON keys the CSV lacks: ${[...extra]}`);
    const spanS = json.length > 1 ? Number(json[json.length - 1].ns - json[0].ns) / 1e9 : 0;
    const markers = c.on("/r1/markers").map((m) => JSON.parse(text.decode(m.data)));
    const events = c.on("/r1/events").map((m) => JSON.parse(text.decode(m.data)).message);
    const poses = c.on("/r1/pose").map((m) => JSON.parse(text.decode(m.data)));
    const truePoses = c.on("/r1/true_pose").map((m) => JSON.parse(text.decode(m.data)));
    check(truePoses.length >= 50 * 55 && truePoses[0].frame_id === "room", `${c.ws.protocol}: ${truePoses.length} true poses`);
    const last = poses[poses.length - 1]?.pose.position;
    summary.clients.push({ subprotocol: c.ws.protocol, telemetry: json.length, ros2: cdr.length, spanS, fields, markers: markers.map((m) => m.message), events, lastPosition: last });
    // 60 s at 50 a second, less what came before the subscriptions took.
    check(json.length >= 50 * 55 && json.length <= 50 * spanS + 2, `${c.ws.protocol}: ${json.length} telemetry messages over ${spanS} s (at most 50 a second)`);
    check(cdr.length >= 50 * 55, `${c.ws.protocol}: ${cdr.length} ROS 2 messages`);
    check(markers.some((m) => m.message === "halfway" && m.name === "marker"), `${c.ws.protocol}: the marker: ${JSON.stringify(markers)}`);
    check(events.includes("Mode Passive → Safe") || events.includes("Mode Safe"), `${c.ws.protocol}: the mode change: ${events}`);
    check(last && Math.hypot(last.x, last.y) > 0.5 && poses[0].frame_id === "r1/odom", `${c.ws.protocol}: the robot moved: ${JSON.stringify(last)}`);
  }
  return summary;
}

async function replay() {
  const rig = startRig(["replay", dir]);
  const url = await rig.expect("url", 120000);
  const c = connect(url, "foxglove.sdk.v1");
  await c.opened;
  await until(() => c.channels.size >= kTopics.length, 10000, "the advertisement");
  c.subscribe("/r1/telemetry");
  rig.send("go");
  await rig.expect("playing");
  await until(() => c.times.length > 0, 10000, "the first time message");
  const first = c.times[c.times.length - 1];
  await sleep(3000); // the wall clock the replay's time is measured against
  const last = c.times[c.times.length - 1];
  rig.send("quit");
  const protocolS = Number(last.ns - first.ns) / 1e9, wallS = (last.wallMs - first.wallMs) / 1000;
  const ratio = protocolS / wallS;
  const sessions = new Set(c.serverInfo.map((i) => i.sessionId));
  const telemetry = c.on("/r1/telemetry");
  const lag = telemetry.length ? Number(last.ns - telemetry[telemetry.length - 1].ns) / 1e9 : NaN;
  check(ratio > 3.4 && ratio < 4.6, `the protocol's time ran ${ratio.toFixed(2)} times the wall clock, not 4`);
  check(sessions.size >= 2, `the replay, a new source, started a new session: ${[...sessions]}`);
  check(Math.abs(lag) < 1, `the telemetry's times are the replay's clock (${lag} s from the time messages)`);
  return { protocolS, wallS, ratio, sessions: sessions.size, telemetry: telemetry.length };
}

// The HTTP status a client offering `subprotocols` gets.
function handshakeStatus(url, subprotocols) {
  return new Promise((resolve) => {
    const ws = new WebSocket(url, subprotocols);
    ws.on("open", () => {
      resolve(`open (${ws.protocol})`);
      ws.close();
    });
    ws.on("unexpected-response", (req, res) => {
      resolve(res.statusCode);
      req.destroy();
    });
    ws.on("error", (e) => resolve(`error: ${e.message}`));
  });
}

async function fleet() {
  const rig = startRig(["fleet"]);
  const url = await rig.expect("url");
  const refused = {
    bogus: await handshakeStatus(url, ["foxglove.bogus.v1"]),
    none: await handshakeStatus(url, []),
    websocket: await handshakeStatus(url, ["foxglove.websocket.v1"]),
    sdk: await handshakeStatus(url, ["foxglove.sdk.v1"]),
    both: await handshakeStatus(url, ["x.y", "foxglove.sdk.v1"]),
  };
  check(refused.bogus === 400 && refused.none === 400, `an unknown subprotocol refused with 400: ${JSON.stringify(refused)}`);
  check(String(refused.websocket).startsWith("open") && String(refused.sdk).startsWith("open") && refused.both === "open (foxglove.sdk.v1)",
    `both names accepted: ${JSON.stringify(refused)}`);
  const c = connect(url, "foxglove.websocket.v1");
  await c.opened;
  const topics = () => [...c.channels.values()].filter((ch) => !c.withdrawn.includes(ch.id)).map((ch) => ch.topic).sort();
  rig.send("add");
  check((await rig.expect("added")) === "r1", "the first robot is r1");
  await until(() => topics().length === kTopics.length, 10000, "r1's advertisement");
  rig.send("add");
  check((await rig.expect("added")) === "r2", "the second robot is r2");
  await until(() => topics().length === 2 * kTopics.length, 10000, "r2's advertisement");
  const r1Ids = [...c.channels.values()].filter((ch) => ch.topic.startsWith("/r1/")).map((ch) => ch.id).sort();
  rig.send("remove r1");
  await rig.expect("removed");
  await until(() => c.withdrawn.length >= kTopics.length, 10000, "r1's withdrawal");
  check(JSON.stringify([...c.withdrawn].sort()) === JSON.stringify(r1Ids), `r1's channels withdrawn: ${c.withdrawn} (had ${r1Ids})`);
  check(topics().every((t) => t.startsWith("/r2/")), `r2's channels remain: ${topics()}`);
  const sessions = new Set(c.serverInfo.map((i) => i.sessionId));
  check(sessions.size === 3, `a session per robot added: ${[...sessions]}`);
  check(c.serverInfo[c.serverInfo.length - 1].metadata["r2.profile"] === "create2", `r2 in the metadata: ${JSON.stringify(c.serverInfo[c.serverInfo.length - 1])}`);
  rig.send("quit");
  return { refused, topics: topics(), withdrawn: c.withdrawn, sessions: sessions.size };
}

// A client that stops reading for a minute of robot time: not dropped,
// what waits for it within the limit, and once it reads again its last
// telemetry is the newest; the client that reads keeps its rate.
async function slowClient() {
  const limit = 1024 * 1024;
  const rig = startRig(["slow", String(limit)]);
  const url = await rig.expect("url");
  const good = connect(url, "foxglove.websocket.v1");
  await good.opened;
  await until(() => good.channels.size >= kTopics.length, 10000, "the advertisement");
  for (const t of kTopics) good.subscribe(`/r1/${t}`);
  // A client that subscribes to everything, then stops reading.
  const slow = new WebSocket(url, ["foxglove.sdk.v1"]);
  let slowClosed = false;
  let telemetryId = null;
  const slowTelemetry = [];
  slow.on("close", () => (slowClosed = true));
  slow.on("error", () => {});
  slow.on("message", (data, isBinary) => {
    if (isBinary && data[0] === 1 && data.readUInt32LE(1) === telemetryId) slowTelemetry.push(data.readBigUInt64LE(5));
  });
  await new Promise((resolve) => slow.on("message", (data, isBinary) => {
    if (isBinary) return;
    const m = JSON.parse(data.toString());
    if (m.op !== "advertise") return;
    telemetryId = m.channels.find((ch) => ch.topic === "/r1/telemetry").id;
    slow.send(JSON.stringify({ op: "subscribe", subscriptions: m.channels.map((ch) => ({ id: ch.id, channelId: ch.id })) }));
    resolve();
  }));
  await sleep(200); // the subscription reaches the server before the robot starts
  slow._socket.pause();
  rig.send("go");
  const [robotSeconds, most, dropped] = (await rig.expect("done", 120000)).split(" ").map(Number);
  await untilQuiet([good], 500);
  const goodClosed = good.closed;
  const telemetry = good.on("/r1/telemetry");
  slow._socket.resume();
  const newest = telemetry[telemetry.length - 1].ns;
  await until(() => slowTelemetry.length && slowTelemetry[slowTelemetry.length - 1] === newest, 10000, "the newest frame at the slow client");
  rig.send("quit");
  let gap = 0;
  for (let i = 1; i < telemetry.length; i++) gap = Math.max(gap, Number(telemetry[i].ns - telemetry[i - 1].ns) / 1e6);
  check(dropped === 0 && !slowClosed, `the slow client kept its connection (dropped ${dropped}, closed ${slowClosed})`);
  check(most <= limit + 64 * 1024, `what waited for the clients stayed within the limit: at most ${most} bytes`);
  check(slowTelemetry.length < telemetry.length, `the slow client was spared the older frames: ${slowTelemetry.length} of ${telemetry.length}`);
  check(goodClosed === null, `the reading client kept its connection (closed: ${goodClosed})`);
  check(telemetry.length >= 50 * (robotSeconds - 1) && gap <= 40, `the reading client kept its rate: ${telemetry.length} messages over ${robotSeconds} s, longest gap ${gap} ms`);
  return { robotSeconds, mostQueuedBytes: most, telemetry: telemetry.length, slowTelemetry: slowTelemetry.length, longestGapMs: gap };
}

const scenarios = { telemetry, replay, fleet, slow: slowClient };
if (!scenarios[scenario]) {
  console.error("usage: node live_check.js telemetry|replay|fleet|slow RIG DIR");
  process.exit(2);
}
const watchdog = setTimeout(() => {
  console.error(`FAIL: ${scenario} did not finish within 170 s`);
  process.exit(1);
}, 170000);
scenarios[scenario]()
  .then((summary) => {
    clearTimeout(watchdog);
    finish(summary);
  })
  .catch((e) => {
    failures.push(String(e.stack || e));
    finish({});
  });
