"""The arm is stopped by obstacles as the base is: held at the wall, following again after.

Every configuration the run went through is measured with Coal against the wall, with the
links placed by ``kinematics.link_poses`` (the URDF tree) from the description's collision
elements, not by the simulator's shape code.
"""

from __future__ import annotations

import math
from typing import Any

import coal
import numpy as np
import pytest

from servicebot_cli.kinematics.link_poses import link_transforms
from servicebot_cli.simulate import simulator
from servicebot_cli.simulate.world.solids import world_solids
from tests.simulate.helpers import body, coal_primitives, run, scenario

BODY = body()
ARM = list(BODY.arm_joints)
WALL = {"thickness_m": 0.1, "height_m": 1.0}
# The base stands still; link 1 turns toward a wall at y = 0.6 m, then back.
SWING: dict[str, Any] = {
    "duration_s": 6,
    "arm": {"joint_names": ["arm_base_to_link1"],
            "points": [{"time_from_start_s": 2, "positions": [1.5]},
                       {"time_from_start_s": 4, "positions": [0.0]}]},
    "world": {"walls": [{"from_m": [-2, 0.6], "to_m": [2, 0.6], **WALL}]}}
# The base drives at a wall while the arm reaches forward, presses there, then backs away.
PRESS: dict[str, Any] = {
    "duration_s": 9,
    "controller": {"max_linear_acceleration_m_s2": 2.0, "max_angular_acceleration_rad_s2": 3.0},
    "cmd_vel": [{"duration_s": 4, "linear_m_s": 0.4},
                {"duration_s": 2, "angular_rad_s": 0.5},
                {"duration_s": 3, "linear_m_s": -0.3}],
    "arm": {"joint_names": ["arm_base_to_link1", "arm_link1_to_link2"],
            "points": [{"time_from_start_s": 2, "positions": [0.3, -0.2]},
                       {"time_from_start_s": 8, "positions": [-0.2, 0.1]}]},
    "world": {"walls": [{"from_m": [0.9, -2], "to_m": [0.9, 2], **WALL}]}}


def _wall_box(document: dict[str, Any]) -> tuple[coal.Box, coal.Transform3s]:
    wall = document["world"]["walls"][0]
    (x0, y0), (x1, y1) = wall["from_m"], wall["to_m"]
    yaw = math.atan2(y1 - y0, x1 - x0)
    rotation = np.array([[math.cos(yaw), -math.sin(yaw), 0], [math.sin(yaw), math.cos(yaw), 0],
                         [0, 0, 1]])
    centre = np.array([(x0 + x1) / 2, (y0 + y1) / 2, wall["height_m"] / 2])
    box = coal.Box(math.hypot(x1 - x0, y1 - y0), wall["thickness_m"], wall["height_m"])
    return box, coal.Transform3s(rotation, centre)


def _gaps(result: simulator.SimResult, document: dict[str, Any],
          links: set[str] | None = None) -> np.ndarray:
    """Signed distance from the links to the wall at every tick boundary [m] (< 0: inside)."""
    wall, wall_pose = _wall_box(document)
    shapes = coal_primitives(BODY.robot, links)
    truth, height = result.truth, BODY.base_height_m
    gaps = np.empty(len(truth.x_m))
    for k in range(len(gaps)):
        c, s = math.cos(truth.yaw_rad[k]), math.sin(truth.yaw_rad[k])
        base = np.array([[c, -s, 0, truth.x_m[k]], [s, c, 0, truth.y_m[k]], [0, 0, 1, height],
                         [0, 0, 0, 1]])
        placed = link_transforms(BODY.robot, dict(zip(ARM, result.arm_positions_rad[k],
                                                      strict=True)))
        least = np.inf
        for link, geometry, origin in shapes:
            pose = base @ placed[link] @ origin
            request, answer = coal.DistanceRequest(), coal.DistanceResult()
            request.enable_signed_distance = True
            coal.distance(geometry, coal.Transform3s(pose[:3, :3], pose[:3, 3]), wall,
                          wall_pose, request, answer)
            least = min(least, answer.min_distance)
        gaps[k] = least
    return gaps


def _corners_moved(result: simulator.SimResult, link: str) -> np.ndarray:
    """How far the farthest corner of ``link``'s box moved in each tick [m] (base standing)."""
    [(_, box, origin)] = coal_primitives(BODY.robot, {link})
    half = np.array(box.halfSide)
    corners = np.array([[x, y, z, 1] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]) \
        * np.append(half, 1)
    placed = [link_transforms(BODY.robot, dict(zip(ARM, q, strict=True)))[link] @ origin
              for q in result.arm_positions_rad]
    points = np.array([(p @ corners.T).T[:, :3] for p in placed])
    return np.asarray(np.linalg.norm(np.diff(points, axis=0), axis=2).max(axis=1))


def test_the_arm_stops_at_the_wall_and_follows_again_when_the_reference_comes_back():
    result = run(SWING)
    dt = result.plan.dt_s
    assert [(c.link, c.obstacle) for c in result.contacts] == [("arm_link4", "wall 1")]
    q = result.arm_positions_rad[:, ARM.index("arm_base_to_link1")]
    times = np.arange(len(q)) * dt
    reference = np.clip(np.interp(times, [0, 2, 4], [0, 1.5, 0]), -1.57, 1.57)
    held = np.flatnonzero((np.diff(q) == 0) & (reference[1:] > q[:-1]))
    assert len(held) > 50, "the arm never waited at the wall"
    q_held = q[held[0]]
    assert 0.3 < q_held < 1.2 and np.all(q[held] == q_held)
    assert result.contacts[0].time_s == pytest.approx(held[0] * dt)
    gaps = _gaps(result, SWING, {"arm_link4"})
    assert gaps.min() >= -1e-9, "arm_link4 went into the wall"
    # where it waits, it is less than one tick of its own motion from the wall
    assert 0 <= gaps[held[0]] <= _corners_moved(result, "arm_link4").max()
    # once the reference is back below the held angle, the arm follows it again
    back = np.flatnonzero((times > 2) & (reference < q_held))[0]
    assert q[back + 1] < q_held
    np.testing.assert_allclose(q[back + 2:], reference[back + 2:], atol=1e-9)
    assert q[-1] == 0.0


def test_base_and_arm_pressed_against_a_wall_wait_and_both_back_away():
    result = run(PRESS)
    dt, truth = result.plan.dt_s, result.truth
    assert result.contacts and {c.obstacle for c in result.contacts} == {"wall 1"}
    assert _gaps(result, PRESS).min() >= -1e-9, "a link went into the wall"
    first = round(result.contacts[0].time_s / dt)
    ahead = slice(first + 5, round(4 / dt))  # still asked forward, against the wall
    assert np.all(np.diff(truth.x_m[ahead]) == 0) and np.all(result.plan.left_rad_s[ahead] > 0)
    q = result.arm_positions_rad
    assert np.all(np.diff(q[ahead], axis=0) == 0), "the arm moved through the wall"
    backing = slice(round(6.5 / dt), None)
    assert np.all(np.diff(truth.x_m[backing]) < 0)  # the base backs away from the wall
    # the arm follows its reference again and reaches the last point
    assert q[-1, :2].tolist() == pytest.approx([-0.2, 0.1], abs=1e-12)


@pytest.mark.parametrize("document", [SWING, PRESS], ids=["swing", "press"])
def test_pieces_of_any_length_hold_the_same_contacts_and_motion(document):
    s = scenario(document)
    solids = world_solids(s.world)
    whole = simulator.run(BODY, s, seed=3, solids=solids)
    assert whole.contacts
    for piece_s in (0.01, 0.37, 2.0):
        pieces = list(simulator.pieces(BODY, s, seed=3, solids=solids, piece_s=piece_s))
        for name in ("x_m", "y_m", "yaw_rad", "linear_m_s", "angular_rad_s"):
            boundaries = not name.endswith("_s")  # a piece's first boundary ended the last one
            joined = np.concatenate([getattr(p.truth, name)[1 if boundaries and i else 0:]
                                     for i, p in enumerate(pieces)])
            assert joined.tobytes() == getattr(whole.truth, name).tobytes(), (name, piece_s)
        arm = np.vstack([p.arm_positions_rad[1 if i else 0:] for i, p in enumerate(pieces)])
        assert arm.tobytes() == whole.arm_positions_rad.tobytes(), piece_s
        assert [c for p in pieces for c in p.contacts] == whole.contacts
