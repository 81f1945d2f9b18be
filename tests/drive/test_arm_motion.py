"""The arm's way to its targets, and how finely it is checked: the math."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pinocchio as pin
import pytest

from servicebot_cli.drive.arm_motion import arm_legs, polyline
from servicebot_cli.drive.plan import Step
from tests.drive.arm_reference import ARM, ArmReference

SIGNS = np.array(list(itertools.product((-1.0, 1.0), repeat=3)))


@pytest.mark.parametrize(("start", "target", "speeds", "corners"), [
    ((0, 0, 0), (1, -0.5, 0), (1, 1, 1), [(0, 0, 0), (0.5, -0.5, 0), (1, -0.5, 0)]),
    ((0, 0), (1, 1), (2, 0.5), [(0, 0), (1, 0.25), (1, 1)]),  # each at its own speed
    ((0, 0), (1, 1), (math.inf, 1), [(0, 0), (1, 0), (1, 1)]),  # no limit: a jump at once
    ((0.3, 0.2), (0.3, 0.2), (1, 1), [(0.3, 0.2)]),  # already there
])
def test_each_joint_goes_at_its_limit_and_stops_when_it_arrives(start, target, speeds,
                                                                 corners):
    assert np.array(polyline(start, target, speeds)) == pytest.approx(np.array(corners))


def test_a_way_is_whole_and_the_next_starts_where_the_arm_is(real_motors):
    steps = [Step(0.5, 0, 0, ((ARM[0], 1.0),)), Step(1.0, 0, 0),
             Step(2.0, 0, 0, ((ARM[1], 1.0),))]
    first, second = arm_legs(steps, (0.0,) * 4, real_motors)
    whole = np.array([(0, 0, 0, 0), (1, 0, 0, 0)])
    assert np.array(first.path_rad) == pytest.approx(whole)  # not cut at 0.5 s
    assert second.step is steps[2] and second.target_rad == (1.0, 1.0, 0.0, 0.0)
    assert second.path_rad[0] == pytest.approx((1.0, 0, 0, 0))  # arrived during step 2


def test_a_target_before_the_arm_arrived_turns_it_where_it_is(real_motors):
    steps = [Step(0.25, 0, 0, ((ARM[0], 1.0),)), Step(1.0, 0, 0, ((ARM[1], -0.5),))]
    _, second = arm_legs(steps, (0.0,) * 4, real_motors)
    assert np.array(second.path_rad) == pytest.approx(np.array(
        [(0.25, 0, 0, 0), (0.75, -0.5, 0, 0), (1.0, -0.5, 0, 0)]))


def test_no_point_of_the_arm_moves_more_than_the_levers_say():
    """sum(L_i |dq_i|) bounds how far any corner of the arm's boxes moves (finite steps)."""
    from servicebot_cli.kinematics.arm_collisions import levers_m

    ref = ArmReference()
    model, geometry = ref.model, ref.geometry
    levers = levers_m(model, geometry, [model.getJointId(n) for n in ARM])
    rng = np.random.default_rng(7)

    def corners(arm):
        q = pin.neutral(model)
        q[ref.columns] = arm
        data, placed = model.createData(), pin.GeometryData(geometry)
        pin.updateGeometryPlacements(model, data, geometry, placed, q)
        return np.array([pose.act(signs * obj.geometry.halfSide)
                         for obj, pose in zip(geometry.geometryObjects, placed.oMg, strict=True)
                         if obj.parentJoint in ref.arm_joint_ids for signs in SIGNS])

    tightest = 0.0
    for _ in range(200):
        arm = rng.uniform(-1.5, 1.5, 4)
        step = rng.normal(size=4) * rng.uniform(1e-4, 0.05)
        moved = np.linalg.norm(corners(arm + step) - corners(arm), axis=1).max()
        bound = float(levers @ np.abs(step))
        assert moved <= bound + 1e-12
        tightest = max(tightest, moved / bound)
    assert tightest > 0.5  # and not so loose that it would check far too often
