"""Joint columns that say their unit: how ``ik`` writes joint values and ``fk`` reads them.

Every other batch column carries its unit (``x_m``, ``roll_deg``, ``base_yaw_deg``); joint
columns do too when their values are in degrees: ``NAME_deg``, and ``NAME_m`` for a
prismatic joint (always in metres). In radians a joint's column is its bare name, as it has
always been, so files written before keep their meaning. A JSON Lines result says
``"angle_unit"`` beside its ``joints`` object.

Reading, a column that names its unit is read in it, whatever ``--deg`` says; a bare name
is read in the unit the line states (``angle_unit``), else in the unit ``--deg`` gives.
Units that disagree (``a_deg`` beside ``b_rad``, or a bare ``b`` that the flags would read in
another unit than ``a_deg`` states) are refused: a guess would give another pose. Pure.
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.kinematics.json_types import JsonValue
from servicebot_cli.kinematics.user_joints import unit_of

if TYPE_CHECKING:
    from servicebot_cli.description.joint_space import JointSpace

ANGLE_UNITS = ("deg", "rad")
_WORDS = {"deg": "degrees", "rad": "radians"}


class UnitConflict(ServicebotError):
    """Joint values whose units disagree, or a unit that does not fit its joint."""


def joint_column_names(space: JointSpace, deg: bool) -> dict[str, str]:
    """Each joint's column: its name in radians; ``NAME_deg`` or ``NAME_m`` in degrees."""
    if not deg:
        return {name: name for name in space.names}
    return {name: f"{name}_{unit_of(space, k, deg)}" for k, name in enumerate(space.names)}


def angle_unit(value: JsonValue) -> str:
    """A line's ``angle_unit``: ``deg`` or ``rad``.

    Raises:
        UnitConflict: Any other value.
    """
    if isinstance(value, str) and value in ANGLE_UNITS:
        return value
    raise UnitConflict(f"angle_unit is {json.dumps(value)}; give \"deg\" or \"rad\" (or leave "
                       "it out: --deg then says)")


def joint_of(name: str, space: JointSpace) -> tuple[str, str | None]:
    """The joint a column names, and the unit it states: ``(name, None)`` for a bare name.

    A name that is neither a joint nor ``JOINT_deg``, ``JOINT_rad`` or ``JOINT_m`` is given
    back unchanged (the caller refuses it as an unknown joint). A joint's own name wins over
    a suffix: a joint named ``wrist_deg`` is that joint.

    Raises:
        UnitConflict: A unit that does not fit the joint (``slider_deg``, ``elbow_m``).
    """
    if name in space.names:
        return name, None
    stem, _, unit = name.rpartition("_")
    if unit not in (*ANGLE_UNITS, "m") or stem not in space.names:
        return name, None
    kind = space.types[space.names.index(stem)]
    if (kind == "prismatic") != (unit == "m"):
        fits = f"'{stem}_m' or '{stem}'" if kind == "prismatic" else \
            f"'{stem}_deg' or '{stem}_rad'"
        what = "in metres" if kind == "prismatic" else "an angle"
        raise UnitConflict(f"'{name}': joint '{stem}' is {kind}, {what}; name the column {fits}")
    return stem, unit


@dataclass(frozen=True)
class ColumnUnits:
    """How a line names its joints, and the unit of its angles.

    Attributes:
        joints: Column to joint, for the columns that state a unit (others are their joint).
        deg: The line's joint angles are in degrees.
    """

    joints: Mapping[str, str]
    deg: bool

    def joint(self, column: str) -> str:
        """The joint ``column`` names (an unknown name as it is)."""
        return self.joints.get(column, column)


def read_units(names: Iterable[str], space: JointSpace, *, deg: bool,
               line_unit: str | None = None,
               declared: Sequence[tuple[str, str]] = ()) -> ColumnUnits:
    """The joints and the angle unit of a line whose joint columns (or keys) are ``names``.

    Args:
        names: Joint columns: bare joint names, ``JOINT_deg``/``_rad``/``_m``, or unknown
            names (left for the caller to refuse).
        space: The robot's joints.
        deg: ``--deg``: bare angles in degrees when the line does not state a unit.
        line_unit: The line's ``angle_unit`` (see :func:`angle_unit`); None: not stated.
        declared: Other columns that state an angle unit, as ``(what, unit)`` such as
            ``("'base_yaw_deg'", "deg")``.

    Raises:
        UnitConflict: A unit that does not fit its joint, a joint given by two columns, two
            units, or bare angles that ``--deg`` (or its absence) would read in another unit
            than the line states.
    """
    joints: dict[str, str] = {}
    said = [("angle_unit is \"" + line_unit + "\"", line_unit)] if line_unit else []
    said += [(f"{what} is in {_WORDS[unit]}", unit) for what, unit in declared]
    bare: list[str] = []
    column_of: dict[str, str] = {}
    for name in names:
        joint, unit = joint_of(name, space)
        if joint in column_of:
            raise UnitConflict(f"'{column_of[joint]}' and '{name}' both give joint '{joint}'; "
                               "give it once")
        column_of[joint] = name
        if unit is not None:
            joints[name] = joint
            if unit != "m":
                said.append((f"'{name}' is in {_WORDS[unit]}", unit))
        elif joint in space.names and space.types[space.names.index(joint)] != "prismatic":
            bare.append(name)
    stated = [unit for _, unit in said]
    if len(set(stated)) > 1:
        first = said[0]
        other = next(s for s in said if s[1] != first[1])
        raise UnitConflict(f"joint angles in two units: {first[0]}, {other[0]}; give them all "
                           "in one unit")
    unit = stated[0] if stated else "deg" if deg else "rad"
    flags = "deg" if deg else "rad"
    if bare and line_unit is None and unit != flags:
        how = "--deg reads it in degrees" if deg else "it is read in radians without --deg"
        way = "drop --deg" if deg else "give --deg"
        raise UnitConflict(f"'{bare[0]}' has no unit, so {how}, but {said[0][0]}; {way}, or "
                           f"name it '{bare[0]}_{unit}'")
    return ColumnUnits(joints, unit == "deg")
