// SPDX-License-Identifier: MIT
// Writes the recordings semhap's MCAP tests read, with the reference libraries, as rosbag2
// would: a two-fingertip grasp as geometry_msgs/msg/WrenchStamped in CDR, a tactile count as
// std_msgs/msg/Int32, and a JSON topic. The same messages go into four files, chunked with
// zstd, with lz4, uncompressed, and as a plain stream without chunks, summary or indexes,
// and into OUT/grasp.expected.json as the reference decoder reads them back.
//
//   node mcap-recordings.mjs OUT [TICKS]
//
// TICKS (1000 by default, 2 s) shortens the grasp: the fuzzer's seeds are 4 ticks long.
import { McapWriter } from "@mcap/core";
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

// As rosbag2 stores a type: its own fields, then each type it uses after a rule of '='.
const rule = "=".repeat(80);
const wrenchText = [
  "std_msgs/Header header\nWrench wrench",
  `${rule}\nMSG: std_msgs/Header\nbuiltin_interfaces/Time stamp\nstring frame_id`,
  `${rule}\nMSG: builtin_interfaces/Time\nint32 sec\nuint32 nanosec`,
  `${rule}\nMSG: geometry_msgs/Wrench\nVector3  force\nVector3  torque`,
  `${rule}\nMSG: geometry_msgs/Vector3\n# a vector in free space\nfloat64 x\nfloat64 y\nfloat64 z`,
].join("\n");
const int32Text = "# a count\nint32 data";
const types = {
  wrench: { name: "geometry_msgs/msg/WrenchStamped", text: wrenchText },
  int32: { name: "std_msgs/msg/Int32", text: int32Text },
};
for (const type of Object.values(types)) {
  const definitions = parse(type.text, { ros2: true });
  type.writer = new MessageWriter(definitions);
  type.reader = new MessageReader(definitions);
}

// A grasp at 500 Hz: the force closes over 0.4 s, holds at 30 N, and opens after 1.2 s. The
// right fingertip's sensor is mounted with its normal along -y; header stamps lag log time
// by 3 ms, as a driver's do.
const start = 1_700_000_000n * 1_000_000_000n;
const messages = [];
for (let i = 0; i < ticks; i++) {
  const t = i / 500;
  const f = t < 0.2 ? 0 : t < 0.6 ? ((t - 0.2) / 0.4) * 30 : t < 1.4 ? 30 : 0;
  const log = start + BigInt(i) * 2_000_000n;
  const stamp = log - 3_000_000n;
  const header = {
    stamp: { sec: Number(stamp / 1_000_000_000n), nanosec: Number(stamp % 1_000_000_000n) },
    frame_id: "",
  };
  const wrench = (normal, frame) => ({
    header: { ...header, frame_id: frame },
    wrench: {
      force: { x: 0.1 * f, y: normal * f, z: 0.05 * f },
      torque: { x: 0, y: 0, z: 0.001 * i },
    },
  });
  messages.push({ topic: "/right/left_tip/wrench", type: "wrench", log, message: wrench(1, "left_tip") });
  messages.push({ topic: "/right/right_tip/wrench", type: "wrench", log, message: wrench(-1, "right_tip") });
  if (i % 5 === 0)
    messages.push({ topic: "/right/right_tip/contacts", type: "int32", log, message: { data: f > 0.5 ? 12 : 0 } });
  if (i % 100 === 0)
    messages.push({ topic: "/operator/note", type: "json", log, message: { text: `tick ${i}`, i } });
}

const jsonSchema = JSON.stringify({ type: "object", properties: { text: { type: "string" }, i: { type: "number" } } });

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

// What the reference decoder reads back: numbers as numbers, 64-bit integers as strings.
const expected = messages.map((m) => ({
  topic: m.topic,
  logTime: m.log.toString(),
  data: Buffer.from(m.data).toString("base64"),
  decoded: m.type === "json" ? m.message : types[m.type].reader.readMessage(m.data),
}));
writeFileSync(path.join(out, "grasp.expected.json"), JSON.stringify(expected, (k, v) => (typeof v === "bigint" ? v.toString() : v)));
console.log(`${messages.length} messages in 4 recordings in ${out}`);
