"""SB502 and a sensor's range min: 0 is fine for a Gazebo Classic "ray", not for a GPU lidar.

pepper_description's sonars (ros-naoqi/pepper_robot, pepper1.0_generated_urdf) are "ray"
sensors with ``<range><min>0</min>``, sdformat's default: Gazebo Classic casts them in the
physics engine from the sensor out. A ``gpu_ray`` makes range min its camera's near clip,
which OGRE refuses at 0.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings

SONAR = """<robot name="sonar_bot">
  <link name="base_link">
    <inertial><mass value="1"/>
      <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <gazebo reference="base_link">
    <sensor name="SonarFront" type="{kind}">
      <update_rate>20</update_rate>
      <ray>
        <scan><horizontal><samples>5</samples><resolution>3</resolution>
          <min_angle>-0.52</min_angle><max_angle>0.52</max_angle></horizontal></scan>
        <range><min>{near}</min><max>5.0</max><resolution>0.01</resolution></range>
      </ray>
    </sensor>
  </gazebo>
</robot>
"""


@pytest.mark.parametrize(("kind", "near", "problem"), [
    ("ray", "0", None),
    ("ray", "-0.1", "range min -0.1 m must not be negative"),
    ("gpu_ray", "0", "range min 0 m must be positive"),
])
def test_range_min(run, tmp_path, kind, near, problem):
    robot = tmp_path / "sonar.urdf"
    robot.write_text(SONAR.format(kind=kind, near=near))
    result = run("check", "urdf", robot, "--format", "json", "--isolated", "--select", "SB502")
    messages = [f["message"] for f in findings(result.stdout)]
    if problem is None:
        assert messages == [] and result.exit_code == 0
    else:
        assert messages == [f"sensor 'SonarFront': {problem}"] and result.exit_code == 1


SINGLE_BEAM = """<robot name="r">
  <link name="base_link"/>
  <gazebo reference="base_link">
    <sensor type="ray" name="cliff">
      <ray>
        <scan><horizontal><samples>{samples}</samples><min_angle>0</min_angle>
          <max_angle>0</max_angle></horizontal></scan>
        <range><min>0.01</min><max>0.04</max></range>
      </ray>
    </sensor>
  </gazebo>
</robot>
"""


def test_a_single_beam_points_where_its_equal_angles_say(run, tmp_path):
    """create_robot's cliff and wall sensors: one sample, min_angle = max_angle = 0, which
    Gazebo reads as the ray's direction. Many samples at one angle stay an error."""
    for samples, expected in ((1, []), (5, ["SB502"])):
        robot = tmp_path / f"beam{samples}.urdf"
        robot.write_text(SINGLE_BEAM.format(samples=samples))
        result = run("check", robot, "--select", "SB502", "--format", "json", "--isolated")
        assert [f["code"] for f in findings(result.stdout)] == expected
