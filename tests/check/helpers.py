"""Helpers shared by the check tests: fixture paths and JSON runs."""

from __future__ import annotations

import json
import math
import struct
from pathlib import Path
from typing import Any

FIXTURES = Path(__file__).resolve().parent / "fixtures"


def fixture(code: str) -> Path:
    """The one fixture of rule ``code``."""
    (found,) = [p for p in FIXTURES.iterdir() if p.name.startswith(f"{code}_")]
    return found


def findings(stdout: str) -> list[dict[str, Any]]:
    """Every finding of a ``--format json`` run."""
    document = json.loads(stdout)
    return [f for file in document["files"] for f in file["findings"]]


def codes(stdout: str) -> set[str]:
    """The codes found by a ``--format json`` run."""
    return {f["code"] for f in findings(stdout)}


def tetrahedron_stl(size: float) -> bytes:
    """A binary STL of a closed tetrahedron with legs of ``size`` along the axes."""
    corners = [(0, 0, 0), (size, 0, 0), (0, size, 0), (0, 0, size)]
    faces = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    data = b"\0" * 80 + struct.pack("<I", len(faces))
    for face in faces:
        data += struct.pack("<3f", 0, 0, 0)
        data += b"".join(struct.pack("<3f", *corners[i]) for i in face) + b"\0\0"
    return data


def wheel_stl(radius: float, width: float, centre_y: float, sides: int = 48) -> bytes:
    """A binary STL of a closed wheel (a prism of ``sides``) about y, centred at ``centre_y``."""
    angles = [2 * math.pi * k / sides for k in range(sides)]
    rim = [(radius * math.cos(a), radius * math.sin(a)) for a in angles]
    near, far = centre_y - width / 2, centre_y + width / 2
    triangles = []
    for k in range(sides):
        (x0, z0), (x1, z1) = rim[k], rim[(k + 1) % sides]
        triangles += [((x0, near, z0), (x1, near, z1), (x1, far, z1)),
                      ((x0, near, z0), (x1, far, z1), (x0, far, z0)),
                      ((0, near, 0), (x1, near, z1), (x0, near, z0)),
                      ((0, far, 0), (x0, far, z0), (x1, far, z1))]
    data = b"\0" * 80 + struct.pack("<I", len(triangles))
    for corners in triangles:
        data += struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *c) for c in corners)
        data += b"\0\0"
    return data


def check_controllers(run: Any, directory: Path, yaml_text: str,
                      urdf: Path | None = None) -> tuple[int, list[dict[str, Any]]]:
    """Exit code and findings of ``check controllers`` on ``yaml_text`` (written to
    ``directory``) against ``urdf``, the bundled simulated robot by default."""
    from tests.conftest import SIM_URDF

    path = directory / "controllers.yaml"
    path.write_text(yaml_text)
    result = run("check", "controllers", path, "--urdf", urdf or SIM_URDF, "--format", "json",
                 "--isolated")
    return result.exit_code, findings(result.stdout)


def ros2_package(workspace: Path, name: str) -> Path:
    """``workspace/src/NAME`` with its package.xml, urdf/ and config/, as users lay one out."""
    package = workspace / "src" / name
    (package / "urdf").mkdir(parents=True)
    (package / "config").mkdir()
    (package / "package.xml").write_text(
        f'<?xml version="1.0"?><package format="3"><name>{name}</name><version>0.0.1</version>'
        '<description>d</description><maintainer email="a@b.c">a</maintainer>'
        "<license>MIT</license></package>")
    return package
