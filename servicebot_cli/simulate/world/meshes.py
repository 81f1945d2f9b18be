"""Mesh obstacles: files loaded with trimesh and placed in the world.

A mesh (a room, a shelf) is placed with its pose and scale. LIDAR rays hit it through trimesh
(Embree when ``embreex`` is installed); the robot's links touch its surface through Coal
(:mod:`.contacts`).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.library_logs import captured
from servicebot_cli.kinematics.transforms import rpy_matrix
from servicebot_cli.simulate.scenario.definition import Scenario
from servicebot_cli.simulate.scenario.located import Located
from servicebot_cli.simulate.world.raycast import Mesh

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
            with captured():  # texture chatter: only the geometry matters here
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
