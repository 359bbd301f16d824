// SPDX-License-Identifier: MIT
// Writes the recordings semhap's MCAP tests read, with the reference libraries, as rosbag2
// would: a two-fingertip grasp as geometry_msgs/msg/WrenchStamped in CDR, a tactile count as
// std_msgs/msg/Int32, and a JSON topic. The same messages go into four files, chunked with
// zstd, with lz4, uncompressed, and as a plain stream without chunks, summary or indexes,
// and into OUT/grasp.expected.json as the reference decoder reads them back. OUT/kinds.mcap
// holds a message of every kind of field, with OUT/kinds.expected.json; OUT/grasp.topics.json
// and OUT/grasp.frames.jsonl are the map of the grasp and the frames it should give.
//
//   node mcap-recordings.mjs OUT [TICKS]
//
// TICKS (1000 by default, 2 s) shortens the grasp: the fuzzer's seeds are 4 ticks long.
import { McapWriter } from "@mcap/core";
import { grasp, rule } from "./grasp.mjs";
import { parse } from "@foxglove/rosmsg";
import { MessageReader, MessageWriter } from "@foxglove/rosmsg2-serialization";
import zstd from "@foxglove/wasm-zstd";
import lz4 from "lz4js";
import { mkdirSync, writeFileSync } from "node:fs";
import { open } from "node:fs/promises";
import path from "node:path";

const out = process.argv[2];
const ticks = Number(process.argv[3] ?? 1000);
if (!out || !(ticks > 0)) {
  console.error("usage: node mcap-recordings.mjs OUT [TICKS]");
  process.exit(2);
}
mkdirSync(out, { recursive: true });

const { types, messages, map, frames, start } = grasp(ticks);
writeFileSync(path.join(out, "grasp.topics.json"), JSON.stringify(map, null, 1));
writeFileSync(path.join(out, "grasp.frames.jsonl"), frames);

const jsonSchema = JSON.stringify({ type: "object", properties: { text: { type: "string" }, i: { type: "number" } } });

// JSON of what the reference reader returns: typed arrays as arrays, 64-bit integers as text.
function plain(key, value) {
  if (typeof value === "bigint") return value.toString();
  if (ArrayBuffer.isView(value)) return Array.from(value, (v) => (typeof v === "bigint" ? v.toString() : v));
  return value;
}

class FileWritable {
  constructor(handle) {
    this.handle = handle;
    this.written = 0n;
  }
  async write(buffer) {
    await this.handle.write(buffer);
    this.written += BigInt(buffer.byteLength);
  }
  position() {
    return this.written;
  }
}

async function record(file, options) {
  const handle = await open(path.join(out, file), "w");
  const writer = new McapWriter({ writable: new FileWritable(handle), ...options });
  await writer.start({ profile: "ros2", library: "semhap-tests mcap-recordings" });
  const channels = {};
  const schemaIds = {};
  for (const [key, type] of Object.entries(types))
    schemaIds[key] = await writer.registerSchema({ name: type.name, encoding: "ros2msg", data: new TextEncoder().encode(type.text) });
  schemaIds.json = await writer.registerSchema({ name: "semhap_tests/Note", encoding: "jsonschema", data: new TextEncoder().encode(jsonSchema) });
  let sequence = 0;
  for (const m of messages) {
    if (!(m.topic in channels)) {
      channels[m.topic] = await writer.registerChannel({
        topic: m.topic,
        schemaId: schemaIds[m.type],
        messageEncoding: m.type === "json" ? "json" : "cdr",
        metadata: new Map([["offered_qos_profiles", ""]]),
      });
    }
    const data = m.type === "json" ? new TextEncoder().encode(JSON.stringify(m.message)) : types[m.type].writer.writeMessage(m.message);
    m.data = data;
    await writer.addMessage({ channelId: channels[m.topic], sequence: sequence++, logTime: m.log, publishTime: m.log, data });
  }
  await writer.addMetadata({ name: "rosbag2", metadata: new Map([["storage", "mcap"]]) });
  await writer.end();
  await handle.close();
}

await zstd.isLoaded;
const small = { chunkSize: ticks < 1000 ? 256 : 16 * 1024 };
await record("grasp-zstd.mcap", { ...small, compressChunk: (data) => ({ compression: "zstd", compressedData: zstd.compress(data, 3) }) });
await record("grasp-lz4.mcap", { ...small, compressChunk: (data) => ({ compression: "lz4", compressedData: Uint8Array.from(lz4.compress(data)) }) });
await record("grasp-none.mcap", { ...small });
await record("grasp-stream.mcap", {
  useChunks: false,
  useStatistics: false,
  useSummaryOffsets: false,
  repeatSchemas: false,
  repeatChannels: false,
  useAttachmentIndex: false,
  useMetadataIndex: false,
  useMessageIndex: false,
  useChunkIndex: false,
});

// Every kind of field a .msg may have, with constants and a comment in the way, for the CDR
// decoder: a few messages whose strings and sequences shift what follows out of alignment.
const kindsText = [
  "# every kind of field",
  "bool flag",
  "byte b",
  "char c",
  "int8 i8",
  "uint8 u8",
  "int16 i16  # a comment",
  "uint16 u16",
  "int32 i32",
  "uint32 u32",
  "int64 i64",
  "uint64 u64",
  "float32 f32",
  "float64 f64",
  "string text",
  "string<=8 short_text",
  "float64[3] fixed",
  "int16[] sequence",
  "uint8[<=4] bounded",
  "Point[] points",
  "Point[2] pair",
  "int32 CONSTANT=7",
  'string NAME="a # b"',
  rule,
  "MSG: semhap_tests/Point",
  "float32 x",
  "float64 y 0.5",
  "string label",
].join("\n");
const kinds = parse(kindsText, { ros2: true });
const kindsWriter = new MessageWriter(kinds);
const kindsReader = new MessageReader(kinds);
const point = (k) => ({ x: k + 0.25, y: -k * 1.5, label: "p".repeat(k % 4) });
const kindsMessages = [];
for (let k = 0; k < 6; k++) {
  kindsMessages.push({
    flag: k % 2 === 1,
    b: 200 + k,
    c: 65 + k,
    i8: -100 + k,
    u8: 250 - k,
    i16: -30000 + k,
    u16: 60000 + k,
    i32: -2_000_000_000 + k,
    u32: 4_000_000_000 + k,
    i64: -9_000_000_000_000n + BigInt(k),
    u64: 18_000_000_000_000n + BigInt(k),
    f32: 1.5 * k,
    f64: Math.PI * k,
    text: "x".repeat(k * 3),
    short_text: "s".repeat(k),
    fixed: [k, k + 0.5, -k],
    sequence: Array.from({ length: k }, (_, j) => j * 7 - 3),
    bounded: Array.from({ length: k % 5 }, (_, j) => j + 1),
    points: Array.from({ length: k }, (_, j) => point(j + k)),
    pair: [point(k), point(k + 1)],
  });
}
{
  const handle = await open(path.join(out, "kinds.mcap"), "w");
  const writer = new McapWriter({ writable: new FileWritable(handle) });
  await writer.start({ profile: "ros2", library: "semhap-tests mcap-recordings" });
  const schemaId = await writer.registerSchema({ name: "semhap_tests/msg/Kinds", encoding: "ros2msg", data: new TextEncoder().encode(kindsText) });
  const channelId = await writer.registerChannel({ topic: "/kinds", schemaId, messageEncoding: "cdr", metadata: new Map() });
  for (const [k, m] of kindsMessages.entries())
    await writer.addMessage({ channelId, sequence: k, logTime: start + BigInt(k), publishTime: start + BigInt(k), data: kindsWriter.writeMessage(m) });
  await writer.end();
  await handle.close();
}
const asRead = [];
{
  // Read back through the reference reader, so the expectation is what it decodes.
  for (const m of kindsMessages) asRead.push(kindsReader.readMessage(kindsWriter.writeMessage(m)));
}
writeFileSync(path.join(out, "kinds.expected.json"), JSON.stringify(asRead, plain));

// What the reference decoder reads back: numbers as numbers, 64-bit integers as strings.
const expected = messages.map((m) => ({
  topic: m.topic,
  logTime: m.log.toString(),
  data: Buffer.from(m.data).toString("base64"),
  decoded: m.type === "json" ? m.message : types[m.type].reader.readMessage(m.data),
}));
writeFileSync(path.join(out, "grasp.expected.json"), JSON.stringify(expected, plain));
console.log(`${messages.length} messages in 4 recordings, ${kindsMessages.length} in kinds.mcap, in ${out}`);
