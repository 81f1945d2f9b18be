"""ROSArduinoBridge firmware as a pure state machine in front of a :class:`MotorModel`.

It parses input as the firmware does (a command letter, arguments split by spaces, CR ends
the command) and implements the commands a motor board answers:

    b          " <baud>"           the baud rate
    e          "<left> <right>"    encoder counts [ticks]
    m L R      "OK"                target ticks per PID interval; ``m 0 0`` stops
    o L R      "OK"                raw PWM, -255..255 (open loop: proportional to the limit)
    r          "OK"                reset the encoders
    u P:D:I:O  "OK"                PID gains (accepted; the emulated motors need no tuning)

Anything else answers ``Invalid Command``, as the firmware does for pins and servos this
emulator has none of. The stock firmware's auto-stop is 2000 ms (AUTO_STOP_INTERVAL).
"""

from __future__ import annotations

import math

from servicebot_cli.drive.emulator.firmware import MotorModel, State
from servicebot_cli.drive.protocols.arduino import TWO_PI, ArduinoConfig

STOCK_AUTO_STOP_MS = 2000
_MAX_ARG = 31  # the firmware's argument buffers hold 32 chars with the terminator


class ArduinoFirmware:
    """ROSArduinoBridge in front of a motor model."""

    protocol = "arduino"

    def __init__(self, model: MotorModel, config: ArduinoConfig, baud: int) -> None:
        self.model = model
        self.config = config
        self.baud = baud
        self._cmd = ""
        self._args = ["", ""]
        self._arg = 0
        self._offset_rad = [0.0] * len(model.wheel_position_rad)
        self._max_ticks = config.max_ticks(model.motors.max_wheel_rad_s)

    def receive(self, data: bytes, now_s: float) -> bytes:
        """Handle the bytes received at ``now_s``; return the reply lines."""
        out = []
        for char in data.decode("latin-1"):
            if char == "\r":
                out.append(self._run(now_s) + "\r\n")
                self._cmd, self._args, self._arg = "", ["", ""], 0
            elif char == " ":
                self._arg = min(self._arg + 1, 2)
            elif self._arg == 0:
                self._cmd = char
            elif len(self._args[self._arg - 1]) < _MAX_ARG:
                self._args[self._arg - 1] += char
        self.model.advance(now_s)
        return "".join(out).encode("latin-1")

    def _run(self, now_s: float) -> str:
        self.model.counters.frames += 1
        first, second = _atoi(self._args[0]), _atoi(self._args[1])
        if self._cmd == "b":
            return f" {self.baud}"
        if self._cmd == "e":
            left, right = self.encoder_ticks(now_s)
            return f"{left} {right}"
        if self._cmd == "m":
            self._set_sides(self.config.speed_rad_s(self._limit(first)),
                            self.config.speed_rad_s(self._limit(second)), now_s)
        elif self._cmd == "o":
            top = self.model.motors.max_wheel_rad_s
            self._set_sides(top * max(-255, min(255, first)) / 255,
                            top * max(-255, min(255, second)) / 255, now_s)
        elif self._cmd == "r":
            self.model.advance(now_s)
            self._offset_rad = list(self.model.wheel_position_rad)
        elif self._cmd != "u":
            return "Invalid Command"
        return "OK"

    def _limit(self, ticks: int) -> int:
        return max(-self._max_ticks, min(self._max_ticks, ticks))

    def _set_sides(self, left_rad_s: float, right_rad_s: float, now_s: float) -> None:
        if left_rad_s == 0.0 and right_rad_s == 0.0:
            self.model.stop(now_s)
            return
        self.model.command_wheels(self.model.motors.side_speeds(left_rad_s, right_rad_s), now_s)

    def encoder_ticks(self, now_s: float) -> tuple[int, int]:
        """Left and right encoder counts (mean of each side's wheels) [ticks]."""
        self.model.advance(now_s)
        motors = self.model.motors
        sides: dict[str, list[float]] = {"left": [], "right": []}
        for i, (side, sign) in enumerate(zip(motors.wheel_sides, motors.wheel_axis_signs,
                                             strict=True)):
            sides[side].append(sign * (self.model.wheel_position_rad[i] - self._offset_rad[i]))
        per_rad = self.config.ticks_per_rev / TWO_PI
        left, right = (math.floor(sum(v) / len(v) * per_rad + 0.5)
                       for v in (sides["left"], sides["right"]))
        return left, right

    def state(self) -> State:
        """Extra state for the emulator's state file."""
        left, right = self.encoder_ticks(self.model.now_s)
        return {"encoder_ticks": {"left": left, "right": right}}


def _atoi(text: str) -> int:
    """C's ``atoi``: leading sign and digits, 0 when there are none."""
    digits = ""
    for i, char in enumerate(text):
        if char.isdigit() or (i == 0 and char in "+-"):
            digits += char
        else:
            break
    try:
        return int(digits)
    except ValueError:
        return 0
