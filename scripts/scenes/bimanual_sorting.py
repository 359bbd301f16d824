# SPDX-License-Identifier: MIT
"""bimanual_sorting: the left gripper holds a container, the right sorts cubes into it."""
from parts import CUBE, OBJECT_CONTACT, gripper, closing, open_box, cubes, CUBE_COUNT, opening


def scene(max_cubes=16):
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
