"""Options that ``drive`` and ``emulate`` share: protocol, baud and encoder counting.

Light: Click only (the domain is imported when a value is built). Validation happens here,
at the parsing edge: ``--ticks-per-rev`` and ``--pid-rate`` are refused without
``--protocol arduino``, where they would have no effect.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any, TypeVar

import click

from servicebot_cli.commands.options import Number, refuse_without

if TYPE_CHECKING:
    from servicebot_cli.drive.protocols.arduino import ArduinoConfig

F = TypeVar("F", bound=Callable[..., Any])


def serial_options(f: F) -> F:
    """``--protocol``, ``--baud``, ``--ticks-per-rev`` and ``--pid-rate``."""
    f = click.option(
        "--pid-rate", type=Number("HZ", positive=True), default=30.0, show_default=True,
        help="arduino: the firmware's PID_RATE; `m` speeds are ticks per 1/PID_RATE s.",
    )(f)
    f = click.option(
        "--ticks-per-rev", type=Number("TICKS", positive=True), default=None,
        help="arduino: encoder ticks per wheel revolution (needed with --protocol arduino).",
    )(f)
    f = click.option(
        "--baud", type=click.IntRange(min=50), default=None, metavar="N",
        help="Baud rate (default: the description's ros2_control baud_rate, 9600 for the "
        "real robot).",
    )(f)
    f = click.option(
        "--protocol", type=click.Choice(["servicebot", "arduino"]), default="servicebot",
        show_default=True,
        help="servicebot: binary frames with CRC (docs/serial-protocol.md); arduino: the "
        "ROSArduinoBridge text protocol (two motors, no arm).",
    )(f)
    return f


def arduino_config(protocol: str, ticks_per_rev: float | None,
                   pid_rate: float) -> ArduinoConfig | None:
    """The ArduinoConfig for ``--protocol arduino``, else None.

    Raises:
        click.UsageError: ``--ticks-per-rev`` or ``--pid-rate`` without arduino.
        click.BadParameter: arduino without ``--ticks-per-rev``.
    """
    ctx = click.get_current_context()
    for option in ("--ticks-per-rev", "--pid-rate"):
        refuse_without(ctx, option, "--protocol arduino", present=protocol == "arduino")
    if protocol != "arduino":
        return None
    if ticks_per_rev is None:
        raise click.BadParameter(
            "needed with --protocol arduino: encoder ticks per wheel revolution, since the "
            "`m` command counts ticks", param_hint="--ticks-per-rev")
    from servicebot_cli.drive.protocols.arduino import ArduinoConfig

    return ArduinoConfig(ticks_per_rev, pid_rate)


@contextlib.contextmanager
def bad_options() -> Iterator[None]:
    """Report the domain's :class:`~servicebot_cli.drive.request.BadOption` as Click does.

    Raises:
        click.BadParameter: For a BadOption, naming its option.
    """
    from servicebot_cli.drive.request import BadOption

    try:
        yield
    except BadOption as exc:
        raise click.BadParameter(str(exc), param_hint=exc.option) from None
