#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes resources/traces/demo.jsonl: a scripted 8 s box-and-block + container trace.

Until the MuJoCo scenes exist this is the bundled contact trace of the headless demo. It
walks both detectors through their rules: the right gripper grasps a cube, squeezes into
the break zone and back, releases, then crushes a second cube past F_max; the left gripper
holds the container while its grip decays and the contact count falls row by row (slip),
loses it, and grasps it again. Standard library only; deterministic.
"""
import json
import math
import sys

RATE = 200  # frames per second per gripper


def lerp(a, b, u):
    return a + (b - a) * min(max(u, 0.0), 1.0)


def right_hand(t):
    """Total grip force and the cube held by the right gripper at time t."""
    if t < 0.5:
        return 0.0, None
    if t < 1.0:
        return lerp(0, 30, (t - 0.5) / 0.5), "cube_3"
    if t < 2.0:
        return 30 + 3 * math.sin(2 * math.pi * 1.5 * (t - 1.0)), "cube_3"
    if t < 3.0:
        return lerp(30, 105, (t - 2.0) / 1.0), "cube_3"
    if t < 3.5:
        return lerp(105, 40, (t - 3.0) / 0.5), "cube_3"
    if t < 4.5:
        return 40.0, "cube_3"
    if t < 5.0:
        return lerp(40, 0, (t - 4.5) / 0.5), "cube_3"
    if t < 5.5:
        return 0.0, None
    if t < 6.5:
        return lerp(0, 50, (t - 5.5) / 1.0), "cube_4"
    if t < 7.0:
        return lerp(50, 130, (t - 6.5) / 0.5), "cube_4"
    if t < 7.2:
        return 130.0, "cube_4"
    return 0.0, None  # the cube fractured: nothing left to touch


def left_hand(t):
    """Grip force, contact count and actor of the left gripper holding the container."""
    if t < 0.3:
        return 0.0, 0, None
    if t < 0.8:
        f = lerp(0, 30, (t - 0.3) / 0.5)
        return f, 32 if f > 0 else 0, "container"
    if t < 3.0:
        return 30.0, 32, "container"
    if t < 4.0:
        # The grip decays and the container slides out a row of taxels at a time.
        u = (t - 3.0) / 1.0
        return lerp(30, 21, u), 32 - 8 * min(int(u * 4.0), 3), "container"
    if t < 4.5:
        return 0.0, 0, None
    if t < 5.0:
        return lerp(0, 25, (t - 4.5) / 0.5), 32, "container"
    if t < 7.0:
        return 25.0, 32, "container"
    return lerp(25, 10, (t - 7.0) / 0.5), 32, "container"


def tip(f, n, actor, share):
    if actor is None or f <= 0:
        return None
    return {"f": round(f * share, 6), "n": n, "actor": actor}


def main(out):
    for k in range(int(8.0 * RATE)):
        t = round(k / RATE, 6)
        f, n, actor = left_hand(t)
        out.write(json.dumps({"t": t, "gripper": "left",
                              "left": tip(f, n // 2, actor, 0.5),
                              "right": tip(f, n - n // 2, actor, 0.5)}) + "\n")
        f, actor = right_hand(t)
        frame = {"t": t, "gripper": "right",
                 "left": tip(f, 16, actor, 0.52), "right": tip(f, 16, actor, 0.48)}
        if frame["left"]:
            frame["left"]["fxyz"] = [0.0, round(f * 0.52, 6), -0.8]
        out.write(json.dumps(frame) + "\n")


if __name__ == "__main__":
    main(sys.stdout)
