"""A level fan of rays meets only the mesh triangles that cross its plane.

Moller-Trumbore against every triangle is the reference: the fan's answer with the
triangles off its plane left out is the same, to the bit, and trimesh's own ray caster
agrees on where the rays enter.
"""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from servicebot_cli.simulate.world import robot_rays
from servicebot_cli.simulate.world.robot_rays import mesh_entry


def _fan(origin, count: int = 180, tilt: float = 0.0):
    angles = np.linspace(-np.pi, np.pi, count, endpoint=False)
    directions = np.column_stack((np.cos(angles), np.sin(angles), np.full(count, tilt)))
    directions /= np.linalg.norm(directions, axis=1)[:, None]
    origins = np.broadcast_to(np.asarray(origin, dtype=float), directions.shape)
    return [origins[:, j].copy() for j in range(3)], [directions[:, j].copy() for j in range(3)]


@pytest.fixture(scope="module")
def sphere():
    mesh = trimesh.creation.icosphere(subdivisions=4, radius=0.3)  # 5,120 triangles
    mesh.apply_translation([1.0, 0.2, 0.05])
    return np.asarray(mesh.vertices, dtype=float), np.asarray(mesh.faces, dtype=np.int64), mesh


@pytest.mark.parametrize("tilt", [0.0, 0.02])  # a level fan, and a cone (no plane)
def test_the_fan_sees_what_every_triangle_gives(sphere, monkeypatch, tilt):
    vertices, faces, mesh = sphere
    o, d = _fan((0.0, 0.0, 0.0), tilt=tilt)
    culled = mesh_entry(o, d, vertices, faces)
    monkeypatch.setattr(robot_rays, "_crossing_the_rays_plane",
                        lambda origins, directions, v, f: np.ones(len(f), dtype=bool))
    every = mesh_entry(o, d, vertices, faces)
    assert np.array_equal(culled, every)
    assert np.isfinite(culled).sum() >= 10  # the sphere is in view
    locations, rays, _ = mesh.ray.intersects_location(np.column_stack(o), np.column_stack(d))
    reference = np.full(len(culled), np.inf)
    np.minimum.at(reference, rays, np.linalg.norm(locations, axis=1))
    assert np.allclose(culled, reference, atol=1e-9)


def test_only_triangles_across_a_level_fans_plane_are_kept(sphere):
    vertices, faces, _ = sphere
    o, d = _fan((0.0, 0.0, 0.0))
    kept = robot_rays._crossing_the_rays_plane(np.column_stack(o), np.column_stack(d),
                                               vertices, faces)
    z = vertices[faces][:, :, 2]
    assert np.array_equal(kept, (z.min(axis=1) <= 1e-9) & (z.max(axis=1) >= -1e-9))
    assert 0 < kept.sum() < len(faces) / 10
    tilted = _fan((0.0, 0.0, 0.0), tilt=0.02)
    assert robot_rays._crossing_the_rays_plane(np.column_stack(tilted[0]),
                                               np.column_stack(tilted[1]),
                                               vertices, faces).all()
