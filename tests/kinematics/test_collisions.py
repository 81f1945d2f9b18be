"""Collision-aware IK on real geometry: the arm folded into its base, free space, SRDF, floor."""

from __future__ import annotations

import json
import time

import coal
import numpy as np
import pinocchio as pin
import pytest

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.kinematics.collision_floor import FLOOR
from servicebot_cli.kinematics.collisions import Contact, build_check
from servicebot_cli.kinematics.ik import IkRequest, TargetSpec, run
from servicebot_cli.kinematics.ik_problem import CollisionOptions, IkProblem
from servicebot_cli.kinematics.ik_session import is_mobile
from tests.conftest import SIM_URDF, assert_one_line_error
from tests.kinematics.robots import UR5

INTO_THE_BASE = ("--position", "0.1", "0", "0.0")  # inside the base box, above the floor


def _boxes_intersect(robot, q, link_a, size_a, offset_a, link_b, size_b, offset_b) -> bool:
    """Two URDF collision boxes at ``q``, tested by coal directly (not through our pairs)."""
    data = robot.model.createData()
    pin.framesForwardKinematics(robot.model, data, q)

    def placed(link, offset):
        pose = data.oMf[robot.model.getFrameId(link)] * pin.SE3(np.eye(3), np.array(offset))
        return coal.Transform3s(pose.rotation, pose.translation)

    result = coal.CollisionResult()
    coal.collide(coal.Box(*size_a), placed(link_a, offset_a), coal.Box(*size_b),
                 placed(link_b, offset_b), coal.CollisionRequest(), result)
    return result.isCollision()


def test_the_arm_folded_into_its_base_is_refused_and_names_the_links(run):
    result = run("ik", *INTO_THE_BASE, "--seed", "1")
    assert_one_line_error(result, code=1)
    assert "reachable only through a collision" in result.stderr
    assert "'base_link' and 'arm_link" in result.stderr  # the two links, by name
    assert "NOT reached" in result.stdout


def test_allow_collisions_gives_the_pose_through_the_base_which_real_boxes_confirm(run):
    result = run("ik", *INTO_THE_BASE, "--seed", "1", "--allow-collisions", "--format", "json")
    assert result.exit_code == 0
    answer = json.loads(result.stdout)
    robot = load(RobotSource.of(SIM_URDF))
    q = robot.joint_space.to_q(np.array(list(answer["joints"].values())))
    base = ((0.5, 0.5, 0.2), (0, 0, 0))
    assert any(_boxes_intersect(robot, q, "base_link", *base, link, (0.3, 0.1, 0.1),
                                (0.15, 0, 0)) for link in ("arm_link2", "arm_link3", "arm_link4"))


def test_a_target_in_free_space_is_reached_with_no_link_touching_another(run):
    result = run("ik", "--position", "0.5", "0.2", "0.4", "--seed", "1", "--format", "json")
    assert result.exit_code == 0, result.stderr
    answer = json.loads(result.stdout)
    robot = load(RobotSource.of(SIM_URDF))
    q = robot.joint_space.to_q(np.array(list(answer["joints"].values())))
    assert build_check(robot, robot.model, RobotSource.of(SIM_URDF).resolver()).contact(q) is None
    for link in ("arm_link2", "arm_link3", "arm_link4"):
        assert not _boxes_intersect(robot, q, "base_link", (0.5, 0.5, 0.2), (0, 0, 0), link,
                                    (0.3, 0.1, 0.1), (0.15, 0, 0))


def _srdf(tmp_path, pairs):
    lines = "".join(f'  <disable_collisions link1="{a}" link2="{b}" reason="Test"/>\n'
                    for a, b in pairs)
    path = tmp_path / "robot.srdf"
    path.write_text(f'<?xml version="1.0"?>\n<robot name="service_robot">\n{lines}</robot>\n')
    return path


def test_an_srdf_that_disables_the_pairs_lets_the_pose_through(run, tmp_path):
    arm = ("arm_link2", "arm_link3", "arm_link4")
    body = ("base_link", "lidar_link", "camera_link", "imu_link", "arm_base_link")
    srdf = _srdf(tmp_path, [(b, a) for b in body for a in arm])
    result = run("ik", *INTO_THE_BASE, "--seed", "1", "--srdf", srdf)
    assert result.exit_code == 0, result.stderr
    only_one = _srdf(tmp_path, [("lidar_link", "arm_link4")])
    assert run("ik", *INTO_THE_BASE, "--seed", "1", "--srdf", only_one).exit_code == 1


def test_an_srdf_naming_an_unknown_link_is_refused_with_its_line(run, tmp_path):
    srdf = _srdf(tmp_path, [("base_link", "arm_link9")])
    result = run("ik", *INTO_THE_BASE, "--srdf", srdf)
    assert_one_line_error(result, code=2)
    assert "robot.srdf:3:" in result.stderr and "'arm_link9'" in result.stderr
    assert "arm_link" in result.stderr.split("arm_link9", 1)[1]  # the nearest names


def test_srdf_beside_allow_collisions_is_refused(run, tmp_path):
    result = run("ik", *INTO_THE_BASE, "--allow-collisions", "--srdf",
                 _srdf(tmp_path, [("base_link", "arm_link4")]))
    assert_one_line_error(result, code=2)
    assert "--srdf has no effect with --allow-collisions" in result.stderr


def test_the_floor_is_where_the_wheels_touch():
    robot = load(RobotSource.of(SIM_URDF))
    check = build_check(robot, robot.model, RobotSource.of(SIM_URDF).resolver())
    # wheel centres 0.08 m below base_link, radius 0.07 m
    assert check.floor_z_m == pytest.approx(-0.15, abs=1e-6)
    floor_pairs = {a for a, b in check.pairs if b == FLOOR}
    assert "arm_link4" in floor_pairs and "base_link" in floor_pairs
    assert not any("wheel" in link for link in floor_pairs)  # they stand on it
    wheels = [(a, b) for a, b in check.pairs if "wheel" in a and "wheel" in b]
    assert wheels  # the wheels are not adjacent to one another: checked
    assert ("base_link", "front_left_wheel") not in check.pairs  # adjacent: never


def test_only_a_robot_on_wheels_has_a_floor(run):
    """The floor is under a mobile robot; a fixed arm may be mounted on a table or a wall and
    reach below its base plane."""
    assert is_mobile(load(RobotSource.bundled("sim")))
    assert not is_mobile(load(RobotSource.of(UR5)))
    result = run("ik", UR5, "--position", "0.5", "0.1", "-0.2", "--seed", "1")
    assert result.exit_code == 0, result.stderr
    # and the help says so: it promised the floor to every arm
    help_text = " ".join(run("ik", "--help").stdout.split())
    assert "or the floor on a wheeled base" in help_text
    assert "a fixed arm may reach below its base" in help_text


def test_a_configuration_under_the_floor_is_a_contact_with_it():
    robot = load(RobotSource.of(UR5))
    check = build_check(robot, robot.model, RobotSource.of(UR5).resolver())
    q = pin.neutral(robot.model)
    q[1] = 1.2  # shoulder lift down: the arm points into the mounting plane
    contact = check.contact(q)
    assert contact is not None and contact.second == FLOOR
    q[1] = -1.5  # up: clear of everything
    assert check.contact(q) is None


def test_the_search_goes_on_past_a_colliding_answer_in_batch_too(tmp_path, run):
    targets = tmp_path / "t.csv"
    targets.write_text("x_m,y_m,z_m\n0.5,0.2,0.4\n0.1,0,0.0\n")
    result = run("ik", "--targets", targets, "--seed", "1")
    assert result.exit_code == 1
    rows = result.stdout.splitlines()
    assert rows[1].startswith("2,true") and rows[2].startswith("3,false")
    assert "reachable only through a collision" in rows[2]


def test_without_a_check_the_api_answers_as_before():
    problem = IkProblem(RobotSource.of(SIM_URDF), seed=1,
                        collisions=CollisionOptions(check=False))
    answer = run(IkRequest(problem, TargetSpec((0.1, 0.0, 0.0))), clock=time.perf_counter)
    assert answer.success and answer.outcome.result.contact is None
    checked = run(IkRequest(IkProblem(RobotSource.of(SIM_URDF), seed=1),
                            TargetSpec((0.1, 0.0, 0.0))), clock=time.perf_counter)
    assert not checked.success and isinstance(checked.outcome.result.contact, Contact)
    assert str(checked.outcome.result.contact).startswith("'base_link' and 'arm_link")


def test_the_hint_offers_an_srdf_only_for_a_pair_of_links():
    """An SRDF's <disable_collisions> names two links; it cannot name the floor."""
    from servicebot_cli.kinematics.collisions import Contact
    from servicebot_cli.kinematics.diagnosis import collision_hint

    assert "--srdf FILE" in collision_hint(Contact("arm_link3", "base_link"))
    floor = collision_hint(Contact("arm_link3", FLOOR))
    assert "'arm_link3' and the floor" in floor and "--srdf" not in floor
    assert "--allow-collisions" in floor
