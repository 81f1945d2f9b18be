"""Options and parameter types shared by every command, defined once.

The robot description is every command's optional positional argument: a URDF or xacro
file followed by xacro arguments, ``FILE [NAME:=VALUE ...]``. Without a file, the bundled
simulation robot is used; ``--robot sim|real`` picks a bundled file by name.
Validation happens here, at the parsing edge, so commands receive clean values.
"""

from __future__ import annotations

import functools
import math
import os
import re
import stat
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

import click
from click.core import ParameterSource
from click.shell_completion import CompletionItem

from servicebot_cli.common.plain_float import plain_float
from servicebot_cli.description.resources import BUNDLED_ROBOTS, DEFAULT_ROBOT

if TYPE_CHECKING:
    from servicebot_cli.description.loader import RobotSource
    from servicebot_cli.description.robot import RobotDescription

F = TypeVar("F", bound=Callable[..., Any])

# any name xacro's command line takes (robot-name, arm.side, ns/arg): not blank, no ':' or '='
_XACRO_ARG_RE = re.compile(r"^\s*([^\s:=](?:[^:=]*[^\s:=])?)\s*:=(.*)$", re.DOTALL)


def _xacro_arg(value: str) -> re.Match[str] | None:
    """``value`` as xacro's command line reads ``NAME:=VALUE``: both sides stripped."""
    return _XACRO_ARG_RE.match(value)


def _ignored_by_xacro(match: re.Match[str]) -> bool:
    """Whether xacro's command line drops the mapping (xacro/cli.py's load_mappings).

    An empty value (``use_sim:=`` from an empty launch variable: the argument keeps its
    default), or ``_name:=`` (a ROS parameter assignment).
    """
    name = match.group(1)
    return not match.group(2).strip() or (len(name) > 1 and name[0] == "_" and name[1] != "_")
_JOINT_VALUE_RE = re.compile(r"^([^=\s]+)=(.+)$")


@dataclass(frozen=True)
class RobotArgs:
    """The robot arguments of a command line.

    Attributes:
        files: Files (or, for ``check``, directories) in the order given.
        xacro_args: ``name:=value`` pairs in the order given.
        bundled: The ``--robot`` name, or None.
        packages: ``--package NAME=DIR`` pairs.
        values: The positional values as given, files and ``name:=value`` interleaved.
        default: The bundled robot used when neither a file nor ``--robot`` is given.
    """

    files: tuple[str, ...]
    xacro_args: tuple[tuple[str, str], ...]
    bundled: str | None
    packages: tuple[tuple[str, str], ...]
    values: tuple[str, ...] = ()
    default: str = DEFAULT_ROBOT

    def source(self) -> RobotSource:
        """The one RobotSource these arguments name (:attr:`default` when none is named).

        Raises:
            click.UsageError: Several files, or a file and ``--robot`` together.
        """
        from servicebot_cli.description.loader import RobotSource

        if len(self.files) > 1:
            raise click.UsageError(
                f"one robot description at a time, got {len(self.files)}: "
                + " ".join(self.files)
            )
        if self.files and self.bundled:
            raise click.UsageError(f"give a FILE or --robot {self.bundled}, not both")
        if self.files:
            return RobotSource.of(self.files[0], xacro_args=self.xacro_args,
                                  packages=self.packages)
        bundled = RobotSource.bundled(self.bundled or self.default)
        if self.xacro_args:
            raise click.UsageError(
                "xacro arguments need a xacro FILE; the bundled robots are plain URDF "
                "(their source is robots/service_robot.urdf.xacro)"
            )
        return bundled

    def sources(self) -> list[RobotSource]:
        """Every RobotSource named, in order; empty when none is named.

        ``--robot`` comes first, then each file with the xacro arguments that follow it:
        ``A.xacro x:=1 B.xacro x:=2`` gives A with x=1 and B with x=2.

        Raises:
            click.UsageError: A xacro argument before any file.
        """
        from servicebot_cli.description.loader import RobotSource

        sources = [RobotSource.bundled(self.bundled)] if self.bundled else []
        groups: list[tuple[str, list[tuple[str, str]]]] = []
        for value in self.values:
            match = _xacro_arg(value)
            if match is None:
                groups.append((value, []))
            elif _ignored_by_xacro(match):
                continue
            elif groups:
                groups[-1][1].append((match.group(1), match.group(2).strip()))
            else:
                raise click.UsageError(
                    f"xacro argument '{value}' comes before any FILE; put it after the xacro "
                    "file it is for (the bundled robots are plain URDF)"
                )
        sources.extend(RobotSource.of(file, xacro_args=tuple(args), packages=self.packages)
                       for file, args in groups)
        return sources


def split_robot_args(values: Sequence[str]) -> tuple[tuple[str, ...], tuple[tuple[str, str], ...]]:
    """Split positional values into files and ``name:=value`` xacro arguments.

    Raises:
        click.BadParameter: A malformed argument, or one name given twice for one file.
    """
    files: list[str] = []
    xacro_args: list[tuple[str, str]] = []
    group: list[tuple[str, str]] = []  # the arguments after the latest file
    for value in values:
        match = _xacro_arg(value)
        if match and not _utf8(match.group(2)):
            raise click.BadParameter(
                f"the value of '{match.group(1)}' is not UTF-8 text, which xacro needs; "
                "give it in UTF-8", param_hint="xacro argument")
        if match and ":=" in match.group(2):  # xacro: "Invalid remapping argument"
            raise click.BadParameter(
                f"'{value}' holds ':=' twice, which xacro refuses (an invalid remapping); "
                "give one NAME:=VALUE an argument", param_hint="xacro argument")
        if match and _ignored_by_xacro(match):
            continue
        if match:
            pair = (match.group(1), match.group(2).strip())
            group.append(pair)
            _refuse_repeated_xacro_args(group)
            xacro_args.append(pair)
        elif ":=" in value:
            raise click.BadParameter(
                f"'{value}' is not NAME:=VALUE (NAME is not blank, and holds no ':' or '=')",
                param_hint="xacro argument",
            )
        else:
            files.append(value)
            group = []
    return tuple(files), tuple(xacro_args)


def _utf8(text: str) -> bool:
    """Whether ``text`` (from the command line) was UTF-8: no byte escaped as a surrogate."""
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        return False
    return True


def _refuse_repeated_xacro_args(xacro_args: Sequence[tuple[str, str]]) -> None:
    """Raise when one xacro argument is given twice: xacro would keep the last silently."""
    seen: dict[str, str] = {}
    for name, value in xacro_args:
        if name in seen:
            raise click.BadParameter(
                f"{name}:= given twice ({name}:={seen[name]} and {name}:={value}); give it once",
                param_hint="xacro argument")
        seen[name] = value


class Number(click.ParamType[float]):
    """A finite number, optionally bounded. NaN and infinities are always refused.

    Every numeric option of every command uses this type (a test walks them all), so
    ``--tol-m nan`` or ``--duration-s inf`` is one clear line and exit 2, never a wrong run.
    """

    name = "number"

    def __init__(self, unit: str = "", *, positive: bool = False, fraction: bool = False,
                 non_negative: bool = False, maximum: float | None = None) -> None:
        self.unit, self.positive, self.fraction = unit, positive, fraction
        self.non_negative, self.maximum = non_negative, maximum
        self.name = unit or "number"

    def convert(self, value: str | float, param: click.Parameter | None, ctx: click.Context | None
                ) -> float:
        """Parse and check the number."""
        if isinstance(value, float):
            number = value
        else:
            try:
                number = plain_float(str(value))
            except (TypeError, ValueError):
                self.fail(f"'{value}' is not a number", param, ctx)
        if not math.isfinite(number):
            self.fail(f"'{value}' is not a finite number", param, ctx)
        if self.positive and number <= 0:
            self.fail(f"{value} must be above 0", param, ctx)
        if self.non_negative and number < 0:
            self.fail(f"{value} must not be negative", param, ctx)
        if self.fraction and not 0 <= number <= 1:
            self.fail(f"{value} is a probability: give a number from 0 to 1", param, ctx)
        if self.maximum is not None and number > self.maximum:
            self.fail(f"{value} is above the maximum {self.maximum:g}", param, ctx)
        return number


_NAME_MAX = 255
"""The longest file name (one path component) Linux file systems take [bytes]."""


class OutputPath(click.ParamType[str]):
    """A file or directory the command will write, checked before any work is done.

    The extension must be one the writer produces; the directory it goes in must exist and
    be writable; a directory output (``--out``) must not be a file, and with ``fresh`` must
    not exist yet (it is renamed into place at the end). Nothing is created here.
    """

    def __init__(self, suffixes: Sequence[str] = (), *, directory: bool = False,
                 fresh: bool = False, allow_dash: bool = False, what: str = "",
                 parents: bool = False, named_format: bool = False) -> None:
        self.suffixes = tuple(s.lower() for s in suffixes)
        self.named_format = named_format  # the writer takes its format from the suffix
        self.directory, self.fresh, self.allow_dash = directory, fresh, allow_dash
        self.parents = parents  # missing directories above it will be created (as xacro -o)
        self.what = what
        self.name = "DIR" if directory else "FILE" + (self.suffixes[0] if self.suffixes else "")

    def convert(self, value: str | os.PathLike[str], param: click.Parameter | None,
                ctx: click.Context | None) -> str:
        """Check ``value`` as an output path; return it unchanged."""
        text = os.fspath(value)
        if self.allow_dash and text == "-":
            return text
        path = Path(text)
        if not text.strip():
            self.fail("an empty path; give a file name", param, ctx)
        if self.directory and text == "-":  # standard output holds one stream, not a folder
            self.fail("'-' (standard output) cannot hold a directory of files; name a "
                      "directory, e.g. ./run1 (write ./- for a directory named '-')", param, ctx)
        if not self.directory and _is_device_or_pipe(path):
            if self.named_format and not any(text.lower().endswith(s) for s in self.suffixes):
                dash = ", or '-' for standard output" if self.allow_dash else ""
                self.fail(f"'{text}' is a device, and its name gives no format "
                          f"({', '.join(self.suffixes)}): write to a file{dash}", param, ctx)
            return text  # written into as a shell's > would: /dev/stdout, a named pipe
        if os.path.islink(path) and not os.path.exists(path) \
                and not os.path.isdir(os.path.dirname(os.path.realpath(path))):
            self.fail(f"'{text}' is a link to '{os.readlink(path)}', whose directory does not "
                      "exist; give another path, or remove the link", param, ctx)
        longest = max(path.parts, key=lambda part: len(os.fsencode(part)), default="")
        if len(os.fsencode(longest)) > _NAME_MAX:
            self.fail(f"the name '{longest[:40]}...' is too long: {len(os.fsencode(longest))} "
                      f"bytes, where a file system takes {_NAME_MAX}; give a shorter one",
                      param, ctx)
        if self.suffixes and not any(text.lower().endswith(s) for s in self.suffixes):
            what = f"{self.what} " if self.what else ""
            self.fail(f"'{text}': {what}files end in {' or '.join(self.suffixes)}; "
                      f"name it e.g. '{path.stem or 'out'}{self.suffixes[0]}'", param, ctx)
        if self.directory and os.path.exists(path) and not os.path.isdir(path):
            self.fail(f"'{text}' is a file; give a directory", param, ctx)
        if not self.directory and os.path.isdir(path):
            self.fail(f"'{text}' is a directory; give a file name", param, ctx)
        if self.fresh and os.path.exists(path):
            self.fail(f"'{text}' already exists; remove it or give another path", param, ctx)
        target = path if self.directory and os.path.isdir(path) else path.parent
        parent = target if str(target) else Path(".")
        if self.parents:
            parent = next((p for p in (parent, *parent.parents) if os.path.exists(p)), Path("."))
            if not os.path.isdir(parent):
                self.fail(f"'{text}': '{parent}' is a file, not a directory", param, ctx)
        if os.path.exists(parent) and not os.path.isdir(parent):
            self.fail(f"'{text}': '{parent}' is a file, not a directory", param, ctx)
        if not os.path.isdir(parent):
            self.fail(f"'{text}': directory '{parent}' does not exist; create it first",
                      param, ctx)
        if not os.access(parent, os.W_OK | os.X_OK):
            from servicebot_cli.common.files import read_only_file_system

            if read_only_file_system(parent):
                self.fail(f"'{text}': '{parent}' is on a read-only file system; write "
                          "somewhere else", param, ctx)
            self.fail(f"'{text}': permission denied writing in '{parent}'", param, ctx)
        return text


def _is_device_or_pipe(path: Path) -> bool:
    """Whether ``path`` exists as something other than a file or a directory."""
    try:
        mode = path.stat().st_mode
    except OSError:
        return False
    return not (stat.S_ISREG(mode) or stat.S_ISDIR(mode))


def refuse_overwriting(output: str | None, inputs: Iterable[str | os.PathLike[str]],
                       option: str = "-o") -> None:
    """Refuse an output that is one of the files the command reads.

    ``check urdf robot.urdf -o robot.urdf`` would replace the robot with its report.

    Raises:
        click.UsageError: ``output`` is the same file as one of ``inputs``.
    """
    if not output or output == "-" or not os.path.isfile(output):
        return
    for named in inputs:
        try:
            same = os.path.samefile(output, named)
        except OSError:
            continue
        if same:
            raise click.UsageError(f"{option} {output} is the file it reads; give another name")


def given(ctx: click.Context, name: str) -> bool:
    """Whether the user gave parameter ``name`` (on the command line or in the environment)."""
    return ctx.get_parameter_source(name) in (ParameterSource.COMMANDLINE,
                                              ParameterSource.ENVIRONMENT)


def refuse_with(ctx: click.Context, option: str, other: str, *, name: str | None = None,
                present: bool = True, why: str = "") -> None:
    """Refuse ``option`` next to ``other``, with which it would have no effect.

    Args:
        ctx: The command's context.
        option: The flag as the user types it, e.g. ``"--speed"``.
        other: The option it cannot go with, as the user types it, e.g. ``"--headless"``.
        name: The parameter's name in ``ctx.params`` (default: from ``option``).
        present: Whether ``other`` was given.
        why: A short reason, e.g. ``"which has no window"``.

    Raises:
        click.UsageError: ``option`` was given and ``other`` is present.
    """
    if given(ctx, name or option.lstrip("-").replace("-", "_")) and present:
        reason = f" ({why})" if why else ""
        raise click.UsageError(f"{option} has no effect with {other}{reason}; drop {option} or "
                               f"{other}", ctx=ctx)


def refuse_without(ctx: click.Context, option: str, needs: str, *, name: str | None = None,
                   present: bool = False) -> None:
    """Refuse ``option`` when the option it needs is absent: it would have no effect.

    Args:
        ctx: The command's context.
        option: The flag as the user types it, e.g. ``"--view"``.
        needs: What it needs, as the user types it, e.g. ``"--render FILE.png"``.
        name: The parameter's name in ``ctx.params`` (default: from ``option``).
        present: Whether what it needs was given.

    Raises:
        click.UsageError: ``option`` was given and ``present`` is false.
    """
    if given(ctx, name or option.lstrip("-").replace("-", "_")) and not present:
        raise click.UsageError(f"{option} has no effect without {needs}; add {needs} or "
                               f"drop {option}", ctx=ctx)


class BundledRobot(click.ParamType[str]):
    """A bundled robot name (``sim``, ``real``); completes the names."""

    name = "robot"

    def convert(self, value: str, param: click.Parameter | None, ctx: click.Context | None
                ) -> str:
        """Accept a bundled robot name."""
        if value in BUNDLED_ROBOTS:
            return str(value)
        self.fail(f"no bundled robot '{value}'; choose one of: {', '.join(BUNDLED_ROBOTS)}",
                  param, ctx)

    def shell_complete(
        self, ctx: click.Context, param: click.Parameter, incomplete: str
    ) -> list[CompletionItem]:
        """Complete bundled robot names."""
        return [CompletionItem(n) for n in BUNDLED_ROBOTS if n.startswith(incomplete)]


def distinct_packages(_ctx: click.Context, _param: click.Parameter,
                      value: tuple[tuple[str, str], ...]) -> tuple[tuple[str, str], ...]:
    """``--package`` callback: each package named once (the last would win unseen)."""
    where: dict[str, str] = {}
    for name, directory in value:
        if name in where and os.path.realpath(where[name]) != os.path.realpath(directory):
            raise click.BadParameter(f"package '{name}' is given twice ({where[name]} and "
                                     f"{directory}); give each package once")
        where[name] = directory
    return value


class PackageDir(click.ParamType[tuple[str, str]]):
    """``NAME=DIR``: where a ROS package lives, for ``$(find NAME)`` and ``package://NAME``."""

    name = "NAME=DIR"

    def convert(self, value: str | float, param: click.Parameter | None, ctx: click.Context | None
    ) -> tuple[str, str]:
        """Split and check ``NAME=DIR``."""
        if isinstance(value, tuple):
            return value
        name, sep, directory = str(value).partition("=")
        if not sep or not name or not directory:
            self.fail(f"'{value}' is not NAME=DIR, e.g. my_robot_description=./src/desc",
                      param, ctx)
        if not os.path.isdir(Path(directory)):
            self.fail(f"'{directory}' for package '{name}' is not a directory", param, ctx)
        return name, directory


class RobotArgument(click.ParamType[str]):
    """A robot file or a xacro ``NAME:=VALUE``; completes file names."""

    name = "FILE|NAME:=VALUE"

    def shell_complete(
        self, ctx: click.Context, param: click.Parameter, incomplete: str
    ) -> list[CompletionItem]:
        """Let the shell complete paths."""
        return [CompletionItem(incomplete, type="file")]


def robot_arguments(multiple: bool = False, default: str = DEFAULT_ROBOT) -> Callable[[F], F]:
    """Add ``[FILE] [NAME:=VALUE]...``, ``--robot`` and ``--package``; pass ``robot_args``.

    Args:
        multiple: Document several files (``check``); the command then reads
            ``robot_args.files`` itself instead of calling ``robot_args.source()``.
        default: The bundled robot used when neither a file nor ``--robot`` is given
            (``drive`` and ``emulate`` talk to the real robot's motors: ``real``).
    """
    metavar = "[FILE]... [NAME:=VALUE]..." if multiple else "[FILE] [NAME:=VALUE]..."

    def decorate(f: F) -> F:
        @functools.wraps(f)
        def wrapper(*args: Any, robot_values: tuple[str, ...], bundled: str | None,
                    packages: tuple[tuple[str, str], ...], **kwargs: Any) -> Any:
            files, xacro_args = split_robot_args(robot_values)
            robot_args = RobotArgs(files, xacro_args, bundled, packages, tuple(robot_values),
                                   default)
            return f(*args, robot_args=robot_args, **kwargs)

        wrapper = click.option(
            "--package", "packages", type=PackageDir(), multiple=True, metavar="NAME=DIR",
            callback=distinct_packages,
            help="Where ROS package NAME lives, for $(find NAME) and package://NAME "
            "(repeatable; searched before ROS_PACKAGE_PATH and AMENT_PREFIX_PATH).",
        )(wrapper)
        wrapper = click.option(
            "--robot", "bundled", type=BundledRobot(), default=None,
            help=f"Use a bundled robot by name: {', '.join(BUNDLED_ROBOTS)} "
            f"(default: {default} when no FILE is given).",
        )(wrapper)
        wrapper = click.argument(
            "robot_values", nargs=-1, type=RobotArgument(), metavar=metavar
        )(wrapper)
        return wrapper  # type: ignore[return-value]

    return decorate


class JointValue(click.ParamType[tuple[str, float]]):
    """``NAME=VALUE``: a joint and its position (a number; [rad] or [m], or [deg] with --deg)."""

    name = "NAME=VALUE"

    def convert(self, value: str | float, param: click.Parameter | None, ctx: click.Context | None
    ) -> tuple[str, float]:
        """Split and check ``NAME=VALUE``."""
        if isinstance(value, tuple):
            return value
        match = _JOINT_VALUE_RE.match(str(value))
        if not match:
            self.fail(f"'{value}' is not NAME=VALUE, e.g. arm_base_to_link1=0.5", param, ctx)
        name, text = match.group(1), match.group(2)
        try:
            number = plain_float(text)
        except ValueError:
            self.fail(f"'{text}' for joint '{name}' is not a number", param, ctx)
        if number != number or number in (float("inf"), float("-inf")):
            self.fail(f"'{text}' for joint '{name}' is not a finite number", param, ctx)
        return name, number


    def shell_complete(
        self, ctx: click.Context, param: click.Parameter, incomplete: str
    ) -> list[CompletionItem]:
        """Complete ``NAME=`` with the movable joints of the robot on the command line."""
        if "=" in incomplete:
            return []
        robot = robot_for_completion(ctx)
        names = [j.name for j in robot.joints if j.movable] if robot is not None else []
        return [CompletionItem(f"{name}=", help=_joint_help(robot, name))
                for name in names if name.startswith(incomplete)]


class FrameName(click.ParamType[str]):
    """A frame of the robot (a link, or a link fixed to another); completes the names."""

    name = "FRAME"

    def shell_complete(
        self, ctx: click.Context, param: click.Parameter, incomplete: str
    ) -> list[CompletionItem]:
        """Complete the link names of the robot on the command line."""
        robot = robot_for_completion(ctx)
        names = [link.name for link in robot.links] if robot is not None else []
        return [CompletionItem(name) for name in names if name.startswith(incomplete)]


SERIAL_PATTERNS = ("/dev/ttyUSB*", "/dev/ttyACM*", "/dev/ttyAMA*", "/dev/ttyS[0-3]",
                   "/dev/serial/by-id/*", "/dev/cu.*", "/dev/tty.usb*")
"""Where serial adapters appear on Linux and macOS, most likely first."""


class SerialPort(click.ParamType[str]):
    """A serial device path; completes the serial devices present, then any path."""

    name = "PATH"

    def convert(self, value: str, param: click.Parameter | None, ctx: click.Context | None
                ) -> str:
        """Refuse an empty path (``--port "$PORT"`` with PORT unset was read as no port)."""
        if not str(value).strip():
            self.fail("an empty path; give the serial device (/dev/ttyUSB0), or leave --port "
                      "out for the description's", param, ctx)
        return str(value)

    def shell_complete(
        self, ctx: click.Context, param: click.Parameter, incomplete: str
    ) -> list[CompletionItem]:
        """Complete the serial devices that exist now (USB adapters first)."""
        import glob

        found = [path for pattern in SERIAL_PATTERNS for path in sorted(glob.glob(pattern))]
        matching = [CompletionItem(p) for p in found if p.startswith(incomplete)]
        return matching or [CompletionItem(incomplete, type="file")]


def robot_for_completion(ctx: click.Context) -> RobotDescription | None:
    """The robot named on the command line so far, read without building a model.

    None when it cannot be read: completion never fails, and never imports Pinocchio.
    """
    from servicebot_cli.common.errors import ServicebotError
    from servicebot_cli.description.loader import RobotSource, read_description

    # While completing, Click leaves the positional values it has not bound in ctx.args.
    values = tuple(ctx.params.get("robot_values") or ()) + tuple(ctx.args)
    try:
        files, xacro_args = split_robot_args(values)
        if files:
            source = RobotSource.of(files[0], xacro_args=xacro_args,
                                    packages=tuple(ctx.params.get("packages") or ()))
        else:
            source = RobotSource.bundled(ctx.params.get("bundled") or DEFAULT_ROBOT)
        return read_description(source)
    except (ServicebotError, click.ClickException, OSError, ValueError):
        return None  # a half-typed or bad line completes nothing


def _joint_help(robot: RobotDescription | None, name: str) -> str | None:
    """``revolute, -1.57..1.57`` for a joint, shown by shells that show help (zsh, fish)."""
    joint = next((j for j in robot.joints if j.name == name), None) if robot else None
    if joint is None:
        return None
    limits = joint.limits
    if limits is None or limits.lower is None or limits.upper is None \
            or joint.type == "continuous":
        return joint.type
    return f"{joint.type}, {limits.lower:g}..{limits.upper:g}"


format_option = click.option(
    "--format", "fmt", type=click.Choice(["text", "json"]), default="text", show_default=True,
    help="Output for people (text) or for programs (json).",
)
