"""The robot's real shape: the LIDAR sees its own links, every link collides, the true outline.

References are built independently of the simulator's shape code: trimesh primitives placed
with ``kinematics.link_poses`` (the URDF tree) from the description's collision elements.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import trimesh

from servicebot_cli.kinematics.link_poses import link_transforms
from servicebot_cli.kinematics.transforms import pose_matrix
from servicebot_cli.simulate.sensors import lidar
from tests.simulate.helpers import body, run

BODY = body()
ARM = list(BODY.arm_joints)
UP = {"joint_names": ["arm_link1_to_link2"],  # the arm straight up, inside the base's outline
      "points": [{"time_from_start_s": 0, "positions": [-1.57]}]}


def reference_meshes(q: dict[str, float], skip: str = "") -> list[tuple[str, trimesh.Trimesh]]:
    """Every collision primitive as a trimesh, in the base frame, from the URDF tree."""
    robot = BODY.robot
    placed = link_transforms(robot, q)
    out = []
    for link in robot.links:
        if link.name == skip:
            continue
        for shape in link.collisions:
            g, transform = shape.geometry, placed[link.name] @ pose_matrix(shape.origin)
            if g.kind == "box":
                mesh = trimesh.creation.box(extents=g.size, transform=transform)
            else:
                mesh = trimesh.creation.cylinder(radius=g.radius, height=g.length,
                                                 sections=720, transform=transform)
            out.append((link.name, mesh))
    return out


def test_own_ranges_match_trimesh_rays_at_random_arm_configurations():
    mount = BODY.ray_sensors[0]
    directions = lidar.ray_directions(mount.spec, mount.transform_sensor_to_base)
    origin = mount.transform_sensor_to_base[:3, 3]
    rng = np.random.default_rng(4)
    q = np.vstack([np.zeros(4), [0, 1.2, 1.0, 0.5], rng.uniform(-1.5, 1.5, (3, 4))])
    ours = lidar.own_ranges(BODY.shape, mount.link, mount.transform_sensor_to_base, directions, q)
    hits_somewhere = 0
    for k, row in enumerate(q):
        config = dict(zip(ARM, row, strict=True))
        union = trimesh.util.concatenate([m for _, m in reference_meshes(config, mount.link)])
        origins = np.broadcast_to(origin, directions.shape)
        points, index, _ = union.ray.intersects_location(origins, directions)
        expected = np.full(len(directions), np.inf)
        np.minimum.at(expected, index, np.linalg.norm(points - origins[index], axis=1))
        np.testing.assert_allclose(ours[k], expected, atol=2e-4)
        hits_somewhere += int(np.isfinite(expected).sum())
    assert hits_somewhere > 24 * len(q)  # the arm folded down is seen too, not only its base


def test_the_lidar_sees_the_arm_base_behind_it():
    result = run({"duration_s": 1})
    ranges, angles = result.scans[0].ranges_m[0], result.scans[0].angles_rad
    # arm_base_link's front face is 0.23 m behind the LIDAR and 0.1 m wide
    lidar_x = link_transforms(BODY.robot)["lidar_link"][0, 3]
    face_x = link_transforms(BODY.robot)["arm_base_link"][0, 3] + 0.05
    distance = lidar_x - face_x
    assert distance == pytest.approx(0.23)
    behind = np.abs(np.remainder(angles, 2 * np.pi) - np.pi) < math.atan2(0.05, distance)
    assert behind.sum() == 24
    noise = 4 * 0.01  # 4 sigma of the URDF's noise (ranges are not rounded)
    np.testing.assert_allclose(ranges[behind], distance / np.cos(angles[behind] - np.pi),
                               atol=noise)
    assert np.all(np.isinf(ranges[~behind]))  # an empty world otherwise: no return


def _outline_points(q: dict[str, float]) -> list[tuple[str, np.ndarray]]:
    return [(name, mesh.vertices) for name, mesh in reference_meshes(q)]


def test_spinning_next_to_a_wall_stops_where_the_real_outline_touches_it():
    wall_y, thickness, w = 0.40, 0.1, 0.1
    result = run({"duration_s": 20, "arm": UP,
                  "cmd_vel": [{"duration_s": 20, "angular_rad_s": w}],
                  "world": {"walls": [{"from_m": [-3, wall_y], "to_m": [3, wall_y],
                                       "thickness_m": thickness}]}})
    assert result.contacts, "the robot never touched the wall"
    stop = result.truth.yaw_rad[-1]
    points = _outline_points({"arm_link1_to_link2": -1.57})

    def reach(yaw: float) -> tuple[float, str]:
        c, s = math.cos(yaw), math.sin(yaw)
        best = max(((s * p[:, 0] + c * p[:, 1]).max(), name) for name, p in points)
        return float(best[0]), best[1]

    low, high = 0.0, 1.0  # the yaw where the outline first reaches the wall's face
    face = wall_y - thickness / 2
    assert reach(low)[0] < face < reach(high)[0]
    for _ in range(60):
        mid = (low + high) / 2
        low, high = (mid, high) if reach(mid)[0] < face else (low, mid)
    step = result.truth.angular_rad_s.max() * result.plan.dt_s
    assert high - step - 1e-4 <= stop <= high + 1e-4
    assert result.contacts[0].link == reach(high)[1]


def test_a_low_strip_between_the_wheels_passes_under_the_chassis():
    strip = {"center_m": [0.6, 0.0], "size_m": [0.6, 0.3, 0.02]}
    result = run({"duration_s": 40, "arm": UP,
                  "cmd_vel": [{"duration_s": 40, "linear_m_s": 0.03}],
                  "world": {"boxes": [strip]}})
    assert result.contacts == []
    assert result.truth.x_m[-1] > 1.0  # drove right over it
    # the same strip across the path stops a wheel
    across = {"center_m": [0.6, 0.0], "size_m": [0.1, 1.0, 0.02]}
    result = run({"duration_s": 40, "arm": UP,
                  "cmd_vel": [{"duration_s": 40, "linear_m_s": 0.03}],
                  "world": {"boxes": [across]}})
    assert result.contacts[0].link in ("front_left_wheel", "front_right_wheel")
    # the wheel (r = 0.07, centre 0.17 ahead) meets the strip's top edge (x 0.55, z 0.02):
    # its rim at that height is sqrt(r^2 - (r - 0.02)^2) ahead of its axle
    rim = math.sqrt(0.07**2 - 0.05**2)
    assert result.truth.x_m[-1] + 0.17 + rim == pytest.approx(0.55, abs=0.03 * 0.01 + 1e-6)


def test_clearance_is_measured_to_the_real_outline():
    centre, radius = (0.6, 0.6), 0.1
    result = run({"duration_s": 1, "arm": UP,
                  "world": {"cylinders": [{"center_m": list(centre), "radius_m": radius}]}})
    points = np.vstack([p for _, p in _outline_points({"arm_link1_to_link2": -1.57})])
    # the nearest point of a convex part to a circle's centre off its corner is a corner
    expected = np.min(np.hypot(points[:, 0] - centre[0], points[:, 1] - centre[1])) - radius
    assert result.closest.distance_m == pytest.approx(expected, abs=1e-6)
    # the bounding rectangle's corner (0.3, 0.29) would be 44 mm closer
    rectangle = math.hypot(centre[0] - 0.3, centre[1] - 0.29) - radius
    assert result.closest.distance_m > rectangle + 0.04


def test_the_arm_folding_onto_the_camera_is_a_self_collision():
    arm = {"joint_names": ARM, "points": [{"time_from_start_s": 5,
                                           "positions": [0.0, 0.5, 0.5, 0.5]}]}
    result = run({"duration_s": 6, "arm": arm})
    assert [(c.first, c.second) for c in result.self_contacts] == [("arm_link4", "camera_link")]
    tick = round(result.self_contacts[0].time_s / result.plan.dt_s)

    def overlap(k: int) -> float:
        meshes = dict(reference_meshes(dict(zip(ARM, result.arm_positions_rad[k], strict=True))))
        both = trimesh.boolean.intersection([meshes["arm_link4"], meshes["camera_link"]],
                                            engine="manifold")
        return float(both.volume) if len(both.faces) else 0.0

    assert overlap(tick) > 0.0 and overlap(tick - 1) == 0.0  # manifold3d agrees on the tick
    assert result.contacts == []  # the world is empty: no collision with an obstacle


def test_parts_placed_in_a_batch_are_the_bits_of_each_row_placed_alone():
    """The transform memo and the worker place rows in batches of any size: the same bits."""
    shape = BODY.shape
    q = np.random.default_rng(3).uniform(-2.0, 2.0, (257, len(shape.joints)))
    whole = shape.transforms_to_base(q)
    alone = np.concatenate([shape.transforms_to_base(q[k:k + 1]) for k in range(len(q))])
    assert whole.tobytes() == alone.tobytes()
    assert shape.transforms_to_base(q[100:233]).tobytes() == whole[100:233].tobytes()
