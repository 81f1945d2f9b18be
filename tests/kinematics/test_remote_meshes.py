"""A mesh named by an http(s) address (Gazebo Fuel) is said to be remote, not a path.

ik and simulate read it as a relative path: 'http:/example.com/x.stl is not a file', and ik
sent the user to check, which passes it (SB410, information).
"""

from __future__ import annotations

from tests.conftest import assert_one_line_error, run_servicebot

URL = "https://fuel.gazebosim.org/1.0/OpenRobotics/models/Gripper/files/meshes/gripper.stl"
ROBOT = f"""<robot name="arm">
  <link name="base"/>
  <link name="link1"><collision><geometry><mesh filename="{URL}"/></geometry></collision>
  </link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="link1"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <link name="tip"/>
  <joint name="t" type="fixed"><parent link="link1"/><child link="tip"/>
    <origin xyz="0.3 0 0"/></joint>
</robot>
"""


def test_ik_says_the_mesh_is_remote_and_how_to_do_without(tmp_path):
    path = tmp_path / "arm.urdf"
    path.write_text(ROBOT)
    result = run_servicebot("ik", path, "--frame", "tip", "--position", "0", "0.3", "0.1")
    line = assert_one_line_error(result, 2, f"collision mesh '{URL}' of link 'link1' is "
                                 "fetched over the network", "--allow-collisions")
    assert "https:/fuel" not in line
    allowed = run_servicebot("ik", path, "--frame", "tip", "--position", "0", "0.3", "0.1",
                             "--allow-collisions", "--seed", "1")
    assert allowed.returncode == 0, allowed.stderr
    checked = run_servicebot("check", "urdf", path, "--isolated")
    assert "SB410 [remote-mesh]" in checked.stdout and checked.returncode == 0
