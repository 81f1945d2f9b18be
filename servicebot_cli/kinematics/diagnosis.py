"""Why IK failed, in one hint: a collision, out of reach, an orientation, or the limits.

Pure: a solver, a target and a random generator in; a sentence out.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.chain import Chain
from servicebot_cli.kinematics.collision_floor import FLOOR
from servicebot_cli.kinematics.collisions import Contact
from servicebot_cli.kinematics.inverse import IkSolver, IkTarget

FloatArray = npt.NDArray[np.float64]

_PROBE_ATTEMPTS = 20
_PARALLEL_SIN = 1e-9  # |sin| between joint axes that are parallel (they are, in planar arms)


def hint(solver: IkSolver, target: IkTarget, seed: FloatArray, rng: np.random.Generator) -> str:
    """A hint for a target the solver did not reach.

    1. Beyond the sphere that holds everything the chain reaches: by how much.
    2. With orientation: if the position alone is reachable, say so.
    3. Otherwise: the joint limits (or bad luck) are in the way.
    """
    chain, settings = solver.chain, solver.settings
    reach = chain.reach
    beyond = reach.beyond_m(target.position_m, vertical_only=chain.base_nq > 0)
    if beyond > settings.tolerance_m:
        if chain.base_nq:
            return (f"out of reach: the target is {beyond:.3g} m higher or lower than the arm "
                    f"reaches ({reach.radius_m:.3g} m from joint '{reach.around}'), wherever "
                    "the base stands")
        return (f"out of reach: the target is {beyond:.3g} m beyond the arm's reach "
                f"({reach.radius_m:.3g} m from joint '{reach.around}')")
    plane = _plane(solver.chain) if not chain.base_nq else None
    if plane is not None:
        normal, point = plane
        off = abs(float(normal @ (np.asarray(target.position_m, dtype=float) - point)))
        if off > settings.tolerance_m:
            shown = " ".join(f"{v:.3g}" for v in np.round(normal, 3) + 0.0)
            return (f"out of reach: every joint that moves '{chain.frame_name}' turns about "
                    f"({shown}) or slides across it, so it moves in one plane; the target is "
                    f"{off:.3g} m off that plane")
    if target.axes:
        probe = IkSolver(chain, replace(settings, max_attempts=_PROBE_ATTEMPTS, solutions=1),
                         compiled=solver.compiled)
        if probe.solve(replace(target, axes=()), seed, rng).success:
            fewer = "fewer --orientation-axes (e.g. pitch) or none" if len(target.axes) == 3 \
                else "--orientation-axes none, or other angles"
            return ("the position is reachable, but not with that orientation: the joints "
                    f"cannot make it there; ask for {fewer}")
    return (f"the target is within the arm's {reach.radius_m:.3g} m, but no configuration "
            f"within the joint limits reached it in {settings.max_attempts} attempts; the "
            "limits may forbid it, or raise --max-attempts")


def collision_hint(contact: Contact) -> str:
    """A hint for a target reached only with links in collision: which two."""
    return f"reachable only through a collision: {contact} would intersect; {ways_out(contact)}"


def ways_out(contact: Contact) -> str:
    """The options that let a collision through; an SRDF names pairs of links, never the floor."""
    if contact.second == FLOOR:
        return "--allow-collisions accepts it"
    return "--allow-collisions accepts it, or --srdf FILE can disable the pair"


def timeout_hint(timeout_s: float, attempts: int) -> str:
    """A hint for a search that ran out of time before it found an answer."""
    return (f"stopped by --timeout-s {timeout_s:g} after {attempts} attempt"
            f"{'s' if attempts != 1 else ''}; give it more time, or check the target can be "
            "reached")


def _plane(chain: Chain) -> tuple[FloatArray, FloatArray] | None:
    """The plane the chain's frame moves in, when every joint keeps it in one; else None.

    Revolute joints about parallel axes n (and prismatic ones across n) move the frame in the
    plane through its position with normal n, in every configuration: their axes stay
    parallel. Returns ``(n, point)`` in the root frame.
    """
    import pinocchio as pin

    model, data = chain.model, chain.data
    q = pin.neutral(model)
    pin.computeJointJacobians(model, data, q)
    pin.updateFramePlacements(model, data)
    # Columns: the frame's linear [m/unit] and angular velocity [rad/unit] per joint.
    jacobian = np.reshape(pin.getFrameJacobian(model, data, chain.frame,
                                               pin.LOCAL_WORLD_ALIGNED), (6, model.nv))
    turning = [column[3:] for column in jacobian.T if np.linalg.norm(column[3:]) > 0.5]
    if not turning:
        return None
    normal = turning[0] / np.linalg.norm(turning[0])
    if any(np.linalg.norm(np.cross(normal, axis)) > _PARALLEL_SIN for axis in turning) \
            or np.any(np.abs(normal @ jacobian[:3]) > _PARALLEL_SIN):
        return None
    return normal, np.array(data.oMf[chain.frame].translation)
