"""The ``camera:`` field of a scenario: which camera images a run renders, if any.

Images are off by default: the bundled robot's camera is documented at 1920x1080 and 30 Hz,
6 MB a frame. A ``camera:`` mapping (or ``simulate --camera-scale`` / ``--camera-rate-hz``)
turns them on. ``scale`` (0 < scale <= 1, default :data:`DEFAULT_SCALE`) shrinks the URDF's
image size; ``rate_hz`` (default: the URDF camera's ``<update_rate>``) may not exceed that
rate (a camera cannot be asked for frames it does not take) nor the control rate (checked
with the robot, see :mod:`~servicebot_cli.simulate.scenario.world_check`); ``depth: true``
adds the depth image.
"""

from __future__ import annotations

from dataclasses import dataclass

from servicebot_cli.simulate.scenario.colour import Color
from servicebot_cli.simulate.scenario.located import Path
from servicebot_cli.simulate.scenario.schema import Reader

DEFAULT_SCALE = 0.125
"""1/8 of the documented 1920x1080: 240x135, about 36 ms a frame with numpy."""
KEYS = ("scale", "rate_hz", "depth")


@dataclass(frozen=True)
class CameraImages:
    """Camera images a run renders.

    Attributes:
        enabled: Render images at all (off: only ``camera_info``, at the URDF's size).
        scale: Rendered size over the URDF's ``<image>`` size, in (0, 1].
        rate_hz: Frames per simulated second; None: the URDF camera's update rate.
        depth: Render a depth image (``32FC1``) with each colour image.
        from_cli: The fields the command line set (its errors name the option, not a line).
        floor_color: The world's ``floor.color`` (None: the camera's grey checker).
        mesh_colors: Each mesh obstacle's ``color`` (None: the camera's default), in order.
            Solids carry their own (:class:`~servicebot_cli.simulate.world.solids.Solid`).
    """

    enabled: bool = False
    scale: float = DEFAULT_SCALE
    rate_hz: float | None = None
    depth: bool = False
    from_cli: frozenset[str] = frozenset()
    floor_color: Color | None = None
    mesh_colors: tuple[Color | None, ...] = ()


def read_camera(r: Reader, path: Path) -> CameraImages:
    """The ``camera:`` mapping at ``path``; images off when it is absent.

    Raises:
        ScenarioError: An unknown key, a scale outside (0, 1], a rate that is not a positive
            number, or a ``depth`` that is not true or false.
    """
    if not r.has(path):
        return CameraImages()
    r.mapping(path, KEYS)
    rate = r.number((*path, "rate_hz"), positive=True) if r.has((*path, "rate_hz")) else None
    depth = False
    if r.has((*path, "depth")):
        value = r.get((*path, "depth"))
        if not isinstance(value, bool):
            raise r.error((*path, "depth"), f"expected true or false, got {value!r}")
        depth = value
    return CameraImages(True, r.number((*path, "scale"), DEFAULT_SCALE, positive=True,
                                       maximum=1.0), rate, depth)
