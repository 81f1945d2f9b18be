"""A camera's messages: CameraInfo and, with images on, rgb8 and 32FC1 Image payloads.

As gazebo_ros_camera fills them: the camera's frame (or the root link's), the image size of
the run, rows top to bottom. Split from :mod:`.ros_messages`, which names their topics.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.bag import cdr
from servicebot_cli.simulate.bag.byte_rows import ByteRows
from servicebot_cli.simulate.simulator import SimResult


def camera_info(result: SimResult) -> ByteRows:
    """The camera's intrinsics at each frame's stamp, no binning, no region of interest."""
    camera, spec = result.camera, result.body.camera
    assert camera is not None and spec is not None
    layout = cdr.Layout()
    layout.header(spec.spec.frame or result.body.root_link)
    layout.constant("<I", camera.height_px)
    layout.constant("<I", camera.width_px)
    layout.string(camera.distortion_model)
    layout.sequence("d", "<f8", len(camera.d))
    for name, count in (("k", 9), ("r", 9), ("p", 12)):
        layout.field(name, "<f8", count)
    for _ in range(6):  # binning_x, binning_y, roi x_offset, y_offset, height, width
        layout.constant("<I", 0)
    layout.constant("<B", 0)  # roi.do_rectify
    return cdr.serialize(layout, result.camera_times_s, {
        "d": np.array(camera.d), "k": np.array(camera.k),
        "r": np.eye(3).ravel(), "p": np.array(camera.p)})


def colour_images(result: SimResult) -> ByteRows:
    """``rgb8`` images: 3 bytes a pixel, rows top to bottom."""
    return _images(result, "rgb8", 3, [f.rgb.reshape(-1) for f in result.frames])


def depth_images(result: SimResult) -> ByteRows:
    """``32FC1`` depth images [m] along the optical axis, little-endian float32."""
    return _images(result, "32FC1", 4,
                   [f.depth_m.astype("<f4").reshape(-1).view(np.uint8) for f in result.frames])


def _images(result: SimResult, encoding: str, pixel_bytes: int,
            data: list[npt.NDArray[np.uint8]]) -> ByteRows:
    camera, mounted = result.camera, result.body.camera
    assert camera is not None and mounted is not None
    if not data:
        return np.zeros((0, 0), dtype=np.uint8)
    layout = cdr.Layout()
    layout.header(mounted.spec.frame or result.body.root_link)
    layout.constant("<I", camera.height_px)
    layout.constant("<I", camera.width_px)
    layout.string(encoding)
    layout.constant("<B", 0)  # is_bigendian
    layout.constant("<I", pixel_bytes * camera.width_px)  # step: bytes a row
    layout.sequence("data", "u1", pixel_bytes * camera.width_px * camera.height_px)
    return cdr.serialize(layout, result.camera_times_s, {"data": np.stack(data)})
