"""The camera's one-origin ray casting: culling never drops what a ray meets.

Spheres placed at random around a camera, culled or not, are cast against every ray of the
view with numpy's own quadratic: a culled sphere is never met.
"""

from __future__ import annotations

import math

import numpy as np

from servicebot_cli.simulate.sensors import camera_rays
from servicebot_cli.simulate.sensors.camera_image import camera_view, scaled
from servicebot_cli.simulate.sensors.camera_info import Intrinsics


def _view():
    f = 1920 / (2 * math.tan(1.085595 / 2))
    full = Intrinsics(1920, 1080, (f, 0, 960.5, 0, f, 540.5, 0, 0, 1),
                      (f, 0, 960.5, 0, 0, f, 540.5, 0, 0, 0, 1, 0))
    return camera_view(scaled(full, 0.05), 0.05, 100.0)


def _met(directions, centre, radius):
    """Whether any ray from the origin along ``directions`` meets the sphere (by the roots)."""
    b = directions @ centre
    disc = b * b - (centre @ centre - radius**2)
    return bool(np.any((disc >= 0) & (b + np.sqrt(np.maximum(disc, 0)) >= 0)))


def test_a_culled_sphere_is_met_by_no_ray_and_culling_drops_most_behind():
    view = _view()
    half_angle = math.acos(float(view.forward.min()))
    rng = np.random.default_rng(4)
    axis, origin = np.array([1.0, 0.0, 0.0]), np.zeros(3)
    culled = 0
    for _ in range(400):
        centre = rng.uniform(-3, 3, 3)
        radius = float(rng.uniform(0.01, 0.8))
        if not camera_rays.in_view(centre, radius, origin, axis, half_angle):
            culled += 1
            assert not _met(view.directions, centre, radius), (centre, radius)
    assert culled > 150  # most of the space is outside a 62-degree view


def test_a_sphere_in_front_is_kept_and_its_distance_is_exact():
    view = _view()
    d = camera_rays.columns(view.directions)
    transform = np.eye(4)
    transform[:3, 3] = (2.0, 0.0, 0.0)
    distances = camera_rays.primitive_distances("sphere", np.full(3, 0.5), transform,
                                                np.zeros(3), d)
    assert camera_rays.in_view(transform[:3, 3], 0.5, np.zeros(3), np.array([1.0, 0, 0]), 0.6)
    # the sphere's nearest point is 1.5 m ahead; the rays nearest the axis pass within 0.006 rad
    assert 1.5 - 1e-12 <= float(np.min(distances)) < 1.5 + 1e-3
    assert np.isinf(distances).sum() > len(distances) / 2  # a small sphere: most rays miss
