"""The scenario's colours and the URDF's materials in the camera's frames.

A run's frame is read where ``camera_info``'s K projects an obstacle's centre: the pixel
shows the obstacle's colour, shaded (each channel scaled alike) and with the URDF camera's
noise (stddev 0.007, under 2 of 255).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np
import pytest

from tests.simulate.helpers import body, run

CAMERA_X_M = 0.275  # camera_joint's xyz in service_robot.urdf.xacro
CAMERA_Z_M = 0.05
SCENARIO = {
    "duration_s": 0.5,
    "camera": {"scale": 0.1, "rate_hz": 2},
    "world": {
        "boxes": [{"center_m": [1.4, 0.35, 0.3], "size_m": [0.3, 0.3, 0.6],
                   "color": "#ff0000"}],
        "cylinders": [{"center_m": [1.4, -0.4], "radius_m": 0.12, "height_m": 0.6,
                       "color": [0.0, 0.0, 1.0]}],
        "floor": {"color": [0.0, 0.5, 0.0]},
    },
}


@pytest.fixture(scope="module")
def frame_and_pixel():
    result = run(SCENARIO)
    info = result.camera
    fx, cx, fy, cy = info.k[0], info.k[2], info.k[4], info.k[5]
    camera = np.array([CAMERA_X_M, 0.0, body().base_height_m + CAMERA_Z_M])

    def pixel(world):
        """Row and column of a world point, projected with camera_info's K (one-based)."""
        x, y, z = np.asarray(world, dtype=float) - camera
        u, v = fx * -y / x + cx, fy * -z / x + cy
        return round(v) - 1, round(u) - 1

    return result.frames[-1].rgb.astype(int), pixel


def test_a_red_box_is_red_where_k_projects_its_centre(frame_and_pixel):
    rgb, pixel = frame_and_pixel
    red, green, blue = rgb[pixel([1.4, 0.35, 0.3])]
    assert red > 100 and green <= 6 and blue <= 6


def test_a_cylinder_given_as_a_list_is_blue_at_its_centre(frame_and_pixel):
    rgb, pixel = frame_and_pixel
    red, green, blue = rgb[pixel([1.4, -0.4, 0.3])]
    assert blue > 100 and red <= 6 and green <= 6


def test_the_floor_takes_its_colour_in_a_checker(frame_and_pixel):
    rgb, pixel = frame_and_pixel
    near, far = rgb[pixel([1.1, 0.1, 0.0])], rgb[pixel([2.5, 0.1, 0.0])]  # two 1 m squares
    for red, green, blue in (near, far):
        assert green > 50 and red <= 6 and blue <= 6
    lighter, darker = max(near[1], far[1]), min(near[1], far[1])
    assert darker / lighter == pytest.approx(0.8, abs=0.05)


def test_links_take_their_urdf_material_colour_inline_or_named(tmp_path):
    from servicebot_cli.description.loader import RobotSource, load
    from servicebot_cli.simulate.sensors.camera_colours import link_colours

    bundled = link_colours(load(RobotSource.bundled("sim")))
    assert bundled["base_link"] == (64, 64, 64)  # dark_grey: rgba 0.25 0.25 0.25 1
    assert bundled["arm_link1"] == (255, 128, 26)  # orange: rgba 1.0 0.5 0.1 1
    urdf = tmp_path / "two.urdf"
    robot = ET.Element("robot", name="two")
    ET.SubElement(ET.SubElement(robot, "material", name="teal"), "color", rgba="0 0.5 0.5 1")
    for name, material in (("a", ET.Element("material", name="teal")),
                           ("b", ET.Element("material", name="own")), ("c", None)):
        visual = ET.SubElement(ET.SubElement(robot, "link", name=name), "visual")
        ET.SubElement(ET.SubElement(visual, "geometry"), "sphere", radius="0.1")
        if material is not None:
            if name == "b":
                ET.SubElement(material, "color", rgba="1 1 0 1")
            visual.append(material)
    joint = ET.SubElement(robot, "joint", name="j", type="fixed")
    ET.SubElement(joint, "parent", link="a")
    ET.SubElement(joint, "child", link="b")
    joint = ET.SubElement(robot, "joint", name="k", type="fixed")
    ET.SubElement(joint, "parent", link="a")
    ET.SubElement(joint, "child", link="c")
    urdf.write_text(ET.tostring(robot, encoding="unicode"))
    colours = link_colours(load(RobotSource.of(urdf)))
    assert colours == {"a": (0, 128, 128), "b": (255, 255, 0)}  # c: the palette's
