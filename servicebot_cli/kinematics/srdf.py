"""Link pairs an SRDF says never to check: ``<disable_collisions link1="a" link2="b"/>``.

MoveIt's setup assistant writes these for pairs that always touch, never meet, or are
adjacent. Only those elements are read; every other SRDF element is left alone. The file is
read through ``common.inputs``; this module itself parses values.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from servicebot_cli.common.errors import NameNotFound, ServicebotError
from servicebot_cli.common.inputs import display_path, read_input_bytes
from servicebot_cli.description.safe_xml import parse_xml

if TYPE_CHECKING:
    from servicebot_cli.description.robot import RobotDescription

LinkPair = tuple[str, str]
"""Two link names, in the order written."""


class BadSrdf(ServicebotError):
    """An SRDF that cannot be read, or names a link the robot does not have."""


class SrdfLinkNotFound(NameNotFound):
    """A link named in an SRDF that the robot does not have."""

    kind = "link"


def robot_disabled_pairs(path: str | None, robot: RobotDescription) -> tuple[LinkPair, ...]:
    """:func:`disabled_pairs` of the SRDF ``path`` for ``robot``'s links; none without one.

    Raises:
        BadSrdf: See :func:`disabled_pairs`.
    """
    if path is None:
        return ()
    from servicebot_cli.kinematics.frames import link_names

    return disabled_pairs(path, link_names(robot))


def disabled_pairs(path: str, links: Sequence[str]) -> tuple[LinkPair, ...]:
    """The ``<disable_collisions>`` pairs of the SRDF file ``path``.

    Args:
        path: The SRDF file.
        links: Every link of the robot, to check the names against.

    Raises:
        BadSrdf: Unreadable, not XML, an element without ``link1``/``link2``, or a link
            the robot does not have (the file's line and the nearest names).
    """
    display = display_path(Path(path))
    data = read_input_bytes(Path(path), display, kind="an SRDF file (MoveIt's "
                            "<robot><disable_collisions .../></robot>)", error=BadSrdf)
    try:
        root = parse_xml(data, display).root
    except ServicebotError as exc:
        raise BadSrdf(str(exc)) from None
    known = set(links)
    pairs: list[LinkPair] = []
    for element in root.iter("disable_collisions"):
        where = f"{display}:{getattr(element, 'sourceline', 0)}"
        first, second = element.get("link1"), element.get("link2")
        if not first or not second:
            raise BadSrdf(f"{where}: <disable_collisions> needs link1 and link2")
        for name in (first, second):
            if name not in known:
                found = SrdfLinkNotFound.for_name(name, links)
                raise BadSrdf(f"{where}: {found}")
        pairs.append((first, second))
    return tuple(pairs)
