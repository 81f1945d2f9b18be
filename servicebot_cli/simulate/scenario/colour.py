"""The ``color`` field of walls, boxes, cylinders, meshes and the floor: what the camera draws.

Two spellings, the same colour: ``[r, g, b]`` with each number in [0, 1] (as a URDF
``<color rgba>`` without the alpha), or the web's ``"#rrggbb"`` (quoted: in YAML an
unquoted ``#`` starts a comment). Shading darkens it as for the defaults.
"""

from __future__ import annotations

import re

from servicebot_cli.simulate.scenario.located import Path
from servicebot_cli.simulate.scenario.schema import Reader

Color = tuple[float, float, float]
_HEX = re.compile(r"#([0-9a-fA-F]{6})")
_EXPECTED = 'expected [r, g, b] with each in 0-1, or "#rrggbb"'


def read_color(r: Reader, path: Path) -> Color | None:
    """The colour at ``path`` as rgb in [0, 1]; None when there is no such key.

    Raises:
        ScenarioError: Not three numbers in [0, 1] nor ``#rrggbb``; or an empty value (an
            unquoted ``#rrggbb`` is a YAML comment).
    """
    parent = r.get(path[:-1]) if r.has(path[:-1]) else None
    if not isinstance(parent, dict) or path[-1] not in parent:
        return None
    value = r.get(path)
    if value is None:
        raise r.error(path, f'{_EXPECTED}, got nothing (quote a "#rrggbb": an unquoted # '
                      "starts a YAML comment)")
    if isinstance(value, str):
        match = _HEX.fullmatch(value)
        if match is None:
            raise r.error(path, f"{_EXPECTED}, got {value!r}")
        digits = match.group(1)
        red, green, blue = (int(digits[i:i + 2], 16) / 255.0 for i in (0, 2, 4))
        return red, green, blue
    if not isinstance(value, list) or len(value) != 3:
        shown = f"a list of {len(value)}" if isinstance(value, list) else repr(value)
        raise r.error(path, f"{_EXPECTED}, got {shown}")
    red, green, blue = (r.number((*path, i), minimum=0.0, maximum=1.0) for i in range(3))
    return red, green, blue
