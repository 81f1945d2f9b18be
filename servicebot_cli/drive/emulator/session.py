"""``servicebot emulate`` without Click: build the firmware, serve it on a pty until told to stop.

SIGINT, SIGTERM and SIGHUP end the serve loop cleanly (the port closes, the symlink goes,
the state file says ``"ended": "stopped"``), so the run exits 0; ``--die-after-s`` ends it
as a crash would look to the host (``"died"``).
"""

from __future__ import annotations

import random
import signal
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from types import FrameType, TracebackType
from typing import TYPE_CHECKING

from servicebot_cli.drive.emulator.board import Board, Firmware
from servicebot_cli.drive.emulator.firmware import State
from servicebot_cli.drive.emulator.pty import PtyEmulator
from servicebot_cli.drive.emulator.wire import FaultInjector, Faults
from servicebot_cli.drive.session.signals import SignalHandler

if TYPE_CHECKING:
    from servicebot_cli.description.loader import RobotSource
    from servicebot_cli.drive.motors import MotorMap
    from servicebot_cli.drive.protocols.arduino import ArduinoConfig

STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
BINARY_WATCHDOG_MS = 500


@dataclass(frozen=True)
class EmulateRequest:
    """One ``emulate`` invocation.

    Attributes:
        robot: The robot whose motors and limits to emulate.
        protocol: ``servicebot`` or ``arduino``.
        arduino: How the ROSArduinoBridge firmware counts (``arduino`` only).
        baud: Baud rate, or None for the description's (9600, said, when it names none).
        watchdog_ms: Watchdog timeout, or None for the protocol's default [ms].
        faults: Faults to inject.
        seed: Seed of the fault injection's random numbers.
        pace: Pace bytes at the baud rate, each way.
        state_file: Where to keep the state (JSON), or None.
        link: A symlink to make to the device, or None.
        boot_s: Reset whenever a host opens the port and boot for this long, or None for
            a board that runs on regardless [s].
    """

    robot: RobotSource
    protocol: str
    arduino: ArduinoConfig | None
    baud: int | None
    watchdog_ms: int | None
    faults: Faults
    seed: int
    pace: bool
    state_file: Path | None = None
    link: Path | None = None
    boot_s: float | None = None


@dataclass(frozen=True)
class EmulateResult:
    """How the emulator ended: ``stopped`` (a signal) or ``died`` (``--die-after-s``)."""

    ending: str


class StopFlag:
    """Context manager: SIGINT, SIGTERM and SIGHUP set the flag; the serve loop sees it."""

    def __init__(self) -> None:
        self.signal: int | None = None
        self._previous: dict[int, SignalHandler] = {}

    def is_set(self) -> bool:
        """Whether a stop signal arrived."""
        return self.signal is not None

    def __enter__(self) -> StopFlag:
        for signum in STOP_SIGNALS:
            self._previous[signum] = signal.signal(signum, self._set)
        return self

    def __exit__(self, kind: type[BaseException] | None, value: BaseException | None,
                 traceback: TracebackType | None) -> None:
        for signum, handler in self._previous.items():
            signal.signal(signum, handler)

    def _set(self, signum: int, frame: FrameType | None) -> None:
        self.signal = signum


def emulate(request: EmulateRequest, *, log: Callable[[str], None],
            announce: Callable[[str], None]) -> EmulateResult:
    """Serve the robot's motor controller on a pty until a stop signal (or ``--die-after-s``).

    Args:
        request: What to emulate, and how.
        log: Told status lines.
        announce: Told the device path hosts open, once it is ready.

    Raises:
        DescriptionError: The robot cannot be loaded or carried by the protocol.
        EmulatorError: ``--link`` names a path that is not ours to replace, or cannot be made.
        OutputError: The state file cannot be written.
    """
    emulator, note = build_emulator(request, log)
    state_file = request.state_file
    stop = StopFlag()
    with stop:  # from here on, the stop signals end the serve loop cleanly
        try:
            device = emulator.open(request.link)
            if state_file is not None:
                write_state(state_file, emulator.state())  # a bad path fails before any wait
            announce(device)
            log(banner(emulator, device, request.seed))
            if note is not None:
                log(note)
            ending = emulator.serve(
                stop.is_set, (lambda s: write_state(state_file, s)) if state_file else None)
            if state_file is not None:
                write_state(state_file, {**emulator.state(), "ended": ending})
        finally:
            emulator.close()
    return EmulateResult(ending)


_FALLBACK_BAUD = 9600  # the real robot's


def build_emulator(request: EmulateRequest,
                   log: Callable[[str], None]) -> tuple[PtyEmulator, str | None]:
    """A PtyEmulator (not yet opened) for the robot of ``request``, and a note for the user.

    The note says the baud rate was assumed: the description names none, and ``drive``
    then needs ``--baud``.
    """
    from servicebot_cli.description.loader import load
    from servicebot_cli.drive.link_setup import serial_defaults
    from servicebot_cli.drive.motors import motor_map

    robot = load(request.robot)
    motors = motor_map(robot, request.robot.resolver())
    baud = request.baud or serial_defaults(robot)[1]
    note = None
    if baud is None:  # drive refuses such a description without --baud: say what to give
        baud = _FALLBACK_BAUD
        note = (f"{robot.display} names no baud_rate in <ros2_control><hardware>: the "
                f"firmware runs at {baud} baud; give drive --baud {baud}")
    start_s = time.monotonic()
    stall = request.faults.stall_after_s
    board = Board(firmware_builder(request, motors, baud,
                                   None if stall is None else start_s + stall),
                  start_s, request.boot_s)
    injector = FaultInjector(request.faults, random.Random(request.seed))
    return PtyEmulator(board, injector, baud=baud, pace=request.pace, log=log), note


def firmware_builder(request: EmulateRequest, motors: MotorMap, baud: int,
                     stall_at_s: float | None = None) -> Callable[[float], Firmware]:
    """What builds the firmware as it is when the board is powered or reset, at a time [s].

    ``stall_at_s``: when the wheels stop turning (``--stall-after-s``), a reset or not.

    Raises:
        DescriptionError: The robot cannot be carried by the binary protocol.
    """
    from servicebot_cli.drive.emulator.arduino_firmware import STOCK_AUTO_STOP_MS, ArduinoFirmware
    from servicebot_cli.drive.emulator.firmware import BinaryFirmware, MotorModel

    arduino = request.protocol == "arduino"
    watchdog_ms = request.watchdog_ms
    if watchdog_ms is None:
        watchdog_ms = STOCK_AUTO_STOP_MS if arduino else BINARY_WATCHDOG_MS
    if arduino:
        config = request.arduino
        if config is None:
            raise ValueError("the arduino protocol needs an ArduinoConfig")
        return lambda now_s: ArduinoFirmware(
            MotorModel(motors, watchdog_ms / 1000.0, now_s=now_s, stall_at_s=stall_at_s),
            config, baud)
    from servicebot_cli.drive.protocols.binary import BinaryLink

    BinaryLink(motors)  # refuses a robot the binary protocol cannot carry
    return lambda now_s: BinaryFirmware(MotorModel(motors, watchdog_ms / 1000.0, now_s=now_s,
                                                   stall_at_s=stall_at_s))


def banner(emulator: PtyEmulator, device: str, seed: int) -> str:
    """The first status line: whose controller, which protocol, watchdog, pacing and faults."""
    board = emulator.board
    pacing = f"paced at {emulator.baud} baud" if emulator.pace else "unpaced"
    if board.boot_s is not None:
        pacing += f", resets when the port opens and boots for {board.boot_s:g} s"
    faults = emulator.faults
    injected = ", ".join(f"{k} {v:g}" for k, v in (
        ("drop", faults.drop), ("corrupt", faults.corrupt), ("latency_s", faults.latency_s)) if v)
    return (f"{board.model.motors.robot}'s motor controller ({board.protocol} protocol, "
            f"watchdog {board.model.watchdog_s * 1000:.0f} ms, {pacing}"
            + (f", faults: {injected}, seed {seed}" if injected else "") + f") on {device}")


def write_state(path: Path, state: State) -> None:
    """Write the emulator's state as JSON, atomically."""
    from servicebot_cli.common.files import write_atomic
    from servicebot_cli.common.jsonable import dumps

    write_atomic(path, dumps(state))
