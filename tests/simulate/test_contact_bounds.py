"""The contact tests' shortcuts give the answers of Coal asked about every part and obstacle.

The simulator bounds groups of parts before parts, measures clearances only where a bound
could beat the best so far, and reuses the parts' transforms for configurations it has
composed. The references here ask Coal about every pair, with the links placed by
``kinematics.link_poses`` (the URDF tree) and Coal shapes built from the description's
collision elements, not by the simulator's shape code.
"""

from __future__ import annotations

import math

import coal
import numpy as np
import pytest
import trimesh

from servicebot_cli.kinematics.link_poses import link_transforms
from servicebot_cli.simulate.shape_memo import TransformMemo
from servicebot_cli.simulate.world import contacts
from servicebot_cli.simulate.world.clearance import closest
from servicebot_cli.simulate.world.part_groups import (
    SLACK_M,
    box_bounds,
    group_bounds,
    part_bounds,
)
from servicebot_cli.simulate.world.solids import world_solids
from tests.simulate.helpers import body, coal_primitives, scenario

BODY = body()
SHAPE = BODY.shape
HEIGHT = BODY.base_height_m
WORLD = {"walls": [{"from_m": [-1.5, -1.0], "to_m": [1.5, -1.0], "thickness_m": 0.1,
                    "height_m": 1.0}],
         "boxes": [{"center_m": [0.9, 0.6], "size_m": [0.5, 0.3, 0.15], "yaw_rad": 0.4}],
         "cylinders": [{"center_m": [-0.9, 0.7], "radius_m": 0.15, "height_m": 0.8}]}
BALL = trimesh.creation.icosphere(subdivisions=1, radius=0.2)  # 80 triangles
BALL.apply_translation([0.0, 1.1, 0.9])  # where the arm reaches, above the base


def _world() -> tuple[contacts.Tester, list[tuple[object, coal.Transform3s]]]:
    """The simulator's tester, and Coal's own objects for the same obstacles."""
    solids = world_solids(scenario({"duration_s": 1, "world": WORLD}).world)
    reference = []
    for s in solids:
        shape = coal.Box(*(2 * s.half_m)) if s.kind == "box" else \
            coal.Cylinder(float(s.half_m[0]), 2 * float(s.half_m[2]))
        reference.append((shape, coal.Transform3s(s.rotation, s.center_m)))
    mesh = coal.BVHModelOBBRSS()
    mesh.beginModel(len(BALL.faces), len(BALL.vertices))
    mesh.addVertices(np.asarray(BALL.vertices, dtype=np.float64))
    mesh.addTriangles(np.asarray(BALL.faces, dtype=np.int64))
    mesh.endModel()
    reference.append((mesh, coal.Transform3s()))
    return contacts.Tester(SHAPE, contacts.obstacles(solids, [BALL])), reference


def _parts() -> list[tuple[str, coal.ShapeBase, np.ndarray]]:
    """(link, Coal shape, transform_shape_to_link) of every collision primitive, URDF order."""
    out = coal_primitives(BODY.robot)
    assert [link for link, _, _ in out] == list(SHAPE.links)
    return out


def _poses(count: int, seed: int) -> tuple[np.ndarray, ...]:
    """Base poses over the world and the arm anywhere within its limits."""
    rng = np.random.default_rng(seed)
    x, y = rng.uniform(-1.4, 1.4, count), rng.uniform(-1.3, 1.3, count)
    yaw = rng.uniform(-math.pi, math.pi, count)
    q = rng.uniform(-1.5, 1.5, (count, len(SHAPE.joints)))
    return x, y, yaw, q


def _placed_by_the_urdf(x: float, y: float, yaw: float, q: np.ndarray) -> list[np.ndarray]:
    """``transform_part_to_world`` of every part, from the URDF tree."""
    c, s = math.cos(yaw), math.sin(yaw)
    base = np.array([[c, -s, 0, x], [s, c, 0, y], [0, 0, 1, HEIGHT], [0, 0, 0, 1]])
    links = link_transforms(BODY.robot, dict(zip(SHAPE.joints, q, strict=True)))
    return [base @ links[link] @ origin for link, _, origin in _parts()]


def _every_pair(poses: tuple[np.ndarray, ...], touching: bool) -> np.ndarray:
    """Coal's answer for every pose, part and obstacle: touching, or the distance [m]."""
    reference, parts = _world()[1], _parts()
    out = np.empty((len(poses[0]), len(parts), len(reference)))
    for p in range(len(poses[0])):
        placed = _placed_by_the_urdf(*(v[p] for v in poses))
        for s, ((_, shape, _), transform) in enumerate(zip(parts, placed, strict=True)):
            pose = coal.Transform3s(transform[:3, :3], transform[:3, 3])
            for o, (target, target_pose) in enumerate(reference):
                if touching:
                    result = coal.CollisionResult()
                    coal.collide(shape, pose, target, target_pose, coal.CollisionRequest(),
                                 result)
                    out[p, s, o] = result.isCollision()
                else:
                    answer = coal.DistanceResult()
                    coal.distance(shape, pose, target, target_pose, coal.DistanceRequest(),
                                  answer)
                    out[p, s, o] = max(answer.min_distance, 0.0)
    return out


def _placed(poses: tuple[np.ndarray, ...]) -> contacts.Placed:
    x, y, yaw, q = poses
    return contacts.Placed(SHAPE.transforms_to_base(q), x, y, yaw, HEIGHT)


def test_transforms_looked_up_have_the_bits_of_a_fresh_composition():
    rng = np.random.default_rng(3)
    q = np.repeat(rng.uniform(-1.5, 1.5, (40, len(SHAPE.joints))), 3, axis=0)  # held rows
    new = rng.uniform(-1.5, 1.5, (5, len(SHAPE.joints)))
    memo = TransformMemo(SHAPE)
    for rows in (q[::2], np.vstack((q, new)), q[::-1], new[:2], q[:1]):
        assert memo(rows).tobytes() == SHAPE.transforms_to_base(rows).tobytes()
    memo.clear()
    assert memo(q[5:9]).tobytes() == SHAPE.transforms_to_base(q[5:9]).tobytes()


def test_a_group_bound_is_below_each_of_its_parts_bounds():
    tester, _ = _world()
    placed = _placed(_poses(300, seed=1))
    centres = placed.centres()
    groups = group_bounds(tester.world, centres, tester.radius_m, tester.groups)
    assert len(tester.groups) == 2 and groups.shape == (300, 2, len(tester.world))
    for g, members in enumerate(tester.groups):
        for o, obstacle in enumerate(tester.world):
            parts = part_bounds(obstacle, centres[:, members], tester.radius_m[members])
            assert np.all(groups[:, g, o] <= parts.min(axis=1))
            assert np.any(groups[:, g, o] > 0.5)  # and far from all of them, somewhere


def test_first_hits_are_coals_first_touching_obstacle_then_part():
    tester, _ = _world()
    poses = _poses(120, seed=2)
    touching = _every_pair(poses, touching=True).astype(bool)  # (P, S, O)
    obstacle, part = tester.first_hits(_placed(poses))
    assert 10 < np.count_nonzero(touching.any(axis=(1, 2))) < 110  # some free, some not
    for p in range(len(poses[0])):
        hits = [(o, s) for o in range(touching.shape[2]) for s in range(touching.shape[1])
                if touching[p, s, o]]
        assert (obstacle[p], part[p]) == (hits[0] if hits else (-1, -1))


@pytest.mark.parametrize("free", [True, False], ids=["clear poses", "with contacts"])
def test_closest_is_the_least_distance_of_every_pair(free):
    tester, _ = _world()
    poses = _poses(150, seed=4)
    distances = _every_pair(poses, touching=False)  # (P, S, O)
    if free:  # only the poses touching nothing: the answer is a real clearance
        keep = distances.min(axis=(1, 2)) > 0
        poses = tuple(v[keep] for v in poses)
        distances = distances[keep]
    found = closest(tester, _placed(poses))
    flat = int(np.argmin(distances))  # the first of equal distances: pose, part, obstacle
    p, s, o = np.unravel_index(flat, distances.shape)
    assert (found.index, found.part, found.obstacle) == (p, s, o)
    assert found.distance_m == pytest.approx(distances[p, s, o], abs=1e-9)
    if free:
        assert found.distance_m > 0.001
        # a clearance known already counts: none is found unless below it
        assert closest(tester, _placed(poses), below=found.distance_m).index == -1
        assert closest(tester, _placed(poses), below=found.distance_m + 1e-6) == found


def test_a_box_bound_is_below_coals_distance_and_meets_it_face_to_face():
    tester, reference = _world()
    [wall] = [o for o in tester.world if o.name == "wall 1"]
    wall_shape, wall_pose = reference[tester.world.index(wall)]
    rng = np.random.default_rng(5)
    half = rng.uniform(0.02, 0.3, (200, 3))
    centres = np.column_stack((rng.uniform(-1, 1, 200), rng.uniform(-1.8, -0.2, 200),
                               rng.uniform(0, 1.2, 200)))
    axes = rng.normal(size=(200, 3))
    rotations = np.array([coal.AngleAxis(rng.uniform(0, math.pi), a / np.linalg.norm(a))
                          .toRotationMatrix() for a in axes])
    bounds = box_bounds(wall, centres, rotations, half)
    for c, r, h, b in zip(centres, rotations, half, bounds, strict=True):
        answer = coal.DistanceResult()
        coal.distance(coal.Box(*(2 * h)), coal.Transform3s(r, c), wall_shape, wall_pose,
                      coal.DistanceRequest(), answer)
        # Coal's GJK is exact to about 1e-11 m here; the simulator takes SLACK_M off
        distance = max(answer.min_distance, 0.0)
        assert b - SLACK_M < distance and b <= distance + 1e-9
    assert np.count_nonzero(bounds > 0.05) > 20  # it clears boxes, not only says 0
    # a box facing the wall square on, 0.2 m from its face: the bound is the distance
    face = np.array([[0.3, -1.0 + 0.05 + 0.2 + 0.1, 0.5]])
    assert box_bounds(wall, face, np.eye(3)[None], np.array([[0.1, 0.1, 0.1]]))[0] == \
        pytest.approx(0.2, abs=1e-12)
