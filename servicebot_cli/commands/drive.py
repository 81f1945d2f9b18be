"""``servicebot drive``: stream commands to the motors over serial, and stop them on every exit."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import click

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.options import JointValue, RobotArgs, format_option, robot_arguments
from servicebot_cli.commands.serial_options import (
    Number,
    arduino_config,
    serial_options,
)


@click.command(cls=Command)
@robot_arguments(default="real")
@click.option("--port", metavar="PATH",
              help="Serial device (default: the description's ros2_control port, "
              "/dev/ttyUSB0 for the real robot).")
@serial_options
@click.option("--script", metavar="FILE",
              help="Drive a script of timed twists and arm targets ('-' reads stdin).")
@click.option("--linear", type=Number("M_S"), help="One-shot forward speed [m/s].")
@click.option("--angular", type=Number("RAD_S"), help="One-shot yaw rate [rad/s].")
@click.option("--duration", type=Number("S", positive=True), help="One-shot duration [s].")
@click.option("--arm", "arm", type=JointValue(), multiple=True,
              help="One-shot arm target NAME=VALUE [rad] (repeatable).")
@click.option("--rate", type=Number("HZ", positive=True), default=20.0, show_default=True,
              help="Commands per second; refused above what the baud rate carries.")
@click.option("--max-accel", type=Number("RAD_S2", positive=True), default=1.0,
              show_default=True, help="Wheel acceleration limit [rad/s^2].")
@click.option("--link-timeout", type=Number("S", positive=True), default=1.0,
              show_default=True, help="No reply for this long is a lost link (exit 5) [s].")
@click.option("--connect-timeout", type=Number("S", positive=True), default=2.0,
              show_default=True, help="How long the firmware may take to answer at first [s].")
@click.option("--reconnect", is_flag=True,
              help="After a lost link, reopen the port and go on (motors at zero meanwhile).")
@click.option("--log", "log_path", metavar="FILE.csv",
              help="Write every telemetry reply to a CSV file (kept on every exit).")
@click.option("--dry-run", is_flag=True, help="Print the frames a run would send; no port.")
@format_option
def drive(robot_args: RobotArgs, port: str | None, baud: int | None, protocol: str,
          ticks_per_rev: float | None, pid_rate: float, script: str | None,
          linear: float | None, angular: float | None, duration: float | None,
          arm: tuple[tuple[str, float], ...], rate: float, max_accel: float,
          link_timeout: float, connect_timeout: float, reconnect: bool,
          log_path: str | None, dry_run: bool, fmt: str) -> None:
    """Stream commands to the motors over serial, safely; stop them on every exit.

    Kinematics and limits come from the robot description (the bundled real robot by
    default): twists become wheel speeds with its radius and track, within its wheel
    velocity limits (curvature kept), acceleration-limited; arm targets stay within its
    joint limits.

    \b
    Modes:
      (none)                       teleop from the keyboard (needs a terminal)
      --script FILE|-              timed twists and arm targets (see README)
      --linear V --angular W --duration S [--arm NAME=VALUE...]   one shot

    \b
    Exit codes: 0 done, motors stopped; 2 bad input; 3 internal error (motors stopped);
    4 link error (port missing, permission, busy, no answer, wrong protocol);
    5 link lost mid-run; 130 Ctrl-C; 143 SIGTERM (each after stopping the motors).
    """
    from servicebot_cli.description.loader import load
    from servicebot_cli.drive.motors import motor_map

    robot = load(robot_args.source())
    motors = motor_map(robot)
    link = _link(protocol, motors, arduino_config(protocol, ticks_per_rev, pid_rate))
    port, baud = _port_and_baud(robot, port, baud, dry_run)
    _check_rate(rate, link, baud, link_timeout)
    source = _source(script, linear, angular, duration, arm, motors, link)
    if dry_run:
        _dry_run(source, link, motors, max_accel, rate, fmt)
        return
    from servicebot_cli.drive.driving import DriveRequest

    request = DriveRequest(port, baud, rate, max_accel, link_timeout, connect_timeout,
                           reconnect, Path(log_path) if log_path else None)
    _run(request, link, motors, source, fmt)


def _link(protocol: str, motors: Any, arduino: Any) -> Any:
    from servicebot_cli.drive.driving import make_link

    return make_link(protocol, motors, arduino)


def _port_and_baud(robot: Any, port: str | None, baud: int | None,
                   dry_run: bool) -> tuple[str, int]:
    from servicebot_cli.drive.driving import serial_defaults

    default_port, default_baud = serial_defaults(robot)
    port = port or default_port
    baud = baud or default_baud
    if port is None and not dry_run:
        raise click.BadParameter(
            f"{robot.display} names no serial port in <ros2_control><hardware>; give --port "
            "(`servicebot emulate` makes a test port)", param_hint="--port")
    if baud is None:
        raise click.BadParameter(
            f"{robot.display} names no baud_rate in <ros2_control><hardware>; give --baud",
            param_hint="--baud")
    return port or "(none)", baud


def _check_rate(rate: float, link: Any, baud: int, link_timeout: float) -> None:
    from servicebot_cli.drive.driving import COMFORT, MIN_RATE_HZ, link_capacity_hz

    capacity = link_capacity_hz(link, baud)
    frame = max(link.command_bytes, link.reply_bytes)
    if rate > capacity:
        raise click.BadParameter(
            f"{rate:g} Hz needs {rate * frame:.0f} bytes/s one way ({frame}-byte frames) but "
            f"{baud} baud carries {baud / 10:.0f}; at most {capacity:.1f} Hz",
            param_hint="--rate")
    if rate < MIN_RATE_HZ:
        raise click.BadParameter(
            f"{rate:g} Hz is too slow to keep the firmware's watchdog fed; give at least "
            f"{MIN_RATE_HZ:g} Hz", param_hint="--rate")
    if rate > COMFORT * capacity:
        click.echo(f"drive: warning: {rate:g} Hz uses {rate / capacity:.0%} of the {baud}-baud "
                   f"link; below {COMFORT * capacity:.0f} Hz leaves room for retries", err=True)
    if link_timeout < 2.0 / rate:
        raise click.BadParameter(
            f"{link_timeout:g} s is shorter than two command periods at {rate:g} Hz",
            param_hint="--link-timeout")


def _source(script: str | None, linear: float | None, angular: float | None,
            duration: float | None, arm: tuple[tuple[str, float], ...], motors: Any,
            link: Any) -> Any:
    one_shot = any(v is not None for v in (linear, angular, duration)) or bool(arm)
    if script is not None and one_shot:
        raise click.UsageError("give --script or --linear/--angular/--duration/--arm, not both")
    if script is not None:
        from servicebot_cli.commands._drive_plans import script_plan

        return script_plan(script, motors, link)
    if one_shot:
        from servicebot_cli.commands._drive_plans import one_shot_plan

        return one_shot_plan(linear, angular, duration, arm, motors, link)
    return None  # teleop, set up once the terminal is checked


def _dry_run(plan: Any, link: Any, motors: Any, max_accel: float, rate: float, fmt: str) -> None:
    from servicebot_cli.common.jsonable import dumps
    from servicebot_cli.drive.dry_run import dry_run_lines, planned_frames

    if plan is None:
        raise click.UsageError("--dry-run needs a plan: --script FILE or "
                               "--linear/--angular/--duration (teleop has no frames to plan)")
    if fmt == "json":
        click.echo(dumps(list(planned_frames(plan, link, motors, max_accel, rate))), nl=False)
        return
    for line in dry_run_lines(plan, link, motors, max_accel, rate):
        click.echo(line)


def _run(request: Any, link: Any, motors: Any, source: Any, fmt: str) -> None:
    from servicebot_cli.commands._drive_plans import teleop_session
    from servicebot_cli.common.jsonable import dumps
    from servicebot_cli.drive.driving import run_drive

    def log(line: str) -> None:
        click.echo(f"\r\x1b[Kdrive: {line}" if sys.stderr.isatty() else f"drive: {line}",
                   err=True)

    def on_summary(summary: Any) -> None:
        if fmt == "json":
            click.echo(dumps(summary), nl=False)

    with teleop_session(source, motors) as (plan, on_tick):
        summary = run_drive(request, link, motors, plan, log=log, on_tick=on_tick,
                            on_summary=on_summary)
    if fmt == "text":
        confirmed = " (the firmware confirmed)" if summary.stop_confirmed else ""
        log(f"done: {summary.commands} commands and {summary.replies} replies in "
            f"{summary.duration_s:.1f} s, {summary.errors} errors, {summary.reconnects} "
            f"reconnects; motors stopped{confirmed}")
