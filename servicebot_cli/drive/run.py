"""``servicebot drive`` without Click: a request in, a dry run or a finished run out.

Everything that can be checked is checked before the port opens: the robot's motors, the
protocol, the port and baud rate, the command rate, the plan (every script line, every arm
target, and with ``--dry-run`` the arm's way to each) and, for teleop, the terminal. Then
the run streams, and stops on every way out; before it sends the first arm target, it checks
the arm's way from where the firmware reports it (see :mod:`~servicebot_cli.drive.arm_guard`).
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable
from typing import TYPE_CHECKING, TypeAlias

from servicebot_cli.common.errors import OutOfLimits
from servicebot_cli.drive.arm_guard import ArmGuard, Refusal, arm_guard
from servicebot_cli.drive.driving import Driven, StreamSettings, run_drive
from servicebot_cli.drive.dry_run import DryRun, assumed_arm, dry_run
from servicebot_cli.drive.link_setup import check_rate, make_link, port_and_baud
from servicebot_cli.drive.motors import MotorMap, motor_map
from servicebot_cli.drive.plan import Plan
from servicebot_cli.drive.plans import arm_origin, one_shot_plan, script_plan
from servicebot_cli.drive.request import BadOption, DriveRequest, Keyboard, Mode, OneShot
from servicebot_cli.drive.script import ScriptError
from servicebot_cli.drive.session.commander import HostLink
from servicebot_cli.drive.teleop.terminal import Terminal, keyboard_session

if TYPE_CHECKING:
    from pathlib import Path

    from servicebot_cli.description.robot import RobotDescription

DriveResult: TypeAlias = DryRun | Driven


def drive(request: DriveRequest, *, log: Callable[[str], None],
          terminal: Terminal | None = None) -> DriveResult:
    """Plan or run ``request``; warnings and progress lines go to ``log``.

    Args:
        request: What to drive, and how.
        log: Told warnings (before the run) and events (during it), one line each.
        terminal: The keyboard and status line for teleop (default: stdin and stderr).

    Raises:
        BadOption: A value the robot or the link rules out (exit 2).
        DescriptionError: The description cannot be loaded or driven (exit 2).
        ScriptError: A script line that is wrong, or whose arm target collides (exit 2).
        BadSrdf: An ``--srdf`` file that cannot be read or names unknown links (exit 2).
        NoTerminal: Teleop without a terminal on stdin (exit 2).
        LinkError: The port cannot be opened (exit 4).
    """
    from servicebot_cli.description.loader import load

    robot = load(request.robot)
    try:
        motors = motor_map(robot, request.robot.resolver()).capped(request.max_wheel_rad_s)
    except OutOfLimits as exc:
        raise BadOption("--max-speed", str(exc)) from None
    link = make_link(request.protocol, motors, request.arduino)
    port, baud = port_and_baud(robot, request.port, request.baud, need_port=not request.dry_run)
    _refuse_log_into_port(request.log, port)
    check_rate(request.rate_hz, link, baud, None if request.dry_run else request.link_timeout_s,
               log)
    settings = StreamSettings(port, baud, request.rate_hz, request.max_accel_rad_s2,
                              request.link_timeout_s, request.connect_timeout_s,
                              request.reconnect, request.log, request.boot_s,
                              request.reconnect_attempts)
    if isinstance(request.mode, Keyboard):
        if request.dry_run:
            raise BadOption("--dry-run", "teleop has no frames to plan; give --script FILE or "
                            "--linear/--angular/--duration-s")
        keys = terminal or Terminal(sys.stdin, sys.stderr)
        with keyboard_session(keys, motors, request.mode.deadman_s) as session:
            return run_drive(settings, link, motors, session.teleop, log=log,
                             on_tick=session.on_tick, suspender=session.job_control)
    plan = _plan(request, motors, link, log)
    guard = _guard(request, robot, plan, motors)
    if request.dry_run:
        _refuse(request.mode, guard.from_start(assumed_arm(motors)) if guard else None)
        return dry_run(plan, link, motors, request.max_accel_rad_s2, request.rate_hz)
    _refuse(request.mode, guard.known_targets() if guard else None)
    return run_drive(settings, link, motors, plan, log=log,
                     arm_guard=guard.refuse_from if guard else None)


def _guard(request: DriveRequest, robot: RobotDescription, plan: Plan,
           motors: MotorMap) -> ArmGuard | None:
    """The collision checks of the plan's arm targets; None when there are none to make."""
    if not request.check_collisions or isinstance(request.mode, Keyboard):
        return None
    return arm_guard(robot, request.robot, request.srdf, plan.steps, motors,
                     arm_origin(request.mode))


def _refuse(mode: Mode, refusal: Refusal | None) -> None:
    """Raise ``refusal`` as the mode's bad input: ``--arm``'s value, or the script's line."""
    if refusal is None:
        return
    if isinstance(mode, OneShot):
        raise BadOption("--arm", refusal.reason)
    raise ScriptError(str(refusal))


def _plan(request: DriveRequest, motors: MotorMap, link: HostLink,
          log: Callable[[str], None]) -> Plan:
    if isinstance(request.mode, OneShot):
        return one_shot_plan(request.mode, motors, link, log)
    if isinstance(request.mode, Keyboard):
        raise ValueError("the keyboard has no plan")
    return script_plan(request.mode, motors, link, log)


def _refuse_log_into_port(log: Path | None, port: str) -> None:
    """Refuse a ``--log`` that is the serial port: its rows would go to the motor controller.

    Raises:
        BadOption: ``log`` and ``port`` are one file (a device the suffix check lets by).
    """
    if log is None:
        return
    try:
        same = os.path.samefile(log, port)
    except OSError:  # either is not there (yet): not the same
        return
    if same:
        raise BadOption("--log", f"{log} is the serial port {port}: the log's rows would go "
                        "to the motor controller; give a file name (run.csv)")
