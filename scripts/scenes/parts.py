# SPDX-License-Identifier: MIT
"""What the bundled scenes share: the gripper with its taxel pads, the header, boxes and
cube piles (scripts/make-scenes.py)."""

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
<!-- Generated by scripts/make-scenes.py from scripts/scenes/: edit those, not this file. -->
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
