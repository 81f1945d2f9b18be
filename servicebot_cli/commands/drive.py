"""``servicebot drive``: stream commands to the motors over serial, and stop them on every exit."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import click

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.kinematics_options import srdf_option
from servicebot_cli.commands.options import (
    JointValue,
    Number,
    OutputPath,
    RobotArgs,
    SerialPort,
    format_option,
    refuse_with,
    refuse_without,
    robot_arguments,
)
from servicebot_cli.commands.serial_options import (
    arduino_config,
    bad_options,
    serial_options,
)

if TYPE_CHECKING:
    from servicebot_cli.drive.request import Mode

# Options that only a run on a port uses, and why --dry-run makes them pointless.
_PORT_ONLY = (("--port", "port", "no port is opened"),
              ("--log", "log_path", "no telemetry comes back"),
              ("--reconnect", "reconnect", "no link to lose"),
              ("--connect-timeout-s", "connect_timeout_s", "no firmware to wait for"),
              ("--link-timeout-s", "link_timeout_s", "no link to lose"),
              ("--boot-time-s", "boot_time_s", "no board to boot"),
              ("--reconnect-attempts", "reconnect_attempts", "no link to lose"))


_DAY_S = 86_400.0
"""The longest wait an option may ask for: past it, the system's clock calls overflow (1e10 s
ended in an internal error), and no board takes a day to answer."""

@click.command(cls=Command)
@robot_arguments(default="real")
@click.option("--port", type=SerialPort(), metavar="PATH",
              help="Serial device (default: the description's ros2_control port, "
              "/dev/ttyUSB0 for the real robot).")
@serial_options
@click.option("--script", metavar="FILE",
              help="Drive a script of timed twists and arm targets ('-' reads stdin).")
@click.option("--linear", type=Number("M_S"), help="One-shot forward speed [m/s].")
@click.option("--angular", type=Number("RAD_S"), help="One-shot yaw rate [rad/s].")
@click.option("--duration-s", type=Number("S", positive=True), help="One-shot duration [s].")
@click.option("--arm", "arm", type=JointValue(), multiple=True,
              help="One-shot arm target NAME=VALUE [rad] (repeatable).")
@click.option("--allow-collisions", is_flag=True,
              help="Send arm targets even when they, or the arm's way to them, put links of "
              "the robot into each other or the floor (refused by default, as ik does).")
@srdf_option
@click.option("--max-speed", type=Number("RAD_S", positive=True), default=None,
              help="Cap every wheel at this speed [rad/s], below the URDF's limit (first "
              "tests on a real robot).")
@click.option("--deadman-ms", type=click.IntRange(min=1), default=None, metavar="MS",
              help="Teleop: stop the wheels when no key arrived for this long (hold a key: "
              "auto-repeat keeps them going; give more than its delay, ~600 ms).")
@click.option("--rate", type=Number("HZ", positive=True), default=20.0, show_default=True,
              help="Commands per second; refused above what the baud rate carries.")
@click.option("--max-accel", type=Number("RAD_S2", positive=True), default=1.0,
              show_default=True, help="Wheel acceleration limit [rad/s^2].")
@click.option("--link-timeout-s", type=Number("S", positive=True, maximum=_DAY_S), default=1.0,
              show_default=True, help="No reply for this long is a lost link (exit 5) [s].")
@click.option("--connect-timeout-s", type=Number("S", positive=True, maximum=_DAY_S),
              default=2.0,
              show_default=True, help="How long the firmware may take to answer at first [s].")
@click.option("--boot-time-s", type=Number("S", non_negative=True, maximum=_DAY_S), default=0.0,
              show_default=True,
              help="Wait this long after opening the port before the handshake, at the "
              "start and on every reconnect: a board that resets when the port opens "
              "(Arduino Uno) needs ~1.5 s [s].")
@click.option("--reconnect", is_flag=True,
              help="After a lost link, reopen the port and go on (motors at zero meanwhile); "
              "pauses between attempts back off from 0.5 s to 4 s.")
@click.option("--reconnect-attempts", type=click.IntRange(min=1), default=8, show_default=True,
              metavar="N", help="With --reconnect: attempts before a lost link ends the run "
              "(exit 5).")
@click.option("--log", "log_path", type=OutputPath(suffixes=(".csv",)), metavar="FILE.csv",
              help="Write every telemetry reply to a CSV file (kept on every exit).")
@click.option("--dry-run", is_flag=True, help="Print the frames a run would send; no port.")
@format_option
def drive(robot_args: RobotArgs, port: str | None, baud: int | None, protocol: str,
          ticks_per_rev: float | None, pid_rate: float, script: str | None,
          linear: float | None, angular: float | None, duration_s: float | None,
          arm: tuple[tuple[str, float], ...], allow_collisions: bool, srdf: str | None,
          max_speed: float | None,
          deadman_ms: int | None, rate: float, max_accel: float, link_timeout_s: float,
          connect_timeout_s: float, boot_time_s: float, reconnect: bool,
          reconnect_attempts: int, log_path: str | None, dry_run: bool, fmt: str) -> None:
    """Stream commands to the motors over serial, safely; stop them on every exit.

    Kinematics and limits come from the robot description (the bundled real robot by
    default): twists become wheel speeds with its radius and track, within its wheel
    velocity limits (curvature kept), acceleration-limited; arm targets stay within its
    joint limits, and one that puts links of the robot into each other or the floor, there
    or on the arm's way there, is refused before it is sent (ik's collision check).

    \b
    Modes:
      (none)                       teleop from the keyboard (needs a terminal)
      --script FILE|-              timed twists and arm targets (see README)
      --linear V --angular W --duration-s S [--arm NAME=VALUE...]   one shot

    \b
    Exit codes: 0 done, motors stopped; 2 bad input; 3 internal error (motors stopped);
    4 link error (port missing, permission, busy, no answer, wrong protocol);
    5 link lost mid-run (with --reconnect: every attempt failed); 129 SIGHUP;
    130 Ctrl-C; 131 SIGQUIT; 143 SIGTERM (each after stopping the motors).
    """
    from servicebot_cli.drive.driving import Driven
    from servicebot_cli.drive.request import DriveRequest
    from servicebot_cli.drive.run import drive as run_drive
    from servicebot_cli.output.drive_text import drive_log, show_drive

    _refuse_without_effect(dry_run, reconnect, arm_targets=bool(arm) or script is not None,
                           allow_collisions=allow_collisions)
    mode = _mode(script, linear, angular, duration_s, arm, dry_run, deadman_ms)
    request = DriveRequest(
        robot_args.source(), mode, protocol, arduino_config(protocol, ticks_per_rev, pid_rate),
        port, baud, rate, max_accel, link_timeout_s, connect_timeout_s, reconnect,
        Path(log_path) if log_path else None, dry_run, boot_time_s, max_speed,
        reconnect_attempts, not allow_collisions, srdf)
    with bad_options():
        result = run_drive(request, log=drive_log)
    show_drive(result, fmt)
    if isinstance(result, Driven) and result.failure is not None:
        raise result.failure


def _refuse_without_effect(dry_run: bool, reconnect: bool, *, arm_targets: bool,
                           allow_collisions: bool) -> None:
    """Refuse options that would change nothing.

    A port's options with ``--dry-run``, ``--reconnect-attempts`` without a reconnect, the
    collision options without arm targets (teleop, or a one-shot without ``--arm``), and
    ``--srdf`` with ``--allow-collisions``.
    """
    ctx = click.get_current_context()
    for option, name, why in _PORT_ONLY:
        refuse_with(ctx, option, "--dry-run", why=why, present=dry_run, name=name)
    refuse_without(ctx, "--reconnect-attempts", "--reconnect", present=reconnect)
    for option in ("--allow-collisions", "--srdf"):
        refuse_without(ctx, option, "arm targets (--arm NAME=VALUE or a --script)",
                       present=arm_targets)
    refuse_with(ctx, "--srdf", "--allow-collisions", present=allow_collisions,
                why="which checks no pair")


def _mode(script: str | None, linear: float | None, angular: float | None,
          duration_s: float | None, arm: tuple[tuple[str, float], ...], dry_run: bool,
          deadman_ms: int | None) -> Mode:
    """What to drive, from the mode options; refuses a mix of modes and a missing duration."""
    from servicebot_cli.drive.request import Keyboard, OneShot, ScriptFile

    one_shot = any(v is not None for v in (linear, angular, duration_s)) or bool(arm)
    if deadman_ms is not None and (script is not None or one_shot):
        raise click.UsageError("--deadman-ms is for teleop (no --script, no --linear/"
                               "--angular/--duration-s): a plan has no keys to hold")
    if script is not None and one_shot:
        raise click.UsageError("give --script or --linear/--angular/--duration-s/--arm, "
                               "not both")
    if script is not None:
        return ScriptFile(script)
    if not one_shot:
        if dry_run:
            raise click.UsageError("--dry-run needs a plan: --script FILE or --linear/--angular"
                                   "/--duration-s (teleop has no frames to plan)")
        return Keyboard(None if deadman_ms is None else deadman_ms / 1000.0)
    if duration_s is None:
        raise click.BadParameter("needed with --linear, --angular or --arm",
                                 param_hint="--duration-s")
    return OneShot(linear or 0.0, angular or 0.0, duration_s, arm)
