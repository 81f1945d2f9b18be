"""``fk`` results for people (text) and programs (JSON; CSV in ``kinematics_csv``). Rendering only.

JSON (documented in README.md, stable)::

    {"robot": "...", "relative_to": "base_link", "angle_unit": "rad",
     "joints": {"name": value, ...},
     "poses": [{"frame": "...", "position_m": [x, y, z], "rpy_rad": [r, p, y],
                "quaternion_xyzw": [x, y, z, w], "matrix": [[4 x 4]]}]}

With ``--deg`` the angles are in degrees and the keys say so (``rpy_deg``, ``angle_unit``).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator, Sequence
from typing import TYPE_CHECKING

from servicebot_cli.common.jsonable import dumps
from servicebot_cli.output.table import format_number, table

if TYPE_CHECKING:
    from servicebot_cli.kinematics.fk import FkResult
    from servicebot_cli.kinematics.forward import FramePose
    from servicebot_cli.kinematics.json_types import JsonObject

_TINY = 1e-12  # |values| below this print as 0: rounding noise of the transforms


def clean(value: float) -> float:
    """``value``, with rounding noise (and -0.0) shown as 0."""
    return 0.0 if abs(value) < _TINY else float(value)


def rpy_of(pose: FramePose, deg: bool) -> list[float]:
    """Roll, pitch, yaw of ``pose`` in [rad] or [deg]."""
    return [math.degrees(a) if deg else float(a) for a in pose.rpy_rad]


def pose_json(pose: FramePose, deg: bool, matrix: bool = True) -> JsonObject:
    """One pose as a JSON object (keys carry their units)."""
    out: JsonObject = {
        "frame": pose.frame,
        "position_m": [float(v) for v in pose.position_m],
        f"rpy_{'deg' if deg else 'rad'}": rpy_of(pose, deg),
        "quaternion_xyzw": [float(v) for v in pose.quaternion_xyzw],
    }
    if matrix:
        out["matrix"] = pose.matrix.tolist()
    return out


def fk_json(result: FkResult) -> JsonObject:
    """The whole ``fk`` answer as JSON."""
    deg = result.deg
    return {"robot": result.robot, "relative_to": result.relative_to,
            "angle_unit": "deg" if deg else "rad", "joints": dict(result.joints),
            "poses": [pose_json(p, deg) for p in result.poses]}


def fk_output(result: FkResult, fmt: str) -> str:
    """What ``fk`` prints on stdout: JSON, CSV, or text blocks (a table for every frame)."""
    if fmt == "json":
        return dumps(fk_json(result))
    if fmt == "csv":
        from servicebot_cli.output.kinematics_csv import fk_csv

        return fk_csv(result)
    return "".join(f"{line}\n" for line in fk_text(result.poses, result.deg, result.as_table))


def _numbers(values: Iterable[float]) -> str:
    return "  ".join(format_number(clean(v)) for v in values)


def pose_lines(pose: FramePose, deg: bool) -> Iterator[str]:
    """One frame's pose as a labelled block: position, rpy, quaternion, matrix."""
    unit = "deg" if deg else "rad"
    yield f"{pose.frame} in {pose.relative_to}"
    yield f"  position [m]          {_numbers(pose.position_m)}"
    yield f"  roll pitch yaw [{unit}]  {_numbers(rpy_of(pose, deg))}"
    yield f"  quaternion x y z w    {_numbers(pose.quaternion_xyzw)}"
    cells = [[format_number(clean(v)) for v in row] for row in pose.matrix]
    widths = [max(len(r[c]) for r in cells) for c in range(4)]
    for i, row in enumerate(cells):
        label = "  matrix                " if i == 0 else " " * 24
        yield label + "  ".join(c.rjust(w) for c, w in zip(row, widths, strict=True))


def poses_table(poses: Sequence[FramePose], deg: bool) -> list[str]:
    """Many frames as one table: position and roll-pitch-yaw (JSON has the rest)."""
    unit = "deg" if deg else "rad"
    headers = ["frame", "x [m]", "y [m]", "z [m]", f"roll [{unit}]", f"pitch [{unit}]",
               f"yaw [{unit}]"]
    rows = [[p.frame, *(clean(v) for v in p.position_m), *(clean(v) for v in rpy_of(p, deg))]
            for p in poses]
    return table(headers, rows)


def fk_text(poses: Sequence[FramePose], deg: bool, as_table: bool) -> Iterator[str]:
    """The whole ``fk`` answer as text: blocks per frame, or one table."""
    if as_table:
        reference = poses[0].relative_to if poses else ""
        yield f"every frame in {reference}"
        yield from poses_table(poses, deg)
        return
    for i, pose in enumerate(poses):
        if i:
            yield ""
        yield from pose_lines(pose, deg)
