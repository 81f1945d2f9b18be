"""Options of ``servicebot check`` and its subcommands, defined once.

``--list-rules`` and ``--explain`` are eager: they answer from the catalogue (plain data)
before anything is loaded, so they stay instant. ``--select``, ``--ignore`` and
``--explain`` complete rule codes from the same catalogue.
"""

from __future__ import annotations

import functools
import textwrap
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any, TypeVar

import click
from click.shell_completion import CompletionItem

from servicebot_cli.commands.options import OutputPath

F = TypeVar("F", bound=Callable[..., Any])

FORMATS = ("text", "json", "sarif", "junit", "github")
CATALOGUE_OPTIONS = ("list_rules", "explain")


@dataclass(frozen=True)
class ReportOptions:
    """The report and settings options of one ``check`` subcommand, as typed.

    Attributes:
        fmt: ``--format``.
        output: ``--output``: a file, or ``-`` for stdout.
        strict: ``--strict``/``--no-strict``, or None when neither is given.
        select: ``--select`` codes and prefixes, split at commas.
        ignore: ``--ignore`` codes and prefixes, split at commas.
        config: ``--config``, or None.
        isolated: ``--isolated``.
    """

    fmt: str = "text"
    output: str = "-"
    strict: bool | None = None
    select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()
    config: str | None = None
    isolated: bool = False


def rule_completions(incomplete: str, *, names: bool = False, everything: bool = False
                     ) -> list[CompletionItem]:
    """Rule codes, family prefixes (``SB3``) and, with ``names``, rule names that fit.

    Reads the catalogue only (plain data), so a TAB press loads no numeric library.
    """
    from servicebot_cli.check.catalogue import FAMILIES, RULES

    key = incomplete.upper()
    items = [CompletionItem("ALL", help="every rule")] if everything and "ALL".startswith(key) \
        else []
    items += [CompletionItem(prefix, help=title) for prefix, title in FAMILIES.items()
              if prefix.startswith(key)]
    items += [CompletionItem(code, help=rule.name) for code, rule in RULES.items()
              if code.startswith(key)]
    if names and not items:
        items = [CompletionItem(rule.name, help=code) for code, rule in RULES.items()
                 if rule.name.startswith(incomplete.lower())]
    return items


class RuleCode(click.ParamType[str]):
    """A rule, by code or name (``--explain``); completes codes and names."""

    name = "CODE"

    def shell_complete(self, ctx: click.Context, param: click.Parameter, incomplete: str
                       ) -> list[CompletionItem]:
        """Complete rule codes, then names."""
        return rule_completions(incomplete, names=True)


class RuleCodes(click.ParamType[str]):
    """Comma-separated rule codes or prefixes (``--select``, ``--ignore``); completes the last."""

    name = "CODES"

    def __init__(self, everything: bool = False) -> None:
        self.everything = everything

    def shell_complete(self, ctx: click.Context, param: click.Parameter, incomplete: str
                       ) -> list[CompletionItem]:
        """Complete the code after the last comma, keeping the ones before it."""
        done, _, last = incomplete.rpartition(",")
        head = done + "," if done else ""
        return [CompletionItem(head + item.value, help=item.help)
                for item in rule_completions(last, everything=self.everything and not done)]


def _list_rules(ctx: click.Context, _: click.Parameter, value: bool) -> None:
    if not value or ctx.resilient_parsing:
        return
    from servicebot_cli.check.catalogue import RULES
    from servicebot_cli.output.table import table

    rows = [(r.code, r.severity.value, r.name, r.summary) for r in RULES.values()]
    for line in table(["code", "severity", "name", "summary"], rows, max_width=120):
        click.echo(line)
    ctx.exit(0)


def _explain(ctx: click.Context, param: click.Parameter, value: str | None) -> None:
    if value is None or ctx.resilient_parsing:
        return
    from servicebot_cli.check.catalogue import rule

    try:
        found = rule(value)
    except KeyError as exc:
        raise click.BadParameter(exc.args[0], ctx=ctx, param=param) from None
    click.echo(f"{found.code} {found.name} ({found.severity.value}, {found.family})")
    click.echo(f"\n{found.summary}.\n")
    click.echo(textwrap.fill(found.explanation, 88))
    if found.breaks:
        click.echo("\n" + textwrap.fill(f"What breaks: {found.breaks}.", 88))
    if found.fix:
        click.echo("\n" + textwrap.fill(f"Fix: {found.fix}", 88))
    click.echo("\nSilence it on one element with <!-- servicebot: ignore "
               f"{found.code} --> just before the element.")
    ctx.exit(0)


def catalogue_options(f: F) -> F:
    """Add the eager ``--list-rules`` and ``--explain CODE``."""
    f = click.option("--explain", type=RuleCode(), expose_value=False, is_eager=True,
                     callback=_explain, help="Explain a rule (code or name) and exit.")(f)
    return click.option("--list-rules", is_flag=True, expose_value=False, is_eager=True,
                        callback=_list_rules, help="List every rule and exit.")(f)


def refuse_catalogue_mix(command: click.Command, ctx: click.Context, args: list[str]) -> None:
    """Refuse ``--list-rules`` or ``--explain`` beside anything else: it would be ignored.

    They answer from the catalogue and check nothing, so another option or a FILE given with
    them has no effect. Called before Click parses (the eager callbacks exit at once).

    Raises:
        click.UsageError: One line naming what to drop.
    """
    if ctx.resilient_parsing:
        return
    try:
        opts, _, order = command.make_parser(ctx).parse_args(args=list(args))
    except click.UsageError:
        return  # Click's own parse reports it
    given = [p for p in dict.fromkeys(order) if p.name != "help" and _has_value(opts, p)]
    asked = [p for p in given if p.name in CATALOGUE_OPTIONS]
    if not asked:
        return
    if len(asked) > 1:
        raise click.UsageError("--list-rules and --explain each answer alone; give one of them",
                               ctx=ctx)
    other = next((p for p in given if p.name not in CATALOGUE_OPTIONS), None)
    if other is not None:
        flag = _flag(asked[0])
        raise click.UsageError(f"{flag} answers from the rule catalogue and checks nothing; "
                               f"drop {_flag(other)}", ctx=ctx)


def _has_value(opts: dict[str, object], param: click.Parameter) -> bool:
    """Whether ``param`` got a value on the command line (an empty ``nargs=-1`` did not)."""
    value = opts.get(param.name or "")
    return isinstance(value, str | bool | int | float) or (
        isinstance(value, tuple | list) and len(value) > 0)


def _flag(param: click.Parameter) -> str:
    """How the user typed ``param``: its longest flag, or its metavar for an argument."""
    if isinstance(param, click.Option):
        return max(param.opts, key=len)
    return "FILE" if param.name == "robot_values" else (param.name or "").upper()


def _codes(values: tuple[str, ...]) -> tuple[str, ...]:
    return tuple(code.strip() for value in values for code in value.split(",") if code.strip())


def comma_separated(ctx: click.Context, param: click.Parameter,
                    values: tuple[str, ...]) -> tuple[str, ...]:
    """A repeatable option's comma-separated items, in order, each once."""
    return tuple(dict.fromkeys(_codes(values)))


def report_options(f: Callable[..., None]) -> Callable[..., None]:
    """Add ``--format``, ``--output``, ``--strict``, ``--select``, ``--ignore``, ``--config``,
    ``--isolated``; pass them as one ``report: ReportOptions``.
    """  # noqa: D205

    @functools.wraps(f)
    def wrapper(*args: Any, fmt: str, output: str, strict: bool | None,
                select: tuple[str, ...], ignore: tuple[str, ...], config: str | None,
                isolated: bool, **kwargs: Any) -> None:
        report = ReportOptions(fmt, output, strict, _codes(select), _codes(ignore), config,
                               isolated)
        f(*args, report=report, **kwargs)

    options = [
        click.option("--format", "fmt", type=click.Choice(FORMATS), default="text",
                     show_default=True, help="text for people, json for scripts, sarif for "
                     "code scanning, junit for test reports, github for workflow annotations."),
        click.option("-o", "--output", type=OutputPath(allow_dash=True, what="report"),
                     default="-", metavar="FILE",
                     help="Write the report here (atomically) instead of stdout."),
        click.option("--strict/--no-strict", default=None,
                     help="Fail on warnings too (default: the settings' strict, else no)."),
        click.option("--select", multiple=True, type=RuleCodes(everything=True),
                     help="Run only these rules: codes or prefixes, comma-separated (SB3,SB501)."),
        click.option("--ignore", multiple=True, type=RuleCodes(),
                     help="Do not run these rules: codes or prefixes, comma-separated."),
        click.option("--config", type=click.Path(dir_okay=False, exists=True), default=None,
                     help="Read [tool.servicebot.check] from this pyproject.toml instead of "
                     "the nearest one above the current directory."),
        click.option("--isolated", is_flag=True,
                     help="Ignore every pyproject.toml: default settings and options only."),
    ]
    decorated: Callable[..., None] = wrapper
    for option in reversed(options):
        decorated = option(decorated)
    return decorated


def settings_path(report: ReportOptions) -> Path | None:
    """``--config`` as a path, or None."""
    return Path(report.config) if report.config else None
