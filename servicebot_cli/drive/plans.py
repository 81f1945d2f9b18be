"""The plan of a script or a one-shot command, checked against the robot before any motion.

A twist the wheels cannot do is not an error: it is scaled down as a whole (the path keeps
its curvature) and ``warn`` is told so, naming the script line or the options.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from servicebot_cli.common.errors import NameNotFound, OutOfLimits
from servicebot_cli.common.inputs import read_input_text
from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.plan import Plan, Step
from servicebot_cli.drive.request import BadOption, OneShot, ScriptFile
from servicebot_cli.drive.script import ScriptError, parse_script
from servicebot_cli.drive.session.commander import HostLink
from servicebot_cli.drive.shaping import WheelShaper
from servicebot_cli.kinematics.diff_drive import body_twist

NO_ARM = "the ROSArduinoBridge protocol has no arm; arm targets need --protocol servicebot"


def script_plan(script: ScriptFile, motors: MotorMap, link: HostLink,
                warn: Callable[[str], None]) -> Plan:
    """The plan of a script file (``-`` for stdin), checked line by line.

    Raises:
        ScriptError: Unreadable, or a line that is wrong (named by number).
    """
    name = script_name(script)
    text = read_input_text(script.path, kind="a drive script, or '-' for stdin",
                           error=ScriptError)
    steps = parse_script(text, name, motors)
    for step in steps:
        if step.arm and not link.has_arm:
            raise ScriptError(f"{name}:{step.arm_line}: {NO_ARM}")
        warn_if_scaled(step, motors, f"{name}:{step.line}", warn)
    return Plan(steps)


def script_name(script: ScriptFile) -> str:
    """How messages name a script: its path, or ``<stdin>``."""
    return "<stdin>" if script.path == "-" else script.path


def arm_origin(mode: OneShot | ScriptFile) -> Callable[[Step], str]:
    """Names where a step's arm targets came from: ``tour.txt:3``, or ``--arm``."""
    if isinstance(mode, OneShot):
        return lambda step: "--arm"
    name = script_name(mode)
    return lambda step: f"{name}:{step.arm_line}"


def one_shot_plan(one_shot: OneShot, motors: MotorMap, link: HostLink,
                  warn: Callable[[str], None]) -> Plan:
    """The plan of ``--linear/--angular/--duration-s/--arm``.

    Raises:
        BadOption: Arm targets with a protocol without an arm, or a bad arm target.
    """
    if one_shot.arm and not link.has_arm:
        raise BadOption("--arm", NO_ARM)
    try:
        motors.arm_targets(dict(one_shot.arm),
                           motors.clamp_arm([0.0] * len(motors.arm_joints)))
    except (NameNotFound, OutOfLimits) as exc:
        raise BadOption("--arm", str(exc)) from None
    step = Step(one_shot.duration_s, one_shot.linear_m_s, one_shot.angular_rad_s,
                one_shot.arm)
    warn_if_scaled(step, motors, "--linear/--angular", warn)
    return Plan([step])


def warn_if_scaled(step: Step, motors: MotorMap, where: str,
                   warn: Callable[[str], None]) -> None:
    """Tell ``warn`` when ``step``'s twist is beyond the wheels and what it becomes."""
    shaper = WheelShaper(motors, 1.0)
    wanted = shaper.unlimited(step.linear_m_s, step.angular_rad_s)
    left, right = shaper.target(step.linear_m_s, step.angular_rad_s)
    if all(math.isclose(got, asked, rel_tol=1e-9) for got, asked in zip(
            (left, right), wanted, strict=True)):  # at the limit but for rounding
        return
    linear, angular = body_twist(left, right, wheel_radius_m=motors.wheel_radius_m,
                                 track_m=motors.track_m)
    needed = max(map(abs, wanted))
    needs = f"{needed:.3g} rad/s" if math.isfinite(needed) else "more rad/s than a float holds"
    warn(f"warning: {where}: twist {step.linear_m_s:g} m/s, {step.angular_rad_s:g} rad/s "
         f"needs {needs} of the wheels, over their "
         f"{motors.max_wheel_rad_s:g} rad/s limit; scaled to {linear:.4g} m/s, "
         f"{angular:.4g} rad/s (curvature kept)")
