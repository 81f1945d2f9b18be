"""The kinematic tree as a graph: Graphviz dot and Mermaid.

Both draw the graph urdf_to_graphviz draws, links as nodes and joints as edges from parent to
child, with each joint's name, motion and limits on its edge. Mermaid needs nothing
installed: GitHub renders a ``mermaid`` code block.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from servicebot_cli.output import describe as d

if TYPE_CHECKING:
    from servicebot_cli.inspect.joints import JointInfo
    from servicebot_cli.inspect.report import TreeInfo


def edge_label(joint: JointInfo) -> list[str]:
    """The lines written on a joint's edge: name, motion, limits (when it has them)."""
    lines = [joint.name, d.joint_motion(joint.type, joint.axis)]
    if joint.limits is not None:
        lines.append(d.joint_limits(joint.limits))
    return lines


def _links(tree: TreeInfo) -> list[str]:
    return [row.link for row in tree.tree.rows()] + list(tree.unreachable)


def _dot_id(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def dot_lines(tree: TreeInfo, robot: str) -> Iterator[str]:
    """A Graphviz digraph: ``dot -Tpng`` draws it."""
    yield f"digraph {_dot_id(robot)} {{"
    yield "  rankdir=TB;"
    yield '  node [shape=box, style="rounded,filled", fillcolor="#f2f2f2", fontname="Helvetica"];'
    yield '  edge [fontname="Helvetica", fontsize=10];'
    for link in _links(tree):
        # graphviz draws a name starting with '%' as an id of its own ('%3'): label it
        label = f" [label={_dot_id(link)}]" if link.startswith("%") else ""
        yield f"  {_dot_id(link)}{label};"
    for joint in tree.edges:
        label = _dot_id("\n".join(edge_label(joint))).replace("\n", "\\n")
        style = ', style="dashed"' if joint.type == "fixed" else ""
        yield f"  {_dot_id(joint.parent or '')} -> {_dot_id(joint.child or '')} " \
              f"[label={label}{style}];"
    yield "}"


def _mermaid_text(text: str) -> str:
    """Text safe inside a quoted Mermaid label (entity codes for the special characters)."""
    for char, code in (("#", "#35;"), ("&", "#38;"), ('"', "#quot;"), ("<", "#lt;"),
                       (">", "#gt;"), ("|", "#124;")):
        text = text.replace(char, code)
    return text


def mermaid_lines(tree: TreeInfo) -> Iterator[str]:
    """A Mermaid flowchart, top down; node ids are generated, names are labels."""
    ids = {link: f"n{i}" for i, link in enumerate(_links(tree))}
    yield "flowchart TD"
    for link, node in ids.items():
        yield f'  {node}["{_mermaid_text(link)}"]'
    for joint in tree.edges:
        label = "<br/>".join(_mermaid_text(line) for line in edge_label(joint))
        arrow = "-.->" if joint.type == "fixed" else "-->"
        yield f'  {ids[joint.parent or ""]} {arrow}|"{label}"| {ids[joint.child or ""]}'
