"""What rules need beyond the description: package search, mesh files, thresholds.

The only part of a run that touches files other than the description: mesh references are
resolved here (as ``expand`` resolves them) and read through one MeshCache per run.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from servicebot_cli.check.meshes import MeshCache, MeshError, MeshInfo
from servicebot_cli.common.errors import PackageNotFound
from servicebot_cli.description.packages import PackageResolver

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Shape
    from servicebot_cli.description.robot import RobotDescription


class MeshNotFound(Exception):
    """A mesh reference that resolves to no file; the message says where it looked."""


@dataclass
class CheckEnv:
    """Shared by every file of a run.

    Attributes:
        resolver: Package search (``--package``, ROS_PACKAGE_PATH, AMENT_PREFIX_PATH).
        meshes: Mesh files read so far.
        inertia_factor: How far (as a ratio) inertia may stray from the geometry's (SB301).
        load_meshes: False when no mesh rule is selected: mesh files are then never read.
    """

    resolver: PackageResolver = field(default_factory=PackageResolver.from_environment)
    meshes: MeshCache = field(default_factory=MeshCache)
    inertia_factor: float = 2.0
    load_meshes: bool = True

    def mesh_path(self, robot: RobotDescription, shape: Shape) -> Path:
        """The file a ``<mesh filename>`` names.

        Raises:
            MeshNotFound: Saying where it looked.
        """
        filename = shape.geometry.filename or ""
        base_dir = Path(robot.source_of(shape.element).file).parent
        try:
            path = self.resolver.resolve_uri(filename, base_dir)
        except PackageNotFound as exc:
            raise MeshNotFound(f"mesh '{filename}': {exc}") from None
        if not path.is_file():
            where = path if path.is_absolute() else Path.cwd() / path
            kind = "is a directory" if path.is_dir() else "does not exist"
            raise MeshNotFound(f"mesh '{filename}': {where} {kind}")
        return path

    def mesh(self, robot: RobotDescription, shape: Shape, with_mass: bool = False) -> MeshInfo:
        """The summary of the mesh ``shape`` names.

        Raises:
            MeshNotFound: No such file.
            MeshError: The file is not a loadable mesh.
        """
        return self.meshes.get(self.mesh_path(robot, shape), with_mass)


__all__ = ["CheckEnv", "MeshError", "MeshNotFound"]
