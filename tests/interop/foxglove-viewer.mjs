// SPDX-License-Identifier: MIT
// A viewer as Foxglove is one, with the reference client (@foxglove/ws-protocol's
// FoxgloveClient): it connects to URL, subscribes to every channel advertised, and decodes
// every message by its advertised ros2msg schema (@foxglove/rosmsg2-serialization). When
// the server closes, or after --seconds, it prints what it got as JSON:
//
//   {"serverInfo": NAME, "subprotocol": ..., "topics": {TOPIC: {"type", "count", "first",
//    "last", "stamps": [first, last] (ns)}}, "statuses": [{level, message}],
//    "undecoded": N, "errors": [...]}
//
//   node foxglove-viewer.mjs URL [--seconds S] [--stall MS]
//
// A server not yet listening is tried again every 100 ms for 30 s. Each subscription is a
// line "subscribed TOPIC" first. --stall MS: after its first message the viewer prints
// "stalled" and stops reading its socket for MS, as a viewer on a slow link or a stalled
// machine does, then reads on.
import foxglove from "@foxglove/ws-protocol";
import { parse } from "@foxglove/rosmsg";
import { MessageReader } from "@foxglove/rosmsg2-serialization";
import WebSocket from "ws";

const { FoxgloveClient } = foxglove;
const argument = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
};
const url = process.argv[2];
const seconds = Number(argument("--seconds", 0));
const stall = Number(argument("--stall", 0));

const result = { serverInfo: null, subprotocol: null, topics: {}, statuses: [], undecoded: 0, errors: [] };
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
const channels = new Map(); // subscription id → { topic, type, reader }
const plain = (value) =>
  JSON.parse(JSON.stringify(value, (_, v) => (typeof v === "bigint" ? Number(v) : v)));
let stalled = false;

// A client, listening from the start: the server speaks as soon as it accepts, often in the
// same packet as its handshake. Resolves to whether it opened.
function connect() {
  const ws = new WebSocket(url, [FoxgloveClient.SUPPORTED_SUBPROTOCOL]);
  const client = new FoxgloveClient({ ws });
  client.on("serverInfo", (info) => (result.serverInfo = info.name));
  client.on("status", (s) => result.statuses.push({ level: s.level, message: s.message }));
  client.on("advertise", (list) => {
    for (const c of list) {
      try {
        if (c.encoding !== "cdr" || c.schemaEncoding !== "ros2msg")
          throw new Error(`${c.topic}: ${c.encoding}/${c.schemaEncoding}`);
        const reader = new MessageReader(parse(c.schema, { ros2: true }));
        channels.set(client.subscribe(c.id), { topic: c.topic, type: c.schemaName, reader });
        process.stdout.write(`subscribed ${c.topic}\n`);
      } catch (e) {
        result.errors.push(`${c.topic}: ${e.message}`);
      }
    }
  });
  client.on("message", ({ subscriptionId, timestamp, data }) => {
    const channel = channels.get(subscriptionId);
    if (!channel) return;
    let message;
    try {
      message = channel.reader.readMessage(data);
    } catch {
      result.undecoded++;
      return;
    }
    const entry = (result.topics[channel.topic] ??= { type: channel.type, count: 0, first: plain(message), stamps: [Number(timestamp), 0] });
    entry.count++;
    entry.last = plain(message);
    entry.stamps[1] = Number(timestamp);
    if (stall > 0 && !stalled) {
      stalled = true;
      process.stdout.write("stalled\n");
      ws._socket.pause();
      setTimeout(() => ws._socket.resume(), stall);
    }
  });
  return new Promise((resolve) => {
    client.on("open", () => {
      result.subprotocol = ws.protocol;
      client.on("error", (e) => result.errors.push(String(e?.message ?? e)));
      client.on("close", done);
      resolve(true);
    });
    ws.once("error", () => resolve(false));
  });
}

const done = () => {
  process.stdout.write(JSON.stringify(result) + "\n");
  process.exit(0);
};
for (let tries = 0; !(await connect()); tries++) {
  if (tries >= 300) {
    result.errors.push(`${url}: no server`);
    done();
  }
  await sleep(100);
}
if (seconds > 0) setTimeout(done, seconds * 1000);
