"""ROS 2 parameter files as ros2_control reads them: each node's parameters, each controller's type.

A file maps node names to ``ros__parameters``, possibly under namespaces (``/**:``, as
irobot_create_control's ``control.yaml``, or ``robot1:``) or keyed by a path
(``/robot1/controller_manager``). A controller's ``type`` is declared under
``controller_manager`` (Humble) or in the controller's own parameters (ros2_control since
Jazzy). ``check controllers`` reads the same layout from YAML nodes, for their lines.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.common.inputs import read_input_text
from servicebot_cli.description.yaml_size import AliasBomb, bounded_document, bounded_documents

NAMESPACE_DEPTH = 3
"""Namespaces looked through above a node's own key."""

MAX_PARAMETERS_BYTES = 10_000_000
"""A parameters file larger than this is not read [bytes]: real ones are a few kB, and a
device such as /dev/zero never ends."""


def read_parameters_file(path: Path, error: type[ServicebotError]) -> Any:
    """One controllers (parameters) file, parsed; given with ``--controllers`` or found.

    Raises:
        error: Unreadable, empty, not YAML, or nested too deep to read (with the line).
    """
    import yaml  # type: ignore[import-untyped]  # PyYAML ships no types

    text = read_input_text(str(path), kind="a ros2_control controllers YAML (--controllers)",
                           error=error, max_bytes=MAX_PARAMETERS_BYTES, allow_empty=False)
    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)  # libyaml's loader, if built
    try:
        try:
            return bounded_document(loader(text))
        except yaml.composer.ComposerError as exc:
            if "expected a single document" not in str(exc):
                raise
        documents = [d for d in bounded_documents(loader(text)) if d is not None]
        if all(isinstance(d, dict) for d in documents):  # several documents: rcl reads them
            merged: dict[Any, Any] = {}  # as one file, a later value winning
            for document in documents:
                merged = overlaid(merged, document)
            return merged
        raise error(f"{path}: several YAML documents (---) that are not all mappings; fix "
                    "the file or give another with --controllers")
    except AliasBomb as exc:
        raise error(f"{path}: {exc}; give another file with --controllers") from None
    except yaml.YAMLError as exc:
        if "nesting depth" not in str(getattr(exc, "problem", "")):  # libyaml's own bound
            mark = getattr(exc, "problem_mark", None)
            line = f":{mark.line + 1}" if mark is not None else ""
            problem = str(getattr(exc, "problem", None) or "").strip()
            tabs = " (YAML indents with spaces, never tabs)" if tab_indented(text, mark) else ""
            raise error(f"{path}{line}: not valid YAML" + (f": {problem}{tabs}" if problem
                                                           else "")
                        + "; fix the file or give another with --controllers") from None
    except RecursionError:  # PyYAML's own composer recurses once per level of nesting
        pass
    raise error(f"{path}: lists and mappings nested too deep to read; is it a controllers "
                "file? Give another with --controllers")


def tab_indented(text: str, mark: Any) -> bool:
    """Whether the line of ``text`` a YAML error's ``mark`` points at is indented by a tab."""
    lines = text.splitlines()
    written = lines[mark.line] if mark is not None and mark.line < len(lines) else ""
    return "\t" in written[:len(written) - len(written.lstrip())]


def overlaid(base: dict[Any, Any], over: dict[Any, Any]) -> dict[Any, Any]:
    """``base`` with ``over``'s parameters set on it (nested mappings overlaid alike)."""
    out = dict(base)
    for key, value in over.items():
        if isinstance(value, dict) and isinstance(out.get(key), dict):
            out[key] = overlaid(out[key], value)
        else:
            out[key] = value
    return out


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

    Those ``controller_manager`` declares, nested or as a dotted ``NAME.type`` key, come
    first (in its order), then those that declare only their own (in file order). Where both
    say, the controller's own word wins, as the spawner (``--param-file``) sets it on the
    controller manager over what that held; so ``check controllers`` reads it.
    """
    manager = nodes.get("controller_manager", {})
    types: dict[str, str] = {}
    for key, value in manager.items():
        if isinstance(value, dict) and isinstance(value.get("type"), str):
            types[str(key)] = value["type"]
        elif str(key).endswith(".type") and isinstance(value, str):  # "NAME.type: T", the
            types[str(key)[:-len(".type")]] = value  # same parameter (Clearpath's control.yaml)
    for name, params in nodes.items():
        if name != "controller_manager" and isinstance(params.get("type"), str):
            types[name] = params["type"]
    return types
