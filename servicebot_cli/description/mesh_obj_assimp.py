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

# a v or vt line holding a number that starts with its point
_DOT_FIRST = re.compile(rb"^[ \t]*(vt?)[ \t]([^\r\n]*(?<![^ \t])\.[0-9][^\r\n]*)\r?$", re.M)
_ASSIMP_NUMBER = re.compile(rb"[0-9+-]|nan|inf", re.I)
_READ_COUNTS = {b"v": (3, 4, 6), b"vt": (2, 3)}  # what Assimp reads; other counts it cannot


def assimp_misread(data: bytes) -> str | None:
    """Why Assimp reads the OBJ ``data`` wrong, naming the first such line; None: it reads it.

    Only a ``v`` or ``vt`` line with a number like ``.1`` is looked at, so a file without
    one costs a search of its bytes.
    """
    if b" ." not in data and b"\t." not in data:
        return None
    for found in _DOT_FIRST.finditer(data):
        keyword, tokens = found[1], found[2].split()
        dotted = [token for token in tokens if token.startswith(b".")]
        counted = sum(_ASSIMP_NUMBER.match(token) is not None for token in tokens)
        if counted in _READ_COUNTS[keyword] or counted + len(dotted) not in _READ_COUNTS[keyword]:
            continue  # read right, or wrong for more than its points
        line = data.count(b"\n", 0, found.start()) + 1
        text = " ".join(found[0].decode("utf-8", "replace").split())
        first = dotted[0].decode("utf-8", "replace")
        effect = "drops the vertex" if keyword == b"v" else "refuses the file"
        return (f"line {line} '{text[:60]}': Assimp (RViz, Gazebo, MoveIt, Pinocchio) does "
                f"not take '{first}' for a number and {effect}; write 0{first}")
    return None
