// SPDX-License-Identifier: GPL-3.0-or-later
// Reads an MCAP file with the official TypeScript reader, @mcap/core, twice:
// indexed (through the summary, as viewers seek) and streamed from the start
// with every CRC checked. Prints one JSON object with what it found, for
// tests/mcap/tst_mcap_export.cpp to compare with what it wrote.
// Usage: node read_mcap.js FILE.mcap  (run from the folder holding node_modules)
"use strict";
const fs = require("fs");
const { McapIndexedReader, McapStreamReader } = require("@mcap/core");
const { loadDecompressHandlers } = require("@mcap/support");

async function main() {
  const path = process.argv[2];
  const decompressHandlers = await loadDecompressHandlers();
  const fd = fs.openSync(path, "r");
  const readable = {
    size: async () => BigInt(fs.fstatSync(fd).size),
    read: async (offset, size) => {
      const buffer = Buffer.alloc(Number(size));
      fs.readSync(fd, buffer, 0, Number(size), Number(offset));
      return new Uint8Array(buffer.buffer, buffer.byteOffset, buffer.length);
    },
  };
  const reader = await McapIndexedReader.Initialize({ readable, decompressHandlers });
  const text = new TextDecoder();
  const channels = {};
  for (const [id, channel] of reader.channelsById) {
    const schema = reader.schemasById.get(channel.schemaId);
    channels[channel.topic] = {
      id,
      schema: schema ? schema.name : "",
      schemaEncoding: schema ? schema.encoding : "",
      schemaData: schema ? JSON.parse(text.decode(schema.data)) : null,
      messageEncoding: channel.messageEncoding,
      count: 0,
      first: null,
      last: null,
      firstTime: null,
      lastTime: null,
      messages: [],
      logTimes: [],
    };
  }
  const topicOf = new Map([...reader.channelsById].map(([id, c]) => [id, c.topic]));
  for await (const message of reader.readMessages({ validateCrcs: true })) {
    const c = channels[topicOf.get(message.channelId)];
    const value = JSON.parse(text.decode(message.data));
    if (c.count === 0) {
      c.first = value;
      c.firstTime = message.logTime.toString();
    }
    c.last = value;
    c.lastTime = message.logTime.toString();
    if (c.messages.length < 50 && (topicOf.get(message.channelId).endsWith("events") ||
                                   topicOf.get(message.channelId).endsWith("markers"))) {
      c.messages.push(value.message);
      c.logTimes.push(message.logTime.toString());
    }
    c.count++;
  }
  const metadata = {};
  for await (const m of reader.readMetadata())
    metadata[m.name] = Object.fromEntries(m.metadata);
  const s = reader.statistics;
  const statistics = s && {
    messageCount: Number(s.messageCount),
    schemaCount: s.schemaCount,
    channelCount: s.channelCount,
    attachmentCount: s.attachmentCount,
    metadataCount: s.metadataCount,
    chunkCount: s.chunkCount,
    messageStartTime: s.messageStartTime.toString(),
    messageEndTime: s.messageEndTime.toString(),
    channelMessageCounts: Object.fromEntries([...s.channelMessageCounts].map(([id, n]) => [topicOf.get(id), Number(n)])),
  };

  // The whole file again, record by record, with every CRC checked.
  const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true, includeChunks: true });
  stream.append(fs.readFileSync(path));
  const streamed = {};
  for (let record; (record = stream.nextRecord()); )
    streamed[record.type] = (streamed[record.type] || 0) + 1;

  process.stdout.write(JSON.stringify({
    profile: reader.header.profile,
    library: reader.header.library,
    compression: [...new Set(reader.chunkIndexes.map((c) => c.compression))],
    chunkIndexes: reader.chunkIndexes.length,
    metadataIndexes: reader.metadataIndexes.length,
    summaryOffsets: [...reader.summaryOffsetsByOpcode.keys()].sort((a, b) => a - b),
    dataSectionCrc: reader.dataSectionCrc ?? null,
    channels,
    metadata,
    statistics,
    streamDone: stream.done(),
    streamed,
  }) + "\n");
}

main().catch((error) => {
  process.stderr.write(`read_mcap.js: ${error && error.stack ? error.stack : error}\n`);
  process.exit(1);
});
