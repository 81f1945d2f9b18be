"""A YAML alias bomb (500 bytes, a billion items when walked) is refused at once.

``check controllers`` took over 60 s and 5 GB on one in ``left_wheel_names``; the
parameters reader (inspect, simulate) walks what it reads too.
"""

from __future__ import annotations

import json
import time

from servicebot_cli.description.yaml_size import unfolded_nodes
from tests.check.helpers import findings

LEVELS = ["a: &a [x, x, x, x, x, x, x, x, x]"] + [
    f"{chr(98 + i)}: &{chr(98 + i)} [{', '.join(['*' + chr(97 + i)] * 9)}]" for i in range(8)]
BOMB = "\n".join(["bombs:", *("  " + line for line in LEVELS), """
controller_manager:
  ros__parameters:
    diff_controller: {type: diff_drive_controller/DiffDriveController}
diff_controller:
  ros__parameters:
    left_wheel_names: *i
    right_wheel_names: *i
"""])


def test_the_unfolded_size_counts_each_shared_node_once_and_stops_at_a_loop():
    import yaml

    assert unfolded_nodes(yaml.compose("a: &x [1, 2]\nb: *x\n", Loader=yaml.SafeLoader)) == 9
    assert unfolded_nodes(yaml.compose("&a [*a]\n", Loader=yaml.SafeLoader)) is None


def test_check_controllers_refuses_an_alias_bomb_at_once(run, tmp_path):
    bomb = tmp_path / "controllers.yaml"
    bomb.write_text(BOMB)
    start = time.monotonic()
    result = run("check", "controllers", bomb, "--robot", "sim", "--format", "json",
                 "--isolated")
    assert time.monotonic() - start < 10
    (found,) = findings(result.stdout)
    assert found["code"] == "SB601" and "unfold to over 1,000,000 items" in found["message"]
    assert json.loads(result.stdout)["summary"]["errors"] == 1


def test_xacros_load_yaml_refuses_an_alias_bomb_and_reads_a_real_file(run, tmp_path):
    """load_yaml of the bomb built a 2.3-billion-character string (35 s, 4.3 GB)."""
    (tmp_path / "bomb.yaml").write_text(BOMB)
    (tmp_path / "limits.yaml").write_text("shoulder: {lower: -1.5, upper: 1.5}\n")
    robot = tmp_path / "r.urdf.xacro"
    body = ('<xacro:property name="y" value="${{xacro.load_yaml(\'{}\')}}"/>'
            '<link name="a${{len(str(y))}}"/>')
    robot.write_text('<robot xmlns:xacro="http://wiki.ros.org/xacro" name="r">'
                     + body.format("bomb.yaml") + "</robot>")
    start = time.monotonic()
    result = run("expand", robot)
    assert time.monotonic() - start < 10
    assert result.exit_code == 2
    assert "load_yaml: its aliases (*name) unfold to over 1,000,000 items" in result.stderr
    robot.write_text('<robot xmlns:xacro="http://wiki.ros.org/xacro" name="r">'
                     + body.format("limits.yaml") + "</robot>")
    result = run("expand", robot)
    assert result.exit_code == 0, result.stderr
    assert '<link name="a' in result.stdout
