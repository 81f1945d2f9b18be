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
