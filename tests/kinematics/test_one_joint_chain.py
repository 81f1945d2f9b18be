"""ik on a robot of one joint (gz_ros2_control_demos' cart on a rail): Pinocchio hands a
(6, 1) Jacobian back as a flat (6,) array, and ik ended with an internal error (exit 3)."""

from __future__ import annotations

import json

import pytest

CART = """<robot name="cart">
  <link name="world"/>
  <link name="rail"/>
  <link name="cart"><inertial><mass value="1"/>
    <inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="world_to_rail" type="fixed"><origin xyz="0 0 1"/>
    <parent link="world"/><child link="rail"/></joint>
  <joint name="rail_to_cart" type="{kind}"><axis xyz="1 0 0"/>
    <parent link="rail"/><child link="cart"/>
    <limit lower="-15" upper="15" effort="10" velocity="1"/></joint>
</robot>
"""


@pytest.mark.parametrize("kind", ["prismatic", "revolute"])
def test_a_one_joint_robot_is_solved_or_told_why_not(run, tmp_path, kind):
    robot = tmp_path / "cart.urdf"
    robot.write_text(CART.format(kind=kind))
    reachable = run("ik", robot, "-f", "cart", "--position", "0.3", "0", "1", "--format", "json")
    assert reachable.exit_code == 0 if kind == "prismatic" else reachable.exit_code in (0, 1)
    assert "internal error" not in reachable.stderr
    if kind == "prismatic":
        answer = json.loads(reachable.stdout)  # unseeded: any answer within ik's 1e-6 m
        assert answer["position_error_m"] <= 1e-6
        assert answer["joints"]["rail_to_cart"] == pytest.approx(0.3, abs=1e-6)
    off_the_rail = run("ik", robot, "-f", "cart", "--position", "0.3", "0.1", "0.4")
    assert off_the_rail.exit_code == 1, off_the_rail.stderr
    assert "internal error" not in off_the_rail.stderr
