"""What URDF parsers drop: ``<gazebo>`` blocks, sensors, plugins and ``<ros2_control>``.

Values only, read tolerantly like :mod:`elements`; each keeps its XML element.
Plugin and hardware parameters keep document order as ``(path, text)`` pairs, since
plugins repeat tags (``<remapping>``, ``<joint_name>``).
"""

from __future__ import annotations

import dataclasses
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

from servicebot_cli.description.elements import Pose, parse_float

Params = tuple[tuple[str, str], ...]


def _text(element: ET.Element | None) -> str | None:
    if element is None or element.text is None:
        return None
    return element.text.strip()


def _leaf_params(element: ET.Element, prefix: str = "") -> Params:
    """Every leaf below ``element`` as ``("a/b", text)``; attributes as ``("a/b@name", value)``."""
    pairs: list[tuple[str, str]] = []
    stack = [(child, prefix) for child in reversed(list(element))]
    while stack:  # iterative: plugin blocks from the wild can nest deeply
        node, base = stack.pop()
        if not isinstance(node.tag, str):
            continue
        path = f"{base}{node.tag}"
        for key, value in node.attrib.items():
            pairs.append((f"{path}@{key}", value))
        children = list(node)
        if children:
            stack.extend((child, path + "/") for child in reversed(children))
        else:
            pairs.append((path, (node.text or "").strip()))
    return tuple(pairs)


def param(params: Params, path: str, default: str | None = None) -> str | None:
    """The last value at ``path`` (later tags override earlier ones, as in Gazebo)."""
    found = default
    for key, value in params:
        if key == path:
            found = value
    return found


def sdf_true(text: str | None) -> bool:
    """Whether SDF reads ``text`` as true: ``true`` or ``1``, in any case, blanks around."""
    return (text or "").strip().lower() in ("1", "true")


def params_all(params: Params, path: str) -> tuple[str, ...]:
    """Every value at ``path``, in document order (``ros/remapping``, ``joint_name``)."""
    return tuple(value for key, value in params if key == path)


@dataclass(frozen=True)
class Plugin:
    """A Gazebo ``<plugin>``.

    Attributes:
        name: Its ``name`` attribute.
        filename: Its ``filename`` attribute (``libgazebo_ros_camera.so``, ``gz-sim-...``).
        params: Its children as ``(path, text)`` pairs.
    """

    name: str
    filename: str
    params: Params
    element: ET.Element | None = field(default=None, compare=False, repr=False)
    ros2_file: bool = field(default=False, compare=False)
    """One of gazebo_plugins', in a file a plugin of which has a ``<ros>`` block: the file is
    for ROS 2's gazebo_ros, whose plugins read no ROS 1 parameter (``frameName``), whatever
    this one holds."""

    @property
    def has_ros_block(self) -> bool:
        """Whether it holds a ``<ros>`` block: gazebo_ros' ROS 2 node settings."""
        return any(key.startswith("ros/") for key, _ in self.params)

    @property
    def for_ros2(self) -> bool:
        """Whether ROS 2's gazebo_ros runs it: it has a ``<ros>`` block, or its file is ROS 2's."""
        return self.ros2_file or self.has_ros_block


@dataclass(frozen=True)
class Sensor:
    """A Gazebo ``<sensor>`` inside ``<gazebo reference="link">``.

    Attributes:
        reference: The link it is attached to (None outside a referenced block).
        update_rate_hz: ``<update_rate>`` [Hz]; None when absent.
        params: Its non-plugin children as ``(path, text)`` pairs (``ray/scan/horizontal/samples``).
        plugins: The plugins inside the sensor (Gazebo Classic ROS wrappers).
        carrier: The link Gazebo attaches it to: ``reference``, or the link a fixed joint
            lumps ``reference`` into (set by the robot; None outside a referenced block).
    """

    name: str
    type: str
    reference: str | None
    pose: Pose
    update_rate_hz: float | None
    params: Params
    plugins: tuple[Plugin, ...]
    element: ET.Element | None = field(default=None, compare=False, repr=False)
    carrier: str | None = None


@dataclass(frozen=True)
class GazeboBlock:
    """A ``<gazebo>`` element: model-level (no reference) or about one link or joint.

    Attributes:
        properties: Simple children such as ``mu1``, ``material``, ``selfCollide``.
    """

    reference: str | None
    sensors: tuple[Sensor, ...]
    plugins: tuple[Plugin, ...]
    properties: Params
    element: ET.Element | None = field(default=None, compare=False, repr=False)


@dataclass(frozen=True)
class Interface:
    """A ros2_control command or state interface, with its ``<param>`` children."""

    name: str
    params: tuple[tuple[str, str], ...] = ()

    def get(self, key: str) -> str | None:
        """Value of ``<param name="key">``."""
        return dict(self.params).get(key)


@dataclass(frozen=True)
class ControlJoint:
    """A ``<joint>`` (or ``<sensor>``/``<gpio>``) inside ``<ros2_control>``."""

    name: str
    command_interfaces: tuple[Interface, ...]
    state_interfaces: tuple[Interface, ...]
    params: tuple[tuple[str, str], ...] = ()
    element: ET.Element | None = field(default=None, compare=False, repr=False)


@dataclass(frozen=True)
class Ros2Control:
    """A ``<ros2_control>`` block.

    Attributes:
        plugin: The hardware plugin (``<hardware><plugin>``), None if missing.
        hardware_params: ``<hardware><param name=..>`` pairs in document order.
    """

    name: str
    type: str
    plugin: str | None
    hardware_params: tuple[tuple[str, str], ...]
    joints: tuple[ControlJoint, ...]
    sensors: tuple[ControlJoint, ...]
    gpios: tuple[ControlJoint, ...]
    element: ET.Element | None = field(default=None, compare=False, repr=False)

    def hardware_param(self, key: str) -> str | None:
        """Value of ``<hardware><param name="key">``."""
        return dict(self.hardware_params).get(key)


def read_plugin(element: ET.Element) -> Plugin:
    """A Plugin from a ``<plugin>`` element."""
    return Plugin(
        name=element.get("name", ""),
        filename=element.get("filename", ""),
        params=_leaf_params(element),
        element=element,
    )


def read_gazebo(element: ET.Element) -> GazeboBlock:
    """A GazeboBlock from a ``<gazebo>`` element."""
    reference = element.get("reference")
    sensors = tuple(_read_sensor(s, reference) for s in element.findall("sensor"))
    plugins = tuple(read_plugin(p) for p in element.findall("plugin"))
    simple = [c for c in element if isinstance(c.tag, str) and c.tag not in ("sensor", "plugin")]
    properties: list[tuple[str, str]] = []
    for child in simple:
        if len(child):
            properties.extend(_leaf_params(child, child.tag + "/"))
        else:
            properties.append((child.tag, (child.text or child.get("value") or "").strip()))
    return GazeboBlock(reference, sensors, plugins, tuple(properties), element)


GAZEBO_ROS_PLUGINS = frozenset(f"libgazebo_ros_{name}.so" for name in (
    "camera", "multi_camera", "depth_camera", "triggered_camera", "ray_sensor", "imu_sensor",
    "imu", "diff_drive", "skid_steer_drive", "planar_move", "tricycle_drive", "ackermann_drive",
    "joint_state_publisher", "joint_pose_trajectory", "p3d", "ft_sensor", "gps_sensor",
    "bumper", "force", "hand_of_god", "harness", "projector", "vacuum_gripper", "video",
    "elevator", "openni_kinect", "range", "laser", "block_laser", "gpu_laser"))
"""gazebo_ros_pkgs' own plugins (gazebo_plugins), whose ROS 2 versions read no ROS 1 name;
other packages' ROS 2 plugins may (velodyne_simulator's reads ``<frameName>``)."""


ROS2_ONLY_PLUGINS = frozenset(("libgazebo_ros2_control.so", "libgazebo_ros_ray_sensor.so",
                               "libgazebo_ros_ackermann_drive.so", "libgazebo_ros_gps_sensor.so"))
"""Gazebo Classic plugins that exist for ROS 2 only (ROS 1's were gazebo_ros_control and the
laser plugins; it had no Ackermann drive or GPS sensor in gazebo_plugins)."""


def for_ros2_where_one_is(blocks: tuple[GazeboBlock, ...]) -> tuple[GazeboBlock, ...]:
    """``blocks`` with gazebo_plugins' plugins marked ``ros2_file`` where one is ROS 2's.

    One install of Gazebo runs every plugin of the file: ROS 2's where one is written for it
    (a ``<ros>`` block) or exists for ROS 2 only (:data:`ROS2_ONLY_PLUGINS`).
    """
    plugins = [p for b in blocks for p in (*b.plugins, *(q for s in b.sensors for q in s.plugins))]
    if not any(p.has_ros_block or p.filename in ROS2_ONLY_PLUGINS for p in plugins):
        return blocks

    def marked(found: tuple[Plugin, ...]) -> tuple[Plugin, ...]:
        return tuple(dataclasses.replace(p, ros2_file=True) if p.filename in GAZEBO_ROS_PLUGINS
                     else p for p in found)

    return tuple(dataclasses.replace(
        b, plugins=marked(b.plugins),
        sensors=tuple(dataclasses.replace(s, plugins=marked(s.plugins)) for s in b.sensors))
        for b in blocks)


KEEP_APART = ("disableFixedJointLumping", "preserveFixedJoint")
"""<gazebo reference="JOINT"> settings that keep a fixed joint from being lumped away."""


def kept_apart(blocks: tuple[GazeboBlock, ...]) -> dict[str, str]:
    """The fixed joints ``<gazebo reference>`` blocks keep from lumping, with the setting."""
    kept: dict[str, str] = {}
    for block in blocks:
        for key, value in block.properties:
            if key in KEEP_APART and sdf_true(value) and block.reference:
                kept[block.reference] = key
    return kept


def _read_sensor(element: ET.Element, reference: str | None) -> Sensor:
    rate = _text(element.find("update_rate"))
    params = tuple(
        pair for child in element if isinstance(child.tag, str) and child.tag != "plugin"
        for pair in (_leaf_params(child, child.tag + "/") if len(child)
                     else ((child.tag, (child.text or "").strip()),))
    )
    return Sensor(
        name=element.get("name", ""),
        type=element.get("type", ""),
        reference=reference,
        pose=_sdf_pose(_text(element.find("pose"))),
        update_rate_hz=parse_float(rate),
        params=params,
        plugins=tuple(read_plugin(p) for p in element.findall("plugin")),
        element=element,
        carrier=reference,
    )


def _sdf_pose(text: str | None) -> Pose:
    """SDF ``<pose>x y z roll pitch yaw</pose>``; identity when absent or malformed."""
    parsed = [parse_float(v) for v in (text or "").split()]
    values = [v for v in parsed if v is not None]
    if len(parsed) != 6 or len(values) != 6:
        return Pose()
    x, y, z, roll, pitch, yaw = values
    return Pose((x, y, z), (roll, pitch, yaw))


def read_ros2_control(element: ET.Element) -> Ros2Control:
    """A Ros2Control from a ``<ros2_control>`` element."""
    hardware = element.find("hardware")
    return Ros2Control(
        name=element.get("name", ""),
        type=element.get("type", ""),
        plugin=_text(hardware.find("plugin")) if hardware is not None else None,
        hardware_params=_param_pairs(hardware),
        joints=tuple(_control_item(j) for j in element.findall("joint")),
        sensors=tuple(_control_item(s) for s in element.findall("sensor")),
        gpios=tuple(_control_item(g) for g in element.findall("gpio")),
        element=element,
    )


def _param_pairs(element: ET.Element | None) -> tuple[tuple[str, str], ...]:
    if element is None:
        return ()
    return tuple((p.get("name", ""), (p.text or "").strip()) for p in element.findall("param"))


def _control_item(element: ET.Element) -> ControlJoint:
    def interfaces(tag: str) -> tuple[Interface, ...]:
        return tuple(Interface(i.get("name", ""), _param_pairs(i)) for i in element.findall(tag))

    return ControlJoint(
        name=element.get("name", ""),
        command_interfaces=interfaces("command_interface"),
        state_interfaces=interfaces("state_interface"),
        params=_param_pairs(element),
        element=element,
    )
