"""Options that ``fk`` and ``ik`` share, and their parameter types. Light: click only."""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

import click

from servicebot_cli.commands.options import OutputPath, given, refuse_overwriting

F = TypeVar("F", bound=Callable[..., Any])

# What -o/--output writes: CSV (.csv, .tsv with tabs) or JSON Lines (.jsonl, .ndjson, .json).
# The same list as output.batch_rows.OUTPUT_SUFFIXES, which is not imported here: it would
# load the batch package at --help; a test checks that the two agree.
OUTPUT_SUFFIXES = (".csv", ".tsv", ".jsonl", ".ndjson", ".json")

deg_option = click.option(
    "--deg", is_flag=True,
    help="Angles in degrees, in and out (joint values, roll-pitch-yaw); prismatic joints "
    "stay in metres. A batch column that names its unit (roll_rad, NAME_deg) is read in "
    "that unit.",
)
clamp_option = click.option(
    "--clamp", is_flag=True,
    help="Clamp joint values outside their limits instead of refusing them (a note on "
    "stderr says which).",
)

srdf_option = click.option(
    "--srdf", type=click.Path(exists=True, dir_okay=False), default=None, metavar="FILE",
    help="An SRDF whose <disable_collisions link1= link2=> pairs are not checked.",
)


format_option = click.option(
    "--format", "fmt", type=click.Choice(["text", "json", "csv"]), default="text",
    show_default=True,
    help="Output for people (text), for programs (json), or for spreadsheets (csv: a header "
    "and a row per frame for fk, one row for ik). Batch results on stdout: CSV, or JSON Lines "
    "with json.",
)


class InputFile(click.ParamType[str]):
    """A batch input: ``-`` for standard input, or a readable file. Checked before any work."""

    name = "FILE"

    def convert(self, value: str | os.PathLike[str], param: click.Parameter | None,
                ctx: click.Context | None) -> str:
        """Check ``value`` names a readable file (or is ``-``); return it unchanged."""
        text = os.fspath(value)
        if text == "-":
            return text
        path = Path(text)
        kind = "give a CSV or JSON Lines file, or - for stdin"
        if not os.path.exists(path):
            self.fail(f"'{text}': no such file; {kind}", param, ctx)
        if os.path.isdir(path):
            self.fail(f"'{text}' is a directory; {kind}", param, ctx)
        if not os.access(path, os.R_OK):
            self.fail(f"'{text}': permission denied; make it readable (chmod +r)", param, ctx)
        return text


def batch_options(flag: str, help: str) -> Callable[[F], F]:
    """The batch input option ``flag`` (a file, ``-`` for stdin), ``--output``, ``--on-error``."""

    def decorate(f: F) -> F:
        f = click.option(
            "--on-error", type=click.Choice(["stop", "skip"]), default="stop",
            show_default=True,
            help="A bad batch line: stop with its line number (exit 2, no output file), or "
            "skip it, say so on stderr, and go on.",
        )(f)
        f = click.option(
            "-o", "--output", type=OutputPath(suffixes=OUTPUT_SUFFIXES, allow_dash=True,
                                              what="batch result", named_format=True),
            default=None,
            help=f"Batch results to this file (needs {flag}), written atomically (.csv or "
            ".jsonl; default stdout: CSV with --format text, JSON Lines with --format json).",
        )(f)
        return click.option(flag, type=InputFile(), default=None, help=help)(f)

    return decorate


def refuse_format_with_file(ctx: click.Context, output: str | None) -> None:
    """Refuse ``--format`` beside ``--output FILE``: the file's extension names its format.

    Also refuse an ``--output`` that is the batch input file itself.

    Raises:
        click.UsageError: Both were given, or the output would replace the input.
    """
    if given(ctx, "fmt") and output not in (None, "-"):
        raise click.UsageError("--format has no effect with --output FILE: its extension "
                               "names the format (.csv or .jsonl); drop --format", ctx=ctx)
    inputs = [ctx.params.get(p.name) for p in ctx.command.params
              if p.name and isinstance(p.type, InputFile)]
    refuse_overwriting(output, [i for i in inputs if isinstance(i, str) and i != "-"])


class RandomSeed(click.ParamType[int]):
    """``--seed N``: the seed of the random restarts, a whole number from 0.

    ``ik`` once took start values as ``--seed NAME=VALUE``; such a value is refused with
    the option that takes it now.
    """

    name = "N"

    @staticmethod
    def joint_value_message(text: str) -> str:
        """Why ``NAME=VALUE`` is refused, and the option that takes it."""
        return (f"'{text}' is a joint value, not a random seed: use --start {text} for a "
                "start configuration (--seed N seeds the random restarts)")

    def convert(self, value: str | int, param: click.Parameter | None, ctx: click.Context | None
                ) -> int:
        """Parse the seed; point NAME=VALUE at ``--start``."""
        if isinstance(value, int):
            return value
        text = str(value)
        if "=" in text:
            self.fail(self.joint_value_message(text), param, ctx)
        try:
            number = int(text)
        except ValueError:
            self.fail(f"'{text}' is not a whole number", param, ctx)
        if number < 0:
            self.fail(f"{number} is negative; give a whole number from 0", param, ctx)
        return number


def echo_notes(notes: tuple[str, ...] | list[str]) -> None:
    """Each note on its own stderr line."""
    for note in notes:
        click.echo(note, err=True)


def warn(message: str) -> None:
    """One line on stderr: what a batch skipped or changed."""
    click.echo(message, err=True)
