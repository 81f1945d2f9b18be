"""The interfaces table: each ros2_control joint's command and state interfaces."""

from __future__ import annotations

from dataclasses import dataclass

from servicebot_cli.description.elements import Transmission, parse_float
from servicebot_cli.description.extensions import Interface, Ros2Control


@dataclass(frozen=True)
class InterfaceInfo:
    """One command or state interface.

    Attributes:
        name: ``position``, ``velocity``, ``effort``...
        min, max: Its ``<param name="min|max">`` in the joint's units, if given.
        initial_value: Its ``<param name="initial_value">``, if given.
        params: Every ``<param>``, as written.
    """

    name: str
    min: float | None
    max: float | None
    initial_value: float | None
    params: tuple[tuple[str, str], ...]


@dataclass(frozen=True)
class ControlledJoint:
    """A joint (or sensor, gpio) in a ``<ros2_control>`` system."""

    system: str
    kind: str
    name: str
    command: tuple[InterfaceInfo, ...]
    state: tuple[InterfaceInfo, ...]


@dataclass(frozen=True)
class TransmissionInfo:
    """A ``<transmission>``: which joints drive which actuators."""

    name: str
    type: str | None
    joints: tuple[str, ...]
    actuators: tuple[str, ...]


@dataclass(frozen=True)
class InterfacesInfo:
    """What a controller manager can command and read."""

    joints: tuple[ControlledJoint, ...]
    transmissions: tuple[TransmissionInfo, ...]


def _interface(interface: Interface) -> InterfaceInfo:
    def number(key: str) -> float | None:
        return parse_float(interface.get(key))

    return InterfaceInfo(interface.name, number("min"), number("max"), number("initial_value"),
                         interface.params)


def interfaces_info(systems: tuple[Ros2Control, ...],
                    transmissions: tuple[Transmission, ...]) -> InterfacesInfo:
    """Every controlled joint, sensor and gpio of every system, then the transmissions."""
    joints = tuple(
        ControlledJoint(system.name, kind, item.name,
                        tuple(_interface(i) for i in item.command_interfaces),
                        tuple(_interface(i) for i in item.state_interfaces))
        for system in systems
        for kind, items in (("joint", system.joints), ("sensor", system.sensors),
                            ("gpio", system.gpios))
        for item in items
    )
    return InterfacesInfo(joints, tuple(TransmissionInfo(t.name, t.type, t.joints, t.actuators)
                                        for t in transmissions))
