"""Frames by name: safe look-ups, the tool frame of an arm, the joints that move a frame.

A frame is a URDF link (fixed links included). Pinocchio's ``getFrameId`` returns an
out-of-range index for an unknown name instead of raising, so every look-up goes through
:func:`frame_id`, which checks ``existFrame`` first and suggests the nearest names. A link
on a joint loop is in the URDF but in no model: :func:`require_tree` refuses such a robot.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from servicebot_cli.common.errors import DescriptionError, FrameNotFound
from servicebot_cli.description.model import check_hint

if TYPE_CHECKING:
    import pinocchio as pin

    from servicebot_cli.description.elements import Joint
    from servicebot_cli.description.robot import RobotDescription

_TOOL_WORDS = ("tool", "tcp", "end_effector", "ee_link", "flange", "gripper")
_TOOL_FRAME = re.compile(r"(?:^|[_/])(?:tool|tcp|end_effector|flange|ee)(?:\d*)(?:[_/]|$)")


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
    if name in known:  # a link the model left out: no root reaches it (see require_tree)
        raise DescriptionError(f"link '{name}' of {model.name} is not in its model: no root "
                               "link reaches it; a kinematic loop? ('servicebot check' shows it)")
    raise FrameNotFound.for_name(name, known, robot=model.name)


def frame_ids(model: pin.Model, names: Sequence[str], known: Sequence[str]) -> list[int]:
    """:func:`frame_id` of each of ``names``, in one pass over the model's frames.

    Pinocchio's look-up walks every frame, so asking for each of 10,000 frames alone took
    seconds (``fk --all-frames`` on a wide tree).
    """
    import pinocchio as pin

    links = set(known)
    body = {f.name: i for i, f in enumerate(model.frames) if f.type == pin.FrameType.BODY}
    return [body[name] if name in links and name in body else frame_id(model, name, known)
            for name in names]


def require_tree(robot: RobotDescription) -> None:
    """Refuse links no root reaches: joints that close a loop off the tree.

    Pinocchio builds its model from the root down and silently leaves out a joint whose
    parent is its own child, or a ring of joints that nothing joins to the root; every
    frame on it would then be "missing". Iterative, linear in the number of joints.

    Raises:
        DescriptionError: The first such loop, as ``check`` (SB107) words it.
    """
    known = set(link_names(robot))
    parent_joint: dict[str, Joint] = {}
    below: dict[str, list[str]] = {}
    for joint in robot.joints:
        if joint.parent in known and joint.child in known and joint.child not in parent_joint:
            parent_joint[joint.child or ""] = joint
            below.setdefault(joint.parent or "", []).append(joint.child or "")
    reached = [name for name in link_names(robot) if name not in parent_joint]
    seen = set(reached)
    while reached:
        for child in below.get(reached.pop(), ()):
            if child not in seen:
                seen.add(child)
                reached.append(child)
    lost = next((name for name in link_names(robot) if name not in seen), None)
    if lost is not None:
        raise DescriptionError(f"{robot.display}: not a valid URDF: "
                               f"{_loop_text(lost, parent_joint)}; a URDF is a tree "
                               f"{check_hint(robot.display, robot.xacro_args)}")


def _loop_text(link: str, parent_joint: dict[str, Joint]) -> str:
    """The loop above ``link`` (a link no root reaches): ``a -[ab]-> b -[ba]-> a``."""
    order: dict[str, int] = {}
    chain: list[Joint] = []
    while link not in order:  # every lost link has a lost parent: this ends on a loop
        order[link] = len(chain)
        chain.append(parent_joint[link])
        link = chain[-1].parent or ""
    loop = chain[order[link]:][::-1]
    if len(loop) == 1:
        return f"joint '{loop[0].name}' connects link '{link}' to itself"
    hops = [f" -[{j.name}]-> {j.child}" for j in loop]
    if len(hops) > 6:
        hops = [*hops[:3], f" ... ({len(hops) - 5} more joints)", *hops[-2:]]
    return f"kinematic loop: {link}{''.join(hops)}"


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
    """The arm's tool frame: a link whose name says so, else the tip of the longest chain.

    A link with ``tool``, ``tcp``, ``end_effector``, ``flange`` or ``ee`` as a word of its
    name, that a turning joint moves, comes first (the one with the most turning joints):
    the longest chain of a robot with a hand runs into a finger (TIAGo's
    ``hand_little_flex_3_link`` past its ``hand_tool_link``). Otherwise links are ranked by
    the revolute and continuous joints that move them (a gripper's sliding fingers do not
    make a chain longer), then by a name that says tool (``tool``, ``tcp``, ``ee_link``,
    ...), then by being a leaf (no joint's parent), then by all joints, then by URDF order
    (last wins). On the bundled robot this is ``arm_tool_link``; on UR5 ``tool0``; on Panda
    ``panda_hand_tcp``.
    """
    model, links = robot.model, link_names(robot)
    turning_types = {"revolute", "continuous"}
    kinds = {j.name: j.type for j in robot.joints}
    parents = {joint.parent for joint in robot.joints}

    def rank(order: int, name: str) -> tuple[int, bool, bool, int, int]:
        joints = [model.names[j] for j in moving_joints(model, frame_id(model, name, links))]
        turning = sum(kinds.get(j) in turning_types for j in joints)
        return turning, looks_like_tool(name), name not in parents, len(joints), order

    ranks = {name: rank(i, name) for i, name in enumerate(links)}
    named = [name for name in links if _names_a_tool(name) and ranks[name][0] > 0]
    if named:  # TIAGo's arm_tool_link, not the tip of a finger of its hand
        name = max(named, key=ranks.__getitem__)
        return ToolChoice(name, ranks[name][3], True)
    name = max(links, key=ranks.__getitem__)
    return ToolChoice(name, ranks[name][3], looks_like_tool(name))


def link_names(robot: RobotDescription) -> tuple[str, ...]:
    """Every link (frame) name, URDF order."""
    return tuple(link.name for link in robot.links)


def _names_a_tool(name: str) -> bool:
    """A name with a word that says the arm's tool frame.

    ``tool0``, ``panda_hand_tcp``, ``ee_link``, ``ee_gripper_link``; not a gripper's part
    (``gripper_left_link``) nor ``right_knee_link``.
    """
    return _TOOL_FRAME.search(name.lower()) is not None


def looks_like_tool(name: str) -> bool:
    """A name with a word of a tool in it (``tool``, ``tcp``, ``ee_link``, ``gripper``...)."""
    lowered = name.lower()
    return any(word in lowered for word in _TOOL_WORDS)


def pick_frame(robot: RobotDescription, name: str | None) -> tuple[str, str | None]:
    """``name`` if it is a frame of ``robot``; without one, the arm's tool frame.

    Returns:
        The frame, and a note saying which frame was chosen when the tool frame was picked
        by its place in the tree rather than by its name (else None).

    Raises:
        DescriptionError: Joints that close a loop (:func:`require_tree`).
        FrameNotFound: ``name`` is not a link, with the nearest names.
    """
    require_tree(robot)
    if name is not None:
        frame_id(robot.model, name, link_names(robot))
        return name, None
    choice = default_tool_frame(robot)
    if choice.obvious:
        return choice.name, None
    joints = f"{choice.joints} joint" + ("s" if choice.joints != 1 else "")
    return choice.name, (f"note: no --frame given; using '{choice.name}', the tip of the "
                         f"longest chain ({joints})")
