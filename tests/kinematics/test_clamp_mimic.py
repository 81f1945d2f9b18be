"""``--clamp`` and joints that follow another (``<mimic>``): the pose stays one a robot takes.

Clamping each joint alone broke the mimic rule: PR2's gripper (example-robot-data) mirrors
r_gripper_l_finger_joint in r_gripper_r_parallel_root_joint, whose limits [0, 0.548] leave
its leader only 0. ``--clamp`` set the follower to 0 and left its leader at 0.3. And a leader
clamped by its own limits left its followers where the unclamped value put them. Now the
leader is clamped into the range that suits it and every follower, and the followers follow.
"""

from __future__ import annotations

import json

import pytest

from tests.conftest import run_servicebot
from tests.kinematics.robots import example_robot

PR2 = example_robot("pr2_description/urdf/pr2.urdf")
LEADER = "r_gripper_l_finger_joint"

TWO = """<robot name="g"><link name="a"/><link name="b"/><link name="c"/>
<joint name="lead" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
  <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
<joint name="follow" type="revolute"><parent link="a"/><child link="c"/><axis xyz="0 0 1"/>
  <limit lower="-3" upper="3" effort="1" velocity="1"/><mimic joint="lead" multiplier="2"/>
</joint></robot>
"""


def _fk(robot, frame, *joints):
    result = run_servicebot("fk", robot, *(f"-j{j}" for j in joints), "--clamp", "--format",
                            "json", "-f", frame)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)["joints"], result.stderr.splitlines()


def test_pr2s_gripper_closes_together():
    joints, notes = _fk(PR2, "r_gripper_r_finger_link", f"{LEADER}=0.3")
    gripper = {k: v for k, v in joints.items() if k.startswith("r_gripper_") and
               k.endswith(("finger_joint", "root_joint", "tip_joint"))}
    assert set(gripper.values()) == {0.0}, gripper
    assert notes == [f"note: --clamp: joint '{LEADER}' = 0.3 rad puts "
                     "'r_gripper_r_parallel_root_joint', which mimics it, outside its limits; "
                     "using 0 rad"]


@pytest.mark.parametrize(("given", "lead", "why"), [
    ("2", 1.0, "is outside its limits; using its upper limit 1 rad"),  # its own limits
    ("0.9", 0.75, "puts 'follow', which mimics it, outside its limits; using 0.75 rad"),
])
def test_a_leader_is_clamped_where_its_follower_fits_too(tmp_path, given, lead, why):
    robot = tmp_path / "two.urdf"
    robot.write_text(TWO.replace('multiplier="2"', 'multiplier="4"') if given == "0.9"
                     else TWO)
    joints, notes = _fk(robot, "b", f"lead={given}")
    factor = 4 if given == "0.9" else 2
    assert joints == {"lead": lead, "follow": pytest.approx(factor * lead)}
    assert notes == [f"note: --clamp: joint 'lead' = {given} rad {why}"]


def test_fk_batches_and_inspect_clamp_the_same(tmp_path):
    """fk --configs clamped each joint alone on its fast path, and inspect's note said the
    leader was above its upper limit where its follower had held it."""
    robot = tmp_path / "two.urdf"
    robot.write_text(TWO.replace('multiplier="2"', 'multiplier="4"'))
    configs = tmp_path / "configs.csv"
    configs.write_text("lead\n0.9\n0.1\n")
    batch = run_servicebot("fk", robot, "-f", "b", "--configs", configs, "--clamp",
                           "--format", "json")
    assert batch.returncode == 0, batch.stderr
    yaws = [json.loads(line)["poses"][0]["rpy_rad"][2] for line in batch.stdout.splitlines()]
    assert yaws == pytest.approx([0.75, 0.1])
    inspect = run_servicebot("inspect", robot, "--section", "totals", "--joint", "lead=0.9",
                             "--clamp", "--format", "json")
    assert inspect.returncode == 0, inspect.stderr
    assert json.loads(inspect.stdout)["totals"]["configuration_rad_or_m"] == {
        "lead": 0.75, "follow": 3.0}
    assert inspect.stderr.splitlines() == ["note: --clamp: joint 'lead' 0.9 rad puts 'follow', "
                                           "which mimics it, outside its limits; using 0.75 rad"]
