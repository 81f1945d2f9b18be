"""LIDAR fans cast only where a solid's bearings are: the same distances as every ray cast."""

from __future__ import annotations

import math

import numpy as np
import pytest

from servicebot_cli.kinematics.transforms import rpy_matrix
from servicebot_cli.simulate.world.raycast import Fans, cast, facing_rays
from servicebot_cli.simulate.world.solids import Solid


def _solids(rng: np.random.Generator, tilted: bool) -> list[Solid]:
    solids = []
    for i in range(8):
        kind = "box" if i % 3 else "cylinder"
        yaw = rng.choice([0.0, math.pi / 2, rng.uniform(-math.pi, math.pi)])
        rotation = rpy_matrix(0.3, -0.2, yaw) if tilted and kind == "box" and i % 2 \
            else rpy_matrix(0.0, 0.0, yaw)
        half = rng.uniform(0.05, 1.5, 3)
        if kind == "cylinder":
            half[1] = half[0]
        solids.append(Solid(f"s{i}", kind, np.array([*rng.uniform(-2, 2, 2), half[2]]),
                            np.array(rotation), half))
    return solids


def _fans(rng: np.random.Generator, scans: int, bearings: np.ndarray, z_m: float):
    heading = rng.uniform(-math.pi, math.pi, scans)
    origins = np.column_stack((rng.uniform(-2.5, 2.5, (scans, 2)), np.full(scans, z_m)))
    angle = heading[:, None] + bearings[None, :]
    directions = np.stack((np.cos(angle), np.sin(angle), np.zeros_like(angle)), axis=-1)
    return (np.repeat(origins, len(bearings), axis=0), directions.reshape(-1, 3),
            Fans(heading, bearings))


@pytest.mark.parametrize("bearings", [
    np.linspace(-math.pi, math.pi, 360),  # a full turn, both ends included
    np.linspace(-2.0, 1.0, 100),  # a partial fan
    np.linspace(math.pi, -math.pi, 90, endpoint=False),  # bearings decreasing
    np.random.default_rng(3).permutation(np.linspace(0.0, 2 * math.pi, 50, endpoint=False)),
    np.array([0.3]),  # one ray a scan
])
@pytest.mark.parametrize("tilted", [False, True])
def test_fans_give_the_distances_of_every_ray(bearings, tilted):
    rng = np.random.default_rng(len(bearings) + tilted)
    solids = _solids(rng, tilted)
    origins, directions, fans = _fans(rng, 120, bearings, z_m=0.04)
    every = cast(origins, directions, solids)
    culled = cast(origins, directions, solids, fans=fans)
    assert np.array_equal(every, culled)  # bit for bit, inside solids and out
    assert np.isfinite(every).mean() > 0.2  # the solids are in view


def test_a_solid_out_of_the_way_keeps_few_rays_and_one_around_the_fan_keeps_all():
    bearings = np.linspace(-math.pi, math.pi, 360)
    far = Solid("far", "box", np.array([5.0, 0.0, 0.5]), np.eye(3), np.array([0.1, 0.1, 0.5]))
    around = Solid("around", "box", np.array([0.0, 0.0, 0.5]), np.eye(3),
                   np.array([1.0, 1.0, 0.5]))
    fans = Fans(np.array([0.0, math.pi / 2]), bearings)
    (seen_far, fan_far), (seen_around, _) = facing_rays(fans, np.zeros(2), np.zeros(2),
                                                         [far, around])
    assert np.array_equal(fan_far, seen_far // 360)
    # 0.2 m wide at 4.9 m: bearings within 0.0204 rad of the box's; rays 359 / 2 pi apart
    assert sorted(seen_far.tolist()) == [179, 180, 360 + 89, 360 + 90]
    assert sorted(seen_around.tolist()) == list(range(720))
