"""Find ROS packages without ROS: ``$(find pkg)`` and ``package://pkg/...``.

One resolver for every command. A package is looked for, first hit wins:

1. ``--package NAME=DIR`` given by the user;
2. the package that holds the file: the nearest ``package.xml`` above it, by its ``<name>``;
3. every package of the enclosing workspace: ``package.xml`` files under the colcon workspace
   (the directory whose ``src/`` holds the file) or else the repository root, skipping trees
   marked ``COLCON_IGNORE``, ``AMENT_IGNORE`` or ``CATKIN_IGNORE``;
4. ``ROS_PACKAGE_PATH``: each entry a package or a tree of packages;
5. ``AMENT_PREFIX_PATH``: ``PREFIX/share/NAME``;
6. a directory called NAME in a directory of those two paths (Pinocchio's convention).

Steps 1-5 are how ROS finds packages. What only some loaders accept resolves too, with a
warning that ROS would not find it: a directory called NAME above the file (Pinocchio and
yourdfpy search directory names: example-robot-data's ``package://example-robot-data/``),
``NAME/...`` beside the file or one of its parents (pybullet's ``package://meshes/...``),
``package:///abs/path``, and Gazebo's ``model://NAME/...`` (a directory NAME on Gazebo's model
paths, else a package NAME, as gazebo_ros puts packages on the model path). Relative
directories are made absolute once, against the current directory. Every lookup remembers
how it was answered (:attr:`PackageResolver.found`).
Packages and workspaces on disk are read by :mod:`~servicebot_cli.description.package_dirs`.
"""

from __future__ import annotations

import dataclasses
import os
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import unquote, urlparse

from servicebot_cli.common.errors import PackageNotFound, RemoteResource, UnknownScheme
from servicebot_cli.description.package_dirs import (
    holding_package,
    packages_under,
    workspace_root,
)

REMOTE_SCHEMES = ("http://", "https://")
MODEL_PATH_VARIABLES = ("GAZEBO_MODEL_PATH", "GZ_SIM_RESOURCE_PATH", "IGN_GAZEBO_RESOURCE_PATH")
"""Where Gazebo Classic, Gazebo (gz-sim) and Ignition look for ``model://NAME``."""
_SCHEME = re.compile(r"([A-Za-z][A-Za-z0-9+.-]*)://")


@dataclass(frozen=True)
class PackageLocation:
    """Where a package was found, and how.

    Attributes:
        name: The package name asked for.
        path: Its directory.
        how: How it was found, for people: ``"--package"``, ``"workspace /ws (package.xml)"``...
        ros_finds_it: Whether ROS (``ros2 pkg prefix``, robot_state_publisher, Gazebo) would
            find it the same way; False for what only some loaders accept.
        three_slashes: Named as ``package:///NAME/...``, which ROS reads as an empty name.
        named_ros_finds: With three slashes: whether ROS would find NAME with two.
        gazebo_model: Named as Gazebo's ``model://NAME/...``.
    """

    name: str
    path: Path
    how: str
    ros_finds_it: bool = True
    three_slashes: bool = False
    named_ros_finds: bool = True
    gazebo_model: bool = False

    @property
    def warning(self) -> str | None:
        """Why ROS would not find it, or None."""
        if self.ros_finds_it:
            return None
        if self.gazebo_model:
            return (f"model://{self.name}/... is resolved only by Gazebo, on its model path "
                    f"(here: {self.how}); RViz, MoveIt, Pinocchio and MuJoCo do not read "
                    "model://")
        if self.three_slashes:
            return (f"package:///{self.name}/... has three slashes: ROS reads the package name "
                    f"before the third as empty and would not find it; Pinocchio reads package "
                    f"'{self.name}' there ({self.how})")
        return (f"package '{self.name}' resolves only as {self.how}; ROS finds packages by "
                "the <name> of their package.xml on its package paths, so ROS tools would "
                "not find it")


@dataclass(frozen=True)
class PackageResolver:
    """Resolves package names to directories, as ROS and the common loaders do.

    Attributes:
        explicit: ``--package`` mappings, name to directory (absolute).
        ros_package_path: Directories from ``ROS_PACKAGE_PATH`` (absolute).
        ament_prefix_path: Prefixes from ``AMENT_PREFIX_PATH`` (absolute).
        model_path: Gazebo's model directories (``GAZEBO_MODEL_PATH``, ``GZ_SIM_RESOURCE_PATH``,
            ``IGN_GAZEBO_RESOURCE_PATH``; absolute).
        context: The directory of the file being read: where its package and workspace are
            looked for. None: only the paths above.
        found: Every package resolved so far, by name (filled as lookups happen).
    """

    explicit: Mapping[str, Path] = field(default_factory=dict)
    ros_package_path: tuple[Path, ...] = ()
    ament_prefix_path: tuple[Path, ...] = ()
    context: Path | None = None
    model_path: tuple[Path, ...] = ()
    found: dict[str, PackageLocation] = field(default_factory=dict, compare=False)

    @classmethod
    def from_environment(
        cls, explicit: Mapping[str, Path] | None = None, environ: Mapping[str, str] | None = None,
        context: Path | None = None,
    ) -> PackageResolver:
        """Build a resolver from ``--package`` mappings and the environment.

        Args:
            explicit: ``--package`` mappings; relative directories are relative to the current
                directory.
            environ: The environment (default: this process's).
            context: The directory of the file being read, if any.
        """
        env = os.environ if environ is None else environ
        return cls(
            explicit={name: Path(path).absolute() for name, path in (explicit or {}).items()},
            ros_package_path=_split_path(env.get("ROS_PACKAGE_PATH", "")),
            ament_prefix_path=_split_path(env.get("AMENT_PREFIX_PATH", "")),
            context=None if context is None else Path(context).absolute(),
            model_path=tuple(p for name in MODEL_PATH_VARIABLES
                             for p in _split_path(env.get(name, ""))),
        )

    def for_directory(self, directory: Path) -> PackageResolver:
        """The same search for a file in ``directory`` (an included file, another robot)."""
        return PackageResolver(self.explicit, self.ros_package_path, self.ament_prefix_path,
                               directory.absolute(), self.model_path, self.found)

    def probe(self) -> PackageResolver:
        """The same search, remembering its answers apart from this one's."""
        return dataclasses.replace(self, found={})

    def find(self, name: str) -> Path:
        """Directory of package ``name`` (its share directory for ament installs).

        Raises:
            PackageNotFound: Naming the package and every place searched.
        """
        return self.locate(name, self.context).path

    def locate(self, name: str, context: Path | None = None) -> PackageLocation:
        """Where package ``name`` is and how it was found, for a file in ``context``.

        Raises:
            PackageNotFound: Naming the package and every place searched.
        """
        context = None if context is None else context.absolute()  # "." has no parents
        location = self._ros_location(name, context) or self._loader_location(name, context)
        if location is None:
            raise PackageNotFound(f"package '{name}' not found{self._close(name, context)}; "
                                  f"looked in {self._searched(context)}")
        self.found.setdefault(name, location)
        return location

    def resolve_uri(self, uri: str, base_dir: Path) -> Path:
        """File path for a mesh or include reference.

        Args:
            uri: ``package://pkg/rel``, ``package:///abs``, ``file:///abs``, an absolute
                path or a relative path.
            base_dir: Directory of the file that holds the reference (relative paths and the
                file's own package and workspace start there).

        Raises:
            PackageNotFound: A ``package://`` reference to a package that is nowhere.
        """
        if uri.startswith("package://"):
            name, _, rel = uri[len("package://"):].partition("/")
            rel = unquote(rel)
            if not name:  # package:///abs: some loaders read it as a plain path
                return self._rooted(rel, base_dir)
            # package://pkg//meshes/x.stl: resource_retriever joins the two, and the path is
            # the package's, not the root's
            rel = rel.lstrip("/")
            base_dir = base_dir.absolute()  # a file named "r.urdf" is in ".", which has no parents
            if not rel:  # package://body.stl (onshape-to-robot's MuJoCo output)
                beside = " (a file of that name is beside the file)" if os.path.isfile(
                    base_dir / name) else ""
                raise UnknownScheme(f"no file after the package name '{name}' "
                                    f"(package://PACKAGE/PATH){beside}: ROS looks for a "
                                    f"package called '{name}'")
            location = (self._ros_location(name, base_dir)
                        or self._loader_location(name, base_dir)
                        or self._relative_location(name, rel, base_dir))
            if location is None:
                raise PackageNotFound(f"package '{name}' not found{self._close(name, base_dir)}"
                                      f"; looked in {self._searched(base_dir)}")
            from servicebot_cli.description.install_layout import installed_source

            path = Path(installed_source(str(location.path / rel)))
            if not os.path.exists(path):
                elsewhere = self._holding_elsewhere(name, rel, base_dir, location)
                if elsewhere is not None:
                    location, path = elsewhere, elsewhere.path / rel
            self.found.setdefault(name, location)
            return path
        if is_remote(uri):  # not a path: Path() would fold its '//' into 'http:/...'
            raise RemoteResource(f"'{uri}' is fetched over the network, which servicebot "
                                 "does not do")
        if uri.startswith("file://"):
            return Path(unquote(urlparse(uri).path))
        if uri.startswith("model://"):
            return self._model(uri, base_dir)
        scheme = _SCHEME.match(uri)
        if scheme:
            raise UnknownScheme(f"no robot description reader resolves '{scheme[1]}://' "
                                "(ROS reads package:// and file://, Gazebo model:// too)")
        path = Path(uri).expanduser()
        return path if path.is_absolute() else base_dir / path

    def _model(self, uri: str, base_dir: Path) -> Path:
        """Where Gazebo finds ``model://NAME/rel``.

        NAME in a directory of its model path, else package NAME (gazebo_ros exports
        packages' parents as model directories).

        Raises:
            PackageNotFound: Neither is anywhere.
        """
        name, _, rel = uri[len("model://"):].partition("/")
        rel = unquote(rel).lstrip("/")
        if not name or name in (".", ".."):
            raise UnknownScheme(f"'{uri}' names no model: Gazebo reads model://NAME/PATH")
        location = next((PackageLocation(name, d / name, f"model path entry {_short(d)}",
                                         ros_finds_it=False,
                                         gazebo_model=True)
                         for d in self.model_path if os.path.isdir(d / name)), None)
        if location is None:
            package = self._ros_location(name, base_dir)
            if package is not None:
                location = dataclasses.replace(package, how=f"package {name} by {package.how}",
                                               ros_finds_it=False, gazebo_model=True)
        if location is None:
            paths = os.pathsep.join(map(str, self.model_path)) or "unset"
            raise PackageNotFound(f"model '{name}' not found; looked in Gazebo's model path "
                                  f"({', '.join(MODEL_PATH_VARIABLES)}: {paths}); "
                                  f"{self._searched(base_dir)}")
        self.found.setdefault(f"model://{name}", location)
        return location.path / rel

    def _rooted(self, rel: str, base_dir: Path) -> Path:
        """Where ``package:///rel`` leads, as the loaders that accept it read it.

        The absolute path ``/rel`` where that exists; else, as Pinocchio reads it (``rel``
        under one of its package directories), the package named by ``rel``'s first part
        (example-robot-data's Talos: ``package:///example-robot-data/robots/...``). Either
        way ROS would not find it.
        """
        absolute = Path("/") / rel
        name, _, inner = rel.partition("/")
        if not os.path.exists(absolute) and name and inner:
            location = (self._ros_location(name, base_dir)
                        or self._loader_location(name, base_dir))
            if location is not None and location.path / inner != absolute:
                self.found.setdefault(name, PackageLocation(
                    name, location.path, location.how, ros_finds_it=False, three_slashes=True,
                    named_ros_finds=location.ros_finds_it))
                return location.path / inner
        self.found.setdefault("", PackageLocation(
            "", Path("/"), "package:/// (an absolute path)", ros_finds_it=False))
        return absolute

    def warnings(self) -> list[str]:
        """One line per package found only the way some loaders find it."""
        return [w for location in self.found.values() if (w := location.warning)]

    # -- the search, step by step ------------------------------------------------------------

    def _ros_location(self, name: str, context: Path | None) -> PackageLocation | None:
        if name in self.explicit:
            return PackageLocation(name, self.explicit[name], "--package")
        if context is not None:
            holder = holding_package(context)
            if holder is not None and holder[0] == name:
                return PackageLocation(name, holder[1], f"the package holding the file "
                                       f"({_short(holder[1] / 'package.xml')})")
            root = workspace_root(context)
            if root is not None:
                path = packages_under(root).get(name)
                if path is not None:
                    return PackageLocation(name, path, f"workspace {_short(root)} "
                                           f"({_short(path / 'package.xml')})")
        for entry in self.ros_package_path:
            path = packages_under(entry).get(name)
            if path is not None:
                return PackageLocation(name, path, f"ROS_PACKAGE_PATH entry {_short(entry)}")
        for prefix in self.ament_prefix_path:
            share = prefix / "share" / name
            if os.path.isdir(share):
                return PackageLocation(name, share, f"AMENT_PREFIX_PATH prefix {_short(prefix)}")
        for directory in (*self.ros_package_path, *(p / "share" for p in self.ament_prefix_path)):
            if os.path.isdir(directory / name):
                return PackageLocation(name, directory / name,
                                       f"directory {name} in {_short(directory)}")
        return None

    def _loader_location(self, name: str, context: Path | None) -> PackageLocation | None:
        """A directory called ``name`` above the file (Pinocchio's and yourdfpy's way)."""
        if context is None:
            return None
        for ancestor in (context, *context.parents):
            if ancestor.name == name:
                return PackageLocation(name, ancestor, f"the directory {_short(ancestor)} "
                                       "above the file", ros_finds_it=False)
        return None

    def _holding_elsewhere(self, name: str, rel: str, base_dir: Path,
                           first: PackageLocation) -> PackageLocation | None:
        """Where a loader that looks for the file itself finds ``rel`` that ``first`` lacks.

        Gazebo (its model paths) and yourdfpy try each directory called NAME until the file
        is there, so a source tree whose package is assembled at build time (icub-models:
        ``iCub_manual/package.xml`` is named ``iCub``, the meshes are under ``iCub/``)
        still loads. ROS would look only in ``first``.
        """
        for other in (self._loader_location(name, base_dir),
                      self._relative_location(name, rel, base_dir)):
            if other is not None and other.path != first.path and os.path.exists(other.path / rel):
                return PackageLocation(
                    name, other.path, f"{other.how}, which holds '{rel}'; the one ROS finds, "
                    f"through {first.how}, does not", ros_finds_it=False)
        return None

    def _relative_location(self, name: str, rel: str, base_dir: Path) -> PackageLocation | None:
        """``NAME/rel`` beside the file or one of its parents (pybullet's way)."""
        for ancestor in (base_dir, *base_dir.parents):
            if os.path.exists(ancestor / name / rel):
                return PackageLocation(name, ancestor / name, f"the directory "
                                       f"{_short(ancestor / name)} beside the file",
                                       ros_finds_it=False)
        return None

    def _close(self, name: str, context: Path | None) -> str:
        """`` (did you mean 'NAME'?)`` for a package of the search a letter or two off."""
        import difflib

        known = set(self.explicit)
        root = workspace_root(context) if context is not None else None
        for place in (*((root,) if root is not None else ()), *self.ros_package_path):
            known.update(packages_under(place))
        close = difflib.get_close_matches(name, sorted(known), n=1, cutoff=0.85)
        return f" (did you mean '{close[0]}'?)" if close else ""

    def _searched(self, context: Path | None) -> str:
        places = []
        if self.explicit:
            places.append("--package " + ", ".join(sorted(self.explicit)))
        if context is not None:
            root = workspace_root(context)
            places.append(f"the workspace {_short(root)}" if root is not None
                          else f"the packages above {_short(context)}")
        places.append(
            "ROS_PACKAGE_PATH=" + (":".join(map(str, self.ros_package_path)) or "(unset)")
        )
        places.append(
            "AMENT_PREFIX_PATH=" + (":".join(map(str, self.ament_prefix_path)) or "(unset)")
        )
        return "; ".join(places) + "; give its directory with --package NAME=DIR"


def is_remote(uri: str) -> bool:
    """Whether ``uri`` is fetched over the network (Gazebo Fuel meshes): never 'missing'."""
    return uri.lower().startswith(REMOTE_SCHEMES)


def _split_path(value: str) -> tuple[Path, ...]:
    return tuple(Path(p).absolute() for p in value.split(os.pathsep) if p)


def _short(path: Path) -> str:
    """``path`` relative to the current directory when inside it."""
    try:
        return str(path.relative_to(Path.cwd())) or "."
    except ValueError:
        return str(path)
