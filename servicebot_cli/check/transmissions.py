"""SB511: a ``<transmission>`` naming a joint that is not there, weighed by who reads it.

Who reads a transmission, from their sources:

* A top-level ``<transmission>`` is read by ROS 1's ``gazebo_ros_control`` plugin
  (``libgazebo_ros_control.so``) through ros_control's ``TransmissionParser``. The parser keeps
  a transmission with a name, a ``<type>``, joints that have a ``<hardwareInterface>`` and a
  named ``<actuator>``; the default ``DefaultRobotHWSim`` then looks each kept single-joint
  transmission's joint up in the Gazebo model, and a joint that is not there fails
  ``initSim``: the plugin, and every controller, does not start.
* ros2_control, ``gazebo_ros2_control`` and ``gz_ros2_control`` read only ``<ros2_control>``
  tags: a top-level ``<transmission>`` is ignored, as urdfdom, KDL and sdformat ignore it.
  Other readers (a robot's own ROS 1 hardware interface, NASA Valkyrie's motor
  transmissions) are not in the file: a warning.
* A ``<transmission>`` inside ``<ros2_control>`` is read by ros2_control's component parser,
  which refuses the component when the transmission's joint is not one of its ``<joint>``\\ s.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.common.errors import NameNotFound
from servicebot_cli.description.elements import read_transmission
from servicebot_cli.description.extensions import param

if TYPE_CHECKING:
    import xml.etree.ElementTree as ET

    from servicebot_cli.description.extensions import Ros2Control
    from servicebot_cli.description.robot import RobotDescription

GAZEBO_ROS_CONTROL = "gazebo_ros_control"
DEFAULT_SIM = "gazebo_ros_control/DefaultRobotHWSim"


def check(robot: RobotDescription) -> Iterator[Issue]:
    """SB511 for every transmission joint its reader cannot find."""
    joints = [j.name for j in robot.joints]
    known = set(joints)
    consumer = _gazebo_ros_control(robot)
    for transmission in robot.transmissions:
        for name in transmission.joints:
            if name in known:
                continue
            refuses = consumer is not None and _refused_by_default_sim(transmission.element,
                                                                       name)
            reader = (f"; {consumer} does not start with it" if refuses else
                      "; nothing in this file that reads transmissions refuses it (ros2_control "
                      "ignores top-level ones)")
            named = (f"names joint '{name}', which does not exist" if name
                     else "has a <joint> without a name")
            yield Issue("SB511", f"transmission '{transmission.name}' {named}{reader}; "
                        f"{_hint(name, joints)}",
                        transmission.element,
                        severity=Severity.ERROR if refuses else Severity.WARNING)
    for block in robot.ros2_control:
        yield from _in_ros2_control(block)


def _in_ros2_control(block: Ros2Control) -> Iterator[Issue]:
    """SB511 for a transmission inside ``<ros2_control>`` naming none of the block's joints."""
    if block.element is None:
        return
    joints = [j.name for j in block.joints]
    for element in block.element.findall("transmission"):
        transmission = read_transmission(element)
        for name in transmission.joints:
            if name not in joints:
                yield Issue("SB511", f"transmission '{transmission.name}' in ros2_control "
                            f"'{block.name}' names joint '{name}', which is not a <joint> of "
                            "that component; ros2_control refuses the component; "
                            f"{_hint(name, joints)}", element, severity=Severity.ERROR)


def _gazebo_ros_control(robot: RobotDescription) -> str | None:
    """``gazebo_ros_control`` when its plugin runs the default robot simulation, else None.

    A custom ``<robotSimType>`` reads transmissions its own way: nothing is known of it.
    """
    for plugin in robot.plugins:
        if GAZEBO_ROS_CONTROL in plugin.filename:
            sim = (param(plugin.params, "robotSimType") or DEFAULT_SIM).strip()
            if sim == DEFAULT_SIM:
                return GAZEBO_ROS_CONTROL
    return None


def _refused_by_default_sim(element: ET.Element | None, name: str) -> bool:
    """True when ``DefaultRobotHWSim`` looks joint ``name`` up in the Gazebo model.

    It does for a transmission the parser keeps (a ``<type>``, a named ``<actuator>``) with
    exactly one joint that has a ``<hardwareInterface>``: ``name``. Others it skips.
    """
    if element is None or any(j.get("name") is None for j in element.findall("joint")):
        return False  # the parser drops a transmission with a joint without a name
    kept = [j.get("name") for j in element.findall("joint") if _has_text(j, "hardwareInterface")]
    has_type = _has_text(element, "type")
    has_actuator = any(a.get("name") for a in element.findall("actuator"))
    return has_type and has_actuator and kept == [name]


def _has_text(element: ET.Element, tag: str) -> bool:
    return any((child.text or "").strip() for child in element.findall(tag))


def _hint(name: str, names: list[str]) -> str:
    """``did you mean ...?`` (or the list of names) from the shared lookup error."""
    return str(NameNotFound.for_name(name, names)).split("; ", 1)[-1]
