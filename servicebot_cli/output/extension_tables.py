"""The tables of ``servicebot inspect`` for what URDF parsers drop.

Sensors, Gazebo and ros2_control plugins, command and state interfaces, and topics.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from servicebot_cli.output import describe as d
from servicebot_cli.output.blocks import Table
from servicebot_cli.output.table import format_number

if TYPE_CHECKING:
    from servicebot_cli.inspect.interfaces import InterfaceInfo, InterfacesInfo
    from servicebot_cli.inspect.plugins import PluginsInfo
    from servicebot_cli.inspect.report import TopicsInfo
    from servicebot_cli.inspect.sensors import SensorInfo


def sensors_tables(sensors: tuple[SensorInfo, ...]) -> list[Table]:
    """Where each sensor is and what it publishes; then what it measures."""
    table = Table(f"Sensors ({len(sensors)})", ("sensor", "type", "link", "rate [Hz]", "topics"),
                  empty="no sensors")
    details = Table("Sensor details", ("sensor", "property", "value"))
    for s in sensors:
        topics = ", ".join(t.name for t in s.topics) or "-"
        table.rows.append((s.name, s.type, s.link, s.update_rate_hz, topics))
        details.rows.extend((s.name, key, value) for key, value in _details(s))
    return [table] + ([details] if details.rows else [])


def _details(s: SensorInfo) -> list[tuple[str, str]]:
    lumped = s.plugin is not None and s.frame == s.carrier != s.link  # a ROS 2 plugin
    # without <frame_name> stamps the link Gazebo carries the sensor on
    frame = f"{s.frame} (Gazebo lumps {s.link} into it)" if lumped else s.frame or "-"
    rows = [("plugin", s.plugin or "-"), ("frame", frame)]
    if s.topics and s.plugin is None and s.topics_from:
        rows.append(("topics from", s.topics_from))
    if s.lidar is not None:
        lidar = s.lidar
        rows.append(("scan", f"{lidar.samples} samples over "
                             f"{d.span(lidar.min_angle_rad, lidar.max_angle_rad)} rad"))
        if lidar.vertical_samples is not None and lidar.vertical_samples > 1:  # a 3D lidar
            rows.append(("vertical scan", f"{lidar.vertical_samples} rings over "
                         f"{d.span(lidar.vertical_min_angle_rad, lidar.vertical_max_angle_rad)}"
                         " rad"))
        rows += [("range", f"{d.span(lidar.min_range_m, lidar.max_range_m)} m, resolution "
                           f"{d.quantity(lidar.range_resolution_m, 'm')}"),
                 ("noise", d.noise(lidar.noise, "m"))]
    if s.camera is not None:
        cam = s.camera
        size = "-" if cam.width_px is None or cam.height_px is None \
            else f"{cam.width_px} x {cam.height_px}"
        rows += [("image", f"{size} {cam.image_format or ''}".strip()),
                 ("horizontal field of view", d.quantity(cam.horizontal_fov_rad, "rad")),
                 ("clip", f"{d.span(cam.near_clip_m, cam.far_clip_m)} m"),
                 ("noise", d.noise(cam.noise))]
    if s.imu is not None:
        for name, axes, unit in (("angular velocity", s.imu.angular_velocity_noise, "rad/s"),
                                 ("linear acceleration", s.imu.linear_acceleration_noise,
                                  "m/s^2")):
            texts = [d.noise(a, unit) for a in axes]
            if len(set(texts)) == 1:
                rows.append((f"{name} noise (x, y, z)", texts[0]))
            else:
                rows += [(f"{name} noise {axis}", t) for axis, t in zip("xyz", texts, strict=True)]
    return rows


def plugins_tables(plugins: PluginsInfo) -> list[Table]:
    """Gazebo plugins and their parameters, ros2_control hardware, Gazebo link properties."""
    gazebo = Table(f"Gazebo plugins ({len(plugins.gazebo)})", ("plugin", "file", "attached to"),
                   empty="no Gazebo plugins")
    params = Table("Gazebo plugin parameters", ("plugin", "parameter", "value"))
    for p in plugins.gazebo:
        gazebo.rows.append((p.name, p.filename, p.attached_to))
        params.rows.extend((p.name, q.name, q.value) for q in p.params)
    hardware = Table("ros2_control hardware", ("system", "type", "plugin", "parameters"),
                     empty="no <ros2_control>")
    for h in plugins.ros2_control:
        text = ", ".join(f"{q.name}={q.value}" for q in h.params) or "-"
        hardware.rows.append((h.name, h.type, h.plugin, text))
    props = Table("Gazebo link properties", ("link", "properties"))
    for block in plugins.gazebo_properties:
        props.rows.append((block.reference, ", ".join(f"{q.name}={q.value}"
                                                       for q in block.properties)))
    tables = [gazebo] + ([params] if params.rows else []) + [hardware]
    return tables + ([props] if props.rows else [])


def interfaces_tables(interfaces: InterfacesInfo) -> list[Table]:
    """Command and state interfaces of each controlled joint; transmissions if any."""
    table = Table("ros2_control interfaces", ("joint", "command", "state"),
                  empty="no <ros2_control> joints")
    systems = {j.system for j in interfaces.joints}
    for j in interfaces.joints:
        name = j.name if len(systems) == 1 else f"{j.system}/{j.name}"
        name = name if j.kind == "joint" else f"{name} ({j.kind})"
        table.rows.append((name, _interfaces(j.command), _interfaces(j.state)))
    tables = [table]
    if interfaces.transmissions:
        tables.append(Table("Transmissions", ("transmission", "type", "joints", "actuators"),
                            [(t.name, t.type, ", ".join(t.joints), ", ".join(t.actuators))
                             for t in interfaces.transmissions]))
    return tables


def _interfaces(items: tuple[InterfaceInfo, ...]) -> str:
    texts = []
    for i in items:
        text = i.name
        if i.min is not None or i.max is not None:
            text += f" {d.span(i.min, i.max) if i.min is not None and i.max is not None else ''}"
        if i.initial_value is not None:
            text += f" (initial {format_number(i.initial_value)})"
        texts.append(text.strip())
    return ", ".join(texts) or "-"


def topics_tables(topics: TopicsInfo) -> list[Table]:
    """The controllers read, then what the robot consumes and what it publishes."""
    found = {"--controllers": "given with --controllers",
             "gazebo_ros2_control": "named by the gazebo_ros2_control plugin",
             "beside": "found beside the description"}
    title = (f"Controllers ({topics.controllers_file}, {found[topics.controllers_found_by]})"
             if topics.controllers_file and topics.controllers_found_by else "Controllers")
    controllers = Table(title, ("controller", "type"),
                        [(c.name, c.type) for c in topics.controllers],
                        topics.notes, empty="no controller configuration")
    tables = [controllers]
    for direction, title in (("in", "Consumed"), ("out", "Published")):
        rows = [t for t in topics.topics if t.direction == direction]
        notes = tuple(f"{t.name}: {t.note}" for t in rows if t.note)
        tables.append(Table(f"{title} ({len(rows)})", ("topic", "type", "from"),
                            [(_name(t.name, t.kind), t.message, t.provider) for t in rows],
                            notes))
    return tables


def _name(name: str, kind: str) -> str:
    """Devices say so; an action's type already does (``.../action/...``)."""
    return f"{name} (device)" if kind == "device" else name
