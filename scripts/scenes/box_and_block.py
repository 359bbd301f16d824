# SPDX-License-Identifier: MIT
"""box_and_block: the Box and Block Test with one gripper: cubes from box A over the
partition into box B."""
from parts import CUBE, gripper, closing, open_box, cubes, CUBE_COUNT, opening


def scene(max_cubes=24):
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
