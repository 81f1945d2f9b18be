"""Link poses from the URDF tree equal Pinocchio's forward kinematics."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.kinematics.link_poses import link_transforms


@pytest.mark.parametrize("name", ["sim", "real"])
def test_link_poses_match_pinocchio(name):
    robot = load(RobotSource.bundled(name))
    space = robot.joint_space
    rng = np.random.default_rng(7)
    for _ in range(5):
        values = rng.uniform(-1.5, 1.5, len(space.names))
        ours = link_transforms(robot, dict(zip(space.names, values, strict=True)))
        data = robot.model.createData()
        pin.framesForwardKinematics(robot.model, data, space.to_q(values))
        assert len(ours) == len(robot.links)
        for link, transform in ours.items():
            frame = robot.model.getFrameId(link, pin.FrameType.BODY)
            assert transform == pytest.approx(data.oMf[frame].homogeneous, abs=1e-12), link


def test_prismatic_joints_slide(tmp_path):
    urdf = tmp_path / "slider.urdf"
    urdf.write_text('<robot name="s"><link name="a"/><link name="b"/>'
                    '<joint name="j" type="prismatic"><parent link="a"/><child link="b"/>'
                    '<axis xyz="0 0 2"/><limit lower="0" upper="1" effort="1" velocity="1"/>'
                    "</joint></robot>")
    robot = load(RobotSource.of(urdf))
    assert link_transforms(robot, {"j": 0.25})["b"][:3, 3] == pytest.approx([0, 0, 0.25])
