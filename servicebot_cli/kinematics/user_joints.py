"""Joint values in the user's units: radians or degrees for angles, metres for slides.

``--deg`` changes angles only: a prismatic joint is always in metres. Limits are checked,
and reported, in the unit the user typed. Pure: values in, arrays out.
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Collection, Iterable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.errors import JointNotFound, OutOfLimits, ServicebotError
from servicebot_cli.common.plain_float import plain_float, plainly_written
from servicebot_cli.kinematics.json_types import JsonValue
from servicebot_cli.kinematics.mimics import Mimics, leader_range, rules_of

if TYPE_CHECKING:
    from servicebot_cli.description.joint_space import JointSpace

FloatArray = npt.NDArray[np.float64]
_DIMENSIONS = {"floating": "six", "planar": "three"}


class BadNumber(ServicebotError):
    """A value that is not a finite number, or a joint named twice."""


def angular(space: JointSpace) -> npt.NDArray[np.bool_]:
    """True for each joint whose value is an angle (revolute, continuous)."""
    return np.array([kind != "prismatic" for kind in space.types], dtype=bool)


def unit_of(space: JointSpace, index: int, deg: bool) -> str:
    """``deg``, ``rad`` or ``m`` for joint ``index``."""
    if space.types[index] == "prismatic":
        return "m"
    return "deg" if deg else "rad"


@dataclass(frozen=True)
class Clamped:
    """A joint value ``--clamp`` moved onto a limit, in the user's unit.

    Attributes:
        joint: The joint.
        given: The value given [rad, deg or m].
        limit: The limit used instead, same unit.
        unit: ``rad``, ``deg`` or ``m``.
        side: ``lower`` or ``upper``.
    """

    joint: str
    given: float
    limit: float
    unit: str
    side: str
    because: str = ""
    """A joint that follows this one (``<mimic>``), whose limits moved it; "" for its own."""

    def note(self) -> str:
        """One stderr line: which joint, the value given, the limit used."""
        if self.because:
            return (f"note: --clamp: joint '{self.joint}' = {self.given:g} {self.unit} puts "
                    f"'{self.because}', which mimics it, outside its limits; using "
                    f"{self.limit:g} {self.unit}")
        return (f"note: --clamp: joint '{self.joint}' = {self.given:g} {self.unit} is outside "
                f"its limits; using its {self.side} limit {self.limit:g} {self.unit}")


def user_vector(space: JointSpace, pairs: Iterable[tuple[str, float]], *, deg: bool = False,
                clamp: bool = False, mimics: Mimics | None = None) -> FloatArray:
    """One value per joint [rad or m] from ``(name, value)`` pairs in the user's units.

    Unnamed joints stay at zero (even where zero is outside their limits, as for Panda's
    fourth joint: see :func:`unnamed_outside`), or follow their leader when ``mimics`` says
    they mimic one. Only the values the user gave are checked against the limits.

    Raises:
        JointNotFound: An unknown name, nearest names first.
        BadNumber: A joint named twice.
        OutOfLimits: A given value outside its limits (unless ``clamp``), in the user's unit.
    """
    return clamped_user_vector(space, pairs, deg=deg, clamp=clamp, mimics=mimics)[0]


def clamped_user_vector(space: JointSpace, pairs: Iterable[tuple[str, float]], *,
                        deg: bool = False, clamp: bool = False, mimics: Mimics | None = None,
                        fixed: Collection[str] | Mapping[str, str] = ()
                        ) -> tuple[FloatArray, tuple[Clamped, ...]]:
    """As :func:`user_vector`, with what ``clamp`` moved onto a limit, joint by joint.

    ``fixed`` names the robot's joints that take no single value (fixed, floating, planar;
    with their types, when a mapping): giving one a value is refused as such.

    Raises:
        JointNotFound: An unknown name, nearest names first; a fixed joint, as fixed.
        BadNumber: A joint named twice.
        OutOfLimits: A given value outside its limits (unless ``clamp``), in the user's unit.
    """
    assignments: dict[str, float] = {}
    for name, value in pairs:
        if name in assignments:
            raise BadNumber(f"joint '{name}' is given twice; give each joint once")
        if name in fixed and name not in space.names:
            near = difflib.get_close_matches(name, space.names, n=3, cutoff=0.0)
            kind = fixed[name] if isinstance(fixed, Mapping) else "fixed"
            what = "it has no value to give" if kind == "fixed" else \
                f"it moves in {_DIMENSIONS.get(kind, 'several')} dimensions, not by one value"
            raise JointNotFound(f"joint '{name}' is {kind}: {what}; name a joint of one degree "
                                f"of freedom ({', '.join(near)}, ...)")
        assignments[name] = value
    values = np.zeros(len(space.names))
    named = np.zeros(len(space.names), dtype=bool)
    for name, value in assignments.items():
        values[space.index(name)] = value
        named[space.index(name)] = True
    if deg:
        values = np.where(angular(space), np.radians(values), values)
    if mimics is not None and mimics.follower:
        values = mimics.apply(values, assignments, space)
        for follower, leader in zip(mimics.follower, mimics.leader, strict=True):
            named[follower] |= named[leader]  # in rule order: a follower's follower too
    if clamp:
        held = {} if mimics is None else _hold_leaders(
            space, values, named, rules_of(mimics, assignments, space))
        inside = space.clamped(values)
        return np.where(named, inside, values), _clamped(space, values, inside, named, deg,
                                                         held)
    inside = space.clamped(values)
    probe = np.where(named, values, inside)
    try:
        space.checked(probe)
    except OutOfLimits:
        raise _out_of_limits(space, probe, deg, rules_of(mimics, assignments, space)) from None
    return values, ()


def _hold_leaders(space: JointSpace, values: FloatArray, named: npt.NDArray[np.bool_],
                  rules: Mapping[int, tuple[int, float, float]]) -> dict[int, tuple[float, str]]:
    """Bring each given leader, in place, where it and every joint that follows it are in limits.

    ``--clamp`` clamping a follower, or its leader, alone would break ``<mimic>``: a pose no
    robot takes (PR2's gripper, whose mirrored parallel links allow only 0). The leader is
    clamped into the range where it and its followers are all within their limits, when
    there is one, and the followers set from it again. Returns, for each leader moved, the
    value given and the follower whose limits moved it ("" for its own).
    """
    held: dict[int, tuple[float, str]] = {}
    for root in sorted({root for root, _, _ in rules.values()}):
        if not named[root]:
            continue
        given = float(values[root])
        low, high = space.lower[root], space.upper[root]
        low, high = (-math.inf, math.inf) if math.isnan(low) else (low, high)
        by_low = by_high = ""  # the follower whose limits set each end; "" for its own
        for follower, (lead, k, c) in rules.items():
            if lead != root or k == 0.0 or math.isnan(space.lower[follower]):
                continue
            ends = leader_range(space, follower, k, c)
            if ends[0] > low:
                low, by_low = ends[0], space.names[follower]
            if ends[1] < high:
                high, by_high = ends[1], space.names[follower]
        if low > high or low <= given <= high:
            continue  # no value suits them all (each is clamped alone), or it is in range
        values[root] = min(max(given, low), high) + 0.0
        held[root] = (given, by_low if given < low else by_high)
        for follower, (lead, k, c) in rules.items():
            if lead == root:
                values[follower] = k * values[root] + c
    return held


def _clamped(space: JointSpace, values: FloatArray, inside: FloatArray,
             named: npt.NDArray[np.bool_], deg: bool,
             held: Mapping[int, tuple[float, str]]) -> tuple[Clamped, ...]:
    """The named joints whose value ``inside`` moved by more than the limits' slack.

    A leader ``held`` by a follower is said so, from the value given; its followers, which
    follow it, are not.
    """
    given = values.copy()
    for leader, (value, _) in held.items():
        given[leader] = value
    moved = named & (np.abs(given - inside) > 1e-9)
    out = []
    for i in np.flatnonzero(moved):
        scale = math.degrees(1.0) if deg and space.types[i] != "prismatic" else 1.0
        side = "lower" if given[i] < inside[i] else "upper"
        out.append(Clamped(space.names[i], float(given[i] * scale), float(inside[i] * scale),
                           unit_of(space, int(i), deg), side, held.get(int(i), (0.0, ""))[1]))
    return tuple(out)


def unnamed_outside(space: JointSpace, values: FloatArray) -> list[str]:
    """Joints whose value lies outside their limits (after :func:`user_vector`: unnamed ones)."""
    with np.errstate(invalid="ignore"):
        outside = (values < space.lower - 1e-9) | (values > space.upper + 1e-9)
    return [name for name, out in zip(space.names, outside, strict=True) if out]


def _out_of_limits(space: JointSpace, values: FloatArray, deg: bool,
                   rules: Mapping[int, tuple[int, float, float]]) -> OutOfLimits:
    """The first joint outside its limits; a follower's names the leader that put it there."""
    scale = np.where(angular(space), math.degrees(1.0) if deg else 1.0, 1.0)
    for i, value in enumerate(values):
        lo, hi = space.lower[i], space.upper[i]
        if not math.isnan(lo) and not lo - 1e-9 <= value <= hi + 1e-9:
            unit = unit_of(space, i, deg)
            where = (f"joint '{space.names[i]}' = {value * scale[i]:g} {unit} is outside its "
                     f"limits [{lo * scale[i]:g}, {hi * scale[i]:g}] {unit}")
            if i not in rules:
                return OutOfLimits(f"{where}; give a value inside them, or --clamp")
            lead, k, c = rules[i]
            leader = space.names[lead]
            factor = k * scale[i] / scale[lead]  # in the units shown: deg to m, say
            offset = c * scale[i]
            sign = "-" if offset < 0 else "+"
            return OutOfLimits(
                f"{where}: it mimics '{leader}' = {values[lead] * scale[lead]:g} "
                f"{unit_of(space, lead, deg)} (x {factor:g} {sign} {abs(offset):g} {unit}); "
                f"give '{leader}' a value that keeps it inside, or --clamp")
    return OutOfLimits("a joint value is outside its limits")  # not reached: checked() failed


def user_values(space: JointSpace, values: FloatArray, *, deg: bool = False) -> dict[str, float]:
    """``{name: value}`` in the user's units from one value per joint [rad or m]."""
    shown = np.where(angular(space), np.degrees(values), values) if deg else values
    return {name: float(v) for name, v in zip(space.names, shown, strict=True)}


def number(value: JsonValue, what: str) -> float:
    """A finite float from a CSV cell (text) or a JSON value (a number).

    Raises:
        BadNumber: Empty, not a number, or not finite; the message names ``what``.
    """
    if isinstance(value, bool) or value is None:
        raise BadNumber(f"{what} is {str(value).lower() if value is not None else 'null'}, "
                            "not a number")
    if isinstance(value, str):
        if not value.strip():
            raise BadNumber(f"{what} is empty; give a number")
        try:
            value = plain_float(value)
        except ValueError:
            raise BadNumber(f"{what} is '{value}', not a number") from None
    if not isinstance(value, int | float):
        raise BadNumber(f"{what} is not a number")
    try:
        number = float(value)  # an integer of 400 digits is beyond a double
    except OverflowError:
        raise BadNumber(f"{what} is an integer beyond any double, not a finite number") from None
    if not math.isfinite(number):
        raise BadNumber(f"{what} is {value}, not a finite number")
    return number


def row_pairs(values: Mapping[str, JsonValue],
              ignore: Iterable[str] = ()) -> list[tuple[str, float]]:
    """``(joint, value)`` pairs of a batch row, each value checked to be a number.

    Keys in ``ignore`` (result columns such as ``line`` or ``success``) are left out. All
    values are converted at once; a row with a bad one goes one by one, for the message.
    """
    skip = set(ignore)
    names = [name for name in values if name not in skip]
    raw = [values[name] for name in names]
    if all(type(v) is float or type(v) is int or type(v) is str and plainly_written([v])
           for v in raw):
        try:
            numbers = np.array(raw, dtype=float)
        except (ValueError, OverflowError):  # one by one below, for the message
            numbers = None
        if numbers is not None and np.isfinite(numbers).all():
            return list(zip(names, numbers.tolist(), strict=True))
    return [(name, number(value, f"joint '{name}'")) for name, value in zip(names, raw,
                                                                           strict=True)]
