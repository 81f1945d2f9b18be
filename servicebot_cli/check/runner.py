"""Run the catalogue over one description: read, run each family, place and filter findings.

The order keeps broken files cheap: reading errors stop at once; the Pinocchio model is
built only when every cheaper rule found no error.
"""

from __future__ import annotations

import os
import re
import stat
import xml.etree.ElementTree as ET
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from servicebot_cli.check import names, read_errors, syntax, tree
from servicebot_cli.check.catalogue import RULES
from servicebot_cli.check.env import CheckEnv
from servicebot_cli.check.findings import Finding, Issue, Severity
from servicebot_cli.check.settings import Settings
from servicebot_cli.check.xacro_warnings import xacro_warning
from servicebot_cli.common.errors import DescriptionError, XmlError
from servicebot_cli.description.load_warnings import LoadWarning
from servicebot_cli.description.safe_xml import ENTITY_FIX, MAX_BYTES, read_as_written

if TYPE_CHECKING:
    from servicebot_cli.check.model_ahead import ModelAhead
    from servicebot_cli.description.loader import RobotSource
    from servicebot_cli.description.packages import PackageLocation
    from servicebot_cli.description.robot import RobotDescription

_SUPPRESS = re.compile(r"servicebot:\s*ignore\b([\s,A-Za-z0-9]*)", re.IGNORECASE)


@dataclass(frozen=True)
class FileReport:
    """The findings of one checked file, in reporting order.

    Attributes:
        file: The file as the user named it (or as found in a directory).
        findings: Its findings.
        packages: Every package the file uses, by name: where and how it was found, or None
            when it was found nowhere.
        read: Every file reading it read (xacro's includes too), as named in messages.
        expanded: False when it could not be read as a robot (xacro failed: a package or an
            argument it needs is not given): its finding says why, and nothing in it was
            checked.
    """

    file: str
    findings: tuple[Finding, ...]
    packages: Mapping[str, PackageLocation | None] = field(default_factory=dict)
    read: tuple[str, ...] = ()
    expanded: bool = True


def check_source(source: RobotSource, settings: Settings, env: CheckEnv,
                 named: bool = True) -> FileReport:
    """Check one description; ``named``: the user named it (else a directory walk found it).

    Raises:
        DescriptionError: The file itself cannot be read (missing, a directory, permission).
    """
    from servicebot_cli.description.loader import read_description

    try:
        found = os.stat(source.path)
        size = found.st_size if stat.S_ISREG(found.st_mode) else 0
    except OSError:  # the reader says what is wrong with it
        size = 0
    if size > MAX_BYTES:
        issue = Issue("SB015", f"file is {size / 1e6:.1f} MB, over the {MAX_BYTES / 1e6:.0f} MB "
                      "limit for a robot description; refused unread", where=(source.display, 0, 0))
        return _report(source.display, place_issues(None, [issue], settings))
    try:
        robot = read_description(source)
    except DescriptionError as exc:
        if _unreadable(exc, source):
            raise
        issue = read_errors.issue_of(exc, source.display, walked=not named)
        if not isinstance(exc, XmlError):  # no robot at all says more than why xacro failed
            issue = read_errors.root_not_robot(str(source.path), source.display) or issue
        said = [xacro_warning(w, source.display) for w in exc.said_before
                if isinstance(w, LoadWarning)]  # xacro's warnings before it failed
        return _report(source.display, place_issues(None, [*said, issue], settings),
                       expanded=False)
    from servicebot_cli.check import packages

    part = _part_of_another(robot, source)
    if part is not None:
        note, parent = part
        own: list[Issue] = []
        if parent is not None:  # nothing includes it: its own defects, without its parent's
            own = [issue for issue in _issues(robot, settings, env)
                   if not _from_missing_parent(issue, parent)]
        return _report(source.display, place_issues(robot, [note, *own], settings),
                       packages.used(robot, env.search), robot.files)
    ahead = _model_ahead(robot, settings, env)
    try:
        findings = place_issues(robot, _issues(robot, settings, env), settings)
        return _report(source.display, findings + _model(robot, findings, settings, ahead),
                       packages.used(robot, env.search), robot.files)
    finally:
        if ahead is not None:
            ahead.close()  # at once when no verdict was asked for


def _part_of_another(robot: RobotDescription,
                     source: RobotSource) -> tuple[Issue, str | None] | None:
    """SB018 for a xacro part that hangs from a link of the robot that includes it.

    Only with evidence that it is one (:func:`fragments.part_evidence`); a robot file that
    merely lacks its root's parent is checked, and fails with SB103. With the link it hangs
    from when nothing includes it but in a comment (an alternative part, stretch's tools):
    no robot checks it, so it is checked alone, but for what that link's absence causes.
    """
    from servicebot_cli.check.fragments import ALTERNATIVE_PART, external_parent, part_evidence
    from servicebot_cli.description.robot import is_xacro_name

    if not is_xacro_name(source.path) or not os.path.isfile(source.path):
        return None
    parent = external_parent(robot)
    if parent is None:
        return None
    why = part_evidence(source.path, parent)
    if why is None:
        return None
    if why.startswith(ALTERNATIVE_PART):
        return Issue("SB018", f"a part of another robot ({why}): every link hangs from "
                     f"'{parent}', which it does not define; nothing includes it, so it is "
                     f"checked alone, without what the absence of '{parent}' causes",
                     where=(robot.display, 0, 0),
                     fix="the other findings of the file are the part's own"), parent
    return Issue("SB018", f"a part of another robot ({why}): every link hangs from "
                 f"'{parent}', which it does not define; checked through the files that "
                 "include it, not alone", where=(robot.display, 0, 0)), None


def _from_missing_parent(issue: Issue, parent: str) -> bool:
    """Whether ``issue`` is about the link ``parent`` a part hangs from, which it lacks."""
    return issue.code.startswith("SB1") and f"'{parent}'" in issue.message


def _model_ahead(robot: RobotDescription, settings: Settings, env: CheckEnv) -> ModelAhead | None:
    """The child building SB701's model while the other rules run, when ``env`` asks for one."""
    if not env.model_ahead or not settings.enabled("SB701"):
        return None
    from servicebot_cli.check import model_ahead

    return model_ahead.start(robot.xml_text, robot.display)


def _model(robot: RobotDescription, findings: list[Finding], settings: Settings,
           ahead: ModelAhead | None = None) -> list[Finding]:
    """SB701 when every reported finding is below error level, else SB702.

    ``ahead``: the child building the model meanwhile, whose verdict stands for building it.
    """
    from servicebot_cli.check import model

    if any(f.code in ("SB008", "SB015") for f in findings):
        return []
    if any(f.severity is Severity.ERROR for f in findings):
        skipped = Issue("SB702", "Pinocchio model not built: fix the errors above first",
                        where=(robot.display, 0, 0))
        return place_issues(robot, [skipped], settings)
    if not settings.enabled("SB701"):
        return []
    return place_issues(robot, model.check(robot, ahead), settings)


def _unreadable(exc: DescriptionError, source: RobotSource) -> bool:
    """True for the loader's refusals of the file itself, which are not findings."""
    text = str(exc)
    return text.startswith(f"{source.display}: ") and any(
        reason in text for reason in ("no such file", "is a directory", "permission denied",
                                      "cannot read:", "not a xacro file"))


def _issues(robot: RobotDescription, settings: Settings, env: CheckEnv) -> Iterator[Issue]:
    """Every rule family but the model, skipping families with no selected rule."""
    from servicebot_cli.check import (
        control_parameters,
        drive_frames,
        drive_plugins,
        gazebo,
        geometry,
        inertia,
        joints,
        packages,
        ros1_parameters,
        ros2_control,
        transmissions,
    )

    for warning in dict.fromkeys(robot.warnings):  # a call site's warning once
        yield xacro_warning(warning, robot.display)
    if robot.external_dtd is not None:  # named, never loaded: by no reader either
        dtd = robot.external_dtd
        yield Issue("SB005", f"external DTD '{dtd.identifier}' is never loaded, as no robot "
                    "description reader loads it", severity=Severity.WARNING,
                    where=(robot.display, 0, 0) if robot.expanded else
                    (robot.display, dtd.line, dtd.column), fix="remove the DOCTYPE")
    for name, line, column in robot.entities_used[:1]:  # xacro's output has them expanded
        yield Issue("SB005", read_as_written(name), where=(robot.display, line, column),
                    fix=ENTITY_FIX)
    found = list(syntax.check(robot.root))
    if not robot.expanded:  # xacro's own parser turned such blanks into spaces already
        found += syntax.vectors_split_wrong(robot.xml_text, robot.display)
    yield from found
    if any(i.code in ("SB008", "SB015") for i in found):
        return
    wanted = settings.enabled
    env.load_meshes = any(wanted(c) for c in ("SB402", "SB403", "SB404", "SB301"))
    env.resolve_meshes = env.load_meshes or any(wanted(c) for c in ("SB401", "SB408", "SB409",
                                                                    "SB410"))
    # each family by the code prefixes of its rules (gazebo's: SB501-SB503 and SB513)
    families: list[tuple[tuple[str, ...], Callable[[], Iterable[Issue]]]] = [
        (("SB1",), lambda: names.check(robot)), (("SB1",), lambda: tree.check(robot)),
        (("SB2",), lambda: joints.check(robot)), (("SB3",), lambda: inertia.check(robot, env)),
        (("SB4",), lambda: geometry.check(robot, env)),
        (("SB409",), lambda: packages.find_issues(robot, env.search)),
        (("SB50", "SB513", "SB518"), lambda: gazebo.check(robot)),
        (("SB5",), lambda: ros2_control.check(robot)),
        (("SB516",), lambda: drive_plugins.check(robot, env.mesh_points(robot))),
        (("SB519",), lambda: ros1_parameters.check(robot)),
        (("SB520",), lambda: drive_frames.check(robot)),
        (("SB521",), lambda: control_parameters.check(robot)),
        (("SB511",), lambda: transmissions.check(robot)),
    ]
    for prefixes, family in families:
        if any(settings.any_enabled(prefix) for prefix in prefixes):
            yield from family()


def place_issues(robot: RobotDescription | None, issues: Iterable[Issue],
                 settings: Settings) -> list[Finding]:
    """Findings for the enabled, unsuppressed ``issues``, placed in their source files."""
    parents: dict[ET.Element, ET.Element] | None = None
    findings = []
    # no comment can silence a finding in a text that never names the tool
    marked = robot is not None and "servicebot" in robot.xml_text.lower()  # (a regex
    # that ignores case reads 10 ns a character: 2 ms for a large URDF, at every call)
    texts = _SourceTexts(robot) if robot is not None else None
    for issue in issues:
        if not settings.enabled(issue.code):
            continue
        if marked and robot is not None and issue.element is not None:
            if parents is None:
                parents = {child: parent for parent in robot.root.iter() for child in parent}
            if _suppressed(issue, parents):
                continue
        findings.append(_place(robot, issue, settings, texts))
    return findings


def _suppressed(issue: Issue, parents: dict[ET.Element, ET.Element]) -> bool:
    """True when ``<!-- servicebot: ignore CODE -->`` precedes the element or an ancestor.

    A bare ``servicebot: ignore`` silences every rule there.
    """
    element = issue.element
    while element is not None:
        for comment in getattr(element, "leading_comments", ()):
            match = _SUPPRESS.search(comment)
            if match:
                codes = re.findall(r"SB\d{3}", match.group(1).upper())
                if not codes or issue.code in codes:
                    return True
        element = parents.get(element)
    return False


def _place(robot: RobotDescription | None, issue: Issue, settings: Settings,
           texts: _SourceTexts | None = None) -> Finding:
    calls: tuple[str, ...] = ()
    if issue.where is not None:
        file, line, column = issue.where
    elif robot is not None:
        ref = robot.source_of(issue.element)
        file, line, column = ref.file, ref.line, ref.column
        calls = tuple(call.location() for call in ref.calls)
        if issue.attribute is not None and line > 0 and texts is not None:
            line, column = texts.attribute_place(file, line, column, issue.attribute)
    else:  # pragma: no cover - issues without a robot always carry `where`
        file, line, column = "", 0, 0
    severity = settings.severity.get(issue.code) or issue.severity or RULES[issue.code].severity
    return Finding(issue.code, severity, issue.message, file, line, column,
                   issue.fix or RULES[issue.code].fix, calls)


class _SourceTexts:
    """The text of each source file findings are placed in, and where its lines start.

    Read once for all the findings of a file (an exporter's comma decimals give hundreds).
    """

    def __init__(self, robot: RobotDescription) -> None:
        self.robot = robot
        self.known: dict[str, tuple[str, list[int]] | None] = {}

    def lines(self, file: str) -> tuple[str, list[int]] | None:
        """``file``'s text and the offset each line starts at; None where it cannot be read."""
        if file not in self.known:
            robot = self.robot
            text = robot.xml_text if file == robot.display and not robot.expanded \
                else _text_of(file)
            self.known[file] = None if text is None else (
                text, [0, *(found.end() for found in re.finditer("\n", text))])
        return self.known[file]

    def attribute_place(self, file: str, line: int, column: int,
                        attribute: str) -> tuple[int, int]:
        """Where ``attribute`` is written in the tag at ``line``:``column`` of ``file``.

        The tag's own place where the text cannot be read or the attribute is not in it.
        """
        found_text = self.lines(file)
        if found_text is None or line > len(found_text[1]):
            return line, column
        text, starts = found_text
        start = starts[line - 1] + column - 1
        end = text.find(">", start)
        found = re.compile(rf"(?<![\w:.-]){re.escape(attribute)}\s*=").search(
            text, start, end if end >= 0 else len(text))
        if found is None:
            return line, column
        before = text.count("\n", start, found.start())
        if not before:
            return line, column + found.start() - start
        return line + before, found.start() - starts[line + before - 1] + 1


def _text_of(file: str) -> str | None:
    """The text of a source file (a xacro include), None where it cannot be read."""
    try:
        return Path(file).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError, ValueError):
        return None


def _report(file: str, findings: list[Finding],
            used: Mapping[str, PackageLocation | None] | None = None,
            read: tuple[str, ...] = (), *, expanded: bool = True) -> FileReport:
    ordered = sorted(findings, key=lambda f: (f.code == "SB702", f.file != file, *f.sort_key()))
    return FileReport(file, tuple(ordered), dict(used or {}), read, expanded)
