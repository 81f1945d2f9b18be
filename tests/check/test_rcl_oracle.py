"""check controllers' reading of a parameters file's layout, against rcl's own reader.

tests/check/rcl_oracle holds rcl_yaml_param_parser (with the rmw name checks and the rcutils it
needs), what ros2_control_node reads its --params-file with, built here against libyaml. A file
it accepts, check.rcl_layout accepts; a layout it refuses (a value outside every
ros__parameters, an empty one, a value with nothing, a node or namespace name rmw refuses),
rcl_layout refuses, quoting rcl's own words.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
import yaml

from servicebot_cli.check.rcl_layout import layout_issue
from tests.conftest import REPO

ORACLE = REPO / "tests" / "check" / "rcl_oracle"
BUNDLED = (REPO / "robots" / "controllers.yaml").read_text()


@pytest.fixture(scope="session")
def rcl_reader(tmp_path_factory):
    """The built reader; skipped, saying why, without a C compiler or libyaml's header."""
    compiler = shutil.which("gcc") or shutil.which("cc")
    if compiler is None:
        pytest.skip("no C compiler to build rcl's parameter reader (.ci/run installs gcc)")
    if not any(Path(d, "yaml.h").is_file() for d in ("/usr/include", "/usr/local/include")):
        pytest.skip("no libyaml header to build rcl's parameter reader (apt-get install "
                    "libyaml-dev; .ci/run does)")
    binary = tmp_path_factory.mktemp("rcl") / "rclyaml"
    sources = [ORACLE / "main.c", *sorted(ORACLE.glob("rcl/rcl_yaml_param_parser/src/*.c")),
               *sorted(ORACLE.glob("rmw/rmw/src/*.c")), *sorted(ORACLE.glob("rcutils/src/*.c"))]
    subprocess.run([compiler, "-O0", "-w", "-o", str(binary), *map(str, sources),
                    f"-I{ORACLE / 'rcl/rcl_yaml_param_parser/include'}",
                    f"-I{ORACLE / 'rcutils/include'}", f"-I{ORACLE / 'rmw/rmw/include'}",
                    "-lyaml"], check=True, capture_output=True)
    return binary


def _verdicts(reader: Path, path: Path) -> tuple[str, str | None]:
    """rcl's answer (ACCEPT or REFUSE and its words), and rcl_layout's message or None."""
    said = subprocess.run([str(reader), str(path)], capture_output=True, text=True).stdout
    issue = layout_issue(yaml.parse(path.read_text(), Loader=yaml.SafeLoader), str(path))
    return said.strip(), None if issue is None else issue.message


_HEAD, _ARM = BUNDLED.split("\narm_controller:\n", 1)
CASES = {
    "as written": BUNDLED,
    "/** for every node": "/**:\n  ros__parameters:\n    use_sim_time: true\n" + BUNDLED,
    "/*/ and ** wildcards": BUNDLED + "/*/robot1/**:\n  ros__parameters:\n    a: 1\n",
    "a namespace": BUNDLED + "robot1:\n  extra_node:\n    ros__parameters:\n      a: 1\n",
    "/ as a namespace": "/:\n  my_node:\n    ros__parameters:\n      a: 'b'\n" + BUNDLED,
    "a quoted empty string": BUNDLED + "extra_node:\n  ros__parameters:\n    name: ''\n",
    "an empty mapping last": BUNDLED + "extra_node:\n  ros__parameters:\n    a: 1\n    b: {}\n",
    "use_sim_time at the top": "use_sim_time: true\n" + BUNDLED,
    "use_sim_time beside ros__parameters": BUNDLED.replace(
        "controller_manager:\n", "controller_manager:\n  use_sim_time: true\n", 1),
    "ROS 1's type": _HEAD + "\narm_controller:\n  type: joint_trajectory_controller/"
    "JointTrajectoryController\n" + _ARM,
    "an empty ros__parameters": BUNDLED + "extra_node:\n  ros__parameters:\n",
    "a list outside": BUNDLED + "extra:\n  - a\n",
    "no node name": "ros__parameters:\n  a: 1\n" + BUNDLED,
    "a parameter with nothing": BUNDLED + "extra_node:\n  ros__parameters:\n    frame_id:\n",
    "an empty mapping among parameters": BUNDLED + "extra_node:\n  ros__parameters:\n    a: {}"
    "\n    b: 1\n",
    "a hyphen in a node name": BUNDLED + "extra-node:\n  ros__parameters:\n    a: 1\n",
    "a digit first": BUNDLED + "2wd_controller:\n  ros__parameters:\n    a: 1\n",
    "a hyphen in a namespace": BUNDLED + "my-robot/extra:\n  ros__parameters:\n    a: 1\n",
    "a doubled slash": BUNDLED + "robot1//extra:\n  ros__parameters:\n    a: 1\n",
    "an empty parameter name": BUNDLED + "extra:\n  ros__parameters:\n    '': 1\n",
    "an empty node name": BUNDLED + "'':\n  ros__parameters:\n    a: 1\n",
    "a section nested beside ros__parameters": BUNDLED.replace(
        "\ndiff_controller:\n  ros__parameters:\n", "\n  diff_controller:\n    ros__parameters:\n"
        "      left_wheel_names: [front_left_wheel_joint]\n", 1),
    "an empty mapping deeper": BUNDLED + "extra:\n  ros__parameters:\n    x:\n      y: {}\n"
    "    z: 1\n",
    "a node name over 255 characters": BUNDLED + f"{'n' * 256}:\n  ros__parameters:\n"
    "    a: 1\n",
    "a node name of 255 characters": BUNDLED + f"{'n' * 255}:\n  ros__parameters:\n    a: 1\n",
    "ros__parameters twice": BUNDLED + "extra:\n  ros__parameters:\n    x: 1\n"
    "  ros__parameters:\n    y: 2\n",
}


@pytest.mark.parametrize("name", list(CASES))
def test_rcl_layout_refuses_what_rcl_refuses(rcl_reader, tmp_path, name):
    path = tmp_path / "controllers.yaml"
    path.write_text(CASES[name])
    said, message = _verdicts(rcl_reader, path)
    assert said.startswith(("ACCEPT", "REFUSE")), said
    assert (message is None) == said.startswith("ACCEPT"), (said, message)
    if message is not None:  # the words it quotes are rcl's, line included
        quoted = message.split("rcl refuses the whole file ('", 1)[1].split("')", 1)[0]
        assert quoted in said, (quoted, said)


def _read_alike(path: Path) -> bool:
    """A YAML controllers file of the tests that no launch file rewrites first."""
    text = path.read_text(errors="replace")
    if "ros__parameters" not in text or any(mark in text for mark in ("$", "<", "*")):
        return False
    try:
        yaml.safe_load(text)
    except yaml.YAMLError:  # not YAML (SB601's fixture): nothing to compare
        return False
    return True


@pytest.mark.parametrize("path", sorted(p for p in (REPO / "tests").rglob("*.yaml")
                                        if _read_alike(p)),
                         ids=lambda p: str(p.relative_to(REPO)))
def test_every_controllers_file_of_the_tests_reads_alike(rcl_reader, path):
    said, message = _verdicts(rcl_reader, path)
    assert (message is None) == said.startswith("ACCEPT"), (said, message)
