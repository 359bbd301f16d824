# SPDX-License-Identifier: MIT
"""usb_insertion: a USB plug taken from the table and seated in a port."""
from parts import TAXEL_R, OBJECT_CONTACT, gripper, closing, HEADER


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


def scene():
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
