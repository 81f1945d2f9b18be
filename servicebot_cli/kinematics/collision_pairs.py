"""Which collision pairs are not worth checking, taken out of a Pinocchio ``GeometryModel``.

A pair is left out when none of the joints IK moves changes its relative pose, or when it
touches at the neutral configuration and at every one of :data:`SAMPLES` random
configurations within the limits (a fixed seed: the same pairs every run), "always in
collision", as MoveIt's setup assistant has it. For
:func:`~servicebot_cli.kinematics.collisions.build_check`. Pure.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Iterable
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.sampling import sampling_bounds

if TYPE_CHECKING:
    import pinocchio as pin

FloatArray = npt.NDArray[np.float64]

SAMPLES = 200
"""Random configurations that decide which pairs always touch."""
_SAMPLE_SEED = 0


def keep_moved_pairs(model: pin.Model, geometry: pin.GeometryModel,
                     moving: Collection[str]) -> None:
    """Remove the pairs whose relative pose none of the ``moving`` joints changes."""
    chosen = {model.getJointId(name) for name in moving if model.existJointName(name)}
    objects = geometry.geometryObjects

    def movers(k: int) -> frozenset[int]:
        return frozenset(int(j) for j in model.supports[objects[k].parentJoint]) & chosen

    still = [(pair.first, pair.second) for pair in geometry.collisionPairs
             if movers(pair.first) == movers(pair.second)]
    _remove(geometry, still)


def _remove(geometry: pin.GeometryModel, pairs: Iterable[tuple[int, int]]) -> None:
    """Remove pairs given by object indices (copies: the model's own pairs move on removal)."""
    import pinocchio as pin

    for first, second in pairs:
        geometry.removeCollisionPair(pin.CollisionPair(first, second))


def placed(model: pin.Model, geometry: pin.GeometryModel,
           q: FloatArray) -> pin.GeometryData:
    """``geometry``'s objects placed at the configuration ``q``."""
    import pinocchio as pin

    geometry_data = pin.GeometryData(geometry)
    pin.updateGeometryPlacements(model, model.createData(), geometry, geometry_data, q)
    return geometry_data


def sample_configurations(model: pin.Model, count: int,
                          rng: np.random.Generator) -> list[FloatArray]:
    """``count`` random configurations: bounded joints within their limits, others any angle.

    A planar or free root joint stays at its neutral pose (moving it moves every link alike).
    """
    import pinocchio as pin

    out = []
    for _ in range(count):
        q: FloatArray = pin.neutral(model)
        for j in range(1, model.njoints):
            joint, name = model.joints[j], model.names[j]
            i = joint.idx_q
            if name == "root_joint":
                continue
            if joint.nq == 1:
                lo, hi = model.lowerPositionLimit[i], model.upperPositionLimit[i]
                if math.isfinite(lo) and math.isfinite(hi):
                    q[i] = rng.uniform(*sampling_bounds(lo, hi))  # not +-1e308
                else:
                    q[i] = rng.uniform(-math.pi, math.pi)
            elif joint.nq == 2 and joint.nv == 1:  # continuous: cos, sin
                angle = rng.uniform(-math.pi, math.pi)
                q[i:i + 2] = math.cos(angle), math.sin(angle)
        out.append(q)
    return out


def drop_always_touching(model: pin.Model, geometry: pin.GeometryModel, samples: int) -> None:
    """Remove the pairs that intersect at the neutral configuration and every sample."""
    import pinocchio as pin

    rng = np.random.default_rng(_SAMPLE_SEED)
    always = list(range(len(geometry.collisionPairs)))
    for q in [pin.neutral(model), *sample_configurations(model, samples, rng)]:
        if not always:
            return
        placed_data = placed(model, geometry, q)
        always = [k for k in always if pin.computeCollision(geometry, placed_data, k)]
    pairs = geometry.collisionPairs
    _remove(geometry, [(pairs[k].first, pairs[k].second) for k in always])
