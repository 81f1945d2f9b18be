"""Controllers files in the layouts ros2_control reads, the same for inspect and simulate:
nodes under namespaces (``/**:``) or keyed by a path, types declared in the controller's own
parameters (Jazzy)."""

from __future__ import annotations

import json
from pathlib import Path

import yaml

from servicebot_cli.description.ros_parameters import controller_types, node_parameters
from servicebot_cli.inspect.controllers import parse_controllers
from servicebot_cli.simulate.controllers.config import read_controllers_file

NAMESPACED = """\
/**:
  controller_manager:
    ros__parameters:
      update_rate: 40
      joint_state_broadcaster:
        type: joint_state_broadcaster/JointStateBroadcaster
  base_controller:
    ros__parameters:
      type: diff_drive_controller/DiffDriveController
      wheel_separation: 0.233
      linear:
        x:
          max_velocity: 0.3
/robot1/tool_controller:
  ros__parameters:
    type: forward_command_controller/ForwardCommandController
"""


def test_nodes_under_namespaces_and_paths_and_their_types():
    nodes = node_parameters(yaml.safe_load(NAMESPACED))
    assert list(nodes) == ["controller_manager", "base_controller", "tool_controller"]
    assert controller_types(nodes) == {
        "joint_state_broadcaster": "joint_state_broadcaster/JointStateBroadcaster",
        "base_controller": "diff_drive_controller/DiffDriveController",
        "tool_controller": "forward_command_controller/ForwardCommandController"}


def test_inspect_and_simulate_read_the_same_controllers(tmp_path: Path):
    path = tmp_path / "control.yaml"
    path.write_text(NAMESPACED)
    listed = parse_controllers(yaml.safe_load(NAMESPACED), str(path), "--controllers")
    assert [c.name for c in listed.controllers] == [
        "joint_state_broadcaster", "base_controller", "tool_controller"]
    read = read_controllers_file(path)
    assert read.name == "base_controller"
    assert read.values["update_rate_hz"] == 40
    assert read.values["max_linear_velocity_m_s"] == 0.3


TWO_TYPES = """\
controller_manager:
  ros__parameters:
    arm_controller:
      type: vendor_controllers/ArmController
    joint_state_broadcaster:
      type: joint_state_broadcaster/JointStateBroadcaster
arm_controller:
  ros__parameters:
    type: joint_trajectory_controller/JointTrajectoryController
    joints: [arm_joint_1]
"""


def test_a_controllers_own_type_wins_over_the_managers_as_the_spawner_sets_it():
    types = controller_types(node_parameters(yaml.safe_load(TWO_TYPES)))
    assert types == {"arm_controller": "joint_trajectory_controller/JointTrajectoryController",
                     "joint_state_broadcaster": "joint_state_broadcaster/JointStateBroadcaster"}
    assert list(types) == ["arm_controller", "joint_state_broadcaster"]


def test_inspect_lists_the_type_check_controllers_reads(run, tmp_path: Path):
    path = tmp_path / "controllers.yaml"
    path.write_text(TWO_TYPES.replace("arm_joint_1", "no_such_joint"))
    listed = parse_controllers(yaml.safe_load(path.read_text()), str(path), "--controllers")
    arm = next(c for c in listed.controllers if c.name == "arm_controller")
    assert arm.type == "joint_trajectory_controller/JointTrajectoryController"
    # a ros2_controllers type names URDF joints (a vendor's need not): check looks for it
    checked = run("check", "controllers", path)
    assert "no_such_joint" in checked.stdout + checked.stderr


def test_a_dotted_type_key_is_the_controllers_type(run, tmp_path):
    """Clearpath's control.yaml declares 'platform_velocity_controller.type: ...' under
    controller_manager: the same ROS 2 parameter as a nested type. simulate and inspect
    read only the nested form, so the diff drive and its limits went unread; the controller
    configuration of the bundled robot, written dotted, must run as the nested one does."""
    import re

    from servicebot_cli.description.ros_parameters import controller_types
    from tests.conftest import REPO

    nested = (REPO / "robots" / "controllers.yaml").read_text()
    dotted = re.sub(r"\n(\s+)(\w+):\n\s+type: (\S+)", r"\n\1\2.type: \3", nested)
    assert dotted != nested and ".type: diff_drive_controller" in dotted
    types = controller_types({"controller_manager": {"a.type": "x/Y", "b": {"type": "p/Q"}}})
    assert types == {"a": "x/Y", "b": "p/Q"}
    distances = []
    for text in (nested, dotted):
        path = tmp_path / "controllers.yaml"
        path.write_text(text)
        result = run("simulate", "--headless", "--duration-s", "1", "--controllers", path,
                     "--format", "json")
        assert result.exit_code == 0, result.stderr
        distances.append(json.loads(result.stdout)["distance_m"])
    assert distances[0] == distances[1]
