r"""What IK drives to zero: the error between a frame and its target, and its Jacobian.

Three kinds of target, one class each:

- :class:`FullPose`: position and orientation. The error is the twist
  :math:`e = \log_6(T_{frame}^{-1} T_{target})` that would carry the frame onto the
  target, expressed in the frame (``LOCAL``), with the frame Jacobian in the same frame.
- :class:`PositionOnly`: :math:`e = p_{target} - p`, with the linear rows of the
  ``LOCAL_WORLD_ALIGNED`` Jacobian.
- :class:`SomeAxes`: position plus chosen roll-pitch-yaw angles (for example pitch only):
  wrapped angle differences, with rows that map angular velocity to angle rates.

Each ``evaluate(q)`` runs the kinematics once and returns ``(e, J)``; ``errors()`` then gives
the exact position error [m] and orientation error [rad] at that ``q``. Pure.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.rotations import AXES, rpy_from_matrix

if TYPE_CHECKING:
    import pinocchio as pin

    from servicebot_cli.kinematics.chain import Chain

FloatArray = npt.NDArray[np.float64]


class Residual:
    """Shared set-up: the chain, the target, the frame pose of the last evaluation.

    Attributes:
        extra: Unknowns besides the joints (free angles of orientation).
        last_q: The configuration of the last evaluation.
    """

    extra = 0  # unknowns besides the joints (free angles of orientation)

    def __init__(self, chain: Chain, position_m: FloatArray,
                 rotation: FloatArray | None = None) -> None:
        import pinocchio as pin

        self._pin = pin
        self._model, self._data, self._frame = chain.model, chain.data, chain.frame
        self._position = np.array(position_m, dtype=float)
        self._rotation = None if rotation is None else np.array(rotation, dtype=float)
        self._pose = pin.SE3.Identity()
        self.last_q: FloatArray | None = None

    def _kinematics(self, q: FloatArray, reference: pin.ReferenceFrame) -> FloatArray:
        """Forward kinematics and the frame Jacobian; remembers ``q`` and the frame pose."""
        pin = self._pin
        self.last_q = q
        pin.computeJointJacobians(self._model, self._data, q)
        self._pose = pin.updateFramePlacement(self._model, self._data, self._frame)
        # (6, nv) even for one joint, which eigenpy would hand back as a flat vector
        jacobian: FloatArray = pin.getFrameJacobian(self._model, self._data, self._frame,
                                                    reference).reshape(6, self._model.nv)
        return jacobian

    def reset(self, q: FloatArray) -> None:
        """Prepare an attempt that starts at ``q`` (only :class:`SomeAxes` has state)."""

    def shift(self, step: FloatArray) -> None:
        """Move the extra unknowns (only :class:`SomeAxes` has any)."""

    def evaluate(self, q: FloatArray) -> tuple[FloatArray, FloatArray]:
        """``(e, J)`` at ``q``: the error to drive to zero and its Jacobian."""
        raise NotImplementedError

    def position_error_m(self) -> float:
        """Distance from the frame to the target position [m], at the last evaluation."""
        offset = self._position - self._pose.translation
        return math.sqrt(offset.dot(offset))

    def errors(self) -> tuple[float, float | None]:
        """Position error [m] and orientation error [rad] (None: not asked for)."""
        raise NotImplementedError


class FullPose(Residual):
    """Position and all three angles of orientation."""

    def __init__(self, chain: Chain, position_m: FloatArray, rotation: FloatArray) -> None:
        super().__init__(chain, position_m, rotation)
        self._target = self._pin.SE3(self._rotation, self._position)
        self._local = self._pin.ReferenceFrame.LOCAL

    def evaluate(self, q: FloatArray) -> tuple[FloatArray, FloatArray]:
        """``(e, J)``: the twist to the target in the frame, and the frame Jacobian."""
        jacobian = self._kinematics(q, self._local)
        return self._pin.log6(self._pose.actInv(self._target)).vector, jacobian

    def errors(self) -> tuple[float, float | None]:
        """Position error [m] and the angle between frame and target orientations [rad]."""
        angle = self._pin.log3(self._pose.rotation.T.dot(self._rotation))
        return self.position_error_m(), math.sqrt(angle.dot(angle))


class PositionOnly(Residual):
    """Position only: orientation is free."""

    def __init__(self, chain: Chain, position_m: FloatArray) -> None:
        super().__init__(chain, position_m)
        self._aligned = self._pin.ReferenceFrame.LOCAL_WORLD_ALIGNED

    def evaluate(self, q: FloatArray) -> tuple[FloatArray, FloatArray]:
        """``(e, J)``: target minus frame position [m], and the linear Jacobian rows."""
        jacobian = self._kinematics(q, self._aligned)
        return self._position - self._pose.translation, jacobian[:3]

    def errors(self) -> tuple[float, float | None]:
        """Position error [m]; no orientation error."""
        return self.position_error_m(), None


class SomeAxes(Residual):
    r"""Position and some of roll, pitch and yaw; the other angles are free.

    The free angles become unknowns of their own, beside the joints: the target is
    :math:`T(\phi, \theta, \psi)` with the chosen angles fixed, and the solver moves the
    free ones along with ``q`` to drive :math:`\log_6(T_{frame}^{-1} T)` to zero. Unlike a
    difference of angles, this error has no fold where pitch passes +-90 degrees, so a
    tool may tip over the vertical on its way to the target. A free angle ``k`` turns the
    target about the world axis :math:`a_k` (roll: the target's x axis; pitch:
    :math:`R_z(\psi) y`; yaw: z), which adds the column
    :math:`-(R^T (a_k \times (p - p_{target})), R^T a_k)` to the Jacobian.
    """

    def __init__(self, chain: Chain, position_m: FloatArray, rotation: FloatArray,
                 axes: tuple[str, ...]) -> None:
        super().__init__(chain, position_m, rotation)
        self._free = [k for k, axis in enumerate(AXES) if axis not in axes]
        self._angles = rpy_from_matrix(np.array(rotation, dtype=float))
        self._local = self._pin.ReferenceFrame.LOCAL
        self.extra = len(self._free)
        self._target = self._pin.SE3(self._rotation, self._position)
        self._nv = chain.model.nv
        self._jacobian = np.empty((6, self._nv + self.extra))
        self._world_axes = np.zeros((3, self.extra))
        self._world_axes[2] = [1.0 if k == 2 else 0.0 for k in self._free]  # yaw: world z

    def reset(self, q: FloatArray) -> None:
        """Start the free angles at the frame's own angles at ``q``."""
        self._kinematics(q, self._local)
        current = self._pin.rpy.matrixToRpy(self._pose.rotation)
        self._angles[self._free] = current[self._free]

    def shift(self, step_rad: FloatArray) -> None:
        """Move the free angles by ``step_rad`` (the solver's extra unknowns)."""
        self._angles[self._free] += step_rad

    def evaluate(self, q: FloatArray) -> tuple[FloatArray, FloatArray]:
        """``(e, J)``: the twist to the current target, and ``[J_frame, -C_free]``."""
        pin = self._pin
        jacobian = self._kinematics(q, self._local)
        rotation = pin.rpy.rpyToMatrix(self._angles)
        self._target.rotation = rotation
        pose = self._pose
        world_axes = self._world_axes
        for i, k in enumerate(self._free):
            if k == 0:
                world_axes[:, i] = rotation[:, 0]
            elif k == 1:
                world_axes[:, i] = -math.sin(self._angles[2]), math.cos(self._angles[2]), 0.0
        to_local = pose.rotation.T
        out = self._jacobian
        out[:, : self._nv] = jacobian
        # a x (p - p_target) = -skew(p - p_target) a
        out[:3, self._nv:] = to_local.dot(pin.skew(pose.translation - self._position)).dot(
            world_axes)
        out[3:, self._nv:] = -to_local.dot(world_axes)
        return pin.log6(pose.actInv(self._target)).vector, out.copy()

    def errors(self) -> tuple[float, float | None]:
        """Position error [m] and the angle to the current target orientation [rad]."""
        angle = self._pin.log3(self._pose.rotation.T.dot(self._target.rotation))
        return self.position_error_m(), math.sqrt(angle.dot(angle))


def residual_for(chain: Chain, position_m: FloatArray, rotation: FloatArray | None,
                 axes: tuple[str, ...]) -> FullPose | PositionOnly | SomeAxes:
    """The residual for a target: position only, some angles, or the full pose."""
    if rotation is None or not axes:
        return PositionOnly(chain, position_m)
    if set(axes) == set(AXES):
        return FullPose(chain, position_m, rotation)
    return SomeAxes(chain, position_m, rotation, axes)
