"""Joint values as users see them, and Pinocchio configuration vectors.

Users name joints and give one number each: an angle [rad] for revolute and continuous
joints, a distance [m] for prismatic ones. Pinocchio stores a continuous joint as
``(cos, sin)`` (two entries of ``q``, one of ``v``); this module is the only place that knows.
Pure: arrays in, arrays out.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.errors import JointNotFound, OutOfLimits
from servicebot_cli.description.elements import ONE_AXIS_TYPES

if TYPE_CHECKING:
    import pinocchio as pin

    from servicebot_cli.description.elements import Joint

FloatArray = npt.NDArray[np.float64]

_LIMIT_SLACK = 1e-9  # values this close outside a limit are the limit, not an error


@dataclass(frozen=True)
class JointSpace:
    """The movable joints of a model, in URDF order.

    Attributes:
        names: Joint names, URDF order.
        types: URDF joint types, same order.
        lower: Lower position limits [rad or m]; NaN for continuous joints.
        upper: Upper position limits [rad or m]; NaN for continuous joints.
        velocity: Velocity limits [rad/s or m/s]; NaN where the URDF gives none.
        idx_q: Index of each joint's first entry in ``q``.
        idx_v: Index of each joint's entry in ``v``.
        nq: Size of the model's ``q``.
        nv: Size of the model's ``v``.
        base_nq: Entries of ``q`` before the first URDF joint (4 for a planar base).
    """

    names: tuple[str, ...]
    types: tuple[str, ...]
    lower: FloatArray
    upper: FloatArray
    velocity: FloatArray
    idx_q: tuple[int, ...]
    idx_v: tuple[int, ...]
    nq: int
    nv: int
    base_nq: int = 0
    model_neutral: FloatArray | None = field(default=None, repr=False, compare=False)
    """The model's own neutral ``q`` (Pinocchio's), which also covers joints left out of
    :attr:`names`: a URDF ``planar`` or ``floating`` joint stands at its identity there."""

    @classmethod
    def of(cls, model: pin.Model, joints: Sequence[Joint]) -> JointSpace:
        """The joint space of ``model`` for the URDF's movable ``joints``.

        Joints Pinocchio does not model as one value (floating, planar) are left out.
        """
        names, types, lower, upper, velocity, idx_q, idx_v = [], [], [], [], [], [], []
        for joint in joints:
            if joint.type not in ONE_AXIS_TYPES:
                continue
            if not model.existJointName(joint.name):
                continue
            pin_joint = model.joints[model.getJointId(joint.name)]
            names.append(joint.name)
            types.append(joint.type)
            limits = joint.limits
            bounded = joint.type != "continuous" and limits is not None
            lower.append(limits.lower if bounded and limits and limits.lower is not None
                         else math.nan)
            upper.append(limits.upper if bounded and limits and limits.upper is not None
                         else math.nan)
            velocity.append(limits.velocity if limits and limits.velocity is not None else math.nan)
            idx_q.append(pin_joint.idx_q)
            idx_v.append(pin_joint.idx_v)
        base = model.joints[1] if model.njoints > 1 else None
        base_nq = base.nq if base is not None and model.names[1] == "root_joint" else 0
        return cls(
            names=tuple(names), types=tuple(types), lower=np.array(lower, dtype=float),
            upper=np.array(upper, dtype=float), velocity=np.array(velocity, dtype=float),
            idx_q=tuple(idx_q), idx_v=tuple(idx_v), nq=model.nq, nv=model.nv, base_nq=base_nq,
            model_neutral=_pin_neutral(model),
        )

    def index(self, name: str) -> int:
        """Position of joint ``name`` in :attr:`names`.

        Raises:
            JointNotFound: With the closest movable joint names.
        """
        try:
            return self.names.index(name)
        except ValueError:
            raise JointNotFound.for_name(name, self.names) from None

    def neutral(self) -> FloatArray:
        """``q`` with every joint at zero (and an identity base)."""
        return self._neutral.copy()

    @cached_property
    def _neutral(self) -> FloatArray:
        if self.model_neutral is not None:
            return np.array(self.model_neutral, dtype=float)
        q = np.zeros(self.nq)
        for i, kind in enumerate(self.types):
            if kind == "continuous":
                q[self.idx_q[i]] = 1.0  # cos 0
        if self.base_nq == 4:  # planar: x, y, cos(yaw), sin(yaw)
            q[2] = 1.0
        elif self.base_nq == 7:  # free flyer: xyz, quaternion x y z w
            q[6] = 1.0
        return q

    @cached_property
    def _layout(self) -> tuple[npt.NDArray[np.intp], ...]:
        """Joints with one ``q`` entry and their indices; continuous joints and theirs."""
        index = np.array(self.idx_q, dtype=np.intp)
        continuous = np.array([kind == "continuous" for kind in self.types], dtype=bool)
        plain, turning = np.flatnonzero(~continuous), np.flatnonzero(continuous)
        return plain, index[plain], turning, index[turning]

    def to_q(self, values: FloatArray, q0: FloatArray | None = None) -> FloatArray:
        """``q`` from one value per joint in :attr:`names` order [rad or m]."""
        q = self.neutral() if q0 is None else np.array(q0, dtype=float)
        values = np.asarray(values, dtype=float)
        plain, plain_q, turning, turning_q = self._layout
        q[plain_q] = values[plain]
        if turning.size:  # continuous joints are (cos, sin) in q
            angles = values[turning]
            q[turning_q] = np.cos(angles)
            q[turning_q + 1] = np.sin(angles)
        return q

    def from_q(self, q: FloatArray) -> FloatArray:
        """One value per joint, :attr:`names` order; continuous angles in (-pi, pi]."""
        values = np.empty(len(self.names))
        for i, kind in enumerate(self.types):
            start = self.idx_q[i]
            values[i] = math.atan2(q[start + 1], q[start]) if kind == "continuous" else q[start]
        return values

    def vector(self, assignments: Mapping[str, float], *, clamp: bool = False) -> FloatArray:
        """One value per joint from ``{name: value}``; unnamed joints stay at zero.

        Args:
            assignments: Joint name to value [rad or m].
            clamp: Clamp values outside the limits instead of refusing them.

        Raises:
            JointNotFound: An unknown name, with the closest names.
            OutOfLimits: A value outside its joint's limits (unless ``clamp``).
        """
        values = np.zeros(len(self.names))
        for name, value in assignments.items():
            values[self.index(name)] = value
        return self.clamped(values) if clamp else self.checked(values)

    def checked(self, values: FloatArray) -> FloatArray:
        """``values`` if every one is within its limits, else OutOfLimits naming the first."""
        bounded = ~np.isnan(self.lower)
        with np.errstate(invalid="ignore"):
            inside = (values >= self.lower - _LIMIT_SLACK) & (values <= self.upper + _LIMIT_SLACK)
        if inside[bounded].all():
            return values
        for i, value in enumerate(values):
            lo, hi = self.lower[i], self.upper[i]
            if not (math.isnan(lo) or lo - _LIMIT_SLACK <= value <= hi + _LIMIT_SLACK):
                unit = "m" if self.types[i] == "prismatic" else "rad"
                raise OutOfLimits(
                    f"joint '{self.names[i]}' = {value:g} {unit} is outside its limits "
                    f"[{lo:g}, {hi:g}] {unit}; give a value inside them, or --clamp"
                )
        return values

    def clamped(self, values: FloatArray) -> FloatArray:
        """``values`` clamped into the position limits (continuous joints untouched)."""
        bounded = ~np.isnan(self.lower)
        out = np.array(values, dtype=float)
        out[bounded] = np.clip(out[bounded], self.lower[bounded], self.upper[bounded])
        return out


def _pin_neutral(model: pin.Model) -> FloatArray:
    """``pin.neutral(model)``: identity rotations where zeros would be no rotation at all."""
    import pinocchio as pin

    neutral: FloatArray = np.array(pin.neutral(model), dtype=float)
    return neutral
