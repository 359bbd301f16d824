// SPDX-License-Identifier: MIT
// Reads an MCAP file the way the lab's viewers do, with the reference libraries: through its
// summary and indexes (@mcap/core's indexed reader), and again start to end with every CRC
// checked (its stream reader); decodes every message by the schema the file carries
// (@foxglove/rosmsg2-serialization) and prints, as JSON, what a test compares: the header,
// the message counts per topic, the first and last message of each topic decoded, the
// metadata, and any message that did not decode whole.
//
//   node mcap-check.mjs FILE.mcap
import { McapIndexedReader, McapStreamReader } from "@mcap/core";
import { loadDecompressHandlers } from "@mcap/support";
import { parse } from "@foxglove/rosmsg";
import { MessageReader } from "@foxglove/rosmsg2-serialization";
import { readFileSync } from "node:fs";
import { open } from "node:fs/promises";

const file = process.argv[2];
const decompressHandlers = await loadDecompressHandlers();
const handle = await open(file, "r");
const size = (await handle.stat()).size;
const readable = {
  size: async () => BigInt(size),
  read: async (offset, length) => {
    const buffer = new Uint8Array(Number(length));
    await handle.read(buffer, 0, Number(length), Number(offset));
    return buffer;
  },
};
const indexed = await McapIndexedReader.Initialize({ readable, decompressHandlers });
const decoders = new Map();
const out = {
  profile: indexed.header.profile,
  chunks: indexed.chunkIndexes.length,
  statisticsMessageCount: String(indexed.statistics?.messageCount ?? "none"),
  schemas: {},
  counts: {},
  first: {},
  last: {},
  undecoded: [],
  metadata: {},
  ordered: true,
};
let lastTime = -1n;
for await (const message of indexed.readMessages()) {
  const channel = indexed.channelsById.get(message.channelId);
  const schema = indexed.schemasById.get(channel.schemaId);
  out.schemas[channel.topic] = schema.name;
  if (!decoders.has(schema.id))
    decoders.set(schema.id, new MessageReader(parse(new TextDecoder().decode(schema.data), { ros2: true })));
  const reader = decoders.get(schema.id);
  let decoded;
  try {
    decoded = reader.readMessage(message.data);
    if (reader.lastReadHadTrailingBytes?.()) out.undecoded.push(`${channel.topic}: trailing bytes`);
  } catch (e) {
    out.undecoded.push(`${channel.topic}: ${e.message}`);
  }
  out.counts[channel.topic] = (out.counts[channel.topic] ?? 0) + 1;
  out.first[channel.topic] ??= decoded;
  out.last[channel.topic] = decoded;
  if (message.logTime < lastTime) out.ordered = false;
  lastTime = message.logTime;
}
for await (const m of indexed.readMetadata()) out.metadata[m.name] = Object.fromEntries(m.metadata);
await handle.close();

// Start to end, every CRC: the chunks', the data section's and the summary's.
const stream = new McapStreamReader({ decompressHandlers, validateCrcs: true });
stream.append(readFileSync(file));
let records = 0;
while (stream.nextRecord()) records++;
out.streamDone = stream.done();
out.streamRecords = records;

const plain = (key, value) =>
  typeof value === "bigint" ? value.toString() : ArrayBuffer.isView(value) ? Array.from(value) : value;
console.log(JSON.stringify(out, plain));
