"""The camera's images over a run: frames rendered where the camera is at each sample time.

The camera sits on its URDF link, posed with the base at the sample time (exact along the
tick's arc, as the LIDAR) and with the arm as it is at the start of that tick. The scene is
the world and the robot's own collision parts (but those of the camera's own link, as the
LIDAR leaves out its own), posed the same way, each link in its URDF material's colour and
the world in the scenario's. Each frame's pixel noise is keyed by one draw from one generator
of the run (``stream_rng(seed, "camera")``), frame after frame, so a run gives the same bytes
for a seed whatever pieces it is simulated in. What does not move (the world's solids, the
meshes' triangles, the parts' sizes and colours) is packed once for the run.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.transforms import planar_matrix
from servicebot_cli.simulate.body import SimRobot
from servicebot_cli.simulate.scenario.camera import CameraImages
from servicebot_cli.simulate.sensors import camera_colours, camera_info
from servicebot_cli.simulate.sensors.camera_image import (
    Frame,
    Scene,
    camera_view,
    render_frames,
    scaled,
)
from servicebot_cli.simulate.sensors.noise import stream_rng
from servicebot_cli.simulate.world.motion import Path2D, pose_at
from servicebot_cli.simulate.world.raycast import Mesh
from servicebot_cli.simulate.world.solids import Solid

FloatArray = npt.NDArray[np.float64]
PIECE_BYTES = 256_000_000
"""At most this many bytes of frames in one piece of a run (pieces are cut shorter)."""


class CameraStream:
    """Renders the frames of one run, a piece at a time.

    Args:
        body: The robot; it must have a camera.
        images: The scale and depth asked for.
        seed: The run's seed.
        solids, meshes: The world.
    """

    def __init__(self, body: SimRobot, images: CameraImages, seed: int,
                 solids: Sequence[Solid], meshes: Sequence[Mesh]) -> None:
        mounted = body.camera
        assert mounted is not None
        spec = mounted.spec
        self.intrinsics = scaled(camera_info.intrinsics(spec), images.scale)
        self.view = camera_view(self.intrinsics, spec.near_clip_m or 0.0,
                                spec.far_clip_m or np.inf)
        noise = spec.noise
        self.stddev = noise.stddev if noise is not None and noise.type != "none" else 0.0
        self.rng = stream_rng(seed, "camera")
        self.depth = images.depth or not spec.colour  # a depth camera's image is its depth
        self.body, self.solids, self.meshes = body, list(solids), list(meshes)
        shape = body.shape
        self.keep = np.array([p.link != mounted.link for p in shape.parts], dtype=bool)
        parts = [p for p, k in zip(shape.parts, self.keep, strict=True) if k]
        colours, palette = camera_colours.link_colours(body.robot), camera_colours.palette(images)
        self.scene = Scene(self.solids, self.meshes, parts, None, palette,
                           tuple(colours.get(p.link, palette.robot) for p in parts),
                           camera_colours.mesh_colours(images, len(self.meshes), palette))
        # the camera on its link: the link's pose in the configuration sim_robot placed it in
        at_rest = shape.link_to_base(np.zeros((1, len(shape.joints))), mounted.link)[0] \
            if mounted.link in _tree(body) else np.eye(4)
        self.camera_to_link = np.linalg.solve(at_rest, mounted.transform_sensor_to_base)
        self.link = mounted.link if mounted.link in _tree(body) else shape.root

    @property
    def frame_bytes(self) -> int:
        """Bytes one frame holds (colour and, with depth, float32 depth)."""
        pixels = self.intrinsics.width_px * self.intrinsics.height_px
        return pixels * (3 + (4 if self.depth else 0))

    def frames(self, truth: Path2D, arm_q: FloatArray, times_s: FloatArray) -> tuple[Frame, ...]:
        """The frames at ``times_s`` of a piece whose motion is ``truth`` and arm ``arm_q``."""
        if not len(times_s):
            return ()
        body, shape = self.body, self.body.shape
        x, y, yaw = pose_at(truth, times_s)
        q = arm_q[truth.tick_index(times_s, boundaries=True)]
        parts_to_base = shape.transforms_to_base(q)[:, self.keep]
        camera_to_base = shape.link_to_base(q, self.link) @ self.camera_to_link
        base_to_world = np.array([planar_matrix(float(x[i]), float(y[i]), float(yaw[i]),
                                                body.base_height_m) for i in range(len(x))])
        return render_frames(self.view, base_to_world @ camera_to_base, self.scene,
                             base_to_world[:, None] @ parts_to_base, self.stddev, self.rng,
                             depth=self.depth)


def _tree(body: SimRobot) -> set[str]:
    """The links :meth:`RobotShape.link_to_base` can place."""
    return {body.shape.root, *(link for link, *_ in body.shape.steps)}


