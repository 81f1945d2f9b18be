r"""A camera's rays, which all leave one point: distances to primitives, normals, culling.

Every ray of a frame starts at the camera, so a primitive's frame needs the camera's
position moved into it once (:math:`R^T (o - c)`, three numbers) and only the directions
per ray (:math:`R^T d`); the slab method, the cylinder's quadratic and caps and the
sphere's quadratic then run on the ray arrays as :mod:`~servicebot_cli.simulate.world.raycast`
does for rays from many points. A ray that starts inside a primitive does not see it.

Culling: all rays lie within a cone about the optical axis (half angle: the corner
pixel's). A primitive whose bounding sphere (centre :math:`c`, radius :math:`r`, at
distance :math:`d` from the camera) is seen at angle :math:`\alpha` from the axis covers
the angles :math:`\alpha \pm \arcsin(r/d)`; when even the nearest of them is outside the
cone, no ray can meet it.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.world.raycast import box_entry, cylinder_entry
from servicebot_cli.simulate.world.robot_rays import sphere_entry

FloatArray = npt.NDArray[np.float64]


def columns(directions: FloatArray) -> list[FloatArray]:
    """The x, y and z components of unit directions (N, 3), each contiguous."""
    return [np.ascontiguousarray(directions[:, i]) for i in range(3)]


def floor_distances(origin: FloatArray, d: list[FloatArray]) -> FloatArray:
    """Distance along each ray to the plane z = 0 from above [m], inf for none."""
    with np.errstate(divide="ignore", invalid="ignore"):
        t = -float(origin[2]) / d[2]
    return np.where((d[2] < 0) & (t >= 0), t, np.inf)


def primitive_distances(kind: str, half_m: FloatArray, transform: FloatArray,
                        origin: FloatArray, d: list[FloatArray]) -> FloatArray:
    """Distance along each ray to a box, cylinder or sphere placed at ``transform`` [m].

    Args:
        kind: ``box``, ``cylinder`` (axis along its local z) or ``sphere``.
        half_m: Box half sizes; ``(r, r, half length)``; ``(r, r, r)``.
        transform: ``transform_primitive_to_world``, (4, 4).
        origin: The rays' common origin in the world, (3,).
        d: The rays' directions as :func:`columns`.
    """
    o, local = into_frame(transform, origin, d)
    if kind == "box":
        return box_entry(o, local, half_m)  # type: ignore[arg-type]  # scalars broadcast
    if kind == "cylinder":
        return cylinder_entry(o, local, half_m)  # type: ignore[arg-type]
    return sphere_entry(o, local, float(half_m[0]))  # type: ignore[arg-type]


def into_frame(transform: FloatArray, origin: FloatArray,
               d: list[FloatArray]) -> tuple[list[float], list[FloatArray]]:
    """The rays in the frame ``transform`` places: :math:`R^T (o - c)` and :math:`R^T d`."""
    rotation = transform[:3, :3]
    shifted = origin - transform[:3, 3]
    o = [float(shifted[0] * rotation[0, i] + shifted[1] * rotation[1, i]
               + shifted[2] * rotation[2, i]) for i in range(3)]
    local = [d[0] * rotation[0, i] + d[1] * rotation[1, i] + d[2] * rotation[2, i]
             for i in range(3)]
    return o, local


def bounding_radius(kind: str, half_m: FloatArray) -> float:
    """Radius of the sphere about a primitive's centre that holds it [m]."""
    if kind == "box":
        return float(np.linalg.norm(half_m))
    if kind == "cylinder":
        return float(math.hypot(half_m[0], half_m[2]))
    return float(half_m[0])


def in_view(centre_m: FloatArray, radius_m: float, origin: FloatArray, axis: FloatArray,
            half_angle_rad: float) -> bool:
    """Whether any ray of the cone (apex ``origin``, unit ``axis``) can meet the sphere."""
    offset = np.asarray(centre_m, dtype=float) - origin
    distance = float(np.linalg.norm(offset))
    if distance <= radius_m:
        return True
    angle = math.acos(max(-1.0, min(1.0, float(offset @ axis) / distance)))
    return angle - math.asin(radius_m / distance) <= half_angle_rad + 1e-9


def primitive_normals(kind: str, half_m: FloatArray, local: FloatArray) -> FloatArray:
    """Outward unit normals at points on a box, cylinder or sphere, in its own frame."""
    normals = np.zeros_like(local)
    rows = np.arange(len(local))
    if kind == "box":
        axis = np.argmax(np.abs(local) / half_m, axis=1)
        normals[rows, axis] = np.sign(local[rows, axis])
        return normals
    if kind == "cylinder":
        radial = np.hypot(local[:, 0], local[:, 1])
        cap = np.abs(local[:, 2]) / half_m[2] >= radial / half_m[0]
        normals[cap, 2] = np.sign(local[cap, 2])
        side = ~cap & (radial > 0)
        normals[side, :2] = local[side, :2] / radial[side, None]
        return normals
    length = np.linalg.norm(local, axis=1, keepdims=True)
    normal: FloatArray = local / np.where(length > 0, length, 1.0)
    return normal
