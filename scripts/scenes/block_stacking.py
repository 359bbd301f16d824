# SPDX-License-Identifier: MIT
"""block_stacking: six wooden blocks in an open box, stacked by the right gripper into a
tower five high on a base beside it (docs/metrics.md, sim/README.md)."""
from parts import CUBE, OBJECT_CONTACT, gripper, closing, open_box, opening

BLOCKS = 6
PILE_X = -0.15
TOWER_X = 0.15
BASE_TOP = 0.02          # the base's face, where the tower's first block stands
# Wood on wood: grippier than the cube tasks' slippery cubes, so that a tower stands.
WOOD = "0.5 0.005 0.0001"


def blocks():
    """One layer of 3 x 2 blocks, 6 cm apart along x and 12 cm along y (the fingers close
    along y, between the rows)."""
    bodies = []
    for k in range(BLOCKS):
        i, j = divmod(k, 2)
        x = PILE_X + (i - 1) * 0.06
        y = (j - 0.5) * 0.12
        bodies.append(
            f'    <body name="block_{k}" pos="{x:.3f} {y:.3f} {CUBE + 0.001:.3f}">\n'
            f'      <freejoint/>\n'
            f'      <geom type="box" size="{CUBE} {CUBE} {CUBE}" mass="0.08" '
            f'friction="{WOOD}" {OBJECT_CONTACT} rgba="0.82 0.66 0.44 1"/>\n'
            f'    </body>')
    return "\n".join(bodies)


def scene():
    custom = '    <text name="semhap:task" data="block_stacking"/>'
    return opening("block_stacking", custom) + f"""
{open_box("box.pile", PILE_X, 0.0, 0.26, 0.04, 0.01, "0.55 0.42 0.3 1")}
    <geom name="tower.base" type="box" pos="{TOWER_X} 0 {BASE_TOP / 2}"
          size="0.04 0.04 {BASE_TOP / 2}" friction="{WOOD}" rgba="0.4 0.45 0.5 1"/>
    <site name="pick" type="box" pos="{PILE_X} 0 0.05" size="0.13 0.13 0.05" rgba="0 0 0 0"/>
    <site name="tower" type="sphere" pos="{TOWER_X} 0 {BASE_TOP}" size="0.005" rgba="0 0 0 0"/>
{gripper("right", (PILE_X, 0.0, 0.3), 0.045, "0.35 0.45 0.6 1")}
{blocks()}
  </worldbody>
{closing(["right"])}
</mujoco>
"""
