"""Run the simulator in-process on a scenario written as a dict."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import TYPE_CHECKING, Any

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.simulate import simulator
from servicebot_cli.simulate.body import SimRobot, sim_robot
from servicebot_cli.simulate.scenario.definition import Scenario, read_scenario
from servicebot_cli.simulate.scenario.located import parse
from servicebot_cli.simulate.world.solids import world_solids

if TYPE_CHECKING:
    import coal
    import numpy as np

    from servicebot_cli.description.robot import RobotDescription

REALWORLD_SRC = Path(__file__).resolve().parents[1] / "realworld" / "ws" / "src"
DIFFBOT = REALWORLD_SRC / "example_2" / "description" / "urdf" / "diffbot.urdf.xacro"
"""ros2_control_demos' diffbot: a differential drive with no arm and no sensor."""
NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}
"""No ROS sourced: the packages are found from the files' own workspace."""
DRIVE_ONLY = """\
duration_s: 12
initial_pose: {x_m: 0, y_m: 0, yaw_rad: 0}
cmd_vel:
  - {duration_s: 6, linear_m_s: 0.1}
  - {duration_s: 6, angular_rad_s: 0.3}
"""
"""A scenario of the base alone: 6 s ahead at 0.1 m/s, 6 s turning at 0.3 rad/s."""


def body() -> SimRobot:
    return sim_robot(load(RobotSource.bundled("sim")))


def scenario(document: dict[str, Any]) -> Scenario:
    return read_scenario(parse(json.dumps(document), "test.json", json_syntax=True))


def run(document: dict[str, Any], seed: int = 0) -> simulator.SimResult:
    s = scenario(document)
    return simulator.run(body(), s, seed=seed, solids=world_solids(s.world))


def bundled_with(links: str, directory: Path) -> Path:
    """The bundled robot with ``links`` (URDF text) added, written in ``directory``: its path.

    The controllers file goes beside it, and so do the links' meshes (the caller's).
    """
    bundled = load(RobotSource.bundled("sim"))
    text = bundled.xml_text.replace("</robot>", links + "</robot>")
    for name in re.findall(r"<parameters>([^<]+)</parameters>", text):  # controllers.yaml
        (directory / name).write_bytes((bundled.path.parent / name).read_bytes())
    (directory / "robot.urdf").write_text(text)
    return directory / "robot.urdf"


def coal_primitives(robot: RobotDescription, links: set[str] | None = None
                    ) -> list[tuple[str, coal.ShapeBase, np.ndarray]]:
    """(link, Coal shape, transform_shape_to_link) of the robot's collision primitives.

    Of ``links`` only, if given; in URDF order. The reference the simulator's parts are held to.
    """
    import coal

    from servicebot_cli.kinematics.transforms import pose_matrix

    out = []
    for link in robot.links:
        if links is not None and link.name not in links:
            continue
        for element in link.collisions:
            g = element.geometry
            shape = (coal.Box(*g.size) if g.kind == "box" else
                     coal.Cylinder(g.radius, g.length) if g.kind == "cylinder" else
                     coal.Sphere(g.radius))
            out.append((link.name, shape, pose_matrix(element.origin)))
    return out
