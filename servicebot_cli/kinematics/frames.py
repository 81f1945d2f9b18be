"""Frames by name: safe look-ups, the tool frame of an arm, the joints that move a frame.

A frame is a URDF link (fixed links included). Pinocchio's ``getFrameId`` returns an
out-of-range index for an unknown name instead of raising, so every look-up goes through
:func:`frame_id`, which checks ``existFrame`` first and suggests the nearest names.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from servicebot_cli.common.errors import FrameNotFound

if TYPE_CHECKING:
    import pinocchio as pin

    from servicebot_cli.description.robot import RobotDescription

_TOOL_WORDS = ("tool", "tcp", "end_effector", "ee_link", "flange", "gripper")


def frame_id(model: pin.Model, name: str, known: Sequence[str]) -> int:
    """Index of the link frame ``name`` in ``model.frames``.

    Args:
        model: The Pinocchio model.
        name: A link name.
        known: Every link name, for the suggestion when ``name`` is not one.

    Raises:
        FrameNotFound: ``name`` is not a link, with the nearest names first.
    """
    import pinocchio as pin

    if name in known and model.existFrame(name, pin.FrameType.BODY):
        return int(model.getFrameId(name, pin.FrameType.BODY))
    raise FrameNotFound.for_name(name, known, robot=model.name)


def moving_joints(model: pin.Model, frame: int) -> tuple[int, ...]:
    """Joint indices (root first) whose motion moves ``frame``; the universe excluded."""
    parent = model.frames[frame].parentJoint
    return tuple(int(j) for j in model.supports[parent] if j != 0)


@dataclass(frozen=True)
class ToolChoice:
    """The frame commands use when none is named.

    Attributes:
        name: The frame.
        joints: Movable joints that move it.
        obvious: True when its name says it is a tool; otherwise commands say which they chose.
    """

    name: str
    joints: int
    obvious: bool


def default_tool_frame(robot: RobotDescription) -> ToolChoice:
    """The arm's tool frame: the tip of the longest chain of turning joints.

    Links are ranked by the revolute and continuous joints that move them (a gripper's
    sliding fingers do not make a chain longer), then by a name that says tool (``tool``,
    ``tcp``, ``ee_link``, ...), then by being a leaf (no joint's parent), then by all joints,
    then by URDF order (last wins). On the bundled robot this is ``arm_tool_link``; on
    UR5 ``tool0``; on Panda ``panda_hand_tcp``.
    """
    model, links = robot.model, link_names(robot)
    turning_types = {"revolute", "continuous"}
    kinds = {j.name: j.type for j in robot.joints}
    parents = {joint.parent for joint in robot.joints}

    def rank(order: int, name: str) -> tuple[int, bool, bool, int, int]:
        joints = [model.names[j] for j in moving_joints(model, frame_id(model, name, links))]
        turning = sum(kinds.get(j) in turning_types for j in joints)
        return turning, _looks_like_tool(name), name not in parents, len(joints), order

    ranks = {name: rank(i, name) for i, name in enumerate(links)}
    name = max(links, key=ranks.__getitem__)
    return ToolChoice(name, ranks[name][3], _looks_like_tool(name))


def link_names(robot: RobotDescription) -> tuple[str, ...]:
    """Every link (frame) name, URDF order."""
    return tuple(link.name for link in robot.links)


def _looks_like_tool(name: str) -> bool:
    lowered = name.lower()
    return any(word in lowered for word in _TOOL_WORDS)


def pick_frame(robot: RobotDescription, name: str | None) -> tuple[str, str | None]:
    """``name`` if it is a frame of ``robot``; without one, the arm's tool frame.

    Returns:
        The frame, and a note saying which frame was chosen when the tool frame was picked
        by its place in the tree rather than by its name (else None).

    Raises:
        FrameNotFound: ``name`` is not a link, with the nearest names.
    """
    if name is not None:
        frame_id(robot.model, name, link_names(robot))
        return name, None
    choice = default_tool_frame(robot)
    if choice.obvious:
        return choice.name, None
    joints = f"{choice.joints} joint" + ("s" if choice.joints != 1 else "")
    return choice.name, (f"note: no --frame given; using '{choice.name}', the tip of the "
                         f"longest chain ({joints})")
