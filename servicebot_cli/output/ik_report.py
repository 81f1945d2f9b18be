"""``ik`` results for people (text) and programs (JSON). Rendering only.

JSON (documented in README.md, stable)::

    {"robot": "...", "frame": "...", "relative_to": "base_link", "success": true,
     "target": {"position_m": [x, y, z], "rpy_rad": [r, p, y] | null,
                "orientation_axes": ["pitch", ...]},
     "angle_unit": "rad", "joints": {"name": value, ...},
     "base": {"x_m": ..., "y_m": ..., "yaw_rad": ...} | null,
     "position_error_m": ..., "orientation_error_rad": ... | null,
     "iterations": n, "attempts": n, "solutions": n, "solve_time_s": ..., "hint": null | "..."}
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from typing import TYPE_CHECKING

import numpy as np

from servicebot_cli.common.jsonable import dumps
from servicebot_cli.kinematics.ik import IkAnswer
from servicebot_cli.kinematics.ik_outcome import base_pose, outcome_values
from servicebot_cli.kinematics.rotations import rpy_from_matrix
from servicebot_cli.kinematics.user_joints import angular, user_values
from servicebot_cli.output.table import format_number, table

if TYPE_CHECKING:
    from servicebot_cli.batch.stream import BatchSummary
    from servicebot_cli.description.joint_space import JointSpace
    from servicebot_cli.kinematics.inverse import IkTarget
    from servicebot_cli.kinematics.json_types import JsonObject

_SHOWN_LINES = 5  # failed batch lines listed in the error line


def ik_json(answer: IkAnswer) -> JsonObject:
    """The whole ``ik`` answer as JSON."""
    return {"robot": answer.robot, "frame": answer.frame, "relative_to": answer.relative_to,
            "target": target_json(answer.target, answer.deg),
            "angle_unit": "deg" if answer.deg else "rad",
            **outcome_values(answer.space, answer.outcome, answer.deg)}


def ik_output(answer: IkAnswer, fmt: str) -> str:
    """What ``ik`` prints on stdout: JSON, CSV, or a headline, the joints and the errors."""
    if fmt == "json":
        return dumps(ik_json(answer))
    if fmt == "csv":
        from servicebot_cli.output.kinematics_csv import ik_csv

        return ik_csv(answer)
    return "".join(f"{line}\n" for line in ik_text(answer))


def refusal(answer: IkAnswer) -> str:
    """The one stderr line when the target was not reached."""
    if answer.outcome.result.contact is not None:  # the hint names the two links
        return f"no IK solution for {answer.frame}: {answer.outcome.hint}"
    return (f"no IK solution for {answer.frame}: best position error "
            f"{answer.outcome.result.position_error_m:.3g} m; {answer.outcome.hint}")


def batch_refusal(summary: BatchSummary) -> str:
    """The one stderr line when some batch targets were not reached."""
    failed = summary.failed
    shown = ", ".join(str(n) for n in failed[:_SHOWN_LINES]) + \
        (", ..." if len(failed) > _SHOWN_LINES else "")
    return (f"{len(failed)} of {summary.rows - summary.skipped} targets not reached "
            f"(line {shown} of {summary.source})")


def target_json(target: IkTarget, deg: bool) -> JsonObject:
    """The target: position [m], roll-pitch-yaw [rad or deg] or null, the axes that count."""
    rpy = None if target.rotation is None else rpy_from_matrix(target.rotation)
    if rpy is not None and deg:
        rpy = np.degrees(rpy)
    return {"position_m": target.position_m.tolist(),
            f"rpy_{'deg' if deg else 'rad'}": None if rpy is None else rpy.tolist(),
            "orientation_axes": list(target.axes)}


def limits(space: JointSpace, deg: bool) -> tuple[list[str], list[float | None],
                                                   list[float | None]]:
    """Each joint's unit, lower and upper limit in that unit (None: continuous)."""
    scale = np.where(angular(space) & deg, math.degrees(1.0), 1.0)
    units = ["m" if t == "prismatic" else "deg" if deg else "rad" for t in space.types]
    lower = [None if math.isnan(v) else float(v * s) for v, s in zip(space.lower, scale,
                                                                       strict=True)]
    upper = [None if math.isnan(v) else float(v * s) for v, s in zip(space.upper, scale,
                                                                       strict=True)]
    return units, lower, upper


def _headline(answer: IkAnswer) -> str:
    axes = answer.target.axes
    kind = "position only" if not axes else "full pose" if len(axes) == 3 else \
        "position and " + ", ".join(axes)
    result = answer.outcome.result
    attempts = result.attempts
    effort = (f"{result.iterations} iterations, {attempts} attempt{'s' if attempts != 1 else ''}"
              f", {answer.outcome.elapsed_s * 1e3:.3g} ms")
    verdict = "reached" if answer.success else "NOT reached (best found below)"
    return f"{answer.frame} {verdict}: {kind}; {effort}"


def ik_text(answer: IkAnswer) -> Iterator[str]:
    """The ``ik`` answer as text: a headline, the joints with their limits, the errors."""
    yield _headline(answer)
    space, deg, result = answer.space, answer.deg, answer.outcome.result
    joints = user_values(space, space.from_q(result.q), deg=deg)
    rows = [[name, value, unit, lo, hi] for (name, value), unit, lo, hi in
            zip(joints.items(), *limits(space, deg), strict=True)]
    yield from table(["joint", "value", "unit", "lower", "upper"], rows)
    pose = base_pose(space, result.q)
    if pose is not None:
        x, y, yaw = pose
        unit = "deg" if deg else "rad"
        yield (f"base: x {format_number(x)} m, y {format_number(y)} m, "
               f"yaw {format_number(math.degrees(yaw) if deg else yaw)} {unit}")
    yield f"position error     {format_number(result.position_error_m, 3)} m"
    orientation = result.orientation_error_rad
    shown = "- (position only)" if orientation is None else f"{format_number(orientation, 3)} rad"
    yield f"orientation error  {shown}"
