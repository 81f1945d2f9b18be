"""OBJ lines Assimp reads wrong: a number written without a digit before its point.

Assimp, the mesh reader of RViz, Gazebo, MoveIt and Pinocchio (through coal), decides how
many numbers a ``v`` or ``vt`` line holds by the first character of each: a digit, a sign,
or ``nan``/``inf``. ``.1`` is not counted, so ``v .1 0 0`` holds two numbers for it and the
vertex is dropped (every later index then names the wrong vertex, and the last ones none:
"vertex index out of range"); ``vt .5 0.5`` refuses the file. numpy, trimesh and this
project's reader take ``.1`` as 0.1. Pure.
"""

from __future__ import annotations

import re
from collections.abc import Iterator

_ASSIMP_NUMBER = re.compile(rb"[0-9+-]|nan|inf", re.I)
_READ_COUNTS = {b"v": (3, 4, 6), b"vt": (2, 3)}  # what Assimp reads; other counts it cannot


def assimp_misread(data: bytes) -> str | None:
    """Why Assimp reads the OBJ ``data`` wrong, naming the first such line; None: it reads it.

    Only the lines holding a blank, a point and a digit are looked at (each found by a byte
    search), so a file without one costs a search of its bytes: ``mtllib ./x.mtl`` does not
    send the whole file through a regular expression.
    """
    for start, line in _dotted_lines(data):
        tokens = line.split()
        keyword = tokens[0] if tokens else b""
        if keyword not in _READ_COUNTS:
            continue
        tokens = tokens[1:]
        dotted = [token for token in tokens if token.startswith(b".")]
        counted = sum(_ASSIMP_NUMBER.match(token) is not None for token in tokens)
        if counted in _READ_COUNTS[keyword] or counted + len(dotted) not in _READ_COUNTS[keyword]:
            continue  # read right, or wrong for more than its points
        number = data.count(b"\n", 0, start) + 1
        text = " ".join(line.decode("utf-8", "replace").split())
        first = dotted[0].decode("utf-8", "replace")
        effect = "drops the vertex" if keyword == b"v" else "refuses the file"
        return (f"line {number} '{text[:60]}': Assimp (RViz, Gazebo, MoveIt, Pinocchio) does "
                f"not take '{first}' for a number and {effect}; write 0{first}")
    return None


def _dotted_lines(data: bytes) -> Iterator[tuple[int, bytes]]:
    """Each line (its start and its bytes) holding a blank before a point before a digit."""
    seen = -1
    for blank in (b" .", b"\t."):
        at = data.find(blank)
        while at >= 0:
            if data[at + 2:at + 3].isdigit():
                start = max(data.rfind(b"\n", 0, at), data.rfind(b"\r", 0, at)) + 1
                end = data.find(b"\n", at)
                end = len(data) if end < 0 else end
                if start != seen:
                    seen = start
                    yield start, data[start:end].rstrip(b"\r")
                at = data.find(blank, end)
            else:
                at = data.find(blank, at + 2)
