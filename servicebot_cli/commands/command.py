"""The Click command and group classes every servicebot command is made with.

They add one rule to Click's parsing: an option that takes one value may be given once.
Click would silently keep the last of ``--robot sim --robot real``; servicebot refuses it, as
it refuses a joint or a xacro argument given twice.
"""

from __future__ import annotations

from collections import Counter

import click


def refuse_repeated_options(command: click.Command, ctx: click.Context,
                            args: list[str]) -> None:
    """Raise a usage error when a single-valued option of ``command`` appears twice in ``args``.

    Raises:
        click.UsageError: The first option given more than once, by its flag.
    """
    if ctx.resilient_parsing:  # shell completion: never refuse a half-typed line
        return
    try:
        _, _, order = command.make_parser(ctx).parse_args(args=list(args))
    except click.UsageError:
        return  # Click's own parse reports it, with its own words
    seen = Counter(param for param in order if isinstance(param, click.Option)
                   and not (param.multiple or param.count or param.is_flag))
    for param, times in seen.items():
        if times > 1:
            flag = max(param.opts, key=len)
            raise click.UsageError(f"{flag} given {times} times; give it once", ctx=ctx)


class Command(click.Command):
    """A command that refuses a single-valued option given twice."""

    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        """Refuse repeated options, then parse as Click does.

        Click's parser reports an option without its value with no context; the command's
        own is given, so that the message points at this command's ``--help``.
        """
        refuse_repeated_options(self, ctx, args)
        try:
            return super().parse_args(ctx, args)
        except click.UsageError as exc:
            if exc.ctx is None:
                exc.ctx = ctx
            raise


class Group(click.Group):
    """A group that refuses a single-valued option of its own given twice."""

    def parse_args(self, ctx: click.Context, args: list[str]) -> list[str]:
        """Refuse repeated options of the group, then parse as Click does."""
        refuse_repeated_options(self, ctx, args[: self._own_args(ctx, args)])
        return super().parse_args(ctx, args)

    def _own_args(self, ctx: click.Context, args: list[str]) -> int:
        """How many leading ``args`` belong to the group: up to its subcommand's name."""
        for index, arg in enumerate(args):
            if arg in self.commands:
                return index
        return len(args)
