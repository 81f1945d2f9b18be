"""Whether rcl takes a parameters file's node name, as its ``_validate_name`` does.

Before each ``ros__parameters`` rcl checks the name the keys above it make
(``ns/node``, ``/**/controller_manager``): ``/**`` and ``/*`` alone pass; else each namespace
token must be one rmw takes (``rmw_validate_namespace``: letters, digits and '_', not a digit
first; ``/*`` and ``/**`` are wildcards), no two slashes in a row, and the node's own name too
(``rmw_validate_node_name``; ``*`` and ``**`` are wildcards). A name it refuses makes it refuse
the whole file. Pure.
"""

from __future__ import annotations

import re

_TOKEN = re.compile(r"[A-Za-z0-9_]*")
_MOST_NODE_NAME = 255


def name_refusal(path: str) -> str | None:
    """Why rmw refuses the node name ``path`` (the keys joined by '/'); None: it does not."""
    if path in ("/**", "/*"):
        return None
    namespace, slash, node = path.rpartition("/")
    if slash and namespace:
        absolute = namespace + "/" if namespace.startswith("/") else f"/{namespace}/"
        tokens = absolute[1:-1].split("/") if absolute != "/" else []
        if "" in tokens:
            return f"{absolute} contains repeated forward slash"
        for token in tokens:
            if token in ("*", "**"):
                continue
            if not _TOKEN.fullmatch(token):
                return ("namespace must not contain characters other than alphanumerics, '_', "
                        "or '/'")
            if token[:1].isdigit():
                return "namespace must not have a token that starts with a number"
    if node in ("*", "**"):
        return None
    return node_name_refusal(node)


def node_name_refusal(name: str) -> str | None:
    """rmw_validate_node_name's reason for refusing ``name``, or None."""
    if not name:
        return "node name must not be empty"
    if not _TOKEN.fullmatch(name):
        return "node name must not contain characters other than alphanumerics or '_'"
    if name[0].isdigit():
        return "node name must not start with a number"
    if len(name) > _MOST_NODE_NAME:
        return f"node name length should not exceed '{_MOST_NODE_NAME}'"  # rmw's words
    return None


def valid_node_name(name: str) -> str:
    """``name`` made a node name rmw takes: other characters as '_', '_' before a digit."""
    fixed = re.sub(r"[^A-Za-z0-9_]+", "_", name).strip("_") or "my_controller"
    return (f"_{fixed}" if fixed[0].isdigit() else fixed)[:_MOST_NODE_NAME]
