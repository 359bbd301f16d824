#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the bundled MuJoCo scenes, resources/scenes/*.xml (MJCF for MuJoCo 2.2.2).

The grippers carry 4x4 taxel pads and follow semhap's naming convention (sim/README.md):
  <hand>.target             mocap body: the 6-DoF pose target the wrist follows
  <hand>.gripper            the gripper body (its frame is the frame of fxyz)
  <hand>.tip.left.*, <hand>.tip.right.*   the taxel geoms of the two fingertips
  <hand>.grip.left/.right   force actuators of the fingers (N, closing)
  fragile:<body>            a <numeric> whose value is the body's fracture force (N)
  site pick / place         box sites: where the operator picks cubes and where they go
  site home                 where a dropped container respawns (bimanual_sorting)
  body container            the container the left hand holds (bimanual_sorting)
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
import os

TAXEL_R = 0.004          # taxel sphere radius
TAXEL_PITCH = 0.010      # 4x4 grid, 1 cm apart: a 4 cm pad
CUBE = 0.025             # half size: 5 cm cubes
CUBE_MASS = 0.08
SLIPPERY = "0.1 0.005 0.0001"
OBJECT_CONTACT = 'priority="1" condim="3" solref="0.004 1" solimp="0.95 0.99 0.001"'


def gripper(hand, pos, half_open, rgba):
    """A parallel-jaw gripper hanging fingers down; `half_open`: finger offset from centre."""
    x, y, z = pos
    taxels = []
    for side, sign in (("left", 1), ("right", -1)):
        pad = []
        for i in range(4):
            for j in range(4):
                px = (i - 1.5) * TAXEL_PITCH
                pz = (j - 1.5) * TAXEL_PITCH
                pad.append(
                    f'          <geom name="{hand}.tip.{side}.t{i}{j}" class="taxel" '
                    f'pos="{px:.4f} {-sign * 0.006:.4f} {pz:.4f}"/>')
        taxels.append("\n".join(pad))
    return f"""
    <body name="{hand}.target" mocap="true" pos="{x} {y} {z}"/>
    <body name="{hand}.gripper" pos="{x} {y} {z}">
      <freejoint name="{hand}.free"/>
      <geom name="{hand}.palm" type="box" size="0.03 {half_open + 0.012:.3f} 0.012" mass="0.4"
            rgba="{rgba}" contype="0" conaffinity="0"/>
      <body name="{hand}.finger.left" pos="0 {half_open:.3f} -0.06">
        <joint name="{hand}.slide.left" type="slide" axis="0 -1 0" range="0 {half_open - 0.006:.3f}"
               damping="60" armature="0.02" solreflimit="0.004 1"/>
        <geom name="{hand}.link.left" type="box" size="0.022 0.002 0.05" pos="0 0.002 0.01"
              mass="0.05" rgba="{rgba}" contype="0" conaffinity="0"/>
{taxels[0]}
      </body>
      <body name="{hand}.finger.right" pos="0 {-half_open:.3f} -0.06">
        <joint name="{hand}.slide.right" type="slide" axis="0 1 0" range="0 {half_open - 0.006:.3f}"
               damping="60" armature="0.02" solreflimit="0.004 1"/>
        <geom name="{hand}.link.right" type="box" size="0.022 0.002 0.05" pos="0 -0.002 0.01"
              mass="0.05" rgba="{rgba}" contype="0" conaffinity="0"/>
{taxels[1]}
      </body>
    </body>"""


def gripper_equality(hand):
    return f"""
    <weld body1="{hand}.gripper" body2="{hand}.target" solref="0.01 1"/>
    <joint joint1="{hand}.slide.left" joint2="{hand}.slide.right"/>"""


def gripper_exclusions(hand):
    # The two fingers never touch each other (taxels skip each other by contype, links have
    # no contacts), but without this MuJoCo tests each of their 17 x 17 geom pairs every step:
    # 2.5 % of box_and_block's mj_step.
    return f"""
    <exclude body1="{hand}.finger.left" body2="{hand}.finger.right"/>"""


def gripper_actuators(hand, max_force):
    return "".join(
        f'\n    <motor name="{hand}.grip.{side}" joint="{hand}.slide.{side}" gear="1" '
        f'ctrllimited="true" ctrlrange="-20 {max_force}"/>' for side in ("left", "right"))


def one_hand_closing(hand):
    """The contact, equality and actuator sections of a scene with one gripper."""
    return f"""  <contact>{gripper_exclusions(hand)}
  </contact>
  <equality>{gripper_equality(hand)}
  </equality>
  <actuator>{gripper_actuators(hand, 160)}
  </actuator>"""


def open_box(name, cx, cy, inner, height, wall, rgba):
    h = inner / 2 + wall / 2
    walls = [
        (f"{name}.wall.n", cx, cy + h, inner / 2 + wall, wall / 2),
        (f"{name}.wall.s", cx, cy - h, inner / 2 + wall, wall / 2),
        (f"{name}.wall.e", cx + h, cy, wall / 2, inner / 2),
        (f"{name}.wall.w", cx - h, cy, wall / 2, inner / 2),
    ]
    return "\n".join(
        f'    <geom name="{n}" type="box" pos="{x:.3f} {y:.3f} {height / 2:.3f}" '
        f'size="{sx:.3f} {sy:.3f} {height / 2:.3f}" rgba="{rgba}"/>' for n, x, y, sx, sy in walls)


def cubes(count, cx, cy, layers_z, prefix="cube"):
    """A pile of 4 x 2 cubes per layer: 6 cm apart along x, 12 cm along y, so the fingers
    (which close along y) fit between the rows."""
    bodies = []
    numerics = []
    k = 0
    for z in layers_z:
        for i in range(4):
            for j in range(2):
                if k == count:
                    break
                x = cx + (i - 1.5) * 0.06
                y = cy + (j - 0.5) * 0.12
                bodies.append(
                    f'    <body name="{prefix}_{k}" pos="{x:.3f} {y:.3f} {z:.3f}">\n'
                    f'      <freejoint/>\n'
                    f'      <geom type="box" size="{CUBE} {CUBE} {CUBE}" mass="{CUBE_MASS}" '
                    f'friction="{SLIPPERY}" {OBJECT_CONTACT} rgba="0.93 0.9 0.78 1"/>\n'
                    f'    </body>')
                numerics.append(f'    <numeric name="fragile:{prefix}_{k}" data="120"/>')
                k += 1
    return "\n".join(bodies), "\n".join(numerics)


# jacobian="sparse": with a dozen resting cubes this is 1.5x faster than MuJoCo's automatic
# (dense) choice here.
HEADER = """<!-- SPDX-License-Identifier: MIT -->
<!-- Generated by scripts/make-scenes.py: edit that, not this file. -->
<mujoco model="{model}">
  <compiler autolimits="true" angle="radian"/>
  <option timestep="0.002" cone="elliptic" impratio="10" jacobian="sparse" gravity="0 0 -9.81"/>
  <size nconmax="{nconmax}" njmax="{njmax}" nstack="1000000"/>
  <visual>
    <global offwidth="1920" offheight="1080"/>
    <quality shadowsize="2048"/>
    <!-- The headlight and the lamp add up where both face a surface (the top view): MuJoCo's
         default headlight (diffuse 0.4, specular 0.5) with the lamp burnt the floor and the
         cubes to white. Together they light a face turned to both at 0.95. -->
    <headlight ambient="0.2 0.2 0.2" diffuse="0.35 0.35 0.35" specular="0.1 0.1 0.1"/>
  </visual>
  <default>
    <!-- Taxels collide with the world (contype 1) but not with each other (2 & 1 = 0), so
         closing on nothing cannot lock the fingers' grids together. -->
    <default class="taxel">
      <geom type="sphere" size="{taxel}" margin="0.0005" gap="0.0005" friction="1 0.005 0.0001"
            contype="2" conaffinity="1"
            rgba="0.2 0.2 0.25 1" mass="0.001" condim="3"/>
    </default>
  </default>
  <asset>
    <!-- A pale sky, so the viewport shows no black void above the floor. -->
    <texture name="sky" type="skybox" builtin="gradient" rgb1="0.93 0.95 0.97"
             rgb2="0.62 0.70 0.80" width="256" height="256"/>
    <texture name="grid" type="2d" builtin="checker" rgb1="0.82 0.84 0.86" rgb2="0.74 0.76 0.78"
             width="512" height="512"/>
    <!-- Matte, not a mirror: MuJoCo 2.2 draws a reflective plane's mirror image of the scene
         wherever the plane shows, also between a wall and the box floor behind it, so the
         pads' and the walls' reflections showed through the boxes and a white strip ran
         under the partition. -->
    <material name="floor" texture="grid" texrepeat="8 8" specular="0.1" shininess="0.2"/>
  </asset>"""


def opening(model, fragile):
    """Everything a scene has before its own bodies: options, assets, the cube count and
    fragile thresholds, light and floor."""
    return HEADER.format(model=model, nconmax=400, njmax=1500, taxel=TAXEL_R) + f"""
  <custom>
    <numeric name="semhap:cubes" data="12"/>
{fragile}
  </custom>
  <worldbody>
    <light pos="0 -0.3 1.2" dir="0 0.2 -1" diffuse="0.4 0.4 0.4" specular="0.1 0.1 0.1"/>
    <geom name="floor" type="plane" size="1 1 0.05" material="floor"/>"""


def box_and_block(max_cubes=24):
    pile, fragile = cubes(max_cubes, -0.15, 0.0,
                          (CUBE + 0.001, 3 * CUBE + 0.003, 5 * CUBE + 0.005))
    return opening("box_and_block", fragile) + f"""
{open_box("box.a", -0.15, 0.0, 0.26, 0.06, 0.01, "0.55 0.42 0.3 1")}
{open_box("box.b", 0.15, 0.0, 0.26, 0.06, 0.01, "0.55 0.42 0.3 1")}
    <geom name="partition" type="box" pos="0 0 0.075" size="0.005 0.14 0.075"
          rgba="0.5 0.38 0.27 1"/>
    <site name="pick" type="box" pos="-0.15 0 0.05" size="0.13 0.13 0.05" rgba="0 0 0 0"/>
    <site name="place" type="box" pos="0.15 0 0.05" size="0.13 0.13 0.05" rgba="0 0 0 0"/>
{gripper("right", (-0.15, 0.0, 0.3), 0.045, "0.35 0.45 0.6 1")}
{pile}
  </worldbody>
{one_hand_closing("right")}
</mujoco>
"""


def bimanual_sorting(max_cubes=16):
    pile, fragile = cubes(max_cubes, 0.2, 0.0, (CUBE + 0.001, 3 * CUBE + 0.003))
    container_half = 0.06    # a 12 cm square container: four cubes side by side
    wall = 0.004
    height = 0.09
    walls = []
    for n, x, y, sx, sy in (("n", 0, container_half - wall / 2, container_half, wall / 2),
                            ("s", 0, -container_half + wall / 2, container_half, wall / 2),
                            ("e", container_half - wall / 2, 0, wall / 2, container_half),
                            ("w", -container_half + wall / 2, 0, wall / 2, container_half)):
        walls.append(f'      <geom name="container.wall.{n}" type="box" '
                     f'pos="{x:.4f} {y:.4f} {height / 2:.4f}" '
                     f'size="{sx:.4f} {sy:.4f} {height / 2:.4f}" mass="0.07" '
                     f'friction="0.1 0.005 0.0001" {OBJECT_CONTACT} rgba="0.4 0.65 0.7 1"/>')
    return opening("bimanual_sorting", fragile) + f"""
    <geom name="container.base" type="cylinder" pos="-0.2 0 0.01" size="0.075 0.01"
          rgba="0.45 0.45 0.5 1"/>
{open_box("box.cubes", 0.2, 0.0, 0.26, 0.04, 0.01, "0.55 0.42 0.3 1")}
    <body name="container" pos="-0.2 0 0.021">
      <freejoint/>
      <geom name="container.floor" type="box" pos="0 0 0.002" size="{container_half:.4f} {container_half:.4f} 0.002"
            mass="0.02" friction="0.1 0.005 0.0001" {OBJECT_CONTACT} rgba="0.4 0.65 0.7 1"/>
{chr(10).join(walls)}
    </body>
    <site name="pick" type="box" pos="0.2 0 0.05" size="0.13 0.13 0.05" rgba="0 0 0 0"/>
    <site name="home" type="sphere" pos="-0.2 0 0.021" size="0.01" rgba="0 0 0 0"/>
{gripper("left", (-0.2, 0.0, 0.3), 0.08, "0.6 0.45 0.35 1")}
{gripper("right", (0.2, 0.0, 0.3), 0.045, "0.35 0.45 0.6 1")}
{pile}
  </worldbody>
  <contact>{gripper_exclusions("left")}{gripper_exclusions("right")}
  </contact>
  <equality>{gripper_equality("left")}{gripper_equality("right")}
  </equality>
  <actuator>{gripper_actuators("left", 160)}{gripper_actuators("right", 160)}
  </actuator>
</mujoco>
"""


# usb_insertion: a USB-A plug (its 12 x 4.5 mm shell, 40 mm long with the overmould the
# fingers take) standing on the table, and a port block with a rectangular opening of
# USB_CLEARANCE per side. The plug is taken by its upper part so that, seated 12 mm deep, the
# pads' lowest taxels stay 3 mm above the port's face.
USB_HALF = (0.006, 0.00225, 0.02)   # the plug's half sizes: width, thickness, length
USB_CLEARANCE = 0.0003              # the opening's play per side (m)
USB_DEPTH = 0.012                   # how deep the opening is: the plug seated
PORT_HALF = (0.02, 0.015)           # the port block's half sizes on the table
PORT_TOP = 0.025                    # the height of the port's face


def usb_port():
    """The port: a mocap body (the task moves it to a seeded pose; sessions record where),
    four walls around the opening over a base, a site at the mouth (its z axis points into
    the opening) and a touch site around the block."""
    hx, hy = USB_HALF[0] + USB_CLEARANCE, USB_HALF[1] + USB_CLEARANCE
    px, py = PORT_HALF
    base = PORT_TOP - USB_DEPTH
    wz = base + USB_DEPTH / 2
    walls = [("n", 0, (py + hy) / 2, px, (py - hy) / 2), ("s", 0, -(py + hy) / 2, px, (py - hy) / 2),
             ("e", (px + hx) / 2, 0, (px - hx) / 2, hy), ("w", -(px + hx) / 2, 0, (px - hx) / 2, hy)]
    geoms = "\n".join(
        f'      <geom name="port.wall.{n}" type="box" pos="{x:.5f} {y:.5f} {wz:.4f}" '
        f'size="{sx:.5f} {sy:.5f} {USB_DEPTH / 2:.4f}" rgba="0.62 0.64 0.68 1"/>'
        for n, x, y, sx, sy in walls)
    return f"""
    <body name="port" mocap="true" pos="0.1 0 0">
      <geom name="port.base" type="box" pos="0 0 {base / 2:.4f}" size="{px} {py} {base / 2:.4f}"
            rgba="0.62 0.64 0.68 1"/>
{geoms}
      <geom name="port.tongue" type="box" pos="0 0 {base + 0.0005:.4f}" size="{hx:.5f} {hy:.5f} 0.0005"
            rgba="0.1 0.3 0.8 1" contype="0" conaffinity="0"/>
      <site name="port.mouth" pos="0 0 {PORT_TOP}" euler="3.14159265358979 0 0" size="0.001"/>
      <site name="port.touch" type="box" pos="0 0 {PORT_TOP / 2:.4f}"
            size="{px + 0.001} {py + 0.001} {PORT_TOP / 2 + 0.001:.4f}" rgba="0 0 0 0"/>
    </body>"""


def usb_insertion():
    x, y, z = USB_HALF
    signals = "\n".join(
        f'    <text name="signal:right:{n}" data="{d}"/>'
        for n, d in (("plug.lateral", "across port.mouth plug.tip z"),
                     ("plug.angle", "angle port.mouth x plug x"),
                     ("plug.depth", "along port.mouth plug.tip z"),
                     ("plug.force", "sensor port.force")))
    return HEADER.format(model="usb_insertion", nconmax=200, njmax=800, taxel=TAXEL_R) + f"""
  <custom>
    <text name="semhap:task" data="usb_insertion"/>
{signals}
  </custom>
  <worldbody>
    <light pos="0 -0.3 1.2" dir="0 0.2 -1" diffuse="0.4 0.4 0.4" specular="0.1 0.1 0.1"/>
    <geom name="floor" type="plane" size="1 1 0.05" material="floor"/>
{usb_port()}
    <body name="plug" pos="-0.1 0 {z + 0.0005:.4f}">
      <freejoint/>
      <geom name="plug.shell" type="box" size="{x} {y} {z}" mass="0.01"
            friction="0.6 0.005 0.0001" {OBJECT_CONTACT} rgba="0.75 0.75 0.78 1"/>
      <site name="plug.tip" pos="0 0 {-z}" size="0.001"/>
    </body>
{gripper("right", (-0.1, 0.0, 0.3), 0.045, "0.35 0.45 0.6 1")}
  </worldbody>
{one_hand_closing("right")}
  <sensor>
    <touch name="port.force" site="port.touch"/>
  </sensor>
</mujoco>
"""


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "resources", "scenes")
    os.makedirs(root, exist_ok=True)
    for name, text in (("box_and_block", box_and_block()), ("bimanual_sorting", bimanual_sorting()),
                       ("usb_insertion", usb_insertion())):
        with open(os.path.join(root, name + ".xml"), "w") as out:
            out.write(text)


if __name__ == "__main__":
    main()
