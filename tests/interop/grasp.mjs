// SPDX-License-Identifier: MIT
// The grasp the interop tests play, as a robot with two fingertip force/torque sensors and a
// tactile array publishes it: the types, the messages in time order, the topic map of them,
// and the JSON Lines contact frames the map's rules give, worked out here on their own.
//
//   import { grasp } from "./grasp.mjs"; const g = grasp(ticks);
import { parse } from "@foxglove/rosmsg";
import { MessageReader, MessageWriter } from "@foxglove/rosmsg2-serialization";

export const rule = "=".repeat(80);

export function grasp(ticks = 1000) {
  // As rosbag2 stores a type: its own fields, then each type it uses after a rule of '='.
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

  // A grasp at 500 Hz: the force closes over 0.4 s, holds at 30 N, squeezes to 45 N, and opens
  // at 1.4 s, while the tactile count falls from 12 to 6 (a slip). The right fingertip's sensor
  // is mounted with its normal along -y; header stamps lag log time by 3 ms, as a driver's do.
  const start = 1_700_000_000n * 1_000_000_000n;
  const messages = [];
  for (let i = 0; i < ticks; i++) {
    const t = i / 500;
    const f = t < 0.2 ? 0 : t < 0.6 ? ((t - 0.2) / 0.4) * 30 : t < 1.0 ? 30 : t < 1.2 ? 30 + (t - 1.0) * 75 : t < 1.4 ? 45 : 0;
    const contacts = f <= 0.5 ? 0 : t < 1.0 ? 12 : Math.max(6, Math.round(12 - (t - 1.0) * 30));
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
      messages.push({ topic: "/right/right_tip/contacts", type: "int32", log, message: { data: contacts } });
    if (i % 100 === 0)
      messages.push({ topic: "/operator/note", type: "json", log, message: { text: `tick ${i}`, i } });
  }

  // The same grasp as semhap's JSON Lines contact frames, by the rules of docs/ros.md worked
  // out here on their own, and the map that says them: a frame at each left-tip message, at its
  // header stamp; the right tip's latest message stamped at or before it; the count (Int32 has
  // no header) its latest logged at or before it; f the force's length, fxyz the force turned so
  // that the normal axis is +y; n the count, or 1 at or above the contact threshold.
  const map = {
    format: "semhap.topics/1",
    time: "header",
    grippers: {
      right: {
        left: { topic: "/right/left_tip/wrench", force: "wrench.force", normal_axis: "y", contact_threshold: 0.5, actor: "cube", mu: 0.8 },
        right: {
          topic: "/right/right_tip/wrench",
          force: "wrench.force",
          normal_axis: "-y",
          contact_threshold: 0.5,
          actor: "cube",
          count: { topic: "/right/right_tip/contacts", field: "data" },
        },
        signals: { "left.torque_z": { topic: "/right/left_tip/wrench", field: "wrench.torque.z" } },
      },
    },
  };
  let frames;
  {
    const stampOf = (m) => BigInt(m.message.header.stamp.sec) * 1_000_000_000n + BigInt(m.message.header.stamp.nanosec);
    const byTopic = (topic) => messages.filter((m) => m.topic === topic);
    const clock = byTopic("/right/left_tip/wrench");
    const right = byTopic("/right/right_tip/wrench");
    const counts = byTopic("/right/right_tip/contacts");
    const latest = (list, time, at) => list.filter((m) => at(m) <= time).at(-1);
    const tip = (m, turn, count, spec) => {
      const { x, y, z } = m.message.wrench.force;
      const f = Math.sqrt(x * x + y * y + z * z);
      const n = count === undefined ? (f >= spec.contact_threshold ? 1 : 0) : Math.max(0, Math.round(count));
      const out = { f, n, actor: n > 0 ? spec.actor : null, fxyz: turn(x, y, z) };
      if (spec.mu) out.mu = spec.mu;
      return out;
    };
    const start = stampOf(clock[0]);
    const lines = clock.map((c) => {
      const time = stampOf(c);
      const r = latest(right, time, stampOf);
      const k = latest(counts, time, (m) => m.log);
      return JSON.stringify({
        t: Number(time - start) / 1e9,
        gripper: "right",
        left: tip(c, (x, y, z) => [x, y, z], undefined, map.grippers.right.left),
        right: r ? tip(r, (x, y, z) => [-x, -y, z], k ? k.message.data : 0, map.grippers.right.right) : null,
        signals: { "left.torque_z": c.message.wrench.torque.z },
      });
    });
    frames = lines.join("\n") + "\n";
  }


  // Each message's bytes as the robot sends them: CDR, or JSON text.
  for (const m of messages)
    m.data = m.type === "json" ? new TextEncoder().encode(JSON.stringify(m.message)) : types[m.type].writer.writeMessage(m.message);
  return { types, messages, map, frames, start };
}
