"""Run the simulator in-process on a scenario written as a dict."""

from __future__ import annotations

import json
from typing import Any

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.simulate import simulator
from servicebot_cli.simulate.body import SimRobot, sim_robot
from servicebot_cli.simulate.scenario.definition import Scenario, read_scenario
from servicebot_cli.simulate.scenario.located import parse
from servicebot_cli.simulate.world.solids import world_solids


def body() -> SimRobot:
    return sim_robot(load(RobotSource.bundled("sim")))


def scenario(document: dict[str, Any]) -> Scenario:
    return read_scenario(parse(json.dumps(document), "test.json", json_syntax=True))


def run(document: dict[str, Any], seed: int = 0) -> simulator.SimResult:
    s = scenario(document)
    return simulator.run(body(), s, seed=seed, solids=world_solids(s.world))
