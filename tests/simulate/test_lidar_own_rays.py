"""The LIDAR's rays against the robot's own arm: parts out of the scan plane are skipped,
with the ranges of every part cast."""

from __future__ import annotations

import numpy as np

from servicebot_cli.simulate.sensors import lidar
from servicebot_cli.simulate.world.robot_rays import cast_parts
from tests.simulate.helpers import body


def _every_part_cast(robot, q):
    mounted = robot.ray_sensors[0]
    rays = lidar.ray_directions(mounted.spec, mounted.transform_sensor_to_base)
    keep = [p.link != mounted.link for p in robot.shape.parts]
    placed = robot.shape.transforms_to_base(q)[:, keep]
    origin = np.broadcast_to(mounted.transform_sensor_to_base[:3, 3], rays.shape)
    return cast_parts([p for p, k in zip(robot.shape.parts, keep, strict=True) if k], placed,
                      origin, rays)


def test_arm_dipping_into_the_scan_plane_reads_as_every_part_cast():
    robot = body()
    mounted = robot.ray_sensors[0]
    rays = lidar.ray_directions(mounted.spec, mounted.transform_sensor_to_base)
    joints = len(robot.shape.joints)
    # from upright to folded far down behind and ahead: the arm leaves the plane and enters it
    swing = np.linspace(-1.0, 1.0, 40)[:, None]
    q = np.hstack((np.repeat([[0.0, 1.2, 1.2]], 40, axis=0) * swing,
                   np.zeros((40, joints - 3)))) if joints >= 3 else np.zeros((40, joints))
    q = np.vstack((q, np.zeros((5, joints)), np.array([[3.0, 1.5, 1.5, 1.5][:joints]])))
    own = lidar.own_ranges(robot.shape, mounted.link, mounted.transform_sensor_to_base, rays, q)
    every = _every_part_cast(robot, q)
    assert np.array_equal(own, every)
    upright = np.isfinite(every[40])  # the arm at rest: only fixed parts seen (arm_base_link)
    assert (np.isfinite(every).sum(axis=1) > upright.sum()).any()  # the arm in sight at times
