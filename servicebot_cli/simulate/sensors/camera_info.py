r"""camera_info for a pinhole camera from its resolution and horizontal field of view.

As gazebo_ros_camera computes it: :math:`f = w / (2 \tan(\mathrm{hfov}/2))` for both axes
(square pixels), principal point :math:`((w + 1)/2, (h + 1)/2)` (gz-sensors: the centre,
:math:`(w/2, h/2)`), no distortion (plumb_bob with zero coefficients).
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
    centred: bool = False
    """The principal point is given from the image's edge, (w/2, h/2) at its centre
    (gz-sensors); else from the first pixel's centre as 1, ((w + 1)/2, (h + 1)/2)
    (gazebo_ros_camera). Either way the image is rendered centred."""


SDF_WIDTH_PX, SDF_HEIGHT_PX, SDF_HORIZONTAL_FOV_RAD = 320, 240, 1.047
"""SDF's defaults for ``<camera>``'s ``<image><width>``, ``<height>`` and ``<horizontal_fov>``,
which Gazebo (Classic and gz-sim) uses when a description leaves them out."""


MAX_SIDE_PX = 65_535
"""The widest and tallest image simulated (JPEG's limit; a camera of 16k pixels is rare)."""


def principal_point(width: int, height: int, centred: bool) -> tuple[float, float]:
    """gz-sensors' (w/2, h/2) when ``centred``, else gazebo_ros_camera's ((w+1)/2, (h+1)/2)."""
    if centred:
        return width / 2.0, height / 2.0
    return (width + 1) / 2.0, (height + 1) / 2.0


def intrinsics(spec: CameraSpec) -> Intrinsics:
    """Intrinsics of ``spec``; a size or field of view it leaves out is SDF's default.

    Raises:
        DescriptionError: A size that is not 1 to :data:`MAX_SIDE_PX` a side, or a field of
            view not in (0, pi).
    """
    width = SDF_WIDTH_PX if spec.width_px is None else spec.width_px
    height = SDF_HEIGHT_PX if spec.height_px is None else spec.height_px
    fov = SDF_HORIZONTAL_FOV_RAD if spec.horizontal_fov_rad is None else spec.horizontal_fov_rad
    if not (0 < width <= MAX_SIDE_PX and 0 < height <= MAX_SIDE_PX):
        raise DescriptionError(f"its image, {width} x {height} px, is not 1 to "
                               f"{MAX_SIDE_PX:,} px a side, as simulated images are")
    if not 0.0 < fov < math.pi:
        raise DescriptionError(
            f"its horizontal_fov {fov:g} rad is not more than 0 and less than pi, as a "
            "pinhole image's is (Gazebo's camera_info gets no positive focal length)")
    f = width / (2.0 * math.tan(fov / 2.0))
    cx, cy = principal_point(width, height, spec.centred)
    return Intrinsics(width, height,
                      (f, 0.0, cx, 0.0, f, cy, 0.0, 0.0, 1.0),
                      (f, 0.0, cx, 0.0, 0.0, f, cy, 0.0, 0.0, 0.0, 1.0, 0.0),
                      centred=spec.centred)
