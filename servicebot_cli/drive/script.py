"""The drive script format: timed twists and arm targets, one per line.

::

    # comments and blank lines are ignored
    twist LINEAR ANGULAR DURATION   drive at LINEAR [m/s] and ANGULAR [rad/s] for DURATION [s]
    stop DURATION                   wheels at zero for DURATION [s]
    arm NAME=VALUE [NAME=VALUE...]  arm targets [rad] from here on; takes no time

Every error names the file and line. A twist beyond the wheels' limit is not an error: it is
scaled down as a whole, keeping its curvature, and a warning says so.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from servicebot_cli.common.errors import NameNotFound, OutOfLimits, ServicebotError
from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.plan import Step

SYNTAX = {
    "twist": "twist LINEAR ANGULAR DURATION (m/s, rad/s, s)",
    "stop": "stop DURATION (s)",
    "arm": "arm NAME=VALUE [NAME=VALUE...] (rad)",
}


class ScriptError(ServicebotError):
    """A drive script that cannot be run; the message names the file and line."""


def parse_script(text: str, name: str, motors: MotorMap) -> list[Step]:
    """The steps of a drive script.

    Args:
        text: The script.
        name: How to call it in messages (a path or ``<stdin>``).
        motors: The robot's motors, to check arm joint names and limits.

    Raises:
        ScriptError: The first problem, as ``NAME:LINE: what is wrong``.
    """
    steps: list[Step] = []
    pending_arm: list[tuple[str, float]] = []
    pending_line = 0
    for number, raw in enumerate(text.splitlines(), start=1):
        words = raw.split("#", 1)[0].split()
        if not words:
            continue
        where = f"{name}:{number}"
        keyword, args = words[0], words[1:]
        if keyword == "arm":
            pending_arm.extend(_arm(args, motors, where))
            pending_line = pending_line or number
        elif keyword in ("twist", "stop"):
            linear, angular, duration = _timed(keyword, args, where)
            steps.append(Step(duration, linear, angular, tuple(pending_arm), number, pending_line))
            pending_arm, pending_line = [], 0
        else:
            raise ScriptError(f"{where}: unknown command '{keyword}'; use twist, stop or arm "
                              f"({'; '.join(SYNTAX.values())})")
    if pending_arm:
        raise ScriptError(f"{name}:{pending_line}: arm targets after the last timed step are "
                          "never sent; add a 'stop DURATION' after them")
    if not steps:
        raise ScriptError(f"{name}: no twist or stop lines, so nothing to drive "
                          f"({'; '.join(SYNTAX.values())})")
    return steps


def _timed(keyword: str, args: list[str], where: str) -> tuple[float, float, float]:
    names = ("LINEAR", "ANGULAR", "DURATION") if keyword == "twist" else ("DURATION",)
    if len(args) != len(names):
        raise ScriptError(f"{where}: {SYNTAX[keyword]} takes {len(names)} value"
                          f"{'s' if len(names) > 1 else ''}, got {len(args)}")
    values = [_number(text, label, where) for text, label in zip(args, names, strict=True)]
    if values[-1] <= 0:
        raise ScriptError(f"{where}: DURATION must be positive, got {args[-1]}")
    return (values[0], values[1], values[2]) if keyword == "twist" else (0.0, 0.0, values[0])


def _arm(args: list[str], motors: MotorMap, where: str) -> list[tuple[str, float]]:
    if not args:
        raise ScriptError(f"{where}: {SYNTAX['arm']} needs at least one NAME=VALUE")
    pairs = []
    for arg in args:
        joint, sep, text = arg.partition("=")
        if not sep or not joint:
            raise ScriptError(f"{where}: '{arg}' is not NAME=VALUE ({SYNTAX['arm']})")
        pairs.append((joint, _number(text, f"value of {joint}", where)))
    _checked(lambda: motors.arm_targets(dict(pairs), motors.clamp_arm([0.0] * len(
        motors.arm_joints))), where)
    return pairs


def _checked(check: Callable[[], object], where: str) -> None:
    try:
        check()
    except (NameNotFound, OutOfLimits) as exc:
        raise ScriptError(f"{where}: {exc}") from None


def _number(text: str, label: str, where: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise ScriptError(f"{where}: {label} '{text}' is not a number") from None
    if not math.isfinite(value):
        raise ScriptError(f"{where}: {label} '{text}' is not a finite number")
    return value
