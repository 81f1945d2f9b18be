"""The packages a description uses, how each was found, and the findings about them.

Mesh references resolve through :class:`~servicebot_cli.description.packages.PackageResolver`,
once per reference and directory in a run. Per file, a package that cannot be found is one
finding saying how many meshes it hides (SB408), a package found only the way some loaders
find it is one warning (SB409), and meshes fetched over the network are one note (SB410).
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

from servicebot_cli.check import include_names
from servicebot_cli.check.findings import Issue
from servicebot_cli.common.errors import PackageNotFound, RemoteResource, UnknownScheme
from servicebot_cli.common.inputs import read_again
from servicebot_cli.description.loader import comments_blanked
from servicebot_cli.description.package_dirs import package_name
from servicebot_cli.description.packages import PackageLocation, PackageResolver, is_remote

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

_FIND = re.compile(r"\$\(find\s+([^)\s]+)\s*\)")


@dataclass(frozen=True)
class Resolved:
    """Where one mesh reference leads.

    Attributes:
        path: The file it names, or None when its package is nowhere.
        package: The ``package://`` name, or None for paths and ``file://``.
        location: How the package was found, or None.
        error: Why the package was not found (where it looked), or None.
        model: Named as Gazebo's ``model://NAME/...``: ``package`` is a model's name.
    """

    path: Path | None
    package: str | None = None
    location: PackageLocation | None = None
    error: str | None = None
    model: bool = False


@dataclass
class PackageSearch:
    """Resolves references with one resolver, remembering every answer for the run."""

    resolver: PackageResolver = field(default_factory=PackageResolver.from_environment)
    _resolved: dict[tuple[str, Path], Resolved] = field(default_factory=dict)
    _located: dict[tuple[str, Path], PackageLocation | None] = field(default_factory=dict)

    def resolve(self, uri: str, base_dir: Path) -> Resolved:
        """Where ``uri``, written in a file in ``base_dir``, leads."""
        key = (uri, base_dir)
        if key not in self._resolved:
            self._resolved[key] = self._resolve(uri, base_dir)
        return self._resolved[key]

    def _resolve(self, uri: str, base_dir: Path) -> Resolved:
        if not uri.startswith(("package://", "model://")):
            try:
                return Resolved(self.resolver.resolve_uri(uri, base_dir))
            except (RemoteResource, UnknownScheme) as exc:  # check says so before it
                return Resolved(None, error=str(exc))  # resolves anything
        name = uri.partition("://")[2].partition("/")[0]
        probe = self.resolver.probe()
        model = uri.startswith("model://")
        try:
            path = probe.resolve_uri(uri, base_dir)
        except PackageNotFound as exc:
            return Resolved(None, name, None, str(exc), model)
        except UnknownScheme as exc:  # model:///abs: no model named
            return Resolved(None, error=str(exc))
        if model:
            return Resolved(path, name, probe.found.get(f"model://{name}"), model=True)
        if not name and probe.found:  # package:///: an absolute path, or NAME as Pinocchio
            [(name, location)] = probe.found.items()  # reads it: the one the probe found
            return Resolved(path, name, location)
        return Resolved(path, name, probe.found.get(name))

    def locate(self, name: str, directory: Path) -> PackageLocation | None:
        """How ``$(find name)`` in a file in ``directory`` was answered, or None."""
        key = (name, directory)
        if key not in self._located:
            try:
                self._located[key] = self.resolver.locate(name, directory)
            except PackageNotFound:
                self._located[key] = None
        return self._located[key]


def used(robot: RobotDescription, search: PackageSearch) -> dict[str, PackageLocation | None]:
    """Every package the description uses, by name: its location, or None when not found.

    ``$(find)`` packages of the xacro files read, then ``package://`` packages of meshes.
    """
    found: dict[str, PackageLocation | None] = {}
    for file in robot.files if robot.expanded else ():
        path = Path(file)
        data = _source_bytes(path)
        if data is None:
            continue
        for name in dict.fromkeys(_FIND.findall(data.decode("utf-8", "replace"))):
            if "$" not in name:
                found.setdefault(name, search.locate(name, path.parent.absolute()))
    for _, uri, base_dir in mesh_references(robot):
        if uri.startswith("package://") and uri[len("package://"):].partition("/")[0]:
            resolved = search.resolve(uri, base_dir)
            if resolved.package is not None:
                found.setdefault(resolved.package, resolved.location)
    return found


def find_issues(robot: RobotDescription, search: PackageSearch) -> Iterator[Issue]:
    """SB409 per package a ``$(find NAME)`` of the xacro sources names that ROS would not find.

    Found only as a directory named NAME (a package.xml whose <name> is another), ROS's xacro
    fails on the file ('package not found'): it expands here and nowhere else. Once per
    package and file, at its first ``$(find)``.
    """
    for file in robot.files if robot.expanded else ():
        path = Path(file)
        data = _source_bytes(path)
        if data is None:
            continue
        blanked = comments_blanked(data)
        text = blanked.decode("utf-8", "replace")
        constants = include_names.constants(blanked) if b"$(find $" in blanked else None
        seen: set[str] = set()
        for match in _FIND.finditer(text):
            # $(find ${package_name}): the file's own constants name the package
            names = [match[1]] if "$" not in match[1] or constants is None else \
                include_names.substituted(match[1], *constants)
            for name in names:
                if "$" in name or name in seen:
                    continue
                seen.add(name)
                location = search.locate(name, path.parent.absolute())
                if location is None or location.ros_finds_it:
                    continue
                line = text.count("\n", 0, match.start()) + 1
                column = match.start() - text.rfind("\n", 0, match.start())
                yield Issue("SB409", f"$(find {name}) resolves only as {location.how}; ROS "
                            "finds packages by the <name> of their package.xml, so ROS's "
                            f"xacro fails on this file ('package {name} not found')",
                            where=(file, line, column), fix=_find_fix(name, location.path))


def _source_bytes(path: Path) -> bytes | None:
    """A source file's bytes (what a pipe gave, read once); None: it cannot be read."""
    try:
        data = read_again(path)
        return path.read_bytes() if data is None else data
    except OSError:
        return None


def _find_fix(name: str, directory: Path) -> str:
    """Write the package's own name, when its package.xml gives one."""
    own = package_name(directory)
    if own and own != name:
        return f"write $(find {own}), the <name> in its package.xml"
    return f"give {directory.name} a package.xml with <name>{name}</name>"


def mesh_references(robot: RobotDescription) -> Iterator[tuple[ET.Element, str, Path]]:
    """Each ``<mesh>`` with a filename, the filename, and the directory of its source file."""
    for link in robot.links:
        for shape in (*link.visuals, *link.collisions):
            uri = shape.geometry.filename
            if shape.geometry.kind != "mesh" or not uri or shape.element is None:
                continue
            mesh = shape.element.find("geometry/mesh")
            element = mesh if mesh is not None else shape.element
            yield element, uri, Path(robot.source_of(shape.element).file).parent.absolute()


class _Unfound(NamedTuple):
    """A mesh counted missing: why its package is nowhere, where, and its SB401 if made."""

    message: str
    element: ET.Element
    where: str = ""
    uri: str = ""
    missing_file: Issue | None = None


@dataclass
class FileTally:
    """What one file's mesh references found, gathered while the geometry rules run."""

    missing: dict[str, list[_Unfound]] = field(default_factory=dict)
    """By package name (or ``model://NAME`` for a Gazebo model), each mesh it hides. Where
    another mesh finds the package (a directory some loaders take for it), the package is no
    longer nowhere: each of these is a missing file (:meth:`issues`)."""
    loader_only: dict[str, tuple[PackageLocation, ET.Element]] = field(default_factory=dict)
    remote: list[tuple[str, ET.Element]] = field(default_factory=list)

    def add_missing(self, resolved: Resolved, element: ET.Element, where: str = "",
                    uri: str = "") -> None:
        """Count a mesh hidden by a package that is nowhere."""
        self.missing.setdefault(_key(resolved), []).append(
            _Unfound(resolved.error or "", element, where, uri))

    def guessed_wrong(self, resolved: Resolved, element: ET.Element, missing_file: Issue) -> bool:
        """Whether a missing mesh's package was only guessed, by a directory of its name.

        Where ROS would not find the package and the directory some loaders take for it
        does not hold the file, the package is as good as nowhere (SB408, a warning, as for
        a package not found): a folder that happens to share the name (a dataset's
        ``drake/``, a repository's ``ranger_mini/`` beside package ``ranger_mini_v2``) says
        nothing about the file. Unless another mesh is found there (:meth:`issues`): then
        the guess holds, and ``missing_file`` (SB401) stands.
        """
        location = resolved.location
        if location is None or location.ros_finds_it or location.three_slashes or \
                location.gazebo_model:  # Gazebo's model path is no guess: the file is missing
            return False
        name = _key(resolved)
        self.missing.setdefault(name, []).append(_Unfound(
            f"package '{name}' not found as ROS finds packages (by package.xml); looked in "
            f"{location.how}, which holds no such file", element, missing_file=missing_file))
        return True

    def add_found(self, resolved: Resolved, element: ET.Element) -> None:
        """Remember a package found only the way some loaders find it."""
        if resolved.location is not None and not resolved.location.ros_finds_it:
            self.loader_only.setdefault(_key(resolved), (resolved.location, element))

    def issues(self) -> Iterator[Issue]:
        """SB408 per missing package, SB409 per loader-only package, SB410 for remote meshes."""
        for name, unfound in self.missing.items():
            found = self.loader_only.get(name)
            if found is not None:  # another mesh found it: these files are missing there
                for mesh in unfound:
                    yield mesh.missing_file or _missing_there(mesh, found[0])
                continue
            count, message, element = len(unfound), unfound[0].message, unfound[0].element
            meshes = f"{count} mesh{'es' if count != 1 else ''}"
            model = name.removeprefix("model://")
            yield Issue("SB408", f"{message.split(';', 1)[0]}: {meshes} not checked; looked in"
                        f"{message.split('looked in', 1)[-1]}", element,
                        fix=f"set GAZEBO_MODEL_PATH to the directory that holds model {model}, "
                        f"or pass --package {model}=DIR" if model != name else
                        f"pass --package {name}=DIR, or check from the workspace that "
                        "holds the package")
        for location, element in self.loader_only.values():
            message = location.warning or ""
            if not location.name:
                message = ("package:///PATH (three slashes) is read as an absolute path by some "
                           "loaders; ROS resolves package:// by package name and would not find it")
            named = ("write package://NAME/... with a package's name" if location.name in (
                ".", "..") else f"give the package a package.xml with <name>{location.name}</name>")
            fix = ("write the path relative to the file, or package://PKG/... with the name of "
                   "the package that holds it" if not location.name else
                   f"write package://{location.name}/... with two slashes" + (
                       "" if location.named_ros_finds else f", and {named}")
                   if location.three_slashes else
                   f"write package://{location.name}/... if {location.name} is a ROS package "
                   "(Gazebo reads that too), else a path relative to the file"
                   if location.gazebo_model
                   else f"{named}, or use a path relative to the file")
            yield Issue("SB409", message, element, fix=fix)
        if self.remote:
            uri, element = self.remote[0]
            more = f" and {len(self.remote) - 1} more" if len(self.remote) > 1 else ""
            yield Issue("SB410", f"mesh '{uri}'{more} fetched over the network (Gazebo Fuel): "
                        "not read here", element)


def _missing_there(mesh: _Unfound, location: PackageLocation) -> Issue:
    """SB401 for ``mesh``, not in the directory ``location`` where the file's other meshes are."""
    rel = mesh.uri.split("://", 1)[-1].partition("/")[2]
    return Issue("SB401", f"{mesh.where}: mesh '{mesh.uri}': {location.path / rel} does not "
                 f"exist (package '{location.name}' is {location.how}, where its other meshes "
                 "are)", mesh.element, fix="fix the path: the directory holds no such file")


def _key(resolved: Resolved) -> str:
    """What a file's findings about ``resolved`` are gathered under.

    Its package's name, or ``model://NAME``: a model and a package of one name are two things.
    """
    name = resolved.package or ""
    return f"model://{name}" if resolved.model else name


__all__ = ["FileTally", "PackageSearch", "Resolved", "is_remote", "mesh_references", "used"]
