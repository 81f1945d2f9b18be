"""What ``drive`` drives: a script, a one-shot command or the keyboard, checked up front.

Imported by the drive command's callback only (it pulls in the link package).
"""

from __future__ import annotations

import contextlib
import os
import sys
from collections.abc import Callable, Iterator
from typing import Any

import click

from servicebot_cli.common.errors import ExitCode, NameNotFound, OutOfLimits, ServicebotError
from servicebot_cli.common.inputs import read_input_text
from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.plan import Plan, Step
from servicebot_cli.drive.script import ScriptError, parse_script
from servicebot_cli.drive.shaping import WheelShaper
from servicebot_cli.kinematics.diff_drive import body_twist

NO_ARM = "the ROSArduinoBridge protocol has no arm; arm targets need --protocol servicebot"


class NoTerminal(ServicebotError):
    """Teleop asked for without a terminal on stdin."""

    exit_code = ExitCode.USAGE


def script_plan(script: str, motors: MotorMap, link: Any) -> Plan:
    """The plan of a script file (``-`` for stdin), checked line by line.

    Raises:
        ScriptError: Unreadable, or a line that is wrong (named by number).
    """
    name = "<stdin>" if script == "-" else script
    text = read_input_text(script, kind="a drive script, or '-' for stdin", error=ScriptError)
    steps = parse_script(text, name, motors)
    for step in steps:
        if step.arm and not link.has_arm:
            raise ScriptError(f"{name}:{step.arm_line}: {NO_ARM}")
        _warn_if_scaled(step, motors, f"{name}:{step.line}")
    return Plan(steps)


def one_shot_plan(linear: float | None, angular: float | None, duration: float | None,
                  arm: tuple[tuple[str, float], ...], motors: MotorMap, link: Any) -> Plan:
    """The plan of ``--linear/--angular/--duration/--arm``.

    Raises:
        click.BadParameter: No duration, an arm with arduino, or a bad arm target.
    """
    if duration is None:
        raise click.BadParameter("needed with --linear, --angular or --arm",
                                 param_hint="--duration")
    if arm and not link.has_arm:
        raise click.BadParameter(NO_ARM, param_hint="--arm")
    try:
        motors.arm_targets(dict(arm), motors.clamp_arm([0.0] * len(motors.arm_joints)))
    except (NameNotFound, OutOfLimits) as exc:
        raise click.BadParameter(str(exc), param_hint="--arm") from None
    step = Step(duration, linear or 0.0, angular or 0.0, tuple(arm))
    _warn_if_scaled(step, motors, "--linear/--angular")
    return Plan([step])


def _warn_if_scaled(step: Step, motors: MotorMap, where: str) -> None:
    shaper = WheelShaper(motors, 1.0)
    wanted = shaper.unlimited(step.linear_m_s, step.angular_rad_s)
    left, right = shaper.target(step.linear_m_s, step.angular_rad_s)
    if (left, right) != wanted:
        linear, angular = body_twist(left, right, wheel_radius_m=motors.wheel_radius_m,
                                     track_m=motors.track_m)
        click.echo(
            f"drive: warning: {where}: twist {step.linear_m_s:g} m/s, {step.angular_rad_s:g} "
            f"rad/s needs {max(map(abs, wanted)):.3g} rad/s of the wheels, over their "
            f"{motors.max_wheel_rad_s:g} rad/s limit; scaled to {linear:.4g} m/s, "
            f"{angular:.4g} rad/s (curvature kept)", err=True)


@contextlib.contextmanager
def teleop_session(plan: Plan | None, motors: MotorMap
                   ) -> Iterator[tuple[Any, Callable[[Any], None] | None]]:
    """``(source, on_tick)``: the plan with a status line, or the keyboard in cbreak mode.

    Raises:
        NoTerminal: Teleop without a terminal on stdin.
    """
    from servicebot_cli.drive.teleop.keyboard import Teleop, cbreak_terminal, status_line

    if plan is not None:
        yield plan, None
        return
    if not sys.stdin.isatty():
        raise NoTerminal("teleop needs a terminal on stdin; give --script FILE (or - for "
                         "stdin) or --linear/--angular --duration")
    teleop = Teleop(sys.stdin.fileno(), motors.geometry.max_linear_m_s,
                    motors.geometry.max_angular_rad_s)

    def on_tick(status: Any) -> None:
        if sys.stderr.isatty():  # one line that rewrites itself: never wider than the terminal
            width = _columns(sys.stderr.fileno()) - 1
            sys.stderr.write(f"\r\x1b[K{status_line(status, teleop, motors.wheel_sides, width)}")
            sys.stderr.flush()

    with cbreak_terminal(sys.stdin.fileno()):
        try:
            yield teleop, on_tick
        finally:
            sys.stderr.write("\n")


def _columns(fd: int) -> int:
    """Width of the terminal on ``fd`` (80 when it does not say)."""
    try:
        return os.get_terminal_size(fd).columns or 80
    except OSError:
        return 80
