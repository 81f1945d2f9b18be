"""The ``servicebot`` command: a Click group and the one place errors become exit codes.

Every failure a user can cause ends as one ``Error: ...`` line on stderr with a documented
exit code (see :class:`ExitCode`); ``--debug`` shows the traceback instead. Command modules
import only Click and light helpers at the top, so ``--help`` and shell completion stay fast.
"""

from __future__ import annotations

import atexit
import errno
import importlib
import io
import os
import sys
from typing import Any, NoReturn

import click

from servicebot_cli import __version__
from servicebot_cli.common.errors import NO_ROOM, ExitCode, ServicebotError, no_room
from servicebot_cli.common.signals import EndedBySignal, signals_as_exceptions


class OneLineUsageError(click.ClickException):
    """A usage error shown as one line, with where to find help."""

    exit_code = ExitCode.USAGE

    def __init__(self, error: click.UsageError, fallback_path: str = "servicebot") -> None:
        super().__init__(error.format_message())
        # Some parser errors (a missing option value) carry no context; the caller knows better.
        self.command_path = error.ctx.command_path if error.ctx else fallback_path

    def format_message(self) -> str:
        """The message, then a pointer to ``--help``."""
        return f"{self.message.rstrip('.')} (see '{self.command_path} --help')"


COMMANDS = ("check", "drive", "emulate", "expand", "fk", "ik", "inspect", "simulate", "sweep")
"""Each subcommand is the function of that name in ``servicebot_cli.commands.<name>``."""


class ServicebotGroup(click.Group):
    """Translates every error into one stderr line and an exit code.

    Subcommands are imported when named: ``servicebot check`` imports no other command's
    module (``--help`` and completion import them all; each is light).
    """

    def list_commands(self, ctx: click.Context) -> list[str]:
        """Every subcommand's name, sorted."""
        return sorted(COMMANDS)

    def resolve_command(self, ctx: click.Context,
                        args: list[str]) -> tuple[str | None, click.Command | None, list[str]]:
        """The subcommand ``args`` name; an unknown name is refused with the nearest ones."""
        try:
            return super().resolve_command(ctx, args)
        except click.exceptions.NoSuchCommand as exc:  # suggest from every name, not loaded
            raise click.exceptions.NoSuchCommand(exc.command_name, possibilities=COMMANDS,
                                                 ctx=ctx) from None

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        """The subcommand ``cmd_name``, imported now; None for an unknown name."""
        if cmd_name not in COMMANDS:
            return None
        if cmd_name not in self.commands:
            module = importlib.import_module(f"servicebot_cli.commands.{cmd_name}")
            self.add_command(getattr(module, cmd_name), cmd_name)
        return self.commands[cmd_name]

    def make_context(self, info_name: str | None, args: list[str],
                     parent: click.Context | None = None, **extra: Any) -> click.Context:
        """Parse the group's own options, with one-line usage errors."""
        try:
            return super().make_context(info_name, args, parent=parent, **extra)
        except click.exceptions.NoArgsIsHelpError:
            raise
        except click.UsageError as exc:
            raise OneLineUsageError(exc) from None

    def invoke(self, ctx: click.Context) -> Any:
        """Run the subcommand; turn our errors and unexpected ones into exit codes.

        ``--debug`` adds the traceback on stderr and keeps the documented exit code.
        """
        debug = bool(ctx.params.get("debug"))
        try:
            with signals_as_exceptions():
                return super().invoke(ctx)
        except click.exceptions.NoArgsIsHelpError:
            raise
        except click.UsageError as exc:
            path = " ".join(filter(None, [ctx.command_path, ctx.invoked_subcommand]))
            raise OneLineUsageError(exc, path) from None
        except ServicebotError as exc:
            _fail(ctx, str(exc), exc.exit_code, debug)
        except (click.exceptions.Exit, click.ClickException, click.Abort):
            raise
        except StdoutClosed as exc:
            _fail(ctx, str(exc), ExitCode.USAGE, debug)
        except BrokenPipeError:
            sys.stderr.close()  # the reader went away (| head): nothing left to say
            ctx.exit(ExitCode.OK)
        except OSError as exc:
            if exc.errno not in NO_ROOM:
                _fail(ctx, _internal(exc), ExitCode.INTERNAL, debug)
            _fail(ctx, _no_room(exc), ExitCode.USAGE, debug)
        except KeyboardInterrupt:
            _fail(ctx, "interrupted", ExitCode.INTERRUPTED, debug)
        except EndedBySignal as exc:
            _fail(ctx, exc.description, exc.exit_code, debug)
        except Exception as exc:
            _fail(ctx, _internal(exc), ExitCode.INTERNAL, debug)


def _no_room(exc: OSError) -> str:
    """The line for a write refused for want of room: to a named file, else to stdout."""
    return no_room(exc.filename or "standard output", exc)


def _internal(exc: Exception) -> str:
    """The line for an error no one foresaw."""
    return (f"internal error: {type(exc).__name__}: {exc}. This is a bug in servicebot; "
            "rerun as 'servicebot --debug COMMAND ...' for the traceback and report it")


def _fail(ctx: click.Context, message: str, code: int, debug: bool) -> NoReturn:
    """One ``Error:`` line (none for an empty message), the traceback with --debug, the code."""
    if debug:
        import traceback  # only here: about 2 ms of every command's start otherwise

        traceback.print_exc(file=sys.stderr)
    if message.strip():
        click.echo(f"Error: {' '.join(message.split())}", err=True)
    ctx.exit(code)


@click.group(cls=ServicebotGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, "-V", "--version", prog_name="servicebot")
@click.option("--debug", is_flag=True, help="Add the traceback of any error (the exit code stays).")
def main(debug: bool) -> None:
    """Check, inspect, move, simulate and drive a differential-drive service robot.

    Every command takes the robot description as an optional argument: a URDF or xacro
    file, then xacro arguments NAME:=VALUE. Without one it uses the bundled simulation
    robot (drive and emulate: the real one); --robot sim|real picks a bundled one.

    \b
    Exit codes: 0 ok, 1 the answer is no (findings, a difference, no IK solution),
    2 bad input, 3 internal error, 4 serial link error, 5 serial link lost,
    129 hung up (SIGHUP), 130 interrupted (Ctrl-C), 131 quit (SIGQUIT),
    143 terminated (SIGTERM). --debug adds the traceback and keeps the code.
    """


class StdoutClosed(OSError):
    """A write to standard output, which the process was started without (``>&-``)."""

    def __str__(self) -> str:
        return ("standard output is closed, so the output has nowhere to go; redirect it "
                "(> FILE, or > /dev/null to drop it)")


class _ClosedStdout(io.TextIOBase):
    """What stands for standard output when there is none: every write fails, loudly.

    Python sets ``sys.stdout`` to None when file descriptor 1 is closed, and Click then
    drops what is echoed: the command would succeed and its answer be lost.
    """

    def writable(self) -> bool:
        return True

    def write(self, _text: str) -> int:
        raise StdoutClosed(errno.EBADF, "standard output is closed")


def entry() -> NoReturn:
    """The console script: run the command, then end the process without tearing it down.

    When a command returns, its outputs are closed and in place. What the interpreter would
    do next (free every object and module: about 30 ms after a simulation) the system does
    at once. atexit functions still run and the standard streams are flushed; with other
    threads still running, the interpreter ends as usual, waiting for them.
    """
    code: int | str | None = 0
    if sys.stdout is None:
        sys.stdout = _ClosedStdout()
    try:
        main(prog_name="servicebot")
    except SystemExit as exc:
        code = exc.code
    except OSError as exc:  # the group's own help or version, written to a full disk or
        if not isinstance(exc, StdoutClosed) and exc.errno not in NO_ROOM:  # to no stdout
            raise
        print(f"Error: {exc if isinstance(exc, StdoutClosed) else _no_room(exc)}",
              file=sys.stderr)
        code = ExitCode.USAGE
    threading = sys.modules.get("threading")
    if threading is not None and threading.active_count() > 1:
        sys.exit(code)
    if not isinstance(code, int):
        if code is not None:
            print(code, file=sys.stderr)
        code = 0 if code is None else 1
    atexit._run_exitfuncs()
    os._exit(_flushed(code))


def _flushed(code: int) -> int:
    """Flush stdout and stderr; a stdout that cannot take the rest is one error line.

    A stream the shell closed (``>&-``) is None: nothing to flush.
    """
    try:
        if sys.stdout is not None:
            sys.stdout.flush()
    except BrokenPipeError:
        pass  # the reader went away (| head), as in ServicebotGroup.invoke
    except OSError as exc:
        if code == 0:  # else the command has already said what went wrong
            print(f"Error: {_no_room(exc)}", file=sys.stderr)
            code = ExitCode.USAGE
    except ValueError:
        pass  # closed by the command
    try:
        if sys.stderr is not None:
            sys.stderr.flush()
    except (OSError, ValueError):
        pass
    return int(code)
