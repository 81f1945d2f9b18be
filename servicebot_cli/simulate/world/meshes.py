"""Mesh obstacles: files loaded with trimesh, and footprint contact tested with rays.

A mesh (a room, a shelf) is placed with its pose and scale. LIDAR rays hit it through trimesh
(Embree when ``embreex`` is installed). The footprint touches it when a segment of the
footprint's outline, at a few heights between the floor and the top of the base, crosses its
surface, which catches walls and posts the base runs into.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.transforms import rpy_matrix
from servicebot_cli.simulate.scenario.definition import Scenario
from servicebot_cli.simulate.scenario.located import Located
from servicebot_cli.simulate.world.raycast import Mesh, mesh_distances
from servicebot_cli.simulate.world.solids import Footprint

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
_HEIGHTS = (0.02, 0.5, 0.98)  # fractions of the base's height where the outline is tested


def load_meshes(scenario: Scenario, base_dir: Path) -> list[Mesh]:
    """The scenario's meshes, placed in the world (relative files are from ``base_dir``).

    Raises:
        ScenarioError: A missing or unreadable mesh, naming the scenario line.
    """
    if not scenario.world.meshes:
        return []
    import trimesh

    located = scenario.source or Located({}, {}, scenario.name)
    meshes: list[Mesh] = []
    for i, spec in enumerate(scenario.world.meshes):
        path = Path(spec.file) if Path(spec.file).is_absolute() else base_dir / spec.file
        where = ("world", "meshes", i, "file")
        if not path.is_file():
            raise located.error(where, f"'{spec.file}' is not a file (looked in {path})")
        try:
            mesh = trimesh.load(path, force="mesh")
        except Exception as exc:  # trimesh raises many types for unreadable files
            raise located.error(where, f"cannot load '{spec.file}' as a mesh: {exc}") from None
        if not isinstance(mesh, trimesh.Trimesh) or not len(mesh.faces):
            raise located.error(where, f"'{spec.file}' has no triangles")
        transform = np.eye(4)
        transform[:3, :3] = rpy_matrix(*spec.rpy_rad) * spec.scale
        transform[:3, 3] = spec.xyz_m
        mesh.apply_transform(transform)
        meshes.append(mesh)
    return meshes


def footprint_hits_meshes(footprint: Footprint, meshes: Sequence[Mesh], x: FloatArray,
                          y: FloatArray, yaw: FloatArray) -> IntArray:
    """Index of the first mesh each pose's footprint outline crosses, -1 where free."""
    hit = np.full(len(x), -1, dtype=np.int64)
    if not len(x):
        return hit
    corners = footprint.corners()
    c, s = np.cos(yaw)[:, None], np.sin(yaw)[:, None]
    wx = x[:, None] + c * corners[:, 0] - s * corners[:, 1]  # (P, 4)
    wy = y[:, None] + s * corners[:, 0] + c * corners[:, 1]
    ex, ey = np.roll(wx, -1, axis=1) - wx, np.roll(wy, -1, axis=1) - wy
    length = np.hypot(ex, ey)
    for i in reversed(range(len(meshes))):
        crossed = np.zeros(len(x), dtype=bool)
        for fraction in _HEIGHTS:
            z = np.full(wx.shape, fraction * footprint.top_m)
            origins = np.stack((wx, wy, z), axis=-1).reshape(-1, 3)
            dirs = np.stack((ex / length, ey / length, np.zeros_like(ex)), axis=-1).reshape(-1, 3)
            distance = mesh_distances(meshes[i], origins, dirs).reshape(wx.shape)
            crossed |= np.any(distance <= length, axis=1)
        hit[crossed] = i
    return hit
