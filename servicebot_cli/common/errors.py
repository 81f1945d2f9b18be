"""Exit codes and the one error tree every servicebot module raises from.

Core code raises these; only ``cli.py`` turns them into a line on stderr and an exit code.
Each class carries its exit code, so a new error never needs a new ``except`` clause.
"""

from __future__ import annotations

import difflib
import errno
import functools
import re
from collections.abc import Iterable
from enum import IntEnum


class ExitCode(IntEnum):
    """Process exit codes, documented in README.md."""

    OK = 0
    FAILED = 1  # the command ran and the answer is "no": findings, a diff, no IK solution
    USAGE = 2  # bad input: an option, a value, a file that cannot be read or understood
    INTERNAL = 3  # a bug in servicebot; the message says how to get the traceback
    LINK = 4  # the serial link cannot be opened or the firmware does not answer as expected
    LINK_LOST = 5  # the link went silent mid-run; motors were told to stop
    HANGUP = 129  # SIGHUP (128 + SIGHUP): the terminal closed; motors stopped, files cleaned
    INTERRUPTED = 130  # Ctrl-C (128 + SIGINT), after any motors were stopped
    QUIT = 131  # SIGQUIT (128 + SIGQUIT), after any motors were stopped
    TERMINATED = 143  # SIGTERM (128 + SIGTERM), after any motors were stopped


class ServicebotError(Exception):
    """Base of every error servicebot reports to its user.

    The message is one line that names the thing, the problem and, where there is one, the fix.
    """

    exit_code: ExitCode = ExitCode.USAGE


class AnswerIsNo(ServicebotError):
    """The command ran and its answer is "no": findings, a difference, a target not reached.

    Every command says "no" this way (exit 1). The result is already on stdout; the message,
    when there is one, is the one line on stderr that says why.
    """

    exit_code = ExitCode.FAILED


class DescriptionError(ServicebotError):
    """A robot description cannot be read, parsed, expanded or turned into a model.

    Attributes:
        said_before: What xacro printed before it failed (its warnings, often the failure's
            explanation), for the caller to show; none for other failures.
    """

    said_before: tuple[object, ...] = ()


class XmlError(DescriptionError):
    """XML that is not well-formed, too large, or unsafe (a DTD with entities).

    Attributes:
        file: Display path of the offending file.
        line: 1-based line, or 0 when the problem is the whole file.
        column: 1-based column, or 0 when unknown.
        reason: The problem, without the location prefix.
    """

    def __init__(self, file: str, reason: str, line: int = 0, column: int = 0) -> None:
        self.file, self.reason, self.line, self.column = file, reason, line, column
        where = file if not line else f"{file}:{line}:{column}" if column else f"{file}:{line}"
        super().__init__(f"{where}: {reason}")


class UnsafeXmlError(XmlError):
    """XML that declares entities or points at an external DTD; never resolved."""


class XacroError(DescriptionError):
    """xacro could not expand a file: bad expression, unknown macro or argument."""


class PackageNotFound(DescriptionError):
    """A ``$(find pkg)`` or ``package://pkg/`` reference names a package that is nowhere."""


class RemoteResource(DescriptionError):
    """A mesh or file named by an ``http(s)://`` address (Gazebo Fuel): fetched by no one here."""


class UnknownScheme(DescriptionError):
    """A mesh or file named by a URI whose scheme no robot description reader resolves."""


class NameNotFound(ServicebotError):
    """A joint, frame, link or other name that the robot does not have.

    Build with :meth:`for_name` so the message lists the closest names.
    """

    kind = "name"

    @classmethod
    def for_name(cls, name: str, candidates: Iterable[str], *, robot: str = "") -> NameNotFound:
        """Make the error for ``name`` with up to three close matches from ``candidates``."""
        names = tuple(dict.fromkeys(candidates))  # a name defined twice is suggested once
        owner = f" in {robot}" if robot else ""
        hint = _hint(name, names) if names else (
            "there is none to suggest" if cls.kind == "name" else f"the robot has no {cls.kind}s")
        return cls(f"no {cls.kind} '{name}'{owner}; {hint}")


@functools.lru_cache(maxsize=256)
def _hint(name: str, names: tuple[str, ...]) -> str:
    """Up to three close matches of ``name``, else the nearest names.

    Cached: a robot's variants bring the same wrong name back file after file (TIAGo's
    ``wheel_{side}_joint``), and matching it against PR2's 400 names takes 17 ms.
    """
    close = difflib.get_close_matches(name, names, n=3, cutoff=0.5)
    if close:
        return "did you mean " + " or ".join(f"'{c}'" for c in close) + "?"
    nearest = sorted(names, key=lambda candidate: _distance(name, candidate))
    return "known, nearest first: " + ", ".join(nearest[:8]) + (", ..." if len(names) > 8
                                                               else "")


def _distance(name: str, candidate: str) -> tuple[bool, float]:
    """Sort key: names that contain (or are contained in) ``name`` first, then similarity."""
    lowered, other = name.lower(), candidate.lower()
    related = lowered in other or other in lowered
    return not related, -difflib.SequenceMatcher(None, lowered, other).ratio()


class JointNotFound(NameNotFound):
    """A joint name the robot does not have."""

    kind = "joint"


class FrameNotFound(NameNotFound):
    """A frame (link or fixed frame) name the robot does not have."""

    kind = "frame"


class OutOfLimits(ServicebotError):
    """A joint value outside the joint's limits in the URDF."""


class LinkError(ServicebotError):
    """The serial link cannot be used: missing port, permission, busy, silent firmware."""

    exit_code = ExitCode.LINK


class LinkLost(LinkError):
    """The link stopped answering during a run."""

    exit_code = ExitCode.LINK_LOST


NO_ROOM = (errno.ENOSPC, errno.EDQUOT, errno.EFBIG)
"""errno of a write refused for want of room (disk, quota, file size limit): never a bug."""


def no_room(target: object, exc: OSError) -> str:
    """The line for a write to ``target`` refused for want of room."""
    return f"{target}: cannot write: {exc.strerror}; free some space or write somewhere else"


_LOCATED = re.compile(r"^(?P<file>.+?):(?P<line>\d+)(?::(?P<column>\d+))?: (?P<rest>.*)$",
                      re.DOTALL)


def split_location(message: str, display: str) -> tuple[str, int, int, str]:
    """``file:line:col: text`` (as :class:`XmlError` and the loader write it) into its parts.

    Line and column are 0 where the message gives none; the file is ``display`` then, and a
    leading ``display: `` is taken off the text.
    """
    match = _LOCATED.match(message)
    if match:
        return (match["file"], int(match["line"]), int(match["column"] or 0), match["rest"])
    if message.startswith(display + ": "):
        return display, 0, 0, message[len(display) + 2:]
    return display, 0, 0, message
