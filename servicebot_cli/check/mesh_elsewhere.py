"""The ``package://`` name of a mesh written as a path of another machine.

A URDF exported on Windows (``C:\\Users\\me\\robot\\meshes\\base.stl``) or on a colleague's
machine (``file:///home/alice/ws/src/robot/meshes/base.stl``) names a file nowhere else.
Where a package of this workspace holds that file (a part of the path is the package's name
and the rest is in it, or the path's last parts are in a package), its ``package://`` name
is what to write: ROS finds it on every machine.
"""

from __future__ import annotations

import os
import re
from collections.abc import Mapping
from pathlib import Path

from servicebot_cli.description.package_dirs import packages_under, workspace_root

_DRIVE = re.compile(r"^[A-Za-z]:[\\/]")
_MOST_PARTS = 6  # path parts tried below a package: meshes/robot/visual/part.stl and more


def is_windows_path(filename: str) -> bool:
    """``C:\\...`` or ``C:/...``, or a path written with backslashes."""
    return bool(_DRIVE.match(filename)) or ("\\" in filename and "://" not in filename)


def package_uri(filename: str, base_dir: Path,
                explicit: Mapping[str, Path] | None = None) -> str | None:
    """``package://PKG/REL`` for the file ``filename`` names, if a package here holds it."""
    packages = dict(explicit or {})
    root = workspace_root(base_dir)
    if root is not None:
        packages.update(packages_under(root))
    if not packages:
        return None
    text = filename.removeprefix("file://")
    parts = [p for p in re.split(r"[\\/]+", _DRIVE.sub("", text)) if p and p != "."]
    windows = is_windows_path(filename)  # whose file names ignore case
    for k, part in enumerate(parts[:-1]):  # .../PKG/REL: the package named in the path
        rest = _held(packages.get(part), parts[k + 1:], windows) if part in packages else None
        if rest is not None:
            return f"package://{part}/{rest}"
    for count in range(min(len(parts) - 1, _MOST_PARTS), 1, -1):  # its last parts, longest first
        holding = {name: rest for name in sorted(packages)
                   if (rest := _held(packages[name], parts[-count:], windows)) is not None}
        if len(holding) == 1:  # one package: that one; several: no guess
            [(name, rest)] = holding.items()
            return f"package://{name}/{rest}"
        if holding:
            return None
    return None


def _held(package: Path | None, parts: list[str], any_case: bool) -> str | None:
    """The path below ``package`` of the file ``parts`` names, as the disk writes it; None."""
    if package is None:
        return None
    if os.path.isfile(package.joinpath(*parts)):
        return "/".join(parts)
    if not any_case:
        return None
    here, written = package, list[str]()
    for part in parts:  # each level, matched as Windows matches it: in any case
        try:
            entry = next(e for e in os.scandir(here) if e.name.lower() == part.lower())
        except (OSError, StopIteration):
            return None
        here, written = here / entry.name, [*written, entry.name]
    return "/".join(written) if os.path.isfile(here) else None
