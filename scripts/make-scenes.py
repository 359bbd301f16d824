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
import os

TAXEL_R = 0.004          # taxel sphere radius
TAXEL_PITCH = 0.010      # 4x4 grid, 1 cm apart: a 4 cm pad
CUBE = 0.025             # half size: 5 cm cubes
CUBE_MASS = 0.08
SLIPPERY = "0.1 0.005 0.0001"
OBJECT_CONTACT = 'priority="1" condim="3" solref="0.004 1" solimp="0.95 0.99 0.001"'


def gripper(hand, pos, half_open, rgba, quat=None, tool=""):
    """A parallel-jaw gripper, fingers down unless turned by `quat`; `half_open`: finger
    offset from centre; `tool`: bodies fixed to the wrist (a sponge)."""
    x, y, z = pos
    turn = f' quat="{quat}"' if quat else ""
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
    <body name="{hand}.target" mocap="true" pos="{x} {y} {z}"{turn}/>
    <body name="{hand}.gripper" pos="{x} {y} {z}"{turn}>
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
      </body>{tool}
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


def closing(hands, more_actuators=""):
    """The contact, equality and actuator sections of a scene with these grippers, and the
    scene's own actuators."""
    exclusions = "".join(gripper_exclusions(hand) for hand in hands)
    welds = "".join(gripper_equality(hand) for hand in hands)
    actuators = "".join(gripper_actuators(hand, 160) for hand in hands)
    return f"""  <contact>{exclusions}
  </contact>
  <equality>{welds}
  </equality>
  <actuator>{actuators}{more_actuators}
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


CUBE_COUNT = '    <numeric name="semhap:cubes" data="12"/>\n'

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


def opening(model, custom):
    """Everything a scene has before its own bodies: options, assets, its custom numbers and
    texts (the cube count, fragile thresholds, task, signals), light and floor."""
    return HEADER.format(model=model, nconmax=400, njmax=1500, taxel=TAXEL_R) + f"""
  <custom>
{custom}
  </custom>
  <worldbody>
    <light pos="0 -0.3 1.2" dir="0 0.2 -1" diffuse="0.4 0.4 0.4" specular="0.1 0.1 0.1"/>
    <geom name="floor" type="plane" size="1 1 0.05" material="floor"/>"""


def box_and_block(max_cubes=24):
    pile, fragile = cubes(max_cubes, -0.15, 0.0,
                          (CUBE + 0.001, 3 * CUBE + 0.003, 5 * CUBE + 0.005))
    return opening("box_and_block", CUBE_COUNT + fragile) + f"""
{open_box("box.a", -0.15, 0.0, 0.26, 0.06, 0.01, "0.55 0.42 0.3 1")}
{open_box("box.b", 0.15, 0.0, 0.26, 0.06, 0.01, "0.55 0.42 0.3 1")}
    <geom name="partition" type="box" pos="0 0 0.075" size="0.005 0.14 0.075"
          rgba="0.5 0.38 0.27 1"/>
    <site name="pick" type="box" pos="-0.15 0 0.05" size="0.13 0.13 0.05" rgba="0 0 0 0"/>
    <site name="place" type="box" pos="0.15 0 0.05" size="0.13 0.13 0.05" rgba="0 0 0 0"/>
{gripper("right", (-0.15, 0.0, 0.3), 0.045, "0.35 0.45 0.6 1")}
{pile}
  </worldbody>
{closing(["right"])}
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
    return opening("bimanual_sorting", CUBE_COUNT + fragile) + f"""
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
{closing(["left", "right"])}
</mujoco>
"""


# dish_wiping (docs/metrics.md, sim/README.md): a square ceramic plate on a stand, held at its rim by
# the left gripper turned on its side (its jaws close vertically); a sponge on a spring-loaded
# holder under the right wrist, whose force/torque sensor sits between the wrist and the sponge.
PLATE_R = 0.11           # half the side of the square plate
PLATE_HALF = 0.006
STAND_TOP = 0.10
STAINS = 6               # 6 x 6 cells over the plate's middle
STAIN_SPAN = 0.07        # half the side of the stained square
PLATE_BREAK = 40         # N: the press that breaks the plate (fragile:plate)
SPONGE = (0.035, 0.025, 0.015)   # half sizes: a 7 x 5 x 3 cm sponge
SPONGE_DROP = 0.105      # its centre below the wrist, at rest
SPONGE_STIFFNESS = 1000  # N/m: the holder's spring with the sponge, as the run begins
SPONGE_STIFFER = 1500    # N/m more once the seeded change has come (right.sponge.stiffen)
# Boxes, not cylinders: MuJoCo 2.2 collides cylinders through its general convex test, which
# gave the plate one or two contact points on the stand and pads, and it crept and spun away.
# Contact bits: the sponge (4) touches only the plate (4 | 1), so it never catches on the stand
# or the left fingers; the plate touches the world and the taxels (1) too.
SPONGE_BITS = 'contype="4" conaffinity="4"'
PLATE_BITS = 'contype="5" conaffinity="5"'
SOFT_CONTACT = 'condim="3" solref="0.004 1" solimp="0.95 0.99 0.001"'
# The sponge's face is foam: soft at first touch (impedance 0.5) and as firm as a hard contact
# (0.95) within its first millimetre, so the press stays the holder's spring's. With MuJoCo's
# hard default (0.9 at touch) the 80 g sponge bounced on the plate: each 2 ms step out of
# contact the spring's whole press kicked it back down, and the plate and the left fingertips
# rang with it every 20-50 ms.
SPONGE_CONTACT = 'condim="3" solref="0.03 1" solimp="0.5 0.95 0.001" solmix="10"'


def sponge_tool():
    sx, sy, sz = SPONGE
    return f"""
      <geom name="right.holder" type="box" pos="0 0 -0.05" size="0.012 0.012 0.045" mass="0.05"
            rgba="0.3 0.3 0.33 1" contype="0" conaffinity="0"/>
      <body name="right.sponge" pos="0 0 {-SPONGE_DROP}">
        <!-- The sponge and its spring-loaded holder as one spring (4 cm of travel); the
             stiffening actuator adds its gain times the compression when the task sets it. -->
        <joint name="right.sponge.press" type="slide" axis="0 0 1" stiffness="{SPONGE_STIFFNESS}"
               damping="20" range="-0.002 0.04" solreflimit="0.004 1"/>
        <geom name="right.sponge" type="box" size="{sx} {sy} {sz}" mass="0.08"
              rgba="0.96 0.78 0.2 1" friction="0.6 0.005 0.0001" {SPONGE_BITS} {SPONGE_CONTACT}/>
        <!-- The wrist's force/torque sensor, z pointing down: fz is the press on the plate. -->
        <site name="right.ft" pos="0 0 {sz}" quat="0 1 0 0" size="0.004"/>
        <site name="right.sponge.face" type="box" pos="0 0 {-sz}" size="{sx + 0.002} {sy + 0.002} 0.01"
              rgba="0 0 0 0"/>
      </body>"""


def stains():
    cell = 2 * STAIN_SPAN / STAINS
    geoms = []
    for i in range(STAINS):
        for j in range(STAINS):
            x = -STAIN_SPAN + (i + 0.5) * cell
            y = -STAIN_SPAN + (j + 0.5) * cell
            geoms.append(
                f'      <geom name="plate.stain.{i}.{j}" type="box" pos="{x:.4f} {y:.4f} '
                f'{PLATE_HALF + 0.0004:.4f}" size="{cell / 2 - 0.001:.4f} {cell / 2 - 0.001:.4f} 0.0004" '
                f'density="0" rgba="0.5 0.33 0.14 0.85" contype="0" conaffinity="0"/>')
    return "\n".join(geoms)


def dish_wiping():
    custom = f"""    <numeric name="fragile:plate" data="{PLATE_BREAK}"/>
    <text name="semhap:task" data="dish_wiping"/>
    <text name="semhap:router" data="wipe"/>
    <text name="signal:right:wrist.fz" data="sensor right.wrist.force z"/>
    <text name="signal:right:wrist.ft" data="sensor right.wrist.force x"/>
    <text name="signal:right:sponge.contact" data="sensor right.sponge.touch"/>"""
    plate_z = STAND_TOP + PLATE_HALF
    # The left jaws reach 4-8 cm from the wrist along its turned z axis (world +y): the pads
    # take the rim's outer 2.5 cm, clear of the stand (radius 8 cm) and of the sponge.
    left_y = -PLATE_R - 0.054
    sponge_rest = STAND_TOP + 2 * PLATE_HALF + 0.05
    stiffen = f"""
    <general name="right.sponge.stiffen" joint="right.sponge.press" gaintype="affine"
             gainprm="0 {-SPONGE_STIFFER} 0" ctrllimited="true" ctrlrange="0 1"/>"""
    return opening("dish_wiping", custom) + f"""
    <geom name="stand" type="box" pos="0 0 {STAND_TOP / 2}" size="0.08 0.08 {STAND_TOP / 2}"
          friction="1 0.005 0.0001" rgba="0.45 0.47 0.5 1"/>
    <body name="plate" pos="0 0 {plate_z:.4f}">
      <freejoint/>
      <geom name="plate.body" type="box" size="{PLATE_R} {PLATE_R} {PLATE_HALF}" mass="0.4"
            friction="0.3 0.005 0.0001" {PLATE_BITS} {SOFT_CONTACT} rgba="0.97 0.97 0.95 1"/>
{stains()}
    </body>
{gripper("left", (0.0, left_y, plate_z), 0.03, "0.6 0.45 0.35 1", quat="0.70710678 0.70710678 0 0")}
{gripper("right", (0.0, 0.0, sponge_rest + SPONGE_DROP + SPONGE[2]), 0.045, "0.35 0.45 0.6 1",
         tool=sponge_tool())}
  </worldbody>
{closing(["left", "right"], stiffen)}
  <sensor>
    <force name="right.wrist.force" site="right.ft"/>
    <torque name="right.wrist.torque" site="right.ft"/>
    <touch name="right.sponge.touch" site="right.sponge.face"/>
  </sensor>
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
    <text name="semhap:router" data="usb"/>
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
{closing(["right"])}
  <sensor>
    <touch name="port.force" site="port.touch"/>
  </sensor>
</mujoco>
"""


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "resources", "scenes")
    os.makedirs(root, exist_ok=True)
    for name, text in (("box_and_block", box_and_block()), ("bimanual_sorting", bimanual_sorting()),
                       ("usb_insertion", usb_insertion()), ("dish_wiping", dish_wiping())):
        with open(os.path.join(root, name + ".xml"), "w") as out:
            out.write(text)


if __name__ == "__main__":
    main()
