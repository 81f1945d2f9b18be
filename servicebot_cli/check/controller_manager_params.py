"""SB608 for controller_manager's own parameters, and for a controller declared without a type.

controller_manager declares ``update_rate`` an integer (Humble reads it into an int; from
Jazzy on, ``controller_manager_parameters.yaml`` also wants it above 0, and it is read-only):
a string or a double stops the node at start. A controller it declares with no ``type``
(``joint_state_broadcaster: {}``), written nowhere else either, it cannot load ("The 'type'
param was not defined"), so the spawner fails. Pure: YAML nodes in, issues out.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import yaml  # type: ignore[import-untyped]  # PyYAML ships no types

from servicebot_cli.check.controller_params import (
    TYPE_ARTICLE,
    c_integer,
    rcl_number,
    rcl_type,
)
from servicebot_cli.check.controller_sections import Sections, at, get, type_nodes
from servicebot_cli.check.findings import Issue
from servicebot_cli.check.rcl_layout import no_value
from servicebot_cli.check.substitutions import substituted

_DECLARED = {"update_rate": "integer", "use_sim_time": "bool", "thread_priority": "integer",
             "enforce_command_limits": "bool"}
_DEFAULTS = {"integer": "100", "bool": "true"}
_OWN_GROUPS = frozenset(("hardware_components_initial_state", "diagnostics", "diagnostic",
                         "defaults", "statistics"))
"""controller_manager's own nested parameters: no controller declarations."""


def manager_issues(found: Sections, display: str) -> Iterator[Issue]:
    """SB608 for each controller_manager parameter of the wrong type, and typeless controller."""
    typed = type_nodes(found)
    for manager in found.get("controller_manager", []):
        for key, wanted in _DECLARED.items():
            node = get(manager, key)
            if no_value(node):
                continue  # rcl refuses the whole file: rcl_layout says so
            if isinstance(node, yaml.ScalarNode) and not substituted(str(node.value)):
                yield from _typed(key, node, wanted, display)
            elif isinstance(node, yaml.SequenceNode):
                yield Issue("SB608", f"controller_manager.{key}: rcl reads a list as an array, "
                            f"and controller_manager declares {TYPE_ARTICLE[wanted]}: the node "
                            "refuses it and does not start", where=at(display, node.start_mark),
                            fix=f"{key}: {_DEFAULTS[wanted]}")
        for key, value in manager.value:
            name = str(key.value) if isinstance(key, yaml.ScalarNode) else ""
            if isinstance(value, yaml.MappingNode) and name not in _OWN_GROUPS \
                    and name not in typed and get(value, "type") is None:
                yield Issue("SB608", f"controller_manager declares '{name}' without a type: it "
                            "cannot load it ('The 'type' param was not defined'), and the "
                            "spawner fails", where=at(display, key.start_mark),
                            fix=f"write {name}: {{type: package/ControllerClass}}")


def _typed(key: str, node: yaml.ScalarNode, wanted: str, display: str) -> Iterator[Issue]:
    got = rcl_type(node)
    where = at(display, node.start_mark)
    if got != wanted:
        plain = str(node.value).strip()
        rounded = _rounded(plain) if wanted == "integer" and got == "double" else None
        fix = (f"{key}: {plain}" if wanted == "integer" and plain.isdigit() and got == "string"
               else f"{key}: {rounded}" if rounded is not None
               else f"{key}: {_DEFAULTS[wanted]}")
        yield Issue("SB608", f"controller_manager.{key}: rcl reads '{node.value}' as "
                    f"{TYPE_ARTICLE[got]}, and controller_manager declares "
                    f"{TYPE_ARTICLE[wanted]}: the node refuses it and does not start",
                    where=where, fix=fix)
    elif key == "update_rate" and (c_integer(str(node.value)) or 0) <= 0:
        yield Issue("SB608", f"controller_manager.update_rate: {node.value}: from Jazzy on the "
                    "controller manager wants a rate above 0 and does not start; Humble's "
                    "loop divides by it", where=where, fix="update_rate: 100")


def _rounded(text: str) -> int | None:
    """``text``, a double rcl read, as the nearest integer of 64 bits; None where none is.

    None for ``.inf``, ``nan`` and 1e400.
    """
    value = rcl_number(text)
    if value is None or not math.isfinite(value) or not -(2 ** 63) <= round(value) < 2 ** 63:
        return None
    return round(value)
