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
    for k, part in enumerate(parts[:-1]):  # .../PKG/REL: the package named in the path
        rest = "/".join(parts[k + 1:])
        if part in packages and os.path.isfile(packages[part] / rest):
            return f"package://{part}/{rest}"
    for count in range(min(len(parts) - 1, _MOST_PARTS), 1, -1):  # its last parts, longest first
        tail = "/".join(parts[-count:])
        for name in sorted(packages):
            if os.path.isfile(packages[name] / tail):
                return f"package://{name}/{tail}"
    return None
