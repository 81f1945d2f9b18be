"""A chain as the flat arrays the compiled IK loop reads, and its ``q`` as plain angles.

:func:`chain_arrays` reads the reduced model of a :class:`~servicebot_cli.kinematics.chain.Chain`
once: each joint's placement in its parent, its axis and kind (revolute or prismatic), the
tool frame's placement in the last joint, and the limits. A continuous joint, which
Pinocchio stores as ``(cos, sin)``, becomes one angle without limits. Chains the loop does
not handle (a planar base, a spherical or helical joint, a branch) give None, and the solver
keeps to Pinocchio. Pure.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.lm_pose import PRISMATIC, REVOLUTE

if TYPE_CHECKING:
    from servicebot_cli.kinematics.chain import Chain

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
BoolArray = npt.NDArray[np.bool_]

_UNIT = 1e-9  # how far an axis may be from unit length


@dataclass(frozen=True)
class ChainArrays:
    """The chain, flat.

    Attributes:
        frames: Shape (n + 1, 3, 4): ``[R | p]`` of joint ``i`` in joint ``i - 1`` (the
            root for ``i = 0``), then of the tool frame in the last joint; [m].
        axes: Shape (n, 3): each joint's unit axis in its own frame.
        kinds: Shape (n,): :data:`REVOLUTE` or :data:`PRISMATIC`.
        limits: Shape (4, n): lower and upper limit per joint [rad or m] (+-inf when
            none), then the range of random starts (+-pi for continuous joints).
        continuous: Shape (n,): joints Pinocchio stores as ``(cos, sin)``.
        index_q: Shape (n,): each joint's first entry in the chain's ``q``.
        plain: No joint is continuous: the chain's ``q`` is the joint values themselves.
    """

    frames: FloatArray = field(repr=False)
    axes: FloatArray = field(repr=False)
    kinds: IntArray = field(repr=False)
    limits: FloatArray = field(repr=False)
    continuous: BoolArray = field(repr=False)
    index_q: IntArray = field(repr=False)
    plain: bool = True

    @property
    def size(self) -> int:
        """Joints in the chain."""
        return int(self.kinds.shape[0])

    def to_angles(self, q_chain: FloatArray) -> FloatArray:
        """Plain joint values from the chain's ``q`` (continuous joints as angles [rad])."""
        if self.plain:
            return q_chain
        theta = q_chain[self.index_q]
        at = self.index_q[self.continuous]
        theta[self.continuous] = np.arctan2(q_chain[at + 1], q_chain[at])
        return theta

    def to_q(self, theta: FloatArray, nq: int) -> FloatArray:
        """The chain's ``q`` (size ``nq``) from plain joint values (a new array)."""
        if self.plain:
            return theta.copy()
        q = np.empty(nq)
        q[self.index_q] = theta
        at = self.index_q[self.continuous]
        q[at], q[at + 1] = np.cos(theta[self.continuous]), np.sin(theta[self.continuous])
        return q


def chain_arrays(chain: Chain) -> ChainArrays | None:
    """The flat arrays of ``chain``; None when a joint is neither revolute nor prismatic."""
    import pinocchio as pin

    model = chain.model
    n = model.njoints - 1
    if chain.base_nq or n < 1 or model.nv != n or chain.model.frames[chain.frame].parentJoint != n:
        return None
    if any(model.parents[j] != j - 1 for j in range(1, n + 1)):
        return None
    data = model.createData()
    q = pin.neutral(model)
    frames = np.empty((n + 1, 3, 4))
    axes = np.empty((n, 3))
    kinds = np.empty(n, dtype=np.int64)
    continuous = np.zeros(n, dtype=bool)
    index_q = np.empty(n, dtype=np.int64)
    for j in range(1, n + 1):
        joint = model.joints[j]
        # (6, nv) even for one joint, which eigenpy would hand back as a flat vector
        motion = pin.computeJointJacobian(model, data, q, j).reshape(6, n)[:, joint.idx_v]
        kind = _kind(motion[:3], motion[3:])
        if kind is None or joint.nq not in (1, 2):
            return None
        kinds[j - 1], axes[j - 1] = kind, motion[3:] if kind == REVOLUTE else motion[:3]
        continuous[j - 1], index_q[j - 1] = joint.nq == 2, joint.idx_q
        frames[j - 1] = model.jointPlacements[j].homogeneous[:3]
    frames[n] = model.frames[chain.frame].placement.homogeneous[:3]
    lower = chain.lower[index_q].copy()
    upper = chain.upper[index_q].copy()
    lower[continuous], upper[continuous] = -np.inf, np.inf
    sample_low = np.where(np.isfinite(lower), lower, -math.pi)
    sample_high = np.where(np.isfinite(upper), upper, math.pi)
    return ChainArrays(frames, axes, kinds, np.stack([lower, upper, sample_low, sample_high]),
                       continuous, index_q, not continuous.any())


def _kind(linear: FloatArray, angular: FloatArray) -> int | None:
    """Revolute (a unit angular part, no linear part), prismatic (the other way), or None."""
    spin, slide = float(np.linalg.norm(angular)), float(np.linalg.norm(linear))
    if abs(spin - 1.0) < _UNIT and slide < _UNIT:
        return REVOLUTE
    if abs(slide - 1.0) < _UNIT and spin < _UNIT:
        return PRISMATIC
    return None
