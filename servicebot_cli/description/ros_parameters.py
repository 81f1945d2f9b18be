"""ROS 2 parameter files as ros2_control reads them: each node's parameters, each controller's type.

A file maps node names to ``ros__parameters``, possibly under namespaces (``/**:``, as
irobot_create_control's ``control.yaml``, or ``robot1:``) or keyed by a path
(``/robot1/controller_manager``). A controller's ``type`` is declared under
``controller_manager`` (Humble) or in the controller's own parameters (ros2_control since
Jazzy). ``check controllers`` reads the same layout from YAML nodes, for their lines.
"""

from __future__ import annotations

from typing import Any

NAMESPACE_DEPTH = 3
"""Namespaces looked through above a node's own key."""

MAX_PARAMETERS_BYTES = 10_000_000
"""A parameters file larger than this is not read [bytes]: real ones are a few kB, and a
device such as /dev/zero never ends."""


def node_parameters(document: Any, depth: int = 0) -> dict[str, dict[str, Any]]:
    """Each node's ``ros__parameters`` by node name (a path's last part), in file order.

    Of two nodes of one name (in two namespaces), the first is kept.
    """
    found: dict[str, dict[str, Any]] = {}
    if not isinstance(document, dict) or depth > NAMESPACE_DEPTH:
        return found
    for key, value in document.items():
        params = value.get("ros__parameters") if isinstance(value, dict) else None
        if isinstance(params, dict):
            found.setdefault(str(key).rstrip("/").rpartition("/")[2], params)
        elif isinstance(value, dict):
            for name, inner in node_parameters(value, depth + 1).items():
                found.setdefault(name, inner)
    return found


def controller_types(nodes: dict[str, dict[str, Any]]) -> dict[str, str]:
    """Each controller's ``type`` by name.

    Those ``controller_manager`` declares come first (in its order), then those that declare
    only their own (in file order). Where both say, the controller's own word wins, as the
    spawner (``--param-file``) sets it on the controller manager over what that held; so
    ``check controllers`` reads it.
    """
    manager = nodes.get("controller_manager", {})
    types = {name: value["type"] for name, value in manager.items()
             if isinstance(value, dict) and isinstance(value.get("type"), str)}
    for name, params in nodes.items():
        if name != "controller_manager" and isinstance(params.get("type"), str):
            types[name] = params["type"]
    return types
