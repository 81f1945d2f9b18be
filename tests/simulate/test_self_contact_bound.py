"""The self-contact pre-filter: stretches bounded first flag exactly the configurations of
the test made one configuration at a time."""

from __future__ import annotations

import numpy as np
import pytest

from servicebot_cli.simulate import self_contact
from servicebot_cli.simulate.self_contact import _could_touch, _pairs, _touch
from tests.simulate.helpers import body


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_stretch_bounds_flag_the_configurations_one_by_one_would(seed):
    robot = body()
    space = robot.joint_space
    index = [space.index(name) for name in robot.shape.joints]
    low, high = space.lower[index], space.upper[index]
    rng = np.random.default_rng(seed)
    # the arm wandering across its range, still for a while now and then, and folding down
    steps = rng.normal(0.0, 0.08, (1500, len(index))) * (rng.random((1500, 1)) < 0.8)
    wander = np.clip((low + high) / 2 + np.cumsum(steps, axis=0), low, high)
    folding = np.linspace(0.0, 1.0, 300)[:, None] * np.array([0.0, 0.7, 0.7, 0.7])
    q = np.vstack((wander, folding))
    placed = robot.shape.transforms_to_base(q)
    one_by_one = _touch(robot.shape, robot.base_height_m, _pairs(robot.robot, robot.shape),
                        placed[0], placed[..., :3, 3])
    assert 0 < one_by_one.sum() < len(q)  # some configurations flagged, not all
    assert np.array_equal(_could_touch(robot.robot, robot.shape, robot.base_height_m, q,
                                       placed), one_by_one)


def test_a_run_whose_arm_stays_clear_builds_no_collision_check(monkeypatch):
    robot = body()
    watch = self_contact.SelfContactWatch(robot.robot, robot.shape, robot.base_height_m, 0.01)
    q = np.zeros((50, len(robot.shape.joints)))  # the arm at rest, clear of everything
    assert watch.advance(0, q) == []
    assert watch.built is None
