r"""camera_info for a pinhole camera from its resolution and horizontal field of view.

As gazebo_ros_camera computes it: :math:`f = w / (2 \tan(\mathrm{hfov}/2))` for both axes
(square pixels), principal point :math:`((w + 1)/2, (h + 1)/2)`, no distortion (plumb_bob
with zero coefficients).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.description.sensors import CameraSpec


@dataclass(frozen=True)
class Intrinsics:
    """``sensor_msgs/CameraInfo`` content: K (3x3) and P (3x4) row-major, sizes [px]."""

    width_px: int
    height_px: int
    k: tuple[float, ...]
    p: tuple[float, ...]
    distortion_model: str = "plumb_bob"
    d: tuple[float, ...] = (0.0, 0.0, 0.0, 0.0, 0.0)


def intrinsics(spec: CameraSpec) -> Intrinsics:
    """Intrinsics of ``spec``.

    Raises:
        DescriptionError: Missing width, height or field of view.
    """
    if not spec.width_px or not spec.height_px or not spec.horizontal_fov_rad:
        raise DescriptionError("the camera sensor needs <width>, <height> and <horizontal_fov>")
    if not 0.0 < spec.horizontal_fov_rad < math.pi:
        raise DescriptionError(
            f"camera horizontal_fov {spec.horizontal_fov_rad:g} rad is not in (0, pi)")
    f = spec.width_px / (2.0 * math.tan(spec.horizontal_fov_rad / 2.0))
    cx, cy = (spec.width_px + 1) / 2.0, (spec.height_px + 1) / 2.0
    return Intrinsics(spec.width_px, spec.height_px,
                      (f, 0.0, cx, 0.0, f, cy, 0.0, 0.0, 1.0),
                      (f, 0.0, cx, 0.0, 0.0, f, cy, 0.0, 0.0, 0.0, 1.0, 0.0))
