# SPDX-License-Identifier: MIT
"""dish_wiping: the left gripper holds a plate, the right wipes it with a sponge."""
from parts import gripper, closing, opening


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


def scene():
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
