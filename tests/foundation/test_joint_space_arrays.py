"""JointSpace's vectorised conversions agree with their per-joint definition."""

from __future__ import annotations

import math

import numpy as np
import pytest

from servicebot_cli.common.errors import OutOfLimits
from servicebot_cli.description.loader import RobotSource, load


def test_to_q_puts_each_value_where_the_joint_lives():
    space = load(RobotSource.bundled("sim")).joint_space
    values = np.linspace(-1.5, 1.5, len(space.names))
    q = space.to_q(values)
    for i, kind in enumerate(space.types):
        start = space.idx_q[i]
        if kind == "continuous":
            assert q[start: start + 2] == pytest.approx([math.cos(values[i]), math.sin(values[i])])
        else:
            assert q[start] == values[i]
    assert space.from_q(q) == pytest.approx(values)
    assert space.neutral() is not space.neutral()  # a fresh array each time


def test_to_q_keeps_a_given_base():
    robot = load(RobotSource.bundled("sim"))
    from servicebot_cli.description.joint_space import JointSpace

    space = JointSpace.of(robot.model_with_base("planar"), robot.movable_joints)
    q0 = space.neutral()
    q0[:4] = [1.0, 2.0, 0.0, 1.0]
    q = space.to_q(np.full(len(space.names), 0.25), q0)
    assert list(q[:4]) == [1.0, 2.0, 0.0, 1.0]


def test_checked_refuses_nan_and_values_outside_limits_but_not_continuous_angles():
    space = load(RobotSource.bundled("sim")).joint_space
    values = np.zeros(len(space.names))
    values[space.index("front_left_wheel_joint")] = 100.0  # continuous: any angle
    assert space.checked(values) is values
    for bad in (1.6, math.nan):
        values[space.index("arm_link3_to_link4")] = bad
        with pytest.raises(OutOfLimits, match="arm_link3_to_link4"):
            space.checked(values)
