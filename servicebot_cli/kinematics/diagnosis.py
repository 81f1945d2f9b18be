"""Why IK failed, in one hint: a collision, out of reach, an orientation, or the limits.

Pure: a solver, a target and a random generator in; a sentence out.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.collisions import FLOOR, Contact
from servicebot_cli.kinematics.inverse import IkSolver, IkTarget

FloatArray = npt.NDArray[np.float64]

_PROBE_ATTEMPTS = 20


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
