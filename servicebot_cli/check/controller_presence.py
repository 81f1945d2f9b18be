"""SB608: a declared controller whose parameters are nowhere in the file, beside a misnamed section.

The controller manager loads each controller it declares (``NAME: type: ...``) with the
parameters of the section called NAME. A section whose name is a letter or two off
(``diff_drive_controler:``) configures nothing, and the controller starts with its defaults:
a ros2_controllers controller whose validation wants a value (diff_drive_controller's wheel
names, JointTrajectoryController's joints) refuses to configure. Pure: YAML nodes in, issues
out.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterator

import yaml  # type: ignore[import-untyped]  # PyYAML ships no types

from servicebot_cli.check.controller_sections import (
    Sections,
    at,
    get,
    named_at,
    type_nodes,
)
from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.check.rcl_names import node_name_refusal, valid_node_name
from servicebot_cli.check.substitutions import substituted

_FORWARD = ("joints", "interface_name")  # (interface_name absent from a section: an error of
# controller_params.validated_values)
_GROUP = ("joints",)
_GRIPPER = ("joint",)
NEEDED: dict[str, tuple[str, ...]] = {
    "diff_drive_controller/DiffDriveController": ("left_wheel_names", "right_wheel_names"),
    "joint_trajectory_controller/JointTrajectoryController": (
        "joints", "command_interfaces", "state_interfaces"),
    "forward_command_controller/ForwardCommandController": _FORWARD,
    "position_controllers/JointGroupPositionController": _GROUP,
    "velocity_controllers/JointGroupVelocityController": _GROUP,
    "effort_controllers/JointGroupEffortController": _GROUP,
    "position_controllers/GripperActionController": _GRIPPER,
    "effort_controllers/GripperActionController": _GRIPPER,
    "parallel_gripper_action_controller/GripperActionController": _GRIPPER,
    "imu_sensor_broadcaster/IMUSensorBroadcaster": ("sensor_name", "frame_id"),
    "force_torque_sensor_broadcaster/ForceTorqueSensorBroadcaster": ("frame_id",),
}
"""Parameters each controller refuses to configure without (not_empty, size_gt 0 in its
``*_parameters.yaml``; the wheel names checked at configure in Humble's diff drive)."""


_OWN_RULE = {"forward_command_controller/ForwardCommandController": ("interface_name",)}
"""Needed parameters that another rule reports missing from a section, as an error."""


def _node_part(name: str) -> str:
    """The node's part of ``name`` (``/ns/diff_controller``: its end)."""
    return name.rstrip("/").rpartition("/")[2]


def presence_issues(found: Sections, display: str) -> Iterator[Issue]:
    """SB608 for each misnamed section, and each declared controller left without parameters.

    A declared controller with no section is judged only where the file configures other
    controllers (a file of ``controller_manager`` alone may leave them to other files).
    """
    types = type_nodes(found)
    nameable = [name for name in types if node_name_refusal(name) is None or substituted(name)]
    for name, node in types.items():
        if name not in nameable and name not in found:  # a section's own name: rcl_layout
            yield Issue("SB608", f"controller_manager declares '{name}': a controller's name is "
                        "its node's, which rclcpp refuses unless it is letters, digits and '_' "
                        "(not a digit first), so the controller manager cannot load it",
                        where=at(display, node.start_mark),
                        fix=f"declare it as '{valid_node_name(_node_part(name))}': it runs in "
                            "the controller manager's namespace")
    without = [name for name in nameable if name not in found]
    stray = [name for name in found if name != "controller_manager" and name not in types]
    renamed: dict[str, str] = {}
    for name in stray:
        close = difflib.get_close_matches(name, [n for n in without if n not in renamed.values()],
                                          n=1, cutoff=0.8)
        if close:
            renamed[name] = close[0]
    for name, meant in renamed.items():
        kind = str(types[meant].value)
        needs = NEEDED.get(kind)
        result = (f"and refuses to configure without {_listed(needs)}" if needs
                  else "with its defaults")
        yield Issue("SB608", f"section '{name}' configures no controller: controller_manager "
                    f"declares '{meant}' ({kind}), which has no section, so it starts with no "
                    f"parameters {result}", where=at(display, named_at(found[name][0])),
                    severity=Severity.ERROR if needs else Severity.WARNING,
                    fix=f"rename the section '{meant}:'")
    alone = not any(name in types for name in found)  # the manager's file: others may follow
    for name in without:
        kind = str(types[name].value)
        needs = NEEDED.get(kind)
        if needs is None or name in renamed.values():
            continue
        yield Issue("SB608", f"controller '{name}' ({kind}) has no parameters in this file: it "
                    f"refuses to configure without {_listed(needs)}, unless another parameter "
                    "file gives them", where=at(display, types[name].start_mark),
                    severity=Severity.INFO if alone else Severity.WARNING,
                    fix=f"add a section '{name}: ros__parameters:' with {_listed(needs)}")
    for name, sections in found.items():
        kind = str(types[name].value) if name in types else ""
        lacking = tuple(key for key in NEEDED.get(kind, ()) if key not in _OWN_RULE.get(kind, ())
                        and not any(_gives(section, key) for section in sections))
        if lacking:
            yield Issue("SB608", f"{name} gives no {_listed(lacking)}: {kind} refuses to "
                        "configure without them, unless another parameter file gives them",
                        where=at(display, sections[0].start_mark), severity=Severity.WARNING,
                        fix=f"add {_listed(lacking)} to its ros__parameters")


def _gives(section: yaml.MappingNode, key: str) -> bool:
    """Whether ``section`` writes the parameter ``key`` (or, nested, ``key.*``)."""
    return get(section, key) is not None or any(
        isinstance(k, yaml.ScalarNode) and str(k.value).startswith(f"{key}.")
        for k, _ in section.value)


def _listed(names: tuple[str, ...]) -> str:
    return names[0] if len(names) == 1 else f"{', '.join(names[:-1])} and {names[-1]}"
