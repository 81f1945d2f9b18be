"""The joints that move one frame, as a small model of their own, and how far they reach.

IK only needs the chain from the root to its frame: the wheels of the service robot never
move the arm's tool. :class:`Chain` derives a reduced Pinocchio model from the shared one
(``pin.buildReducedModel`` locks every other joint), so each solver iteration touches only
the chain. It also knows the chain's limits in its own ``q`` and maps ``q`` back and forth.
Pure: models in, arrays out.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.description.model import new_data
from servicebot_cli.kinematics.chain_mimic import coupling
from servicebot_cli.kinematics.frames import frame_id, moving_joints
from servicebot_cli.kinematics.sampling import sampling_bounds

if TYPE_CHECKING:
    import pinocchio as pin

    from servicebot_cli.description.joint_space import JointSpace
    from servicebot_cli.kinematics.mimics import Mimics

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.intp]

_ON_AXIS_M = 1e-9  # a joint this close to the previous joint's axis does not move with it


class NothingMoves(ServicebotError):
    """IK was asked to move a frame that no joint moves."""


@dataclass(frozen=True)
class Reach:
    """A sphere that holds every position the chain can put its frame at.

    Attributes:
        center_m: Centre in the root frame [m]: the last joint origin no joint moves.
        radius_m: Sum of the link lengths from there to the frame (plus prismatic travel) [m].
        around: The joint at the centre.
    """

    center_m: FloatArray
    radius_m: float
    around: str

    def beyond_m(self, position_m: FloatArray, *, vertical_only: bool = False) -> float:
        """How far ``position_m`` lies outside the sphere [m] (0 or less: inside).

        With ``vertical_only`` (a mobile base that can stand anywhere on the floor), only
        the height difference counts.
        """
        offset = np.asarray(position_m, dtype=float) - self.center_m
        distance = abs(offset[2]) if vertical_only else float(np.linalg.norm(offset))
        return distance - self.radius_m


_LINK_SUFFIX = " (link)"


def _reduced(model: pin.Model, lock: list[int], reference: FloatArray) -> pin.Model:
    """``pin.buildReducedModel`` of ``model`` with the joints ``lock`` locked at ``reference``.

    URDF lets a joint and a link share a name (baxter's fixed joint ``left_hand`` holds link
    ``left_hand``; nao's joint ``LAnklePitch`` moves link ``LAnklePitch``), and Pinocchio then
    has two frames of that name; ``buildReducedModel`` looks frames up by name alone and
    raises on them. The link frames of such names are renamed in a copy while it reduces,
    and named back after: a joint's own frame must keep the joint's name, which it finds
    its frame by.
    """
    import pinocchio as pin

    others = {frame.name for frame in model.frames if frame.type != pin.FrameType.BODY}
    clashing = [index for index, frame in enumerate(model.frames)
                if frame.type == pin.FrameType.BODY and frame.name in others]
    if not clashing:
        return pin.buildReducedModel(model, lock, reference)
    renamed = pin.Model(model)
    for index in clashing:
        frame = renamed.frames[index]
        frame.name += _LINK_SUFFIX
        renamed.frames[index] = frame
    reduced = pin.buildReducedModel(renamed, lock, reference)
    for index, frame in enumerate(reduced.frames):
        if frame.type == pin.FrameType.BODY and frame.name.endswith(_LINK_SUFFIX):
            frame.name = frame.name[:-len(_LINK_SUFFIX)]
            reduced.frames[index] = frame
    return reduced


class Chain:
    """The joints that move ``frame``, as a reduced model.

    Attributes:
        model: Reduced model: the chain's joints only (a planar base first, if any).
        data: Its data.
        frame: Index of the frame in :attr:`model`.
        names: Joint names of :attr:`model`, in its order (``root_joint`` for a base).
        full_index: For each entry of the chain's ``q``, its index in the full model's ``q``.
        lower: Lower limits per entry of the chain's ``q`` (``-inf`` where unbounded).
        upper: Upper limits per entry (``+inf`` where unbounded).
        vector_space: True when ``q`` is a plain vector (every joint revolute or prismatic),
            so a step is ``q + dq``; otherwise steps go through ``pin.integrate``.
        base_nq: Entries of ``q`` that belong to the planar base (0 or 4).
    """

    def __init__(self, model: pin.Model, space: JointSpace, frame: str, known: Sequence[str],
                 mimics: Mimics | None = None):
        """Reduce ``model`` to the joints that move ``frame``.

        Args:
            model: The full model (fixed or planar base).
            space: Its joint space (URDF limits).
            frame: The frame to move.
            known: Every link name, for suggestions.
            mimics: Joints that follow another: each group of them is solved as one value
                (see :mod:`~servicebot_cli.kinematics.chain_mimic`).

        Raises:
            NothingMoves: No joint moves ``frame``.
            CannotCouple: Followers that cannot be solved with their leader.
        """
        import pinocchio as pin

        # a URDF planar or floating joint has no value a user gives or sees (the joint
        # space leaves it out): it stays at its identity, as fk places it
        keep = tuple(j for j in moving_joints(model, frame_id(model, frame, known))
                     if model.names[j] in space.names or model.names[j] == "root_joint")
        if not keep:
            raise NothingMoves(f"frame '{frame}' is fixed to the root: no joint moves it; "
                               "choose a frame on the arm, or add --with-base")
        self.coupling = None if mimics is None else coupling(model, space, mimics, keep)
        self._space = space
        source = model if self.coupling is None else self.coupling.model
        kept = set(keep) if self.coupling is None else self.coupling.keep
        if not kept:
            raise NothingMoves(f"frame '{frame}' moves only with joints that stand at their "
                               "<mimic> offset (multiplier 0): no joint moves it; choose "
                               "another frame")
        lock = [j for j in range(1, model.njoints) if j not in kept]
        reference = pin.neutral(source) if self.coupling is None else self.coupling.reference
        self.full_nq = model.nq
        self.model = _reduced(source, lock, reference) if lock else source
        self.data = new_data(self.model, f"the joints that move '{frame}'")
        self.frame = frame_id(self.model, frame, known)
        self.frame_name = frame
        self.names = tuple(self.model.names[1:])
        self.base_nq = space.base_nq if "root_joint" in self.names else 0
        self.full_index, self.lower, self.upper = _index_and_limits(model, self.model, space)
        if self.coupling is not None:
            self.coupling.limits(space, self.lower, self.upper, {
                k: self.model.joints[self.model.getJointId(space.names[k])].idx_q
                for _, k in self.coupling.driver})
        self.vector_space = self.model.nq == self.model.nv and self.base_nq == 0
        self.reach = chain_reach(model, frame_id(model, frame, known), keep)

    def to_chain(self, q_full: FloatArray) -> FloatArray:
        """The chain's ``q`` from a full ``q`` (a follower solved for starts at its leader's)."""
        if self.coupling is not None:
            q_full = self.coupling.seeded(self._space, q_full)
        return q_full[self.full_index]

    def to_full(self, q_chain: FloatArray, q_full: FloatArray) -> FloatArray:
        """``q_full`` with the chain's entries replaced by ``q_chain`` (a new array)."""
        out = np.array(q_full, dtype=float)
        out[self.full_index] = q_chain
        return out if self.coupling is None else self.coupling.follow(self._space, out)

    def to_full_rows(self, q_chain: FloatArray, q_full: FloatArray) -> FloatArray:
        """:meth:`to_full` of each row of ``q_chain`` (rows, the chain's ``nq``)."""
        if self.coupling is not None:
            return np.array([self.to_full(row, q_full) for row in q_chain]).reshape(
                len(q_chain), len(q_full))
        full = np.repeat(np.asarray(q_full, dtype=float)[np.newaxis], len(q_chain), axis=0)
        full[:, self.full_index] = q_chain
        return full

    def random_q(self, rng: np.random.Generator, near_m: FloatArray | None = None) -> FloatArray:
        """A random chain ``q`` within the limits; continuous joints at any angle.

        A planar base is put within the arm's reach of ``near_m`` (x, y), facing anywhere.
        """
        import pinocchio as pin

        lower, upper = sampling_bounds(self.lower, self.upper)  # not +-1e308
        if self.vector_space:
            return lower + (upper - lower) * rng.random(int(self.model.nq))
        q: FloatArray = pin.neutral(self.model)
        bounded = np.isfinite(self.lower)
        q[bounded] = rng.uniform(lower[bounded], upper[bounded])
        for j in range(1, self.model.njoints):
            joint = self.model.joints[j]
            if joint.nq == 2 and joint.nv == 1:  # continuous: cos, sin of an angle
                angle = rng.uniform(-math.pi, math.pi)
                q[joint.idx_q: joint.idx_q + 2] = math.cos(angle), math.sin(angle)
        if self.base_nq:
            heading, spread = rng.uniform(-math.pi, math.pi), rng.uniform(-math.pi, math.pi)
            radius = self.reach.radius_m * math.sqrt(rng.uniform())
            centre = np.zeros(2) if near_m is None else np.asarray(near_m[:2], dtype=float)
            q[0:2] = centre + radius * np.array([math.cos(spread), math.sin(spread)])
            q[2:4] = math.cos(heading), math.sin(heading)
        return q

    def clamp(self, q: FloatArray) -> FloatArray:
        """``q`` clamped into the limits, in place."""
        np.maximum(q, self.lower, out=q)
        np.minimum(q, self.upper, out=q)
        return q


def _index_and_limits(full: pin.Model, reduced: pin.Model,
                      space: JointSpace) -> tuple[IntArray, FloatArray, FloatArray]:
    index = np.empty(reduced.nq, dtype=np.intp)
    lower = np.full(reduced.nq, -np.inf)
    upper = np.full(reduced.nq, np.inf)
    for j in range(1, reduced.njoints):
        name, joint = reduced.names[j], reduced.joints[j]
        source = full.joints[full.getJointId(name)]  # the reduced model's names come from full
        index[joint.idx_q: joint.idx_q + joint.nq] = range(source.idx_q, source.idx_q + source.nq)
        if name in space.names and joint.nq == 1:
            k = space.index(name)
            if not math.isnan(space.lower[k]):
                lower[joint.idx_q], upper[joint.idx_q] = space.lower[k], space.upper[k]
    return index, lower, upper


def chain_reach(model: pin.Model, frame: int, moving: Sequence[int] | None = None) -> Reach:
    """A sphere that holds every position the joints can put ``frame`` at.

    The distance between two consecutive joint origins of a serial chain never changes
    (a revolute joint turns about an axis through its origin), so the frame stays within
    the sum of those lengths of the first joint that no joint moves. A joint whose origin lies
    on the previous (revolute) joint's axis does not move with it, so the centre moves on.
    A planar base is left out: it can stand anywhere. ``moving`` narrows the joints that
    move ``frame`` to those the chain solves for.
    """
    import pinocchio as pin

    joints = [j for j in (moving_joints(model, frame) if moving is None else moving)
              if model.names[j] != "root_joint"]
    if not joints:
        origin = pin.updateFramePlacement(model, model.createData(), frame).translation
        return Reach(np.array(origin), 0.0, model.frames[frame].name)
    data = model.createData()
    q = pin.neutral(model)
    pin.forwardKinematics(model, data, q)
    centre = 0
    for k in range(len(joints) - 1):
        if centre == k and _on_axis(model, data, q, joints[k], joints[k + 1]):
            centre = k + 1
    lengths = [float(np.linalg.norm(model.jointPlacements[j].translation))
               for j in joints[centre + 1:]]
    lengths.append(float(np.linalg.norm(model.frames[frame].placement.translation)))
    travel = [_prismatic_travel(model, j) for j in joints[centre:]]
    return Reach(np.array(data.oMi[joints[centre]].translation), sum(lengths) + sum(travel),
                 model.names[joints[centre]])


def _on_axis(model: pin.Model, data: pin.Data, q: FloatArray, joint: int, child: int) -> bool:
    """True when ``child``'s origin lies on ``joint``'s axis of rotation."""
    import pinocchio as pin

    jacobian = np.reshape(pin.computeJointJacobian(model, data, q, joint), (6, model.nv))
    motion = jacobian[:, model.joints[joint].idx_v]
    axis = motion[3:]
    if np.linalg.norm(axis) < 0.5:  # prismatic: the child moves along with it
        return False
    offset = model.jointPlacements[child].translation
    return bool(np.linalg.norm(np.cross(offset, axis)) < _ON_AXIS_M)


def _prismatic_travel(model: pin.Model, joint: int) -> float:
    """Largest distance a prismatic joint can add [m]; 0 for other joints."""
    import pinocchio as pin

    data = model.createData()
    # (6, nv); a model of one degree of freedom gets it back as a (6,) array
    motion = np.reshape(pin.computeJointJacobian(model, data, pin.neutral(model), joint),
                        (6, model.nv))
    if np.linalg.norm(motion[3:, model.joints[joint].idx_v]) > 0.5:
        return 0.0
    i = model.joints[joint].idx_q
    return float(max(abs(model.lowerPositionLimit[i]), abs(model.upperPositionLimit[i])))
