"""A model too deep or too large for Pinocchio: one line, no crash, no runaway memory.

Pinocchio's parser recurses once per joint: a 4,000-link chain overflowed the stack and
every command that builds the model died with a segmentation fault (exit 139, nothing
printed; a worker of a multi-file check hung the run).
"""

from __future__ import annotations

import json

from servicebot_cli.description.model import MOST_JOINTS_DEEP, MOST_MOVING_JOINTS, tree_depth
from tests.conftest import assert_one_line_error


def _chain(links: int, kind: str = "revolute") -> str:
    joints = "".join(f'<joint name="j{i}" type="{kind}"><parent link="l{i}"/>'
                     f'<child link="l{i + 1}"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" '
                     'effort="1" velocity="1"/></joint>' for i in range(links - 1))
    names = "".join(f'<link name="l{i}"/>' for i in range(links))
    return f'<robot name="snake">{names}{joints}</robot>'



def test_depth_counts_the_longest_path_and_goes_round_a_loop_once():
    assert tree_depth(_chain(5)) == 4
    loop = ('<robot name="r"><joint name="a"><parent link="x"/><child link="y"/></joint>'
            '<joint name="b"><parent link="y"/><child link="x"/></joint></robot>')
    assert tree_depth(loop) == 2


def test_a_chain_deeper_than_the_parser_can_take_is_refused_in_one_line(run, tmp_path):
    """Fixed joints: no moving joint to count, but the parser recurses through them too."""
    robot = tmp_path / "rod.urdf"
    robot.write_text(_chain(MOST_JOINTS_DEEP + 2, kind="fixed"))
    why = (f"its kinematic tree is {MOST_JOINTS_DEEP + 1} joints deep, over the "
           f"{MOST_JOINTS_DEEP:,} that Pinocchio's URDF parser can load")
    assert_one_line_error(run("fk", robot, "-f", "l0"), 2, why)
    assert_one_line_error(run("inspect", robot), 2, why)
    result = run("check", robot, "--select", "SB701", "--format", "json", "--isolated")
    assert result.exit_code == 1
    (finding,) = json.loads(result.stdout)["files"][0]["findings"]
    assert finding["code"] == "SB701" and why in finding["message"]


def test_a_model_of_too_many_moving_joints_is_refused_before_its_memory_runs_away(run,
                                                                                  tmp_path):
    """A 1,000-joint snake took 24 GB in fk (Pinocchio's data grows as the cube); inspect,
    which needs no data, still reads it."""
    robot = tmp_path / "snake.urdf"
    robot.write_text(_chain(MOST_MOVING_JOINTS + 2))
    why = f"its model has {MOST_MOVING_JOINTS + 1} degrees of freedom, over the 250 that"
    assert_one_line_error(run("fk", robot), 2, why)
    assert_one_line_error(run("ik", robot, "--position", "0.1", "0", "0"), 2,
                          "the joints that move 'l251'", "over the 250")
    assert run("inspect", robot, "--section", "tree").exit_code == 0
    fine = tmp_path / "fine.urdf"
    fine.write_text(_chain(41))
    assert run("fk", fine).exit_code == 0
