"""One IK solve's outcome, and its values for JSON and CSV in the user's units.

:class:`IkOutcome` is the solver's result with its solve time and, when the target was not
reached, why; :func:`outcome_values` writes it as the report's and the batch rows' values.
Pure.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.description.joint_space import JointSpace
from servicebot_cli.kinematics.inverse import IkResult
from servicebot_cli.kinematics.json_types import JsonObject
from servicebot_cli.kinematics.user_joints import user_values

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class IkOutcome:
    """One solve: the solver's result, how long it took, and why it failed.

    Attributes:
        result: The answer or the best try.
        elapsed_s: Solve time [s].
        hint: Why the target was not reached; None when it was.
    """

    result: IkResult
    elapsed_s: float
    hint: str | None

    @property
    def success(self) -> bool:
        """The target was reached."""
        return self.result.success


def base_pose(space: JointSpace, q: FloatArray) -> tuple[float, float, float] | None:
    """Where a planar base stands in ``q``: ``x`` [m], ``y`` [m], ``yaw`` [rad]; None without."""
    if not space.base_nq:
        return None
    return float(q[0]), float(q[1]), math.atan2(q[3], q[2])


FLAT_TAIL = ("position_error_m", "orientation_error_rad", "iterations", "attempts", "solutions",
             "solve_time_s", "hint")
"""The columns of a flat ik row after its joints and base."""


def flat_values(values: JsonObject, joint_columns: Mapping[str, str]) -> JsonObject:
    """:func:`outcome_values` as one CSV row: success, each joint under its column
    (``joint_columns``, :func:`~.joint_columns.joint_column_names`), the base, the tail.
    """  # noqa: D205
    flat: JsonObject = {"success": values["success"]}
    joints, base = values["joints"], values["base"]
    if isinstance(joints, Mapping):
        flat.update({joint_columns[name]: value for name, value in joints.items()})
    if isinstance(base, Mapping):
        flat.update({f"base_{key}": value for key, value in base.items()})
    flat.update({key: values[key] for key in FLAT_TAIL})
    return flat


def outcome_values(space: JointSpace, outcome: IkOutcome, deg: bool) -> JsonObject:
    """A solve as JSON values: joints (and base) in the user's units, errors, effort, hint."""
    result = outcome.result
    pose = base_pose(space, result.q)
    base: JsonObject | None = None
    if pose is not None:
        x, y, yaw = pose
        base = {"x_m": x, "y_m": y,
                f"yaw_{'deg' if deg else 'rad'}": math.degrees(yaw) if deg else yaw}
    return {"success": result.success,
            "joints": user_values(space, space.from_q(result.q), deg=deg),
            "base": base, "position_error_m": result.position_error_m,
            "orientation_error_rad": result.orientation_error_rad,
            "iterations": result.iterations, "attempts": result.attempts,
            "solutions": result.solutions, "solve_time_s": outcome.elapsed_s,
            "hint": outcome.hint}
