"""``servicebot emulate``: the robot's motor controller on a pseudo-terminal, for testing."""

from __future__ import annotations

import signal
import sys
import time
from pathlib import Path
from typing import Any

import click

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.options import RobotArgs, robot_arguments
from servicebot_cli.commands.serial_options import (
    Number,
    arduino_config,
    serial_options,
)


@click.command(cls=Command)
@robot_arguments(default="real")
@serial_options
@click.option("--pace", is_flag=True,
              help="Pace bytes at the baud rate, each way (10 bits per byte), like a real UART.")
@click.option("--watchdog-ms", type=click.IntRange(min=1), default=None, metavar="MS",
              help="Stop the motors when no motion command came for this long "
              "[default: 500; 2000 with --protocol arduino, as the stock firmware].")
@click.option("--drop", type=Number("P", fraction=True), default=0.0,
              help="Probability that a byte is lost, each way.")
@click.option("--corrupt", type=Number("P", fraction=True), default=0.0,
              help="Probability that a byte has a bit flipped, each way.")
@click.option("--latency", type=Number("S", non_negative=True), default=0.0,
              help="Delay before each reply leaves [s].")
@click.option("--die-after", type=Number("S", positive=True), default=None,
              help="Exit after this long: the port disappears mid-run [s].")
@click.option("--mute-after", type=Number("S", positive=True), default=None,
              help="Stop answering after this long, port still open [s].")
@click.option("--seed", type=int, default=0, show_default=True,
              help="Seed of the fault injection's random numbers.")
@click.option("--state-file", metavar="FILE.json",
              help="Keep the emulator's state in this JSON file (rewritten atomically, 10 Hz).")
@click.option("--link", "link_path", metavar="PATH",
              help="Also make PATH a symlink to the device (a fixed name across restarts).")
def emulate(robot_args: RobotArgs, protocol: str, baud: int | None, ticks_per_rev: float | None,
            pid_rate: float, pace: bool, watchdog_ms: int | None, drop: float, corrupt: float,
            latency: float, die_after: float | None, mute_after: float | None, seed: int,
            state_file: str | None, link_path: str | None) -> None:
    """Act as the robot's motor controller on a pseudo-terminal.

    Prints the device to open (e.g. /dev/pts/3) on stdout, then answers in the chosen
    protocol with the robot's limits (the bundled real robot by default): wheels turn at
    the commanded speed, encoders integrate it, the arm moves to its targets, and a
    watchdog stops everything when commands stop coming. Status goes to stderr. Runs until
    Ctrl-C or SIGTERM, then exits 0.

    \b
    servicebot emulate --state-file state.json &
    servicebot drive --port /dev/pts/3 --linear 0.03 --duration 2
    """
    from servicebot_cli.commands._emulator_setup import build_emulator, write_state
    from servicebot_cli.drive.emulator.wire import Faults

    faults = Faults(drop, corrupt, latency, die_after, mute_after)
    arduino = arduino_config(protocol, ticks_per_rev, pid_rate)
    emulator = build_emulator(robot_args.source(), protocol, baud,
                              arduino, watchdog_ms, faults, seed, pace, _log)
    state_path = Path(state_file) if state_file else None
    stop = _StopFlag()
    with stop:  # from here on, SIGINT and SIGTERM end the serve loop cleanly
        try:
            device = emulator.open(Path(link_path) if link_path else None)
            if state_path is not None:
                write_state(state_path, emulator.state())  # a bad path fails before any wait
            click.echo(device)
            sys.stdout.flush()
            _log(_banner(emulator, device, seed))
            ending = emulator.serve(stop.is_set, lambda s: write_state(state_path, s)
                                    if state_path is not None else None)
            if state_path is not None:
                write_state(state_path, {**emulator.state(), "ended": ending})
        finally:
            emulator.close()
    _log("port closed" if ending == "died" else "stopped; port closed")


def _banner(emulator: Any, device: str, seed: int) -> str:
    firmware = emulator.firmware
    pacing = f"paced at {emulator.baud} baud" if emulator.pace else "unpaced"
    faults = emulator.faults
    injected = ", ".join(f"{k} {v:g}" for k, v in (
        ("drop", faults.drop), ("corrupt", faults.corrupt), ("latency_s", faults.latency_s)) if v)
    return (f"{firmware.model.motors.robot}'s motor controller ({firmware.protocol} protocol, "
            f"watchdog {firmware.model.watchdog_s * 1000:.0f} ms, {pacing}"
            + (f", faults: {injected}, seed {seed}" if injected else "") + f") on {device}")


_START = time.monotonic()


def _log(line: str) -> None:
    click.echo(f"emulate {time.monotonic() - _START:7.2f}s: {line}", err=True)


class _StopFlag:
    """SIGINT and SIGTERM set the flag; the serve loop sees it within 20 ms."""

    def __init__(self) -> None:
        self.signal: int | None = None
        self._previous: dict[int, Any] = {}

    def is_set(self) -> bool:
        return self.signal is not None

    def __enter__(self) -> _StopFlag:
        for signum in (signal.SIGINT, signal.SIGTERM):
            self._previous[signum] = signal.signal(signum, self._set)
        return self

    def __exit__(self, *exc: object) -> None:
        for signum, handler in self._previous.items():
            signal.signal(signum, handler)

    def _set(self, signum: int, frame: object) -> None:
        self.signal = signum
