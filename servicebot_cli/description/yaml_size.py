"""How large a YAML document is once its aliases are followed: alias bombs are refused.

Nine levels of ``&a [*b, *b, ...]`` are 500 bytes of YAML and a billion items to whoever
walks them (``check controllers`` took over 60 s and 5 GB on one in ``left_wheel_names``).
PyYAML builds such a document cheaply, sharing what aliases name; the size of the tree a
reader would walk is counted here on the composed nodes, each shared node once. Pure.
"""

from __future__ import annotations

from typing import Any

MOST_NODES = 1_000_000
"""The most items a parameters or scenario document may unfold to (a real one: thousands)."""


def unfolded_nodes(root: Any, most: int = MOST_NODES) -> int | None:
    """The nodes of the tree under ``root`` (a ``yaml.Node``) with aliases followed.

    None when they are over ``most``, or never end (a recursive alias). Each distinct
    node's unfolded size is worked out once, iteratively: a document nested too deep for
    recursion is counted too.
    """
    sizes: dict[int, int] = {}
    entered: set[int] = set()  # on the way down: met again below itself, it is a loop
    stack: list[tuple[Any, bool]] = [(root, False)]
    while stack:
        node, done = stack.pop()
        if id(node) in sizes:
            continue
        children = _children(node)
        if not done:
            if id(node) in entered:
                return None  # &a [*a]: a recursive alias unfolds without end
            entered.add(id(node))
            stack.append((node, True))
            stack.extend((child, False) for child in children if id(child) not in sizes)
            continue
        size = 1 + sum(sizes.get(id(child), 0) for child in children)
        if size > most:
            return None
        sizes[id(node)] = size
    return sizes.get(id(root), 0)


def _children(node: Any) -> list[Any]:
    value = getattr(node, "value", None)
    if not isinstance(value, list):
        return []  # a scalar
    return [part for item in value
            for part in (item if isinstance(item, tuple) else (item,))]


class AliasBomb(ValueError):
    """A YAML document whose aliases unfold past :data:`MOST_NODES` items."""

    def __init__(self) -> None:
        super().__init__(f"its aliases (*name) unfold to over {MOST_NODES:,} items (an alias "
                         "bomb?)")


def bounded_document(loader: Any) -> Any:
    """The one document a PyYAML ``loader`` reads, built once its unfolded size is known.

    The loader is disposed of. PyYAML's own errors pass through.

    Raises:
        AliasBomb: It unfolds past :data:`MOST_NODES` items.
    """
    try:
        node = loader.get_single_node()
        if node is not None and unfolded_nodes(node) is None:
            raise AliasBomb
        return None if node is None else loader.construct_document(node)
    finally:
        loader.dispose()


def bounded_documents(loader: Any) -> list[Any]:
    """Every document a PyYAML ``loader`` reads (``---`` between them), each bounded so.

    Raises:
        AliasBomb: One unfolds past :data:`MOST_NODES` items.
    """
    documents = []
    try:
        while loader.check_node():
            node = loader.get_node()
            if node is not None and unfolded_nodes(node) is None:
                raise AliasBomb
            documents.append(None if node is None else loader.construct_document(node))
        return documents
    finally:
        loader.dispose()
