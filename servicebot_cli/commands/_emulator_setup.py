"""Building an emulator from the command's options (imported by ``emulate``'s callback only)."""

from __future__ import annotations

import random
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from servicebot_cli.drive.emulator.wire import FaultInjector, Faults


def build_emulator(source: Any, protocol: str, baud: int | None, arduino: Any,
                   watchdog_ms: int | None, faults: Faults, seed: int, pace: bool,
                   log: Callable[[str], None]) -> Any:
    """A PtyEmulator (not yet opened) for the robot of ``source``."""
    from servicebot_cli.description.loader import load
    from servicebot_cli.drive.driving import serial_defaults
    from servicebot_cli.drive.emulator.arduino_firmware import STOCK_AUTO_STOP_MS, ArduinoFirmware
    from servicebot_cli.drive.emulator.firmware import BinaryFirmware, MotorModel
    from servicebot_cli.drive.emulator.pty import PtyEmulator
    from servicebot_cli.drive.motors import motor_map

    robot = load(source)
    motors = motor_map(robot)
    baud = baud or serial_defaults(robot)[1] or 9600
    if watchdog_ms is None:
        watchdog_ms = STOCK_AUTO_STOP_MS if protocol == "arduino" else 500
    model = MotorModel(motors, watchdog_ms / 1000.0, now_s=time.monotonic())
    if protocol == "arduino":
        firmware: Any = ArduinoFirmware(model, arduino, baud)
    else:
        from servicebot_cli.drive.protocols.binary import BinaryLink

        BinaryLink(motors)  # refuses a robot the binary protocol cannot carry
        firmware = BinaryFirmware(model)
    injector = FaultInjector(faults, random.Random(seed))
    return PtyEmulator(firmware, injector, baud=baud, pace=pace, log=log)


def write_state(path: Path, state: dict[str, Any]) -> None:
    """Write the emulator's state as JSON, atomically."""
    from servicebot_cli.common.files import write_atomic
    from servicebot_cli.common.jsonable import dumps

    write_atomic(path, dumps(state))
