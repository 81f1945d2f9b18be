"""xacro includes named on the command line: one note each (SB018), not a check of their own.

``servicebot check urdf $(git ls-files '*.xacro')`` names every xacro file of a package, its
macro libraries and parts too. A directory walk leaves those out (:mod:`files`); named, each
gets SB018, an info finding that says it is an include, checked through the files that
include it, instead of the SB009/SB109 errors a check of it alone would give. Only xacro
files are includes here, and only ones xacro can read: a ``.urdf`` is a robot, and a broken
file (malformed, or with blank lines before its ``<?xml ...?>``) is still checked, so that
its defect is reported.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

from servicebot_cli.check import files
from servicebot_cli.check.findings import Issue
from servicebot_cli.check.runner import FileReport, place_issues
from servicebot_cli.check.settings import Settings
from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.description.loader import RobotSource
from servicebot_cli.description.robot import is_xacro_name
from servicebot_cli.description.safe_xml import parse_xml


def include_reports(sources: Sequence[tuple[RobotSource, bool]],
                    settings: Settings) -> dict[int, FileReport]:
    """The SB018 report of each named xacro include (or SRDF) of ``sources``, by its index.

    An include is a xacro file :func:`files.is_fragment` tells (macros or properties only,
    an unnamed ``<robot>``, another root), or one that another named file includes.
    """
    candidates = {index: source.path for index, (source, named) in enumerate(sources)
                  if named and is_xacro_name(source.path) and os.path.isfile(source.path)}
    includer = files.includers(list(candidates.values()))
    reports: dict[int, FileReport] = {}
    for index, path in candidates.items():
        display = sources[index][0].display
        if files.is_semantic_name(path):  # MoveIt's *.srdf.xacro, which a walk leaves out
            issue = Issue("SB018", "a MoveIt semantic description (SRDF), not a URDF: nothing "
                          "for check urdf here", where=(display, 0, 0),
                          fix="check the URDF it describes; MoveIt reads this file beside it")
            reports[index] = FileReport(display, tuple(place_issues(None, [issue], settings)))
            continue
        by = includer.get(path)
        if (by is None and not files.is_fragment(path)) or not _well_formed(path):
            continue
        what = (f"included by {by}" if by is not None
                else "an include (macros, properties or parts, no robot of its own)")
        issue = Issue("SB018", f"{what}: checked through the files that include it, not alone",
                      where=(display, 0, 0))
        reports[index] = FileReport(display, tuple(place_issues(None, [issue], settings)))
    return reports


def _well_formed(path: Path) -> bool:
    """Whether ``path`` is safe, well-formed XML as xacro reads it; else checking it reports why.

    Blank lines before ``<?xml ...?>`` are refused, as xacro (expat) refuses them: such an
    include is checked, and gets the SB004 that xacro's refusal is.
    """
    try:
        parse_xml(path.read_bytes(), str(path), blanks_before_declaration=False)
    except (OSError, ServicebotError):
        return False
    return True
