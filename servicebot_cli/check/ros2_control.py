"""ros2_control rules: SB504-SB510, SB512, SB514, SB515 and (:mod:`.ros2_control_markup`) SB517.

Transmissions (SB511) are in :mod:`transmissions`.
"""

from __future__ import annotations

import difflib
import math
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from typing import TYPE_CHECKING

from servicebot_cli.check import ros2_control_markup
from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.check.values import NUMBER, is_number
from servicebot_cli.common.errors import JointNotFound
from servicebot_cli.description.elements import parse_float

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Joint
    from servicebot_cli.description.extensions import ControlJoint, Interface, Ros2Control
    from servicebot_cli.description.robot import RobotDescription

INTERFACES = ("position", "velocity", "acceleration", "effort")
GAZEBO_PID = {"position_pid": "position", "velocity_pid": "velocity"}
"""gazebo_ros2_control's GazeboSystem runs a PID loop for these, and exports them under the
plain interface's name (gazebo_system.cpp)."""
BAUD_RATES = (50, 75, 110, 134, 150, 200, 300, 600, 1200, 1800, 2400, 4800, 9600, 19200, 38400,
              57600, 115200, 230400, 460800, 500000, 576000, 921600, 1000000, 1152000, 1500000,
              2000000, 2500000, 3000000, 3500000, 4000000)
_PORT_KEYS = ("port", "serial_port", "device", "serial_device", "usb_port", "port_name")
_BAUD_KEYS = ("baud_rate", "baudrate", "baud")
CUSTOM_BAUD_FROM = 1_000_000
"""From 1 Mbaud, USB-serial adapters (FTDI, ROBOTIS' U2D2) take any rate: Dynamixel buses run
at 4.5, 6.25 (open_manipulator's OMY arms) or 10.5 Mbaud."""
_NO_DEVICE_PLUGINS = ("gz_ros2_control/", "ign_ros2_control/", "gazebo_ros2_control/",
                      "mock_components/", "fake_components/")
"""Hardware plugins that open no device: Gazebo's systems and ros2_control's mock."""
_PORT_RE = re.compile(r"(/dev/\S+|COM\d+|(socket|rfc2217|loop|spy|hwgrep)://\S*)")


_AS_LISTED_PLUGINS = (*_NO_DEVICE_PLUGINS, "topic_based_ros2_control/", "mujoco_ros2_control/",
                      "ros2_control_demo_")
"""Hardware plugins that export what the URDF lists for a joint, and nothing else: Gazebo's
systems, the mock, topic_based_ros2_control, MuJoCo's, ros2_control_demos' examples. Another
driver may export interfaces the URDF does not list (canopen's Cia402System exports position,
velocity and effort of every joint)."""


def exports_as_listed(plugin: str | None) -> bool:
    """Whether the hardware ``plugin`` exports exactly the interfaces the URDF lists.

    True also for a block without a plugin (SB5xx reports that): nothing else exports.
    """
    return not plugin or plugin.strip().startswith(_AS_LISTED_PLUGINS)


def exported_as(name: str, plugin: str | None) -> str:
    """The name under which the hardware ``plugin`` exports the interface ``name``."""
    if name in GAZEBO_PID and (plugin or "").strip().startswith("gazebo_ros2_control/"):
        return GAZEBO_PID[name]
    return name


def check(robot: RobotDescription) -> Iterator[Issue]:
    """Every ros2_control issue of ``robot``."""
    joints = robot.joints_by_name  # a name given twice (SB102): the first
    owner: dict[tuple[str, str, str], str] = {}
    simulator = _simulator(robot)
    yield from ros2_control_markup.check(robot.ros2_control, simulator)
    for block in robot.ros2_control:
        if not block.plugin:
            yield _no_plugin(block, simulator)
        yield from _unknown_elements(block)
        yield from _hardware(block)
        for item in block.joints:
            yield from _joint(item, joints, block)
            yield from _twice(item, block, owner)
        yield from _mimics(block, joints)


_CHILDREN = ("hardware", "joint", "sensor", "gpio", "transmission", "properties")
"""What ros2_control's component parser reads in <ros2_control> (component_parser.cpp)."""


def _unknown_elements(block: Ros2Control) -> Iterator[Issue]:
    """SB514: ros2_control's parser throws 'invalid tag name' for any other child element."""
    for child in block.element if block.element is not None else ():
        if child.tag == "properties":  # read from Jazzy on; Humble's parser refuses it
            yield Issue("SB514", f"<properties> in <ros2_control name=\"{block.name}\">: "
                        "Humble's parser refuses the robot ('invalid tag name'); Jazzy and "
                        "later read it", child, severity=Severity.WARNING,
                        fix="leave it out where the robot runs on Humble")
        elif isinstance(child.tag, str) and child.tag not in _CHILDREN:
            close = difflib.get_close_matches(child.tag, _CHILDREN, n=1, cutoff=0.6)
            yield Issue("SB514", f"<{child.tag}> in <ros2_control name=\"{block.name}\">: "
                        "ros2_control's parser reads only "
                        f"{', '.join(f'<{c}>' for c in _CHILDREN)} there, and refuses the "
                        "robot ('invalid tag name')", child,
                        fix=f"write <{close[0]}>" if close else
                        "remove it, or move it into <hardware> as a <param>")


def _mimics(block: Ros2Control, joints: dict[str, Joint]) -> Iterator[Issue]:
    """SB515: mimic joints in <ros2_control>, as ros2_control reads them from Jazzy on.

    A joint with a URDF <mimic> follows its leader unless ``mimic="false"``: it may have no
    command interface, and its leader must be a joint of the same component; ``mimic="true"``
    on a joint without a URDF <mimic> is refused too (component_parser.cpp). Humble ignores
    both.
    """
    names = {item.name for item in block.joints if item.element is not None
             and item.element.tag == "joint"}
    for item in block.joints:
        element = item.element
        if element is None or element.tag != "joint" or item.name not in joints:
            continue
        urdf_mimic = joints[item.name].mimic
        written = element.get("mimic")
        said = (written or "").strip().lower()
        problem = None
        if written is not None and said not in ("true", "false"):
            yield Issue("SB515", f"ros2_control '{block.name}': joint '{item.name}' has "
                        f"mimic=\"{written}\": ros2_control reads only true or false (recent "
                        "releases refuse the robot; older ones take anything else for false)",
                        element, fix='mimic="true" or mimic="false"')
            continue
        if urdf_mimic is None and said == "true":
            problem = "has mimic=\"true\", but no <mimic> in the URDF"
        elif urdf_mimic is not None and said != "false":
            leader = urdf_mimic.joint or ""
            if item.command_interfaces:
                problem = (f"mimics '{leader}' in the URDF and has a command interface; a "
                           "mimic joint only follows (or write mimic=\"false\")")
            elif leader not in names:
                problem = (f"mimics '{leader}', which is not a joint of this <ros2_control>; "
                           "its leader must be in the same component")
        if problem is not None:
            yield Issue("SB515", f"ros2_control '{block.name}': joint '{item.name}' {problem}: "
                        "from Jazzy on, ros2_control refuses the robot", element)


def _simulator(robot: RobotDescription) -> str | None:
    """The Gazebo plugin that runs the robot's ros2_control components, if any."""
    return next((p.filename for p in robot.plugins if "ros2_control" in p.filename), None)


def _no_plugin(block: Ros2Control, simulator: str | None) -> Issue:
    """SB509: a component without a hardware plugin.

    ros2_control's parser refuses a ``<hardware>`` without ``<plugin>`` (the whole robot).
    A component with no ``<hardware>`` at all parses; ros2_control_node then cannot load it,
    but the Gazebo plugins (gazebo_ros2_control, gz_ros2_control) log the failure, skip the
    component and run the others: open_manipulator's OMY arms leave their end unit's GPIOs
    without hardware in simulation.
    """
    fix = "add <hardware><plugin>package/HardwareClass</plugin></hardware>"
    element = block.element
    if simulator is not None and element is not None and element.find("hardware") is None:
        return Issue("SB509", f"<ros2_control name=\"{block.name}\"> has no <hardware>: "
                     f"{simulator} skips it (with a logged error) and runs the other "
                     "components; ros2_control_node would refuse it", element,
                     fix=fix, severity=Severity.WARNING)
    return Issue("SB509", f"<ros2_control name=\"{block.name}\"> has no <hardware><plugin>",
                 element, fix=fix)


def _twice(item: ControlJoint, block: Ros2Control,
           owner: dict[tuple[str, str, str], str]) -> Iterator[Issue]:
    """SB507: the same interface of a joint in two components.

    One joint in an actuator that only commands and a sensor that only reports (ros2_control
    demos' modular robot) is a supported layout: the interfaces differ.
    """
    interfaces = [("command", i.name) for i in item.command_interfaces]
    interfaces += [("state", i.name) for i in item.state_interfaces]
    for kind, name in interfaces:
        first = owner.setdefault((item.name, kind, name), block.name)
        if first != block.name:
            yield Issue("SB507", f"joint '{item.name}' {kind} interface '{name}' is in "
                        f"ros2_control components '{first}' and '{block.name}'", item.element,
                        fix="keep each interface of a joint in one component")
            return


def _hardware(block: Ros2Control) -> Iterator[Issue]:
    """SB510: a serial port that is not a device path, a baud rate that is not standard.

    A ``port`` that is a number is a network one (ros2_kortex's ``<param name="port">10000``,
    beside ``robot_ip``), not a serial device. Rates from :data:`CUSTOM_BAUD_FROM` are not
    judged. A simulated or mock component opens no port: Gazebo's systems and
    ``mock_components`` never read these parameters (ar4_ros_driver's Gazebo robot reuses its
    driver's macro with ``serial_port="None"``).
    """
    if (block.plugin or "").startswith(_NO_DEVICE_PLUGINS):
        return
    for key, value in block.hardware_params:
        if key in _PORT_KEYS and not _ascii_digits(value.strip()) \
                and not _PORT_RE.fullmatch(value):
            yield Issue("SB510", f"ros2_control '{block.name}': {key} '{value}' is not a serial "
                        "device path", block.element, fix=f"e.g. <param name=\"{key}\">"
                        "/dev/ttyUSB0</param>")
        if key in _BAUD_KEYS and not _is_baud_rate(value.strip()):
            yield Issue("SB510", f"ros2_control '{block.name}': {key} '{value}' is not a standard "
                        "baud rate", block.element,
                        fix="use one of 9600, 19200, 38400, 57600, 115200, ...")


def _is_baud_rate(value: str) -> bool:
    return _ascii_digits(value) and (int(value) in BAUD_RATES or int(value) >= CUSTOM_BAUD_FROM)


def _ascii_digits(value: str) -> bool:
    """``0``-``9`` only: str.isdigit() also takes '²' (which int() refuses) and '٣'."""
    return value.isascii() and value.isdigit()


def _joint(item: ControlJoint, joints: dict[str, Joint], block: Ros2Control) -> Iterator[Issue]:
    joint = joints.get(item.name)
    if joint is None:
        hint = str(JointNotFound.for_name(item.name, list(joints))).split("; ", 1)[-1]
        yield Issue("SB504", f"ros2_control '{block.name}' names joint '{item.name}', which does "
                    f"not exist; {hint}", item.element, fix=None if joints else
                    "add the joint to the robot, or check the file that includes this one")
        return
    if joint.type == "fixed" and item.command_interfaces:
        yield Issue("SB506", f"fixed joint '{item.name}' has command interface(s) "
                    f"{', '.join(i.name for i in item.command_interfaces)}", item.element)
    elif joint.type == "fixed" and item.element is not None and item.element.tag == "joint":
        yield Issue("SB506", f"fixed joint '{item.name}' is in ros2_control "
                    f"'{block.name}': from Jazzy on, ros2_control refuses the robot ('Fixed "
                    "joints do not make sense in ros2_control'); Humble exports its states",
                    item.element, severity=Severity.WARNING,
                    fix="remove the joint from <ros2_control>, or report its values as a "
                        "<sensor>")
    for interface in (*item.command_interfaces, *item.state_interfaces):
        if exported_as(interface.name, block.plugin) != interface.name:
            continue  # position_pid for Gazebo: a name of its own, not a misspelling
        if interface.name != interface.name.strip() and interface.name.strip() in INTERFACES:
            # ros2_control strips attribute values from Jazzy on (its get_attribute_value)
            yield Issue("SB505", f"joint '{item.name}' interface '{interface.name}' has blanks "
                        "around its name: Jazzy and later strip them, Humble looks for "
                        f"'{interface.name}' and finds no such interface", item.element,
                        fix=f'name="{interface.name.strip()}"')
            continue
        close = difflib.get_close_matches(interface.name, INTERFACES, n=1, cutoff=0.75)
        if close and close[0] != interface.name:
            yield Issue("SB505", f"joint '{item.name}' interface '{interface.name}' is not "
                        f"standard; did you mean '{close[0]}'?", item.element,
                        fix=f'name="{close[0]}"')
    for interface in item.command_interfaces:
        yield from _limit_texts(item, interface)
        yield from _command_limits(item, interface, joint)


def _limit_texts(item: ControlJoint, interface: Interface) -> Iterator[Issue]:
    """SB512: a command interface's min or max that ros2_control cannot read as a number.

    ros2_control reads them with its own stod (istringstream, or from_chars since C++20),
    logs "Error parsing the limits" and goes on without them (Interbotix's arms write
    ``"-3.14"`` with the quotes). A number with blanks around it is left alone: the two
    readers differ there.
    """
    for key in ("min", "max"):
        text = interface.get(key)
        beyond = text is not None and NUMBER.fullmatch(text) is not None \
            and math.isinf(float(text))  # 1e400: both readers fail on it (out of range)
        if text is None or (is_number(text) and not beyond):
            continue
        element = _param_element(item, interface.name, key)
        what = "is beyond a double's range" if beyond else "is not a number"
        yield Issue("SB512", f"joint '{item.name}' {interface.name} command interface: {key} "
                    f"'{text}' {what}; ros2_control skips the interface's limits",
                    element if element is not None else item.element,
                    fix="write the limit, a finite number" if beyond else _number_fix(text))


def _param_element(item: ControlJoint, interface: str, key: str) -> ET.Element | None:
    """The ``<param name=key>`` of ``item``'s command interface ``interface``, if found.

    Found by walking, not by an XPath built from the names: a name may hold a quote.
    """
    for element in item.element.iterfind("command_interface") if item.element is not None \
            else ():
        if element.get("name") == interface:
            for param in element.iterfind("param"):
                if param.get("name") == key:
                    return param
    return None


def _number_fix(text: str) -> str:
    """How to write ``text`` as the number it means, where that is plain."""
    unquoted = text.strip().strip("'\"").strip()
    if unquoted != text.strip() and is_number(unquoted):
        return f"write {unquoted}, without the quotes"
    return "write a plain decimal number (a point, no quotes or units)"


def _slack(limit: float) -> float:
    """How far a command limit may pass the URDF's ``limit``: the same value rounded.

    DENSO's descriptions give the command limits to six decimals (-2.617994 for the URDF's
    -2.61799387799149): the same angle, not a wider range.
    """
    return 1e-9 + 1e-6 * abs(limit)


def _told_apart(value: float, limit: float) -> tuple[str, str]:
    """``value`` and ``limit`` written with as few digits as show them different."""
    for digits in range(6, 18):
        shown = f"{value:.{digits}g}", f"{limit:.{digits}g}"
        if shown[0] != shown[1]:
            return shown
    return repr(value), repr(limit)


def _command_limits(item: ControlJoint, interface: Interface, joint: Joint) -> Iterator[Issue]:
    limits = joint.limits
    if limits is None:
        return
    if interface.name == "position" and joint.type in ("revolute", "prismatic"):
        allowed = (limits.lower, limits.upper)
    elif interface.name == "velocity" and limits.velocity is not None \
            and limits.velocity >= 0:  # a negative one: SB205's
        allowed = (0.0 - limits.velocity, limits.velocity)  # 0 - 0 is 0, not -0
    elif interface.name == "effort" and limits.effort is not None and limits.effort >= 0:
        allowed = (0.0 - limits.effort, limits.effort)
    else:
        return
    low, high = parse_float(interface.get("min")), parse_float(interface.get("max"))
    lo, hi = allowed
    outside = []
    if low is not None and lo is not None and math.isfinite(low) and low < lo - _slack(lo):
        outside.append("min {} < {}".format(*_told_apart(low, lo)))
    if high is not None and hi is not None and math.isfinite(high) and high > hi + _slack(hi):
        outside.append("max {} > {}".format(*_told_apart(high, hi)))
    if outside:
        yield Issue("SB508", f"joint '{item.name}' {interface.name} command limits go beyond "
                    f"the URDF: {'; '.join(outside)}", item.element,
                    fix=f"keep min/max inside [{lo:g}, {hi:g}]")
