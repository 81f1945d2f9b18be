"""The world's solids: walls, boxes and cylinders of a scenario, placed in the world.

Walls, boxes and cylinders become :class:`Solid` objects: boxes (a wall is a thin box) and
vertical cylinders with a pose, and the colour the scenario gives them. Rays meet them in
:mod:`.raycast`; the robot's links touch them in :mod:`.contacts`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.scenario.definition import World

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]


@dataclass(frozen=True)
class Solid:
    """A box or a cylinder (axis along its local z) placed in some frame.

    Attributes:
        name: How events and plots name it (``wall 1``, ``box 2``, ``cylinder 1``).
        kind: ``box`` or ``cylinder``.
        center_m: Centre, shape (3,).
        rotation: Local axes in the parent frame (columns), shape (3, 3).
        half_m: Box half sizes; for a cylinder ``(radius, radius, half length)``.
        color: The scenario's ``color``, rgb in [0, 1]; None: the camera's default.
    """

    name: str
    kind: str
    center_m: FloatArray
    rotation: FloatArray
    half_m: FloatArray
    color: tuple[float, float, float] | None = None

    @property
    def z_range_m(self) -> tuple[float, float]:
        """Lowest and highest z of the solid [m]."""
        reach = np.abs(self.rotation) @ self.half_m
        return float(self.center_m[2] - reach[2]), float(self.center_m[2] + reach[2])

    def floor_corners(self) -> FloatArray:
        """A box's corners on the floor plane, counter-clockwise, shape (4, 2)."""
        hx, hy = self.half_m[0], self.half_m[1]
        local = np.array([[hx, hy], [-hx, hy], [-hx, -hy], [hx, -hy]])
        return self.center_m[:2] + local @ self.rotation[:2, :2].T


def yaw_rotation(yaw_rad: float) -> FloatArray:
    """Rotation about z by ``yaw_rad``."""
    c, s = math.cos(yaw_rad), math.sin(yaw_rad)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def world_solids(world: World) -> list[Solid]:
    """Walls, boxes and cylinders of a scenario's world, named in file order."""
    solids = []
    for i, wall in enumerate(world.walls, 1):
        (x0, y0), (x1, y1) = wall.from_m, wall.to_m
        length = math.hypot(x1 - x0, y1 - y0)
        solids.append(Solid(
            f"wall {i}", "box", np.array([(x0 + x1) / 2, (y0 + y1) / 2, wall.height_m / 2]),
            yaw_rotation(math.atan2(y1 - y0, x1 - x0)),
            # Walls reach half a thickness past their ends, so corners close.
            np.array([length / 2 + wall.thickness_m / 2, wall.thickness_m / 2, wall.height_m / 2]),
            wall.color))
    for i, box in enumerate(world.boxes, 1):
        solids.append(Solid(f"box {i}", "box", np.array(box.center_m, float),
                            yaw_rotation(box.yaw_rad), np.array(box.size_m, float) / 2,
                            box.color))
    for i, cyl in enumerate(world.cylinders, 1):
        solids.append(Solid(f"cylinder {i}", "cylinder",
                            np.array([cyl.center_m[0], cyl.center_m[1], cyl.height_m / 2]),
                            np.eye(3), np.array([cyl.radius_m, cyl.radius_m, cyl.height_m / 2]),
                            cyl.color))
    return solids
