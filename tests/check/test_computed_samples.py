"""A LIDAR's ``<samples>`` as sdformat reads it: the leading digits (``std::stoul``).

PAL's pmb2 and TIAGo compute it in xacro from the resolution: ``220.00000000000003`` with
the SICK 551, ``666.518...`` with the default laser. sdformat reads 220 and 666 and says
nothing; check called both SB502 errors. Text without leading digits, or 0, stays an error.
"""

from __future__ import annotations

import pytest

from servicebot_cli.description.sensors import sdf_unsigned
from tests.check.helpers import findings
from tests.conftest import run_servicebot

ROBOT = """<robot name="base">
  <link name="base_link"/>
  <link name="laser"/>
  <joint name="laser_joint" type="fixed"><parent link="base_link"/><child link="laser"/></joint>
  <gazebo reference="laser"><sensor name="laser" type="ray"><update_rate>10</update_rate>
    <ray><scan><horizontal><samples>{samples}</samples><resolution>1</resolution>
      <min_angle>-1.9</min_angle><max_angle>1.9</max_angle></horizontal></scan>
      <range><min>0.05</min><max>10</max></range></ray>
    <plugin name="laser" filename="libgazebo_ros_ray_sensor.so"/></sensor></gazebo>
</robot>
"""


@pytest.mark.parametrize(("samples", "read", "refused"), [
    ("220.00000000000003", 220, False), ("666.518", 666, False), (" +640", 640, False),
    ("0.5", 0, True), ("-3", None, True), ("abc", None, True),
])
def test_samples_are_read_as_sdformat_reads_them(tmp_path, samples, read, refused):
    assert sdf_unsigned(samples) == read
    robot = tmp_path / "base.urdf"
    robot.write_text(ROBOT.format(samples=samples))
    result = run_servicebot("check", "urdf", robot, "--isolated", "--format", "json",
                            "--select", "SB502")
    assert ("SB502" in {f["code"] for f in findings(result.stdout)}) == refused


CAMERA = ROBOT.replace('type="ray"><update_rate>10</update_rate>', 'type="camera">').replace(
    ROBOT[ROBOT.index("<ray>"):ROBOT.index("</ray>") + 6],
    "<camera><horizontal_fov>1.0</horizontal_fov><image><width>{width}</width><height>480"
    "</height></image></camera>").replace("libgazebo_ros_ray_sensor.so", "libgazebo_ros_camera.so")


@pytest.mark.parametrize(("width", "said"), [
    ("640", None), ("640.7", None),  # an unsigned int, read as samples are: its leading digits
    ("wide", "image width 'wide' must be a positive whole number"),
    ("0", "image width '0' must be a positive whole number"),
    ("-640", "image width '-640' must be a positive whole number")])
def test_a_camera_image_size_is_read_as_sdformat_reads_it(tmp_path, width, said):
    """'wide' passed: the spec reader found no number and left the default."""
    robot = tmp_path / "cam.urdf"
    robot.write_text(CAMERA.format(width=width))
    result = run_servicebot("check", "urdf", robot, "--isolated", "--format", "json",
                            "--select", "SB502")
    assert [f["message"].split(": ", 1)[1] for f in findings(result.stdout)] == (
        [said] if said else [])
