"""Mass properties of collision geometry, as a uniform solid: what a link's inertia should be.

Pure numpy. Works with second moments ``C = integral of x x^T dV`` (unit density), which add
up across shapes and transform simply; the inertia tensor is ``I = tr(C) E - C``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from servicebot_cli.description.elements import Geometry, Pose
from servicebot_cli.kinematics.transforms import rpy_matrix


@dataclass(frozen=True)
class Solid:
    """A uniform solid of unit density.

    Attributes:
        volume_m3: Volume [m^3].
        centroid_m: Centre of volume in the link frame [m], shape (3,).
        second_moment: ``integral of (x - c)(x - c)^T dV`` about the centroid, link axes (3x3).
        label: How messages describe it (``solid cylinder r=0.07 m, length 0.04 m``).
    """

    volume_m3: float
    centroid_m: np.ndarray
    second_moment: np.ndarray
    label: str


def primitive(geometry: Geometry) -> tuple[float, np.ndarray, str] | None:
    """Volume, second moment about the centre (own axes) and label of a positive primitive."""
    if geometry.kind == "box" and geometry.size and min(geometry.size) > 0:
        x, y, z = geometry.size
        volume = x * y * z
        return volume, volume / 12.0 * np.diag([x * x, y * y, z * z]), \
            f"solid box {x:g} x {y:g} x {z:g} m"
    r = geometry.radius or 0.0
    if geometry.kind == "cylinder" and r > 0 and (geometry.length or 0.0) > 0:
        length = geometry.length or 0.0
        volume = math.pi * r * r * length
        return volume, volume * np.diag([r * r / 4, r * r / 4, length * length / 12]), \
            f"solid cylinder r={r:g} m, length {length:g} m"
    if geometry.kind == "sphere" and r > 0:
        volume = 4.0 / 3.0 * math.pi * r**3
        return volume, volume * r * r / 5.0 * np.eye(3), f"solid sphere r={r:g} m"
    return None


def placed(volume: float, centroid: np.ndarray, moment: np.ndarray, scale: tuple[float, ...],
           origin: Pose, label: str) -> Solid:
    """A solid given in its own frame, scaled per axis and placed at ``origin`` in the link."""
    s = np.diag(scale)
    det = abs(float(np.prod(scale)))
    rotation = rpy_matrix(*origin.rpy)
    return Solid(
        volume_m3=volume * det,
        centroid_m=rotation @ (s @ centroid) + np.array(origin.xyz),
        second_moment=rotation @ (det * s @ moment @ s) @ rotation.T,
        label=label,
    )


def usable(solid: Solid) -> bool:
    """True when the solid's volume, centroid and moments are finite and the volume positive."""
    return (math.isfinite(solid.volume_m3) and solid.volume_m3 > 0
            and bool(np.all(np.isfinite(solid.centroid_m)))
            and bool(np.all(np.isfinite(solid.second_moment))))


def combined(solids: list[Solid], kind: str = "collision") -> Solid:
    """The solids (``kind`` shapes of a link) as one body of uniform density (parallel axes).

    Callers pass shapes with positive, bounded sizes (:mod:`values`), so the volume is positive.
    """
    volume = sum(s.volume_m3 for s in solids)
    centroid = np.sum([s.volume_m3 * s.centroid_m for s in solids], axis=0) / volume
    moment = np.zeros((3, 3))
    for s in solids:
        d = s.centroid_m - centroid
        moment += s.second_moment + s.volume_m3 * np.outer(d, d)
    label = solids[0].label
    if len(solids) > 1:
        label = f"solid of its {len(solids)} {kind} shapes"
    return Solid(volume, centroid, moment, label)


def inertia_of(solid: Solid, mass_kg: float) -> np.ndarray:
    """Inertia tensor [kg m^2] about the centroid, link axes, for ``mass_kg`` spread uniformly."""
    moment = solid.second_moment * (mass_kg / solid.volume_m3)
    inertia: np.ndarray = np.trace(moment) * np.eye(3) - moment
    return inertia


def principal_moments(values: Sequence[float]) -> np.ndarray:
    """The eigenvalues, ascending, of the inertia of URDF's ``(ixx, ixy, ixz, iyy, iyz, izz)``.

    A diagonal inertia, as most are written, is its sorted diagonal: the bits LAPACK gives
    for it, within the range where LAPACK does not rescale the matrix first, at a twentieth
    of the cost of a call into it.
    """
    ixx, ixy, ixz, iyy, iyz, izz = values
    largest = max(abs(ixx), abs(iyy), abs(izz))
    if ixy == ixz == iyz == 0 and (largest == 0 or _UNSCALED[0] <= largest <= _UNSCALED[1]):
        return np.array(sorted((ixx, iyy, izz)), dtype=float)
    moments: np.ndarray = np.linalg.eigvalsh(tensor(values))
    return moments


_UNSCALED = (1e-100, 1e100)  # LAPACK rescales matrices whose largest entry is near 1e+-150


def tensor(values: Sequence[float]) -> np.ndarray:
    """The 3x3 inertia matrix of URDF's ``(ixx, ixy, ixz, iyy, iyz, izz)``."""
    ixx, ixy, ixz, iyy, iyz, izz = values
    return np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]], dtype=float)
