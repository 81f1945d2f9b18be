"""What rules need beyond the description: package search, mesh files, thresholds.

The only part of a run that touches files other than the description: mesh references are
resolved here (as ``expand`` resolves them) and read through one MeshCache per run.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from servicebot_cli.check.meshes import MeshCache, MeshError, MeshInfo
from servicebot_cli.check.packages import PackageSearch, Resolved
from servicebot_cli.common.inputs import not_a_file
from servicebot_cli.description.packages import PackageResolver, is_remote
from servicebot_cli.kinematics.mesh_wheels import FloatArray, MeshPoints, points_at

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Shape
    from servicebot_cli.description.robot import RobotDescription


class MeshNotFound(Exception):
    """A mesh reference that resolves to no file; the message says where it looked.

    Attributes:
        resolved: Where the reference led (``path`` None: its package is nowhere).
    """

    def __init__(self, message: str, resolved: Resolved) -> None:
        super().__init__(message)
        self.resolved = resolved


class RemoteMesh(MeshNotFound):
    """A mesh fetched over the network (``https://``, Gazebo Fuel): never read here."""


@dataclass
class CheckEnv:
    """Shared by every file of a run.

    Attributes:
        resolver: Package search (``--package``, ROS_PACKAGE_PATH, AMENT_PREFIX_PATH).
        meshes: Mesh files read so far.
        inertia_factor: How far (as a ratio) inertia may stray from the geometry's (SB301).
        load_meshes: False when no rule that reads mesh files is selected: they are then
            never read.
        resolve_meshes: False when no rule about where mesh references lead (or about the
            files they lead to) is selected: they are then not even resolved.
        model_ahead: Build SB701's model in a forked child while the other rules run (a
            one-file run with a second core; see :mod:`~servicebot_cli.check.model_ahead`).
    """

    resolver: PackageResolver = field(default_factory=PackageResolver.from_environment)
    meshes: MeshCache = field(default_factory=MeshCache)
    inertia_factor: float = 2.0
    load_meshes: bool = True
    resolve_meshes: bool = True
    model_ahead: bool = False
    search: PackageSearch = field(init=False)
    _directories: dict[str, Path] = field(init=False, default_factory=dict)
    _not_files: dict[Path, str | None] = field(init=False, default_factory=dict)
    _vertices: dict[Path, FloatArray | None] = field(init=False, default_factory=dict)

    def __post_init__(self) -> None:
        self.search = PackageSearch(self.resolver)

    def resolve(self, robot: RobotDescription, shape: Shape) -> Resolved:
        """Where the ``<mesh filename>`` of ``shape`` leads (cached for the run)."""
        filename = shape.geometry.filename or ""
        return self.search.resolve(filename, self._directory(robot.source_of(shape.element).file))

    def directory_of(self, robot: RobotDescription, shape: Shape) -> Path:
        """The directory of the file that writes ``shape`` (where its relative paths start)."""
        return self._directory(robot.source_of(shape.element).file)

    def _directory(self, file: str) -> Path:
        """The absolute directory of a description's source ``file`` (made once per file)."""
        found = self._directories.get(file)
        if found is None:
            found = self._directories[file] = Path(file).parent.absolute()
        return found

    def mesh_path(self, robot: RobotDescription, shape: Shape) -> Path:
        """The file a ``<mesh filename>`` names.

        Raises:
            MeshNotFound: Saying where it looked.
        """
        filename = shape.geometry.filename or ""
        if is_remote(filename):
            raise RemoteMesh(f"mesh '{filename}' is fetched over the network", Resolved(None))
        resolved = self.resolve(robot, shape)
        path = resolved.path
        if path is None:
            raise MeshNotFound(f"mesh '{filename}': {resolved.error}", resolved)
        if path not in self._not_files:  # a robot names each mesh twice or more
            self._not_files[path] = not_a_file(path)
        problem = self._not_files[path]
        if problem is not None:
            if "$(" in filename:  # sjtu_drone's stale .urdf: file://$(find ...)/models/...
                problem += ("; its '$(...)' is xacro's, and nothing substitutes it in a file "
                            "xacro does not expand")
            elif (twin := case_twin(path)) is not None:
                problem += (f"; '{twin}' beside it differs only in case, which Windows and "
                            "macOS ignore and Linux does not")
            raise MeshNotFound(f"mesh '{filename}': {path} {problem}", resolved)
        return path

    def mesh(self, robot: RobotDescription, shape: Shape, with_mass: bool = False) -> MeshInfo:
        """The summary of the mesh ``shape`` names.

        Raises:
            MeshNotFound: No such file.
            MeshError: The file is not a loadable mesh.
        """
        return self.meshes.get(self.mesh_path(robot, shape), with_mass)

    def mesh_points(self, robot: RobotDescription) -> MeshPoints:
        """The vertices of ``robot``'s mesh shapes, scaled, as the drive's wheels take them.

        Read only for wheels drawn as meshes, each file once a run.
        """
        def path_of(shape: Shape) -> Path | None:
            try:
                return self.mesh_path(robot, shape)
            except MeshNotFound:
                return None

        return points_at(path_of, self._vertices)


__all__ = ["CheckEnv", "MeshError", "MeshNotFound", "RemoteMesh"]



def case_twin(path: Path) -> str | None:
    """The name of a file beside ``path`` that differs from it only in case, if any.

    A mesh exported on Windows or macOS (Left_Tire.STL named left_tire.stl in the URDF) loads
    there and nowhere else: Linux file names are case-sensitive.
    """
    try:
        return next((entry.name for entry in os.scandir(path.parent)
                     if entry.name.lower() == path.name.lower() and entry.name != path.name),
                    None)
    except OSError:
        return None
