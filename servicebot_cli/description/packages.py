"""Find ROS packages without ROS: ``$(find pkg)`` and ``package://pkg/...``.

Search order, first hit wins:

1. ``--package NAME=DIR`` given by the user;
2. ``ROS_PACKAGE_PATH``: each entry is a package or a tree holding packages
   (a directory with a ``package.xml``; its ``<name>`` or, failing that, the directory name);
3. ``AMENT_PREFIX_PATH``: ``PREFIX/share/NAME`` where the ament index lists ``NAME``
   (or the directory simply exists).
"""

from __future__ import annotations

import os
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import unquote, urlparse

from servicebot_cli.common.errors import PackageNotFound

_NAME_RE = re.compile(rb"<name>\s*([^<\s]+)\s*</name>")
_CRAWL_DEPTH = 6  # deep enough for src/<group>/<repo>/<pkg>, shallow enough to stay instant
_SKIP_DIRS = {"build", "install", "log", "node_modules", "__pycache__"}


@dataclass(frozen=True)
class PackageResolver:
    """Resolves package names to directories.

    Attributes:
        explicit: ``--package`` mappings, name to directory.
        ros_package_path: Directories from ``ROS_PACKAGE_PATH``.
        ament_prefix_path: Prefixes from ``AMENT_PREFIX_PATH``.
    """

    explicit: Mapping[str, Path] = field(default_factory=dict)
    ros_package_path: tuple[Path, ...] = ()
    ament_prefix_path: tuple[Path, ...] = ()

    @classmethod
    def from_environment(
        cls, explicit: Mapping[str, Path] | None = None, environ: Mapping[str, str] | None = None
    ) -> PackageResolver:
        """Build a resolver from ``--package`` mappings and the environment."""
        env = os.environ if environ is None else environ
        return cls(
            explicit=dict(explicit or {}),
            ros_package_path=_split_path(env.get("ROS_PACKAGE_PATH", "")),
            ament_prefix_path=_split_path(env.get("AMENT_PREFIX_PATH", "")),
        )

    def find(self, name: str) -> Path:
        """Directory of package ``name`` (its share directory for ament installs).

        Raises:
            PackageNotFound: Naming the package and every place searched.
        """
        if name in self.explicit:
            return self.explicit[name]
        for root in self.ros_package_path:
            found = _crawl(root, name)
            if found is not None:
                return found
        for prefix in self.ament_prefix_path:
            share = prefix / "share" / name
            if share.is_dir():
                return share
        raise PackageNotFound(f"package '{name}' not found; looked in {self._searched()}")

    def resolve_uri(self, uri: str, base_dir: Path) -> Path:
        """File path for a mesh or include reference.

        Args:
            uri: ``package://pkg/rel``, ``file:///abs``, an absolute path or a relative path.
            base_dir: Directory that relative paths are relative to (the URDF's own).
        """
        if uri.startswith("package://"):
            rest = uri[len("package://") :]
            name, _, rel = rest.partition("/")
            return self.find(name) / unquote(rel)
        if uri.startswith("file://"):
            return Path(unquote(urlparse(uri).path))
        path = Path(uri).expanduser()
        return path if path.is_absolute() else base_dir / path

    def _searched(self) -> str:
        places = []
        if self.explicit:
            places.append("--package " + ", ".join(sorted(self.explicit)))
        places.append(
            "ROS_PACKAGE_PATH=" + (":".join(map(str, self.ros_package_path)) or "(unset)")
        )
        places.append(
            "AMENT_PREFIX_PATH=" + (":".join(map(str, self.ament_prefix_path)) or "(unset)")
        )
        return "; ".join(places) + "; give its directory with --package NAME=DIR"


def _split_path(value: str) -> tuple[Path, ...]:
    return tuple(Path(p) for p in value.split(os.pathsep) if p)


def _package_name(directory: Path) -> str | None:
    """The package's name if ``directory`` holds a package.xml, else None."""
    manifest = directory / "package.xml"
    try:
        head = manifest.read_bytes()[:65536]
    except OSError:
        return None
    match = _NAME_RE.search(head)
    return match.group(1).decode("utf-8", "replace") if match else directory.name


def _crawl(root: Path, name: str) -> Path | None:
    """Breadth-first search under ``root`` for package ``name``; packages do not nest."""
    frontier = [root]
    for _ in range(_CRAWL_DEPTH):
        next_frontier = []
        for directory in frontier:
            found = _package_name(directory)
            if found is not None:
                if found == name:
                    return directory
                continue
            try:
                children = sorted(os.scandir(directory), key=lambda e: e.name)
            except OSError:
                continue
            for entry in children:
                hidden = entry.name.startswith(".") or entry.name in _SKIP_DIRS
                if entry.is_dir() and not hidden:
                    next_frontier.append(Path(entry.path))
        frontier = next_frontier
    return None
