// SPDX-License-Identifier: MIT
// A robot as foxglove_bridge serves it, with the reference server (@foxglove/ws-protocol's
// FoxgloveServer): the grasp's topics advertised with their ros2msg schemas, and once a
// client has subscribed to every fingertip topic, the grasp's messages published in CDR at
// their own pace (500 Hz, 2 s), each stamped with its log time. Prints {"port": N} first.
//
//   node foxglove-robot.mjs [--restarts N] [--topics /a,/b] [--hold]
//
// --restarts N: after each grasp the robot goes quiet for 3 s, then stops its server and
// starts again on the same port, N times (each run plays the grasp once more);
// --topics: advertise only these topics (a robot that has none of the map's); --hold: play
// only once a line comes on standard input too (a test's viewers are ready).
import foxglove from "@foxglove/ws-protocol";
import { WebSocketServer } from "ws";
import { grasp } from "./grasp.mjs";

const { FoxgloveServer } = foxglove;

const argument = (name, fallback) => {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
};
const restarts = Number(argument("--restarts", 0));
const only = argument("--topics", null)?.split(",");
const held = process.argv.includes("--hold")
  ? new Promise((resolve) => process.stdin.once("data", resolve))
  : Promise.resolve();
const { types, messages } = grasp();
const topics = [...new Set(messages.filter((m) => m.type !== "json").map((m) => m.topic))];
const advertised = only ?? topics;
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
// A message re-encoded with its header stamp `shift` ns later.
const shifted = (m, shift) => {
  if (!m.message.header) return m.data;
  const { sec, nanosec } = m.message.header.stamp;
  const ns = BigInt(sec) * 1_000_000_000n + BigInt(nanosec) + shift;
  const stamp = { sec: Number(ns / 1_000_000_000n), nanosec: Number(ns % 1_000_000_000n) };
  return types[m.type].writer.writeMessage({ ...m.message, header: { ...m.message.header, stamp } });
};

async function serve(port) {
  const server = new FoxgloveServer({ name: "semhap-tests robot" });
  const ws = new WebSocketServer({
    port,
    handleProtocols: (protocols) => server.handleProtocols(protocols),
  });
  await new Promise((resolve) => ws.once("listening", resolve));
  ws.on("connection", (conn, req) => server.handleConnection(conn, `${req.socket.remoteAddress}:${req.socket.remotePort}`));
  const channels = new Map();
  for (const topic of advertised) {
    const type = only ? types.wrench : types[messages.find((m) => m.topic === topic).type];
    channels.set(topic, server.addChannel({ topic, encoding: "cdr", schemaName: type.name, schema: type.text, schemaEncoding: "ros2msg" }));
  }
  const wanted = topics.filter((t) => t.endsWith("/wrench") && channels.has(t));
  const subscribed = new Set();
  const ready = new Promise((resolve) => {
    server.on("subscribe", (id) => {
      subscribed.add(id);
      if (wanted.every((t) => subscribed.has(channels.get(t)))) resolve();
    });
  });
  return { server, ws, channels, ready, port: ws.address().port };
}

let robot = await serve(0);
console.log(JSON.stringify({ port: robot.port }));
for (let run = 0; ; run++) {
  if (only) break; // nothing of the map's to play: stay up until the client gives up
  await robot.ready;
  await held;
  const startedAt = Date.now();
  const first = messages[0].log;
  // Each run is 10 s later than the one before, in its log times and header stamps alike.
  const shift = BigInt(run) * 10_000_000_000n;
  for (const m of messages) {
    if (m.type === "json" || !robot.channels.has(m.topic)) continue;
    const due = Number(m.log - first) / 1e6;
    const wait = startedAt + due - Date.now();
    if (wait > 0) await sleep(wait);
    robot.server.sendMessage(robot.channels.get(m.topic), m.log + shift, run === 0 ? m.data : shifted(m, shift));
  }
  if (run >= restarts) break;
  await sleep(3000); // quiet: the client's silence ends its messages
  const port = robot.port;
  robot.ws.close();
  for (const client of robot.ws.clients) client.terminate();
  await sleep(300);
  robot = await serve(port); // the robot comes back where it was
}
await sleep(only ? 30000 : 1000);
process.exit(0);
