"""SB501 for a <gazebo reference> a family's shared file writes for another robot's link.

interbotix_xsarm_descriptions' gazebo_configs macro writes a block for every link of every
arm into each arm: wx250s gets one for 'forearm_link', which px100 and the other small arms
beside it define. Gazebo ignores the block in wx250s and nothing changes: a warning naming
the sibling that defines the link. A name no robot defines stays an error. Real xacro
expands the files.
"""

from __future__ import annotations

from tests.check.helpers import findings

_SHARED = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:macro name="gazebo_configs">
    <gazebo reference="$(arg robot_name)/base_link"><material>Gazebo/Grey</material></gazebo>
    <gazebo reference="$(arg robot_name)/forearm_link"><material>Gazebo/Grey</material></gazebo>
    <gazebo reference="$(arg robot_name)/upper_forearm_link"><material>Gazebo/Grey</material>
    </gazebo>
    <gazebo reference="$(arg robot_name)/{stale}"><material>Gazebo/Grey</material></gazebo>
  </xacro:macro>
</robot>
"""
_ARM = """<?xml version="1.0"?>
<robot name="{name}" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <xacro:arg name="robot_name" default="{name}"/>
  <xacro:include filename="gazebo_configs.urdf.xacro"/>
  <link name="$(arg robot_name)/base_link"><visual><geometry><box size="0.1 0.1 0.1"/>
  </geometry></visual></link>
  <link name="$(arg robot_name)/{arm}"><visual><geometry><box size="0.1 0.1 0.1"/>
  </geometry></visual></link>
  <joint name="$(arg robot_name)/elbow" type="revolute"><parent link="$(arg robot_name)/base_link"/>
    <child link="$(arg robot_name)/{arm}"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <xacro:gazebo_configs/>
</robot>
"""


def _family(tmp_path, stale: str):
    (tmp_path / "gazebo_configs.urdf.xacro").write_text(_SHARED.replace("{stale}", stale))
    (tmp_path / "px100.urdf.xacro").write_text(_ARM.format(name="px100", arm="forearm_link"))
    big = tmp_path / "wx250s.urdf.xacro"
    big.write_text(_ARM.format(name="wx250s", arm="upper_forearm_link"))
    return big


def _sb501(run, path):
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB501")
    return {f["message"].split('"')[1]: f for f in findings(result.stdout)}


def test_a_block_for_a_siblings_link_is_a_warning(run, tmp_path):
    found = _sb501(run, _family(tmp_path, "upper_forearm_link"))
    assert list(found) == ["wx250s/forearm_link"]
    block = found["wx250s/forearm_link"]
    assert block["severity"] == "warning"
    assert "px100.urdf.xacro:7, another robot beside it, defines link " \
        "'$(arg robot_name)/forearm_link'" in block["message"]


def test_a_block_no_robot_of_the_family_has_stays_an_error(run, tmp_path):
    found = _sb501(run, _family(tmp_path, "forarm_link"))
    assert found["wx250s/forarm_link"]["severity"] == "error"
    assert found["wx250s/forearm_link"]["severity"] == "warning"


def test_a_file_of_the_same_name_is_not_the_shared_one(run, tmp_path):
    """robot_a and robot_b each include their own a/gazebo.urdf.xacro and b/gazebo.urdf.xacro:
    robot_a's block for lidar_link (only robot_b has one) is a typo of its laser_link."""
    for name, link in (("a", "laser_link"), ("b", "lidar_link")):
        (tmp_path / name).mkdir()
        (tmp_path / name / "gazebo.urdf.xacro").write_text(
            '<?xml version="1.0"?>\n<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
            '  <gazebo reference="lidar_link"><sensor name="l" type="ray"/></gazebo>\n</robot>\n')
        (tmp_path / f"robot_{name}.urdf.xacro").write_text(
            f'<?xml version="1.0"?>\n<robot name="{name}" '
            'xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
            f'  <xacro:include filename="{name}/gazebo.urdf.xacro"/>\n'
            '  <link name="base_link"><visual><geometry><box size="0.1 0.1 0.1"/></geometry>'
            f'</visual></link>\n  <link name="{link}"><visual><geometry><box size="0.1 0.1 0.1"/>'
            '</geometry></visual></link>\n  <joint name="j" type="fixed"><parent '
            f'link="base_link"/><child link="{link}"/></joint>\n</robot>\n')
    found = _sb501(run, tmp_path / "robot_a.urdf.xacro")
    assert found["lidar_link"]["severity"] == "error"
