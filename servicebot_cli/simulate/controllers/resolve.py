"""The controller a run uses: defaults, then the controllers file, the scenario, the command line.

Each later source overrides the earlier ones field by field, and every field remembers where
its value came from, for the summary. As diff_drive_controller does, a minimum limit left
unset mirrors its maximum (``min_acceleration = -max_acceleration``), but not under gz-sim's
DiffDrive system, whose gz-math limiter leaves it unbounded; a maximum the scenario
or the command line sets replaces the file's pair of limits. Odometry and joint states are
published at most at the control rate (a controllers file's ``update_rate`` of 30 Hz with
the default 50 Hz streams).
"""

from __future__ import annotations

import dataclasses
import math

from servicebot_cli.simulate.controllers.config import ControllersFile
from servicebot_cli.simulate.controllers.limiter import GZ_MATH
from servicebot_cli.simulate.scenario.definition import Controller, Scenario
from servicebot_cli.simulate.scenario.located import ScenarioError

DEFAULT = "default"
SCENARIO = "scenario"
COMMAND_LINE = "command line"


def resolve(scenario: Scenario, file: ControllersFile) -> Scenario:
    """``scenario`` with the file's values where neither it nor the command line set one."""
    own = scenario.controller_given | scenario.controller_cli
    # a maximum set here replaces the file's pair: its minimum mirrors it unless set too
    paired = {"min_" + k[4:] for k in own if k.startswith("max_")}
    from_file = {k: v for k, v in file.values.items() if k not in own | paired}
    controller = dataclasses.replace(scenario.controller, **from_file)
    origin = {}
    for name in (f.name for f in dataclasses.fields(Controller)):
        if name in scenario.controller_cli:
            origin[name] = COMMAND_LINE
        elif name in scenario.controller_given:
            origin[name] = SCENARIO
        elif name in from_file:
            origin[name] = file.label
        else:
            origin[name] = DEFAULT
    mirrored = {}
    for name in origin if file.speed_limiter != GZ_MATH else ():
        if name.startswith("min_") and origin[name] == DEFAULT:
            high = getattr(controller, "max_" + name[4:])
            if math.isfinite(high):
                mirrored[name] = -high
                origin[name] = origin["max_" + name[4:]]
    controller = dataclasses.replace(controller, **mirrored)
    # a stream is published at most once per control tick (diff_drive_controller checks its
    # publish period in update(); joint_state_broadcaster publishes in update())
    control_hz = controller.update_rate_hz
    _refuse_partial_tick(scenario.duration_s, control_hz)
    controller = dataclasses.replace(
        controller, publish_rate_hz=min(controller.publish_rate_hz, control_hz))
    broadcaster_hz = control_hz if file.joint_state_update_hz is None \
        else file.joint_state_update_hz
    rates = dataclasses.replace(
        scenario.rates, joint_states_hz=min(scenario.rates.joint_states_hz, broadcaster_hz))
    return dataclasses.replace(scenario, controller=controller, rates=rates,
                               controller_from=tuple(origin.items()),
                               speed_limiter=file.speed_limiter,
                               classic_drive=file.classic_drive)


def _refuse_partial_tick(duration_s: float, control_hz: float) -> None:
    """Refuse a run that does not end on a control tick: it would run to the next one.

    At 30 Hz a run of 1.05 s ran to 1.0667 s (its CSVs and bag past the duration its summary
    gave); at 0.7 Hz a run of 2 s ran to 2.857 s.

    Raises:
        ScenarioError: Saying the two durations on ticks around it.
    """
    ticks = duration_s * control_hz
    if abs(ticks - round(ticks)) <= 1e-6 * max(1.0, ticks) and round(ticks) >= 1:
        return
    below, above = math.floor(ticks) / control_hz, math.ceil(ticks) / control_hz
    shorter = f"{below:.6g} s or " if below > 0 else ""
    raise ScenarioError(f"duration_s {duration_s:g} s is not a whole number of control ticks "
                        f"at {control_hz:g} Hz (one every {1 / control_hz:.6g} s): give "
                        f"{shorter}{above:.6g} s")
