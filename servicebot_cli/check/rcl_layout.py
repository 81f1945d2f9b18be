"""Where rcl refuses a parameters file for its layout: a value that belongs to no node.

rcl's parameter file reader (``rcl_yaml_param_parser``, ``parse_file_events``) walks the YAML
events with a level: above ``ros__parameters`` every key is a namespace or a node name, and a
value there ("Cannot have a value before ros__parameters at line N"), or a list ("Sequences can
only be values and not keys in params"), makes it refuse the whole file; ros2_control_node
then does not start. So does a ``ros__parameters`` with nothing under it, or one no node name
comes before. The usual causes: ``use_sim_time: true`` beside a node's ``ros__parameters``
instead of under it, and ROS 1's ``NAME: type: ...``. Pure: YAML events in, one issue out.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

import yaml  # type: ignore[import-untyped]  # PyYAML ships no types

from servicebot_cli.check.findings import Issue
from servicebot_cli.check.rcl_names import name_refusal, valid_node_name
from servicebot_cli.check.substitutions import substituted

_PARAMETERS_KEY = "ros__parameters"  # rcl compares the key's start: PARAMS_KEY's length
_REFUSED = "rcl refuses the whole file ('{said} at line {line}'), so ros2_control_node " \
           "cannot load it"


@dataclass
class _Walk:
    """rcl's state between events: its map level, depths and namespace counts."""

    in_parameters: bool = False
    depth: int = 0
    named_at: list[yaml.ScalarEvent] = field(default_factory=list)  # namespaces' and node's keys
    parameter_namespaces: int = 0
    expecting_key: bool = True
    in_list: bool = False
    new_mapping: bool = False
    parameters_of: dict[str, int] = field(default_factory=dict)
    node: str = ""
    keys: list[str] = field(default_factory=list)  # the key of each open mapping, for messages
    opened: list[tuple[str, yaml.MappingStartEvent]] = field(default_factory=list)
    keyed: list[bool] = field(default_factory=list)  # whether each open mapping has a key

    @property
    def namespaces(self) -> list[str]:
        """The node's namespaces and name as rcl keeps them, from their keys."""
        return [str(key.value) for key in self.named_at]
    emptied: tuple[str, yaml.MappingStartEvent] | None = None
    last_empty: tuple[str, yaml.MappingStartEvent] | None = None


def layout_issue(events: Iterable[yaml.Event], display: str) -> Issue | None:
    """SB601 for the first value rcl finds outside every node's ``ros__parameters``."""
    walk = _Walk()
    for event in events:
        if isinstance(event, yaml.ScalarEvent):
            found = _scalar(walk, event, display)
        elif isinstance(event, yaml.SequenceStartEvent):
            found = _list_start(walk, event, display)
        elif isinstance(event, yaml.SequenceEndEvent):
            walk.in_list, walk.expecting_key = False, True
            found = None
        elif isinstance(event, yaml.MappingStartEvent):
            if walk.in_list:
                return None  # a mapping in a list: rcl reads it as values, past this replay
            _mapping_start(walk, event)
            found = None
        elif isinstance(event, yaml.MappingEndEvent):
            _mapping_end(walk)
            found = None
        elif isinstance(event, yaml.AliasEvent):
            return None  # rcl refuses aliases first: controller_sections says so
        else:
            found = None
        if found is not None:
            return found
    return None


def _scalar(walk: _Walk, event: yaml.ScalarEvent, display: str) -> Issue | None:
    line = event.start_mark.line + 1
    if walk.expecting_key:
        if not event.value:
            return Issue("SB601", "an empty key: " + _REFUSED.format(said="No key", line=line),
                         where=_at(display, event), fix="name it, or remove it")
        walk.expecting_key = False
        if walk.keyed:
            walk.keyed[-1] = True
        del walk.keys[max(walk.depth - 1, 0):]
        walk.keys.append(str(event.value))
        if walk.in_parameters:
            if walk.new_mapping:
                if not walk.parameters_of.get(walk.node, 0):  # a node's section nested deeper
                    return _nested_section(walk, event, display)
                walk.parameter_namespaces += 1
                walk.new_mapping = False
            walk.parameters_of[walk.node] = walk.parameters_of.get(walk.node, 0) + 1
            return None
        if not str(event.value).startswith(_PARAMETERS_KEY):
            walk.named_at.append(event)
            return None
        if not walk.namespaces:
            said = f"There are no node names before {_PARAMETERS_KEY}"
            owner = ".".join(walk.keys[:-1])
            if owner:  # the node's name went with its first ros__parameters
                return Issue("SB601", f"a second '{event.value}' under '{owner}': "
                             + _REFUSED.format(said=said, line=line), where=_at(display, event),
                             fix="merge the two into one")
            return Issue("SB601", f"'{event.value}' at the top of the file, under no node name: "
                         + _REFUSED.format(said=said, line=line), where=_at(display, event),
                         fix=f"put it under the node's name: NAME: {_PARAMETERS_KEY}:")
        walk.node = _joined(walk.namespaces)
        refused = _node_name_refusal(walk.node, walk.named_at[-1], display)
        if refused is not None:
            return refused
        walk.parameters_of.setdefault(walk.node, 0)
        walk.named_at.pop()
        walk.in_parameters = True
        return None
    if walk.in_parameters and walk.parameters_of.get(walk.node, 0):
        if no_value(event):  # 'name:' and nothing: no value at all
            key = walk.keys[-1] if walk.keys else "?"
            return Issue("SB601", f"'{key}' has no value: " + _REFUSED.format(
                said="No value", line=line), where=_at(display, event),
                fix="give it a value ('' for an empty string), or remove it")
        if not walk.in_list:
            walk.expecting_key = True
        return None
    said = f"Cannot have a value before {_PARAMETERS_KEY}"
    if walk.in_parameters:  # ros__parameters: itself holds the value, or nothing
        what = (f"'{walk.node}: {_PARAMETERS_KEY}:' holds no parameters"
                + (f" but the value '{event.value}'" if event.value else ""))
        return Issue("SB601", f"{what}: " + _REFUSED.format(said=said, line=line),
                     where=_at(display, event),
                     fix="write the node's parameters under it, or remove the section")
    if walk.emptied is not None:
        empty, mark = walk.emptied
        return Issue("SB601", f"'{empty}: {{}}', an empty mapping, ends the parameters of "
                     f"'{walk.node}' for rcl: the value at line {line} after it is outside "
                     f"every {_PARAMETERS_KEY}, and " + _REFUSED.format(said=said, line=line),
                     where=_at(display, mark), fix="remove the empty mapping, or give it a "
                     "parameter")
    key, owner = walk.keys[-1] if walk.keys else "?", ".".join(walk.keys[:-1])
    placed = f"under '{owner}' but outside its {_PARAMETERS_KEY}" if owner else \
        "at the top of the file, under no node"
    return Issue("SB601", f"'{key}: {event.value}' is {placed}: "
                 + _REFUSED.format(said=said, line=line), where=_at(display, event),
                 fix=f"move it under the node's {_PARAMETERS_KEY}:")


def _nested_section(walk: _Walk, event: yaml.ScalarEvent, display: str) -> Issue:
    """SB601 for a node's section indented under another's (beside its ros__parameters).

    rcl takes its ros__parameters' first key for a parameter namespace of a node that has no
    parameter yet: 'Internal error creating param namespace'.
    """
    owner = ".".join(walk.keys[:-3]) or "another node"
    said = "Internal error creating param namespace"
    return Issue("SB601", f"the section '{walk.node}' is indented under '{owner}', beside its "
                 f"{_PARAMETERS_KEY}: " + _REFUSED.format(said=said,
                                                          line=event.start_mark.line + 1),
                 where=_at(display, event), fix=f"move '{walk.node}:' to the top level, "
                 "unindented")


def _joined(names: list[str]) -> str:
    """The node's name from its keys, as rcl joins them: one '/' between, none doubled."""
    path = names[0]
    for name in names[1:]:
        path += name if path.endswith("/") else f"/{name}"
    return path


def no_value(scalar: yaml.Node | yaml.Event | None) -> bool:
    """Whether ``scalar`` (a node or an event) is a plain nothing (``name:``): 'No value'."""
    return isinstance(scalar, yaml.ScalarNode | yaml.ScalarEvent) and scalar.style is None \
        and not scalar.value


def _node_name_refusal(path: str, event: yaml.ScalarEvent, display: str) -> Issue | None:
    """SB601 for a node name rcl refuses, and with it the file (:mod:`.rcl_names`).

    A launch file's placeholders are left to the launch file.
    """
    said = None if substituted(path) else name_refusal(path)
    if said is None:
        return None
    name = path.rpartition("/")[2]
    what = (f"'{name[:40]}...' is longer than the 255 characters rmw takes for a node's name"
            if "length" in said else
            f"'{name}' names no node rcl accepts (letters, digits and '_', not a digit first)"
            if said.startswith("node name") else f"the node name '{path}' has a namespace rcl "
            "refuses")
    fix = (f"name it '{valid_node_name(name)}' (and wherever it is declared)"
           if said.startswith("node name") else "write each namespace in letters, digits and "
           "'_' (not a digit first), one '/' between them")
    return Issue("SB601", f"{what}: rcl refuses the whole file ('{said}'), so ros2_control_node "
                 "cannot load it", where=_at(display, event), fix=fix)


def _list_start(walk: _Walk, event: yaml.SequenceStartEvent, display: str) -> Issue | None:
    if walk.expecting_key:
        return None  # a list as a key: controller_sections says rcl refuses it
    if not walk.in_parameters:
        line = event.start_mark.line + 1
        key = walk.keys[-1] if walk.keys else "?"
        said = "Sequences can only be values and not keys in params. Error"
        return Issue("SB601", f"the list '{key}' is outside every node's {_PARAMETERS_KEY}: "
                     + _REFUSED.format(said=said, line=line), where=_at(display, event),
                     fix=f"move it under the node's {_PARAMETERS_KEY}:")
    walk.in_list = True
    return None


def _mapping_start(walk: _Walk, event: yaml.MappingStartEvent) -> None:
    walk.opened.append((walk.keys[-1] if walk.keys else "?", event))
    walk.keyed.append(False)
    walk.depth += 1
    walk.new_mapping = walk.expecting_key = True
    if walk.in_parameters and walk.depth - (len(walk.named_at) + 1) == 2:
        walk.new_mapping = False  # the ros__parameters mapping itself


def _mapping_end(walk: _Walk) -> None:
    opened = walk.opened.pop() if walk.opened else None
    if walk.keyed and not walk.keyed.pop() and walk.in_parameters:  # it had no key: empty
        walk.last_empty = opened
    if walk.in_parameters:
        if walk.parameter_namespaces:
            walk.parameter_namespaces -= 1
        else:
            walk.in_parameters = False
            if walk.depth - (len(walk.named_at) + 1) != 2:  # not ros__parameters' own end
                walk.emptied = walk.last_empty or opened  # an empty mapping ended them
    elif walk.depth == len(walk.named_at) + 1 and walk.named_at:
        walk.named_at.pop()
    walk.depth -= 1


def _at(display: str, event: yaml.Event) -> tuple[str, int, int]:
    return (display, event.start_mark.line + 1, event.start_mark.column + 1)
