#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the bundled MuJoCo scenes, resources/scenes/*.xml (MJCF for MuJoCo 2.2.2).

Each scene is a module of its own, scripts/scenes/NAME.py, whose scene() returns the text of
resources/scenes/NAME.xml; what they share (the gripper, the header, boxes and cube piles) is
scripts/scenes/parts.py. A new scene is a new module: this script writes every one it finds.

The grippers carry 4x4 taxel pads and follow semhap's naming convention (sim/README.md):
  <hand>.target             mocap body: the 6-DoF pose target the wrist follows
  <hand>.gripper            the gripper body (its frame is the frame of fxyz)
  <hand>.tip.left.*, <hand>.tip.right.*   the taxel geoms of the two fingertips
  <hand>.grip.left/.right   force actuators of the fingers (N, closing)
  fragile:<body>            a <numeric> whose value is the body's fracture force (N)
  site pick / place         box sites: where the operator picks cubes and where they go
  site home                 where a dropped container respawns (bimanual_sorting)
  body container            the container the left hand holds (bimanual_sorting)
  semhap:task               a <text> naming the task when it is not found by the sites
  semhap:router             a <text> naming the router preset made for the scene (else C3)
  signal:<hand>:<name>      a <text> declaring a signal of that hand's frames (sim/README.md)
Run it after changing a dimension; the scenes are data, committed as generated.

Speed (tests/bench/README.md, bench_sim): most of box_and_block's mj_step was the resting
pile, ~46 contacts (4 per cube on the floor, 4 per stacked pair) and ~140 constraint rows
rebuilt and solved every step. semhap's World now puts resting objects to sleep
(sim/README.md), which roughly halves the cost; what is left is the grasp (32 taxel
contacts) and whatever is awake near the hand. Tried here and not kept (callgrind counts or
timings of the same scripted episode): solver CG 4.7x slower, PGS 20x slower; tolerance 1e-5
or 1e-6 no gain (Newton already stops after 1 iteration on 97 % of steps); pyramidal cones
2x slower (4 rows per contact instead of 3); dense Jacobian 2.5x slower; the box walls in
static bodies of their own 0.2 %; solimp power 1 slower; impratio 1 4 % faster but creeps
more (kept at 10). The timestep stays 2 ms: contact frames are one per step (tests/simrun).
"""

import importlib
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "scenes")


def main():
    root = os.path.join(HERE, "..", "resources", "scenes")
    os.makedirs(root, exist_ok=True)
    sys.path.insert(0, SCENES)
    sys.dont_write_bytecode = True  # no __pycache__ in the sources
    for file in sorted(os.listdir(SCENES)):
        name, ext = os.path.splitext(file)
        if ext != ".py" or name == "parts":
            continue
        text = importlib.import_module(name).scene()
        with open(os.path.join(root, name + ".xml"), "w") as out:
            out.write(text)


if __name__ == "__main__":
    main()
