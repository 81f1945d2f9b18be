"""Short texts for people: vectors, axes, limits, shapes, noise. Formatting only."""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from servicebot_cli.output.table import format_number

if TYPE_CHECKING:
    from servicebot_cli.description.sensors import NoiseSpec
    from servicebot_cli.inspect.joints import Limits
    from servicebot_cli.inspect.links import ShapeInfo

_AXES = {(1.0, 0.0, 0.0): "x", (0.0, 1.0, 0.0): "y", (0.0, 0.0, 1.0): "z"}


def vec(values: Sequence[float] | None, sep: str = " ") -> str:
    """``0.17 0.27 -0.08``; ``-`` when absent."""
    if values is None:
        return "-"
    return sep.join(format_number(float(v)) for v in values)


def point(values: Sequence[float] | None) -> str:
    """``(0.17, 0.27, -0.08)``."""
    return "-" if values is None else f"({vec(values, ', ')})"


def axis(values: Sequence[float] | None) -> str:
    """``x``, ``-z``, or the three numbers for an axis that is not a unit axis."""
    if values is None:
        return "-"
    key = tuple(float(v) for v in values)
    for unit, name in _AXES.items():
        if key == unit:
            return name
        if key == tuple(-u for u in unit):
            return f"-{name}"
    return vec(values)


def span(lower: float | None, upper: float | None) -> str:
    """``[-1.57, 1.57]``; ``-`` without bounds."""
    if lower is None or upper is None:
        return "-"
    return f"[{format_number(lower)}, {format_number(upper)}]"


def joint_motion(joint_type: str, joint_axis: Sequence[float] | None) -> str:
    """``revolute z``, ``continuous y``, ``fixed``."""
    return joint_type if joint_axis is None else f"{joint_type} {axis(joint_axis)}"


def joint_limits(limits: Limits | None) -> str:
    """``[-1.57, 1.57] rad, 1 rad/s`` (position and velocity limits) or ``-``."""
    if limits is None:
        return "-"
    parts = []
    if limits.lower is not None and limits.upper is not None:
        parts.append(f"{span(limits.lower, limits.upper)} {limits.units.position}")
    if limits.velocity is not None:
        parts.append(f"{format_number(limits.velocity)} {limits.units.velocity}")
    return ", ".join(parts) or "-"


def shape(info: ShapeInfo) -> str:
    """``box 0.5 x 0.5 x 0.2``, ``cylinder r 0.07 l 0.04``, ``sphere r 0.1``, ``mesh a.stl``."""
    if info.kind == "box":
        return "box " + (vec(info.size_m, " x ") if info.size_m else "(no size)")
    if info.kind == "cylinder":
        return f"cylinder r {format_number(info.radius_m)} l {format_number(info.length_m)}"
    if info.kind == "sphere":
        return f"sphere r {format_number(info.radius_m)}"
    if info.kind == "mesh":
        scale = "" if info.scale in (None, (1.0, 1.0, 1.0)) else f" scale {vec(info.scale)}"
        return f"mesh {info.mesh}{scale}"
    return "(no geometry)"


def noise(spec: NoiseSpec | None, unit: str = "") -> str:
    """``gaussian, mean 0, stddev 0.01 m`` (and the bias when there is one)."""
    if spec is None:
        return "none"
    u = f" {unit}" if unit else ""
    text = (f"{spec.type}, mean {format_number(spec.mean)}{u}, "
            f"stddev {format_number(spec.stddev)}{u}")
    if spec.bias_mean or spec.bias_stddev:
        text += (f", bias mean {format_number(spec.bias_mean)}{u}, "
                 f"bias stddev {format_number(spec.bias_stddev)}{u}")
    return text


def quantity(value: float | None, unit: str) -> str:
    """``0.44 rad/s``; ``-`` when absent."""
    return "-" if value is None else f"{format_number(value)} {unit}"
