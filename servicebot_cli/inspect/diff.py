"""What differs between two robot descriptions.

Each description becomes a list of elements (links, joints, sensors, plugins, ros2_control
systems and joints, Gazebo properties, materials, transmissions), each a flat mapping from a
field path to a value, built from the same summaries ``inspect`` shows. Numbers are equal
when they agree to 1e-9 relative, so ``0.44`` and ``0.440`` are the same limit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from servicebot_cli.common.jsonable import to_jsonable
from servicebot_cli.inspect.interfaces import interfaces_info
from servicebot_cli.inspect.joints import joint_info
from servicebot_cli.inspect.links import links_info
from servicebot_cli.inspect.plugins import plugins_info
from servicebot_cli.inspect.sensors import sensors_info

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

Facts = dict[str, dict[str, Any]]


@dataclass(frozen=True)
class Difference:
    """One difference.

    Attributes:
        element: What differs: ``joint front_left_wheel_joint``, ``sensor lidar``...
        field: The field path (``limits.velocity``); empty when the whole element is missing.
        change: ``changed`` (in both, different), ``removed`` (only in A), ``added`` (only in B).
        a, b: The values in A and B (None where absent).
        unit: The unit of the values, where the field's name does not carry it.
    """

    element: str
    field: str
    change: str
    a: Any
    b: Any
    unit: str | None = None


@dataclass(frozen=True)
class DiffResult:
    """The differences between descriptions A and B, in A's element order, then B's new ones."""

    a: str
    b: str
    differences: tuple[Difference, ...]

    @property
    def equal(self) -> bool:
        """True when nothing differs."""
        return not self.differences


def _flatten(value: Any, prefix: str = "") -> dict[str, Any]:
    """``{"limits": {"velocity": 1}}`` to ``{"limits.velocity": 1}``; lists of numbers stay."""
    if isinstance(value, dict):
        flat: dict[str, Any] = {}
        for key, item in value.items():
            flat.update(_flatten(item, f"{prefix}{key}."))
        return flat
    if isinstance(value, list) and any(isinstance(v, dict | list) for v in value):
        flat = {}
        for i, item in enumerate(value, start=1):
            flat.update(_flatten(item, f"{prefix}{i}."))
        return flat
    return {prefix.rstrip("."): value}


def _named(params: list[dict[str, str]] | list[list[str]]) -> dict[str, Any]:
    """Parameters by name, numbers as numbers; repeated names (remappings) joined in order."""
    merged: dict[str, list[str]] = {}
    for p in params:
        name, value = (p["name"], p["value"]) if isinstance(p, dict) else p
        merged.setdefault(name, []).append(value)
    return {k: _number(v[0]) if len(v) == 1 else "; ".join(v) for k, v in merged.items()}


def _number(text: str) -> Any:
    """``"0.440"`` as 0.44, so equal numbers written differently compare equal."""
    try:
        return int(text)
    except ValueError:
        pass
    try:
        value = float(text)
    except ValueError:
        return text
    return value if math.isfinite(value) else text


def facts(robot: RobotDescription) -> Facts:
    """Every element of ``robot`` as flat fields, in a stable order."""
    out: Facts = {"robot": {"name": robot.name}}
    for link in links_info(robot.links):
        out[f"link {link.name}"] = _flatten(to_jsonable(link))
    for joint in robot.joints:
        out[f"joint {joint.name}"] = _flatten(to_jsonable(joint_info(joint)))
    for sensor in sensors_info(robot.sensors):
        out[f"sensor {sensor.name}"] = _flatten(to_jsonable(sensor))
    plugins = plugins_info(robot.gazebo, robot.sensors, robot.ros2_control)
    for p in plugins.gazebo:
        out[f"gazebo plugin {p.name} ({p.attached_to})"] = {
            "filename": p.filename, **_flatten(_named(to_jsonable(p.params)), "params.")}
    for block in plugins.gazebo_properties:
        out[f"gazebo {block.reference}"] = _named(to_jsonable(block.properties))
    for h in plugins.ros2_control:
        out[f"ros2_control {h.name}"] = {"type": h.type, "plugin": h.plugin,
                                         **_flatten(_named(to_jsonable(h.params)), "params.")}
    for j in interfaces_info(robot.ros2_control, robot.transmissions).joints:
        out[f"ros2_control {j.system} {j.kind} {j.name}"] = _flatten({
            "command": {i.name: _named(to_jsonable(i.params)) for i in j.command},
            "state": {i.name: _named(to_jsonable(i.params)) for i in j.state}})
    for name, rgba in robot.materials.items():
        out[f"material {name}"] = {"rgba": list(rgba) if rgba else None}
    for t in robot.transmissions:
        out[f"transmission {t.name}"] = {"type": t.type, "joints": list(t.joints),
                                         "actuators": list(t.actuators)}
    return out


def same(a: Any, b: Any) -> bool:
    """Equal, with numbers compared to 1e-9 relative (and 1e-12 absolute)."""
    if isinstance(a, bool) or isinstance(b, bool):
        return bool(a == b)
    if isinstance(a, int | float) and isinstance(b, int | float):
        return math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-12)
    if isinstance(a, list | tuple) and isinstance(b, list | tuple):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b, strict=True))
    return bool(a == b)


def compare_facts(a: Facts, b: Facts, a_name: str, b_name: str) -> DiffResult:
    """Differences between two fact sets."""
    found: list[Difference] = []
    for element in [*a, *(e for e in b if e not in a)]:
        if element not in b:
            found.append(Difference(element, "", "removed", True, None))
        elif element not in a:
            found.append(Difference(element, "", "added", None, True))
        else:
            fa, fb = a[element], b[element]
            for field in [*fa, *(f for f in fb if f not in fa)]:
                va, vb = fa.get(field), fb.get(field)
                if not same(va, vb):
                    change = "added" if field not in fa else "removed" if field not in fb \
                        else "changed"
                    found.append(Difference(element, field, change, va, vb,
                                            _unit(field, fa) or _unit(field, fb)))
    return DiffResult(a_name, b_name, tuple(found))


def _unit(field: str, fields: dict[str, Any]) -> str | None:
    """A joint limit's unit, from the ``limits.units`` beside it."""
    group, _, leaf = field.rpartition(".")
    unit = fields.get(f"{group}.units.{'position' if leaf in ('lower', 'upper') else leaf}")
    return unit if isinstance(unit, str) else None


def compare(a: RobotDescription, b: RobotDescription) -> DiffResult:
    """What differs between descriptions ``a`` and ``b``."""
    return compare_facts(facts(a), facts(b), _label(a), _label(b))


def _label(robot: RobotDescription) -> str:
    args = " ".join(f"{k}:={v}" for k, v in robot.xacro_args)
    return f"{robot.display} {args}".strip()
