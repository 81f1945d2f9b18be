"""Options of ``servicebot check`` and its subcommands, defined once.

``--list-rules`` and ``--explain`` are eager: they answer from the catalogue (plain data)
before anything is loaded, so they stay instant.
"""

from __future__ import annotations

import textwrap
from collections.abc import Callable
from typing import Any, TypeVar

import click

F = TypeVar("F", bound=Callable[..., Any])

FORMATS = ("text", "json", "sarif", "junit", "github")


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
    if found.fix:
        click.echo("\n" + textwrap.fill(f"Fix: {found.fix}", 88))
    click.echo("\nSilence it on one element with <!-- servicebot: ignore "
               f"{found.code} --> just before the element.")
    ctx.exit(0)


def catalogue_options(f: F) -> F:
    """Add the eager ``--list-rules`` and ``--explain CODE``."""
    f = click.option("--explain", metavar="CODE", expose_value=False, is_eager=True,
                     callback=_explain, help="Explain a rule (code or name) and exit.")(f)
    return click.option("--list-rules", is_flag=True, expose_value=False, is_eager=True,
                        callback=_list_rules, help="List every rule and exit.")(f)


def _codes(_: click.Context, __: click.Parameter, values: tuple[str, ...]) -> tuple[str, ...]:
    return tuple(code.strip() for value in values for code in value.split(",") if code.strip())


def report_options(f: F) -> F:
    """Add ``--format``, ``--output``, ``--strict``, ``--select``, ``--ignore``, ``--config``."""
    options = [
        click.option("--format", "fmt", type=click.Choice(FORMATS), default="text",
                     show_default=True, help="text for people, json for scripts, sarif for "
                     "code scanning, junit for test reports, github for workflow annotations."),
        click.option("-o", "--output", type=click.Path(dir_okay=False, allow_dash=True),
                     default="-", help="Write the report here (atomically) instead of stdout."),
        click.option("--strict/--no-strict", default=None,
                     help="Fail on warnings too (default: the settings' strict, else no)."),
        click.option("--select", multiple=True, callback=_codes, metavar="CODES",
                     help="Run only these rules: codes or prefixes, comma-separated (SB3,SB501)."),
        click.option("--ignore", multiple=True, callback=_codes, metavar="CODES",
                     help="Do not run these rules: codes or prefixes, comma-separated."),
        click.option("--config", type=click.Path(dir_okay=False, exists=True), default=None,
                     help="Read [tool.servicebot.check] from this pyproject.toml instead of "
                     "the nearest one above the current directory."),
        click.option("--isolated", is_flag=True,
                     help="Ignore every pyproject.toml: default settings and options only."),
    ]
    for option in reversed(options):
        f = option(f)
    return f
