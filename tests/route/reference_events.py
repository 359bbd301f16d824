#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""An independent reference of the detector rules (specs/pipeline.md, section 2).

Reads contact frames (JSON Lines) and prints the semantic events every preset must produce:
right.force (grasp 20, break 80, max 120) on the right gripper, left.slip (grasp 20,
loss 28, min 8) on the left. Written from the spec alone, to check the C++ detectors
against: tst_route compares `semhap route` with the file this writes.

    reference_events.py FRAMES.jsonl > EXPECTED.events.jsonl
"""
import json
import sys


def clip(x, lo, hi):
    return max(lo, min(hi, x))


class Message:
    """One message's lifecycle: begin, update on a changed intensity, end."""

    def __init__(self, node, detector, name, category):
        self.template = {"node": node, "detector": detector, "message": name,
                         "category": category}
        self.active = False
        self.intensity = 1.0

    def event(self, t, gripper, phase):
        return dict(self.template, t=t, gripper=gripper, phase=phase,
                    intensity=self.intensity)

    def step(self, t, gripper, active, intensity, out):
        if active and not self.active:
            self.active, self.intensity = True, intensity
            out.append(self.event(t, gripper, "begin"))
        elif active and intensity != self.intensity:
            self.intensity = intensity
            out.append(self.event(t, gripper, "update"))
        elif not active and self.active:
            self.active = False
            out.append(self.event(t, gripper, "end"))


class Force:
    def __init__(self, node, grasp, brk, fmax):
        self.grasp_t, self.break_t, self.max = grasp, brk, fmax
        self.grasp = Message(node, "force", "grasp", "confirmation")
        self.brk = Message(node, "force", "break", "exception")

    def update(self, frame, out):
        F = frame["left"]["f"] + frame["right"]["f"]
        t, g = frame["t"], frame["gripper"]
        self.grasp.step(t, g, F > self.grasp_t, 1.0, out)
        self.brk.step(t, g, F > self.break_t,
                      clip((F - self.break_t) / (self.max - self.break_t), 0.0, 1.0), out)


class Slip:
    def __init__(self, node, grasp, loss, nmin):
        self.grasp_t, self.loss, self.min = grasp, loss, nmin
        self.actor = None
        self.stable = False
        self.grasp = Message(node, "slip", "grasp", "confirmation")
        self.slip = Message(node, "slip", "slip", "exception")

    def reset(self, t, g, out):
        self.stable = False
        self.grasp.step(t, g, False, 1.0, out)
        self.slip.step(t, g, False, 1.0, out)

    def update(self, frame, out):
        left, right = frame["left"], frame["right"]
        F = left["f"] + right["f"]
        N = left["n"] + right["n"]
        t, g = frame["t"], frame["gripper"]
        a = left["actor"]
        if a is not None and a == right["actor"]:
            if a != self.actor:
                self.actor = a
                self.reset(t, g, out)
            if F > self.grasp_t:
                self.stable = True
                self.grasp.step(t, g, True, 1.0, out)
                self.slip.step(t, g, N < self.loss,
                               clip((self.loss - N) / (self.loss - self.min), 0.0, 1.0), out)
            else:
                self.reset(t, g, out)
        elif self.actor is not None:
            self.actor = None
            self.reset(t, g, out)


def tip(frame, name):
    value = frame.get(name)
    if value is None:
        return {"f": 0.0, "n": 0, "actor": None}
    return {"f": float(value["f"]), "n": int(value["n"]), "actor": value.get("actor")}


def main(path):
    detectors = {"right": Force("right.force", 20.0, 80.0, 120.0),
                 "left": Slip("left.slip", 20.0, 28.0, 8.0)}
    with open(path) as frames:
        for line in frames:
            if not line.strip():
                continue
            raw = json.loads(line)
            frame = {"t": float(raw["t"]), "gripper": raw["gripper"],
                     "left": tip(raw, "left"), "right": tip(raw, "right")}
            out = []
            detectors[frame["gripper"]].update(frame, out)
            for event in out:
                print(json.dumps(event))


if __name__ == "__main__":
    main(sys.argv[1])
