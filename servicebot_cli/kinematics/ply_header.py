"""The header of a PLY mesh: its format and elements, held against the file's size.

Every count a header declares is checked against the bytes that follow it (each value takes
at least a byte, and a blank in ASCII) before :mod:`~servicebot_cli.kinematics.mesh_ply`
reads a row. Pure.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from servicebot_cli.description.mesh_arrays import MeshFormatError

_MAX_HEADER = 1 << 16
_END_HEADER = re.compile(rb"(?:^|\n)end_header[ \t]*\r?\n")
_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
    "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
    "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}
_FORMATS = {"ascii": "", "binary_little_endian": "<", "binary_big_endian": ">"}


@dataclass(frozen=True)
class PlyProperty:
    """A ``property`` line.

    Attributes:
        name: Its name (``x``, ``vertex_indices``).
        kind: Its numpy type code: ``f4``, ``u1``...
        count_kind: A list's count type; None for a scalar.
    """

    name: str
    kind: str
    count_kind: str | None = None

    def least_bytes(self) -> int:
        """The fewest bytes the property takes in a binary file (an empty list's count)."""
        return np.dtype(self.count_kind or self.kind).itemsize


@dataclass(frozen=True)
class PlyElement:
    """An ``element`` line (``vertex``, ``face``): its declared row count and properties."""

    name: str
    count: int
    properties: tuple[PlyProperty, ...]


def ply_header(data: bytes) -> tuple[str, list[PlyElement], bytes]:
    """The format (numpy byte order, "" for ASCII), the elements and the body of a PLY.

    Raises:
        MeshFormatError: Not a PLY file, or a header line that is not PLY.
    """
    if not data.startswith(b"ply") or data[3:4] not in (b"\n", b"\r"):
        raise MeshFormatError("not a PLY file (no 'ply' line first)")
    end = _END_HEADER.search(data, 0, _MAX_HEADER)
    if end is None:
        raise MeshFormatError("a PLY header without 'end_header'")
    fmt: str | None = None
    elements: list[tuple[str, int, list[PlyProperty]]] = []
    for raw in data[:end.start()].decode("ascii", "replace").splitlines()[1:]:
        words = raw.split()
        if not words or words[0] in ("comment", "obj_info"):
            continue
        if words[0] == "format" and len(words) == 3 and words[1] in _FORMATS:
            fmt = _FORMATS[words[1]]
        elif words[0] == "element" and len(words) == 3 and words[2].isdigit():
            elements.append((words[1], int(words[2]), []))
        elif words[0] == "property" and elements and len(words) == 3 and words[1] in _TYPES:
            elements[-1][2].append(PlyProperty(words[2], _TYPES[words[1]]))
        elif (words[0] == "property" and elements and len(words) == 5 and words[1] == "list"
              and words[2] in _TYPES and words[3] in _TYPES):
            elements[-1][2].append(PlyProperty(words[4], _TYPES[words[3]], _TYPES[words[2]]))
        else:
            raise MeshFormatError(f"a PLY header line that is not PLY: '{' '.join(words)[:60]}'")
    if fmt is None:
        raise MeshFormatError("a PLY header without a known 'format' line")
    return fmt, [PlyElement(n, c, tuple(p)) for n, c, p in elements], data[end.end():]


def check_sizes(fmt: str, elements: list[PlyElement], size: int) -> None:
    """Refuse counts the file cannot hold: each value takes a byte (and a blank, in ASCII).

    Raises:
        MeshFormatError: A count the ``size`` bytes of the body cannot hold.
    """
    need = 0
    for element in elements:
        per_row = (sum(p.least_bytes() for p in element.properties) if fmt
                   else 2 * len(element.properties))
        need += element.count * per_row
        if need > size + 1:
            raise MeshFormatError(f"the header declares {element.count} '{element.name}' "
                                  f"elements, more than the file's {size} bytes hold")
