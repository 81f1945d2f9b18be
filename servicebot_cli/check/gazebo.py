"""Gazebo rules: references name real parts, sensors are sane, one simulator, numbers.

SB501-SB503, SB513 for settings sdformat reads as numbers, and SB518 for what a plugin's
``<ros>`` holds that gazebo_ros does not read.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator, Mapping
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.check.optional_parts import (
    Definition,
    defined_by_siblings,
    defined_elsewhere,
)
from servicebot_cli.common.errors import NameNotFound
from servicebot_cli.description import sensors as specs
from servicebot_cli.description.elements import parse_float
from servicebot_cli.description.extensions import Sensor, param
from servicebot_cli.description.sensors import NoiseSpec

if TYPE_CHECKING:
    import xml.etree.ElementTree as ET

    from servicebot_cli.description.robot import RobotDescription

_CLASSIC = ("libgazebo_ros", "gazebo_ros")
# Gazebo Classic casts a "ray" sensor's rays in the physics engine: range min 0 (sdformat's
# default) starts them at the sensor (pepper's sonars). A GPU lidar's range min is its
# camera's near clip, which OGRE refuses at 0.
_CPU_RAYS = ("ray",)
_UNEXPANDED = re.compile(r"(?<!\$)\{[^{}]*\}")
_GZ_SIM = ("gz-sim", "libgz-sim", "ignition-gazebo", "libignition-gazebo", "gz::sim")


def check(robot: RobotDescription) -> Iterator[Issue]:
    """Every Gazebo issue of ``robot``."""
    names = [link.name for link in robot.links] + [joint.name for joint in robot.joints]
    known = robot.part_names
    # reference="" is no reference: sdformat applies the block to the model, as without one
    unknown = [b for b in robot.gazebo if b.reference and b.reference not in known]
    # a reference still holding xacro's braces is a typo, no optional part ('{side}' for '${side}')
    optional = defined_elsewhere(robot, {block.reference or "" for block in unknown
                                         if not _UNEXPANDED.search(block.reference or "")})
    left = {block.reference or "": robot.source_of(block.element).file for block in unknown
            if block.reference not in optional and not _UNEXPANDED.search(block.reference or "")}
    siblings = defined_by_siblings(robot, left)
    for block in unknown:
        sibling = siblings.get(block.reference or "")
        if sibling is not None:
            yield _siblings_reference(block.reference or "", sibling, block.element)
            continue
        yield _unknown_reference(block.reference or "", names, optional, block.element)
    fixed = {joint.name for joint in robot.joints if joint.type == "fixed"}
    kept = robot.kept_apart
    child_of = {name: joint.child for name, joint in robot.joints_by_name.items()}
    links = {link.name for link in robot.links}
    for sensor in robot.sensors:
        if not sensor.reference:
            yield Issue("SB502", f"sensor '{sensor.name}' is in a <gazebo> block that names no "
                        "link: sdformat puts what it holds in the model, where SDF has no "
                        "sensor, so Gazebo makes none", sensor.element,
                        severity=Severity.WARNING,
                        fix="put it in <gazebo reference=\"LINK\">, the link it is on")
        for problem in _sensor_problems(sensor):
            yield Issue("SB502", f"sensor '{sensor.name}': {problem}", sensor.element)
        if sensor.reference in child_of and sensor.reference not in links \
                and sensor.type != "force_torque":  # physics/Joint.cc: 'A joint cannot load'
            yield Issue("SB502", f"sensor '{sensor.name}' ({sensor.type}) is in <gazebo "
                        f"reference=\"{sensor.reference}\">, a joint: Gazebo Classic loads "
                        "only force_torque sensors on a joint, so there this one never exists",
                        sensor.element, fix=f"<gazebo reference=\"{child_of[sensor.reference]}"
                        "\">: the link the joint carries", severity=Severity.WARNING)
        yield from _rate(sensor)
        if sensor.type == "force_torque" and sensor.reference in fixed - kept.keys():
            yield Issue("SB502", f"sensor '{sensor.name}' (force_torque) is on fixed joint "
                        f"'{sensor.reference}', which Gazebo lumps into its parent: the "
                        "joint becomes a frame, and the sensor measures nothing",
                        sensor.element, severity=Severity.WARNING,
                        fix="add <preserveFixedJoint>true</preserveFixedJoint> (gz sim) or "
                            "<disableFixedJointLumping>true</disableFixedJointLumping> "
                            f"(Gazebo Classic) to <gazebo reference=\"{sensor.reference}\">")
    yield from _mixed(robot)
    yield from _numbers(robot)
    yield from _ros_elements(robot)


# what sdformat's URDF converter reads with std::stod or std::stoi (parser_urdf.cc), which
# throws on text that does not start as a number: the conversion fails, Gazebo loads nothing
_NUMERIC = frozenset(("mu1", "mu2", "kp", "kd", "maxVel", "minDepth", "dampingFactor",
                      "maxContacts", "laserRetro", "springReference", "springStiffness",
                      "stopCfm", "stopErp", "fudgeFactor"))
_INTEGER_START = re.compile(r"[ \t\n\r\f\v]*([+-]?[0-9]+)")
_INT_MAX = 2**31 - 1
_NUMBER_START = re.compile(r"[ \t\n\r\f\v]*([+-]?(?:inf|nan|(?:[0-9]+\.?[0-9]*|\.[0-9]+)"
                           r"(?:[eE][+-]?[0-9]+)?))", re.IGNORECASE)


def _numbers(robot: RobotDescription) -> Iterator[Issue]:
    """SB513 for a <gazebo> setting sdformat converts to a number and cannot."""
    for block in robot.gazebo:
        if block.element is None:
            continue
        for child in block.element:
            if not isinstance(child.tag, str) or child.tag not in _NUMERIC or len(child):
                continue
            text = child.text if (child.text or "").strip() else child.get("value", "")
            shown = (text or "").strip()
            why = _unread(child.tag, text or "")
            if why is None:
                continue
            yield Issue("SB513", f"<gazebo{_referring(block.reference)}> <{child.tag}>"
                        f"{shown}</{child.tag}>: {why}; sdformat's conversion of the URDF "
                        "fails, and Gazebo loads nothing of the robot", child,
                        fix=f"write <{child.tag}> as a plain number")


def _unread(tag: str, text: str) -> str | None:
    """Why sdformat's std::stoi (maxContacts) or std::stod cannot read ``text``; None: it can.

    Both skip leading blanks and stop at the first character that is no part of a number;
    both throw when no number starts the text, or when it is beyond their type's range.
    """
    shown = text.strip()
    integer = tag == "maxContacts"
    start = (_INTEGER_START if integer else _NUMBER_START).match(text)
    if start is None:
        return f"'{shown}' is not a number" if shown else "no number"
    if integer and abs(int(start[1])) > _INT_MAX:
        return f"'{shown}' is beyond an int's range"
    if not integer and math.isinf(float(start[1])) and "inf" not in start[1].lower():
        return f"'{shown}' is beyond a double's range"
    return None


def _referring(reference: str | None) -> str:
    return f' reference="{reference}"' if reference is not None else ""


def _siblings_reference(reference: str, sibling: Definition,
                        element: ET.Element | None) -> Issue:
    """SB501, a warning: the block is for a link another robot beside this one defines."""
    file, line, kind, written, _ = sibling
    named = f"'{reference}'" if written == reference else f"'{written}'"
    return Issue("SB501", f"<gazebo reference=\"{reference}\"> names no link or joint of this "
                 f"robot; {file}:{line}, another robot beside it, defines {kind} {named}: a "
                 "block written for each robot of the family, which Gazebo ignores here",
                 element, severity=Severity.WARNING,
                 fix="nothing; or write the block only where the robot has that link")


def _unknown_reference(reference: str, names: list[str],
                       optional: Mapping[str, Definition],
                       element: ET.Element | None) -> Issue:
    """SB501; a warning when the sources define it in a part this expansion leaves out."""
    where = f"<gazebo reference=\"{reference}\">"
    found = optional.get(reference)
    if found is None and element is not None and _empty(element):
        return Issue("SB501", f"{where} names no link or joint, and is empty: Gazebo drops it "
                     "and loses nothing", element, severity=Severity.WARNING,
                     fix="remove the empty block")
    if found is None:
        hint = str(NameNotFound.for_name(reference, names)).split("; ", 1)[-1]
        braces = _UNEXPANDED.search(reference)
        if braces is not None:
            hint = (f"'{braces[0]}' has no '$' before it, so xacro left it as written; "
                    f"{hint}")
        return Issue("SB501", f"{where} names no link or joint; {hint}", element,
                     fix=f"write '${braces[0]}'" if braces is not None else None)
    file, line, kind, written, macro = found
    named = f"'{reference}'" if written == reference else f"'{written}' (here '{reference}')"
    if macro is not None:
        return Issue("SB501", f"{where} names no link or joint of this expansion; {file}:"
                     f"{line} defines {kind} {named} in macro '{macro}', and no call of it in this "
                     "expansion makes it (a call in a part left out, or none at all), so "
                     "Gazebo ignores the block", element, severity=Severity.WARNING,
                     fix=f"call macro '{macro}' where the robot needs that part; nothing if "
                         "it is optional")
    return Issue("SB501", f"{where} names no link or joint of this expansion; {file}:{line} "
                 f"defines {kind} {named} in a part it leaves out (a xacro condition not "
                 "taken, or an include its options leave out), so Gazebo ignores the block",
                 element, severity=Severity.WARNING,
                 fix="nothing if that part is optional; else check the xacro arguments, "
                     "properties or environment that switch it on")


def _empty(element: ET.Element) -> bool:
    """No element, text or attribute other than ``reference`` inside ``element``."""
    return (len(element) == 0 and not (element.text or "").strip()
            and element.attrib.keys() <= {"reference"})


def _rate(sensor: Sensor) -> Iterator[Issue]:
    """SB502 for an update_rate Gazebo cannot read, a warning for one it reads as 0.

    0 is SDF's default: the sensor updates at every simulation step (gz-sensors and Gazebo
    Classic alike), and so does a negative or infinite rate, which cannot be what was meant.
    """
    rate = sensor.update_rate_hz
    if rate is None or 0 <= rate < math.inf:
        return
    where = f"sensor '{sensor.name}': update_rate"
    if math.isnan(rate):
        text = sensor.element.findtext("update_rate") if sensor.element is not None else None
        yield Issue("SB502", f"{where} '{(text or '').strip()}' is not a number: sdformat "
                    "cannot read it", sensor.element, fix="write the rate in Hz, or 0 for "
                    "every simulation step")
        return
    yield Issue("SB502", f"{where} {rate:g} Hz: Gazebo updates the sensor at every simulation "
                "step, as for 0 (SDF's default)", sensor.element, severity=Severity.WARNING,
                fix="write the rate in Hz, or 0 for every simulation step")


_BELONGS_IN = (
    (specs.CAMERA_TYPES, "camera", ("horizontal_fov", "image", "clip", "distortion", "lens",
                                    "depth_camera", "save"),
     "the default camera (320 x 240, horizontal_fov 1.047, clip 0.1 to 100 m)"),
    (specs.LIDAR_TYPES, "ray> or <lidar", ("scan", "range"),
     "sdformat's default rays (640 samples, all at 0 rad, range 0 m)"),
    (("imu",), "imu", ("angular_velocity", "linear_acceleration"), "an IMU without noise"),
)
"""Elements of a sensor type sdformat reads only inside its own element: written directly
under <sensor> (bcr_bot's stereo camera), sdformat warns 'not defined in SDF', keeps them as
unknown children and gives the sensor its defaults."""


_ROS_NODE = ("namespace", "remapping", "argument", "parameter", "qos")
"""What gazebo_ros::Node reads in a ROS 2 plugin's <ros> (gazebo_ros' node.cpp, qos.cpp)."""


def _ros_elements(robot: RobotDescription) -> Iterator[Issue]:
    """SB518: an element in a plugin's ``<ros>`` that gazebo_ros does not read.

    sam_bot's ``<remap from="cmd_vel" to="/cmd_vel"/>`` (roslaunch's form): the plugin
    listens on /demo/cmd_vel, not the /cmd_vel its author meant.
    """
    for plugin in robot.plugins:
        ros = plugin.element.find("ros") if plugin.element is not None else None
        for child in ros if ros is not None else ():
            if not isinstance(child.tag, str) or child.tag in _ROS_NODE:
                continue
            fix = "write it <remapping>FROM:=TO</remapping>" if child.tag == "remap" else \
                f"use one of {', '.join(f'<{name}>' for name in _ROS_NODE)}"
            if child.tag == "remap" and child.get("from") and child.get("to"):
                fix = f"write <remapping>{child.get('from')}:={child.get('to')}</remapping>"
            yield Issue("SB518", f"plugin '{plugin.filename or plugin.name}': <{child.tag}> in "
                        f"<ros>: gazebo_ros reads only {', '.join(f'<{n}>' for n in _ROS_NODE)} "
                        "there, so it does nothing", child, fix=fix)


def _misplaced(sensor: Sensor) -> Iterator[str]:
    for types, home, names, defaults in _BELONGS_IN:
        if sensor.type not in types:
            continue
        tops = dict.fromkeys(key.split("/")[0].split("@")[0] for key, _ in sensor.params)
        found = [name for name in tops if name in names]
        if found:
            listed = ", ".join(f"<{name}>" for name in found)
            yield (f"{listed} directly under <sensor>: sdformat reads "
                   f"{'it' if len(found) == 1 else 'them'} only inside <{home}>, so Gazebo "
                   f"runs {defaults}")


_SDF_SENSOR_TYPES = frozenset((
    "air_pressure", "air_speed", "altimeter", "boundingbox_camera", "camera", "contact",
    "custom", "depth", "depth_camera", "dvl", "force_torque", "gps", "gpu_lidar", "gpu_ray",
    "imu", "lidar", "logical_camera", "magnetometer", "multicamera", "navsat", "ray", "rfid",
    "rfidtag", "rgbd", "rgbd_camera", "segmentation_camera", "sonar", "thermal",
    "thermal_camera", "wideanglecamera", "wireless_receiver", "wireless_transceiver",
    "wireless_transmitter"))
"""sdformat's sensor types (sensor.sdf), each as Gazebo's sensor factories look it up."""


def _sensor_problems(sensor: Sensor) -> Iterator[str]:
    if sensor.element is not None and sensor.element.get("name") is None:
        yield "a <sensor> without a name, which sdformat requires: Gazebo does not load it"
    if sensor.type not in _SDF_SENSOR_TYPES and sensor.type.lower() in _SDF_SENSOR_TYPES:
        yield (f"type '{sensor.type}': Gazebo looks sensor types up as written, in lower case "
               f"('{sensor.type.lower()}'), and creates no sensor of this one")
    yield from _misplaced(sensor)
    if sensor.type in specs.LIDAR_TYPES:
        yield from _lidar(sensor)
    elif sensor.type in specs.CAMERA_TYPES:
        yield from _camera(sensor, specs.camera_spec(sensor))
    elif sensor.type == "imu":
        imu = specs.imu_spec(sensor)
        for noise in (*imu.angular_velocity_noise, *imu.linear_acceleration_noise):
            yield from _noise(noise)


def _lidar(sensor: Sensor) -> Iterator[str]:
    lidar = specs.lidar_spec(sensor)
    root = "lidar" if any(k.startswith("lidar/") for k, _ in sensor.params) else "ray"
    samples = param(sensor.params, f"{root}/scan/horizontal/samples")
    count = specs.sdf_unsigned(samples)  # "666.518" (a computed value) is read as 666
    if samples is not None and not (count is not None and count > 0):
        yield f"horizontal samples '{samples}' must be a positive whole number"
    low, high = lidar.min_angle_rad, lidar.max_angle_rad
    single = count == 1 and low == high  # one ray: its angle (create_robot's cliff sensors)
    if low is not None and high is not None and not low < high and not single:
        yield f"min_angle {low:g} rad must be below max_angle {high:g} rad"
    # the ray's own range: a Velodyne plugin's band narrows the spec's (said below)
    near, far = (parse_float(param(sensor.params, f"{root}/range/{end}")) for end in ("min", "max"))
    if near is not None and math.isnan(near):
        yield "range min is not a number"
    elif near is not None and not (near >= 0 if sensor.type in _CPU_RAYS else near > 0):
        yield (f"range min {near:g} m must not be negative" if sensor.type in _CPU_RAYS
               else f"range min {near:g} m must be positive")
    if near is not None and far is not None and not near < far \
            and not (math.isnan(near) or math.isnan(far)):
        yield f"range min {near:g} m must be below range max {far:g} m"
    elif lidar.output is not None and lidar.output.velodyne and lidar.min_range_m is not None \
            and lidar.max_range_m is not None and not lidar.min_range_m < lidar.max_range_m:
        yield (f"its Velodyne plugin keeps the ranges between {lidar.min_range_m:g} and "
               f"{lidar.max_range_m:g} m (its <min_range> and <max_range> within the ray's): "
               "no point, and it publishes empty clouds")
    yield from _noise(lidar.noise)


def _camera(sensor: Sensor, camera: specs.CameraSpec) -> Iterator[str]:
    for label in ("width", "height"):
        text = param(sensor.params, f"camera/image/{label}")
        count = specs.sdf_unsigned(text)  # camera.sdf: an unsigned int, as samples
        if text is not None and not (count is not None and count > 0):
            yield f"image {label} '{text.strip()}' must be a positive whole number"
    fov = camera.horizontal_fov_rad
    if fov is not None and math.isnan(fov):
        yield "horizontal_fov is not a number"
    elif fov is not None and not 0 < fov < 2 * math.pi:
        yield f"horizontal_fov {fov:g} rad must be more than 0 and less than 2 pi"
    near, far = camera.near_clip_m, camera.far_clip_m
    if near is not None and far is not None and not 0 < near < far:
        yield f"clip near {near:g} m and far {far:g} m need 0 < near < far"
    yield from _noise(camera.noise)


def _noise(noise: NoiseSpec | None) -> Iterator[str]:
    if noise is None:
        return
    for label, value in (("stddev", noise.stddev), ("bias_stddev", noise.bias_stddev)):
        if math.isnan(value):
            yield f"noise {label} is not a number"
        elif value < 0:
            yield f"noise {label} {value:g} must not be negative"


def _mixed(robot: RobotDescription) -> Iterator[Issue]:
    classic = [p for p in robot.plugins if p.filename.startswith(_CLASSIC)]
    modern = [p for p in robot.plugins
              if p.filename.startswith(_GZ_SIM) or p.name.startswith("gz::sim")]
    if classic and modern:
        yield Issue("SB503", f"{len(classic)} Gazebo Classic plugin(s) ('{classic[0].filename}') "
                    f"and {len(modern)} gz-sim plugin(s) ('{modern[0].filename}') in one file; "
                    "each simulator loads only its own", modern[0].element,
                    fix="select the plugins with a xacro argument (sim:=classic|gz)")
