"""IK targets from what users write: a position, roll-pitch-yaw or a quaternion, and axes.

``--orientation-axes`` says which angles of orientation matter: ``all`` (the default when an
orientation is given), ``none`` (position only), or a comma list such as ``pitch`` or
``roll,pitch``. Batch lines use the same names as ``fk`` output, so ``fk`` results feed
``ik`` directly: ``x_m y_m z_m`` (or ``x y z``), then ``roll_rad pitch_rad yaw_rad``
(``_deg``; bare ``roll pitch yaw`` follow ``--deg``) or ``qx qy qz qw``; JSON lines may
instead hold ``position_m``, ``rpy_rad``/``rpy_deg``, ``quaternion_xyzw``, or an ``fk``
result's ``poses``. Pure.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.kinematics.inverse import IkTarget
from servicebot_cli.kinematics.json_types import JsonValue
from servicebot_cli.kinematics.rotations import (
    AXES,
    BadRotation,
    matrix_from_quaternion,
    matrix_from_rpy,
)
from servicebot_cli.kinematics.user_joints import number

MAX_POSITION_M = 1e6
"""Largest target coordinate [m]: beyond it squares overflow long before any robot reaches."""
POSITION_KEYS = (("x_m", "y_m", "z_m"), ("x", "y", "z"))
QUATERNION_KEYS = ("qx", "qy", "qz", "qw")
_JSON_LISTS = {"position_m": ("x_m", "y_m", "z_m"), "position": ("x_m", "y_m", "z_m"),
               "rpy_rad": ("roll_rad", "pitch_rad", "yaw_rad"),
               "rpy_deg": ("roll_deg", "pitch_deg", "yaw_deg"), "rpy": ("roll", "pitch", "yaw"),
               "quaternion_xyzw": QUATERNION_KEYS, "quat": QUATERNION_KEYS}
TARGET_KEYS = frozenset({*(k for keys in POSITION_KEYS for k in keys), *QUATERNION_KEYS,
                         *(k for keys in _JSON_LISTS.values() for k in keys)})
"""Every flat key a target line may use."""


class BadTarget(ServicebotError):
    """A target that cannot be used: missing or malformed numbers, a zero quaternion."""


def parse_axes(text: str | None, has_orientation: bool) -> tuple[str, ...] | None:
    """The orientation axes that matter, from ``--orientation-axes``.

    Returns:
        The axes in roll, pitch, yaw order; None when not given (each target then uses all
        three if it has an orientation, none if not).

    Raises:
        BadTarget: An unknown axis name, or axes without an orientation to take them from.
    """
    if text is None:
        return None
    words = [w.strip().lower() for w in text.split(",") if w.strip()]
    if words in (["none"], []):
        return ()
    if words == ["all"]:
        words = list(AXES)
    unknown = [w for w in words if w not in AXES]
    if unknown:
        raise BadTarget(f"--orientation-axes: '{unknown[0]}' is not an axis; use all, none, "
                        "or a comma list of roll, pitch, yaw (e.g. pitch or roll,pitch)")
    if not has_orientation:
        raise BadTarget("--orientation-axes needs an orientation: give --rpy or --quat")
    return tuple(a for a in AXES if a in words)


_TURN_RAD = 2.0 * math.pi + 1e-9


def make_target(position: Sequence[float], *, rpy: Sequence[float] | None = None,
                quat: Sequence[float] | None = None, deg: bool = False,
                axes: tuple[str, ...] | None = None) -> IkTarget:
    """A target from a position [m] and optionally rpy ([rad], [deg]) or a quaternion."""
    for value in (*position, *(rpy or ()), *(quat or ())):
        if not math.isfinite(value):
            raise BadTarget(f"target value {value} is not a finite number")
    for value in position:
        if abs(value) > MAX_POSITION_M:
            raise BadTarget(f"target position {value:g} m is not a place a robot reaches; "
                            f"give metres within +-{MAX_POSITION_M:g}")
    try:
        rotation = None
        if quat is not None:
            rotation = matrix_from_quaternion(np.array(quat, dtype=float))
        elif rpy is not None:
            angles = np.array(rpy, dtype=float)
            if not deg and np.abs(angles).max() > _TURN_RAD:  # "--rpy 0 90 0" without --deg
                raise BadTarget(f"roll pitch yaw {' '.join(f'{a:g}' for a in rpy)} rad: "
                                "an angle of over a turn (6.28 rad); angles are in radians, "
                                "give --deg for degrees")
            rotation = matrix_from_rpy(np.radians(angles) if deg else angles)
    except BadRotation as exc:
        raise BadTarget(str(exc)) from None
    chosen = (AXES if rotation is not None else ()) if axes is None else axes
    if chosen and rotation is None:
        raise BadTarget("orientation axes are given but the target has no orientation; "
                        "add roll pitch yaw or a quaternion")
    return IkTarget(np.array(position, dtype=float), rotation, chosen)


def row_target(values: Mapping[str, JsonValue], frame: str, *, deg: bool,
               axes: tuple[str, ...] | None) -> IkTarget:
    """A target from a batch line (CSV cells or a JSON object).

    Raises:
        BadTarget: No position, a malformed number, a half-given orientation.
    """
    flat = _flatten(values, frame)
    position = _numbers(flat, _first_present(flat, POSITION_KEYS, "position (x_m y_m z_m)"))
    if all(k in flat for k in QUATERNION_KEYS):
        return make_target(position, quat=_numbers(flat, QUATERNION_KEYS), axes=axes)
    families = ((("roll_rad", "pitch_rad", "yaw_rad"), False),
                (("roll_deg", "pitch_deg", "yaw_deg"), True), (("roll", "pitch", "yaw"), deg))
    for keys, in_deg in families:
        if all(k in flat for k in keys):
            return make_target(position, rpy=_numbers(flat, keys), deg=in_deg, axes=axes)
    # a part of one (roll_rad alone, roll_deg with pitch_rad): no orientation to take
    partial = [k for k in (*QUATERNION_KEYS, *(k for keys, _ in families for k in keys))
               if k in flat]
    if partial:
        raise BadTarget(f"'{partial[0]}' is given without the rest of its orientation; "
                        "give roll pitch yaw (all three in one unit) or qx qy qz qw")
    return make_target(position, axes=axes)


def _flatten(values: Mapping[str, JsonValue], frame: str) -> dict[str, JsonValue]:
    """Flat ``name: value`` from CSV cells or JSON (lists, fk's ``poses``, frame prefixes)."""
    listed = values.get("poses")
    if isinstance(listed, list):
        poses = [p for p in listed if isinstance(p, dict)]
        match = [p for p in poses if p.get("frame") == frame] or (poses if len(poses) == 1
                                                                 else [])
        if not match:
            raise BadTarget(f"the line's poses have no frame '{frame}'")
        values = match[0]
    flat: dict[str, JsonValue] = {}
    prefix = f"{frame}."
    for key, value in values.items():
        key = key[len(prefix):] if key.startswith(prefix) else key
        if key in _JSON_LISTS and isinstance(value, list):
            if len(value) != len(_JSON_LISTS[key]):
                raise BadTarget(f"'{key}' has {len(value)} numbers, not "
                                f"{len(_JSON_LISTS[key])}")
            flat.update(zip(_JSON_LISTS[key], value, strict=True))
        else:
            flat[key] = value
    return flat


def _first_present(flat: Mapping[str, JsonValue], options: Sequence[Sequence[str]],
                   what: str) -> Sequence[str]:
    for keys in options:
        if all(k in flat for k in keys):
            return keys
    raise BadTarget(f"the line has no {what}")


def _numbers(flat: Mapping[str, JsonValue], keys: Sequence[str]) -> list[float]:
    return [number(flat[k], f"'{k}'") for k in keys]
