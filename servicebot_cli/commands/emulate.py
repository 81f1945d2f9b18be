"""``servicebot emulate``: the robot's motor controller on a pseudo-terminal, for testing."""

from __future__ import annotations

from pathlib import Path

import click

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.options import (
    Number,
    OutputPath,
    RobotArgs,
    refuse_without,
    robot_arguments,
)
from servicebot_cli.commands.serial_options import arduino_config, serial_options


@click.command(cls=Command)
@robot_arguments(default="real")
@serial_options
@click.option("--pace", is_flag=True,
              help="Pace bytes at the baud rate, each way (10 bits per byte), like a real UART.")
@click.option("--watchdog-ms", type=click.IntRange(min=1, max=65_535), default=None, metavar="MS",
              help="Stop the motors when no motion command came for this long "
              "[default: 500; 2000 with --protocol arduino, as the stock firmware].")
@click.option("--drop", type=Number("P", fraction=True), default=0.0,
              help="Probability that a byte is lost, each way.")
@click.option("--corrupt", type=Number("P", fraction=True), default=0.0,
              help="Probability that a byte has a bit flipped, each way.")
@click.option("--latency-s", type=Number("S", non_negative=True), default=0.0,
              help="Delay before each reply leaves [s].")
@click.option("--die-after-s", type=Number("S", positive=True), default=None,
              help="Exit after this long: the port disappears mid-run [s].")
@click.option("--mute-after-s", type=Number("S", positive=True), default=None,
              help="Stop answering after this long, port still open (a hung firmware; with "
              "--boot-s, the next open of the port resets it and it answers again) [s].")
@click.option("--stall-after-s", type=Number("S", positive=True), default=None,
              help="The wheels stop turning after this long, commands still answered (an "
              "encoder cable pulled, motor power off, a wheel blocked): the encoders stop "
              "counting [s].")
@click.option("--boot-s", type=Number("S", non_negative=True), default=None,
              help="Be a board that resets whenever a host opens the port (an Arduino Uno, "
              "whose DTR line resets it): it forgets its state (speeds, encoder counts), "
              "loses what it receives for S seconds while it boots, then answers [s].")
@click.option("--seed", type=int, default=0, show_default=True,
              help="Seed of the fault injection's random numbers (with --drop or --corrupt).")
@click.option("--state-file", type=OutputPath(suffixes=(".json",)), metavar="FILE.json",
              help="Keep the emulator's state in this JSON file (rewritten atomically, 10 Hz).")
@click.option("--link", "link_path", metavar="PATH",
              help="Also make PATH a symlink to the device (a fixed name across restarts); "
              "an existing file is never replaced.")
def emulate(robot_args: RobotArgs, protocol: str, baud: int | None, ticks_per_rev: float | None,
            pid_rate: float, pace: bool, watchdog_ms: int | None, drop: float, corrupt: float,
            latency_s: float, die_after_s: float | None, mute_after_s: float | None,
            stall_after_s: float | None, boot_s: float | None, seed: int, state_file: str | None,
            link_path: str | None) -> None:
    """Act as the robot's motor controller on a pseudo-terminal.

    Prints the device to open (e.g. /dev/pts/3) on stdout, then answers in the chosen
    protocol with the robot's limits (the bundled real robot by default): wheels turn at
    the commanded speed, encoders integrate it, the arm moves to its targets, and a
    watchdog stops everything when commands stop coming. Status goes to stderr. Runs until
    Ctrl-C, SIGTERM or SIGHUP, then exits 0.

    \b
    servicebot emulate --state-file state.json &
    servicebot drive --port /dev/pts/3 --linear 0.03 --duration-s 2
    servicebot emulate --boot-s 1.2 &     # resets on every open, like an Uno
    servicebot drive --port /dev/pts/4 --boot-time-s 1.5 --reconnect ...
    """
    from servicebot_cli.drive.emulator.session import EmulateRequest
    from servicebot_cli.drive.emulator.session import emulate as serve
    from servicebot_cli.drive.emulator.wire import Faults
    from servicebot_cli.output.drive_text import announce_device, emulate_end_line, emulate_log

    _refuse_without_effect(drop, corrupt, die_after_s, mute_after_s)
    request = EmulateRequest(
        robot_args.source(), protocol, arduino_config(protocol, ticks_per_rev, pid_rate), baud,
        watchdog_ms,
        Faults(drop, corrupt, latency_s, die_after_s, mute_after_s, stall_after_s), seed, pace,
        Path(state_file) if state_file else None, Path(link_path) if link_path else None,
        boot_s)
    log = emulate_log()
    result = serve(request, log=log, announce=announce_device)
    log(emulate_end_line(result))


def _refuse_without_effect(drop: float, corrupt: float, die_after_s: float | None,
                           mute_after_s: float | None) -> None:
    """Refuse ``--seed`` without random faults, and a mute that comes after the death."""
    ctx = click.get_current_context()
    refuse_without(ctx, "--seed", "--drop P or --corrupt P", present=bool(drop or corrupt))
    if die_after_s is not None and mute_after_s is not None and mute_after_s >= die_after_s:
        raise click.BadParameter(
            f"{mute_after_s:g} s is not before --die-after-s {die_after_s:g} s, so it never "
            "happens; give a shorter --mute-after-s or drop it", param_hint="--mute-after-s")
