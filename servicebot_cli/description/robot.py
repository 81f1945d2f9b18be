"""RobotDescription: one loaded robot, shared by every command.

It holds the URDF text and its parsed XML, and builds on demand (once) everything the
commands need: links and joints in URDF order, fixed frames, Gazebo sensors and plugins,
``ros2_control`` blocks, the source position of every element, and the Pinocchio model and
data. Nothing heavy is built until asked for, so ``check`` on a broken file stays cheap.
"""

from __future__ import annotations

import dataclasses
import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING, TypeVar

from servicebot_cli.common.errors import (
    DescriptionError,
    FrameNotFound,
    JointNotFound,
    NameNotFound,
)
from servicebot_cli.description import elements as el
from servicebot_cli.description import extensions as ext
from servicebot_cli.description.load_warnings import LoadWarning
from servicebot_cli.description.model import build_model, check_hint, new_data
from servicebot_cli.description.safe_xml import ExternalDtd, PositionedElement
from servicebot_cli.description.sources import SourceRef

if TYPE_CHECKING:
    import pinocchio as pin

    from servicebot_cli.description.joint_space import JointSpace


XACRO_NAMES = (".xacro", ".xacro.urdf")
"""How the names of files ROS runs xacro on end: ``robot.urdf.xacro``, and gz_ros2_control_demos'
``test_cart_effort.xacro.urdf``, which its launch files give to xacro."""


def is_xacro_name(path: Path) -> bool:
    """True for a file named as xacro input (see :data:`XACRO_NAMES`)."""
    return path.name.lower().endswith(XACRO_NAMES)


class LinkNotFound(NameNotFound):
    """A link name the robot does not have."""

    kind = "link"


@dataclass(frozen=True)
class FixedFrame:
    """A link attached by a fixed joint (Pinocchio folds these into frames).

    Attributes:
        name: The child link's name.
        parent: The parent link's name.
        joint: The fixed joint's name.
        origin: Pose of the frame in its parent link.
    """

    name: str
    parent: str
    joint: str
    origin: el.Pose


@dataclass(frozen=True, eq=False)
class RobotDescription:
    """A robot description, read once and shared.

    Attributes:
        display: The file as the user named it, for messages.
        path: The file that was read (the xacro source for xacro input).
        xml_text: The URDF text (expanded, for xacro input).
        root: The parsed root element; every element has ``sourceline`` and ``column``.
        doctype: The DOCTYPE name when the document has one.
        external_dtd: The external DTD the DOCTYPE names, never loaded, and where.
        entities_used: Internal DTD entities a plain URDF refers to, where first (read
            expanded here; urdfdom does not expand them).
        files: Every file read: the top one, then xacro includes.
        xacro_args: ``name:=value`` arguments the xacro was expanded with.
        warnings: What reading it warned of (xacro's warnings, a file's messages, the
            loader's own).
    """

    display: str
    path: Path
    xml_text: str
    root: PositionedElement
    doctype: str | None = None
    external_dtd: ExternalDtd | None = None
    entities_used: tuple[tuple[str, int, int], ...] = ()
    files: tuple[str, ...] = ()
    xacro_args: tuple[tuple[str, str], ...] = ()
    warnings: tuple[LoadWarning, ...] = ()
    from_xacro: bool = False  # expanded by xacro, whatever its name (a pipe, nav2's .urdf)
    _models: dict[str, pin.Model] = field(default_factory=dict, repr=False)
    _admitted: list[bool] = field(default_factory=list, repr=False)  # past the refusals

    # -- names and parts, in URDF order ------------------------------------------------------

    @property
    def name(self) -> str:
        """The robot's name (``<robot name>``)."""
        return self.root.get("name", "")

    @property
    def expanded(self) -> bool:
        """True when the description came from xacro."""
        return self.from_xacro or bool(self.xacro_args) or is_xacro_name(self.path) \
            or len(self.files) > 1

    @cached_property
    def links(self) -> tuple[el.Link, ...]:
        """Every ``<link>``, in document order."""
        return tuple(el.read_link(e) for e in self.root.findall("link"))

    @cached_property
    def joints(self) -> tuple[el.Joint, ...]:
        """Every ``<joint>``, in document order."""
        return tuple(el.read_joint(e) for e in self.root.findall("joint"))

    @cached_property
    def joints_by_name(self) -> dict[str, el.Joint]:
        """Each joint by name; of a name given twice (SB102), the first, as :meth:`joint`."""
        return _first_by_name(self.joints)

    @cached_property
    def movable_joints(self) -> tuple[el.Joint, ...]:
        """Joints that are not fixed, in URDF order."""
        return tuple(j for j in self.joints if j.movable)

    @property
    def unvalued_joints(self) -> dict[str, str]:
        """Joints no single value sets (fixed, floating, planar), by name: their types."""
        return {j.name: j.type for j in self.joints
                if not j.movable or j.type in ("floating", "planar")}

    @cached_property
    def materials(self) -> dict[str, tuple[float, float, float, float] | None]:
        """Top-level materials: name to RGBA."""
        return el.read_materials(self.root)

    @cached_property
    def transmissions(self) -> tuple[el.Transmission, ...]:
        """Every ``<transmission>``."""
        return tuple(el.read_transmission(e) for e in self.root.findall("transmission"))

    @cached_property
    def gazebo(self) -> tuple[ext.GazeboBlock, ...]:
        """Every top-level ``<gazebo>`` block."""
        return ext.for_ros2_where_one_is(
            tuple(ext.read_gazebo(e) for e in self.root.findall("gazebo")))

    @cached_property
    def sensors(self) -> tuple[ext.Sensor, ...]:
        """Every Gazebo ``<sensor>``, with its link, and the link Gazebo carries it on."""
        return tuple(dataclasses.replace(s, carrier=self.gazebo_link(s.reference))
                     if s.reference else s for block in self.gazebo for s in block.sensors)

    @cached_property
    def part_names(self) -> frozenset[str]:
        """Every link and joint name: what a ``<gazebo reference>`` may name.

        sdformat drops a block that names none of them.
        """
        return frozenset(link.name for link in self.links) | {j.name for j in self.joints}

    @cached_property
    def kept_apart(self) -> dict[str, str]:
        """The fixed joints a ``<gazebo reference>`` keeps from lumping, with the setting."""
        return ext.kept_apart(self.gazebo)

    def gazebo_link(self, name: str) -> str:
        """The link Gazebo makes of link ``name``.

        sdformat's URDF converter lumps the child of a fixed joint into its parent (unless
        the joint is kept apart, or the parent is ``world``), up to a link that a moving or
        kept joint holds, or the root.
        """
        parents = self._fixed_parents
        seen = {name}
        while name in parents and parents[name] not in seen:
            name = parents[name]
            seen.add(name)
        return name

    @cached_property
    def _fixed_parents(self) -> dict[str, str]:
        kept = self.kept_apart  # and sdformat never lumps a link into "world"
        return {j.child: j.parent for j in self.joints if j.type == "fixed"
                and j.name not in kept and j.child and j.parent and j.parent != "world"}

    @cached_property
    def model_plugins(self) -> tuple[ext.Plugin, ...]:
        """The plugins of the ``<gazebo>`` blocks that name no link: the model's own."""
        return tuple(p for block in self.gazebo if block.reference is None for p in block.plugins)

    @cached_property
    def plugins(self) -> tuple[ext.Plugin, ...]:
        """Every Gazebo ``<plugin>``: model-level ones, then those inside sensors."""
        model_level = [p for block in self.gazebo for p in block.plugins]
        in_sensors = [p for s in self.sensors for p in s.plugins]
        return tuple(model_level + in_sensors)

    @cached_property
    def ros2_control(self) -> tuple[ext.Ros2Control, ...]:
        """Every ``<ros2_control>`` block."""
        return tuple(ext.read_ros2_control(e) for e in self.root.findall("ros2_control"))

    @cached_property
    def root_link(self) -> str | None:
        """The one link that is no joint's child; None if there are zero or several."""
        children = {j.child for j in self.joints}
        roots = [link.name for link in self.links if link.name not in children]
        return roots[0] if len(roots) == 1 else None

    @cached_property
    def fixed_frames(self) -> tuple[FixedFrame, ...]:
        """Links attached by fixed joints, in URDF order."""
        return tuple(
            FixedFrame(j.child or "", j.parent or "", j.name, j.origin)
            for j in self.joints
            if j.type == "fixed"
        )

    @cached_property
    def links_by_name(self) -> dict[str, el.Link]:
        """Each link by name; of a name given twice (SB101), the first, as :meth:`link`."""
        return _first_by_name(self.links)

    def find_link(self, name: str | None) -> el.Link | None:
        """The link called ``name``, or None where there is none (a joint's misspelt child)."""
        return None if name is None else self.links_by_name.get(name)

    def link(self, name: str) -> el.Link:
        """The link called ``name``.

        Raises:
            LinkNotFound: With the closest names.
        """
        link = self.find_link(name)
        if link is None:
            raise LinkNotFound.for_name(name, [lk.name for lk in self.links], robot=self.name)
        return link

    def joint(self, name: str) -> el.Joint:
        """The joint called ``name``.

        Raises:
            JointNotFound: With the closest names.
        """
        joint = self.joints_by_name.get(name)
        if joint is None:
            raise JointNotFound.for_name(name, [j.name for j in self.joints], robot=self.name)
        return joint

    def require_frame(self, name: str) -> str:
        """``name`` if it is a link (every link is a frame), else FrameNotFound."""
        if any(link.name == name for link in self.links):
            return name
        raise FrameNotFound.for_name(name, [lk.name for lk in self.links], robot=self.name)

    # -- where things were written -------------------------------------------------------------

    def source_of(self, element: ET.Element | None) -> SourceRef:
        """Where ``element`` was written: the xacro line for xacro input, else the URDF line."""
        if element is None:
            return SourceRef(self.display, 0)
        origin = getattr(element, "origin", None)  # set by the xacro tracer
        if isinstance(origin, SourceRef):
            return origin
        return SourceRef(self.display, getattr(element, "sourceline", 0),
                         getattr(element, "column", 0))

    # -- Pinocchio -------------------------------------------------------------------------------

    def model_with_base(self, base: str = "fixed") -> pin.Model:
        """The Pinocchio model with root joint ``base``: ``fixed``, ``planar`` or ``free``.

        Each is built once per description.

        Raises:
            DescriptionError: Pinocchio rejected the description.
        """
        if not self._admitted:  # judged once, at the first model asked for
            self._refuse_zero_axes()
            self._refuse_negative_friction()
            self._admitted.append(True)
        return self.pinocchio_model(base)

    def pinocchio_model(self, base: str = "fixed") -> pin.Model:
        """The model as Pinocchio builds it, without this tool's own refusals.

        check's SB701 judges Pinocchio alone; its other rules report what the refusals name.

        Raises:
            DescriptionError: Pinocchio rejected the description.
        """
        if base not in self._models:
            self._models[base] = build_model(self.xml_text, self.display, base,
                                             self.xacro_args)
        return self._models[base]

    def _refuse_zero_axes(self) -> None:
        """A moving joint with ``<axis xyz="0 0 0">`` turns about nothing (check's SB207).

        Pinocchio builds it anyway and places its child with ``cos(q)`` times the identity,
        no rotation at all: every pose past it would be wrong.

        Raises:
            DescriptionError: Naming the joint.
        """
        for joint in self.joints:
            if joint.movable and joint.type != "floating" and not any(joint.axis):
                raise DescriptionError(
                    f"{self.display}: joint '{joint.name}' has <axis xyz=\"0 0 0\">: it "
                    f"turns or slides along no direction; give its axis "
                    f"{check_hint(self.display, self.xacro_args)}")

    def refuse_far_origins(self) -> None:
        """Refuse an ``<origin>`` farther than :data:`~.elements.FARTHEST_M` (check's SB019).

        Each pose past it is computed from a number no robot measures, and overflows to
        infinity once rotated or squared (``1e308``).

        Raises:
            DescriptionError: Naming the first such joint or link.
        """
        places = [(f"joint '{joint.name}'", joint.origin, f"link '{joint.parent}'")
                  for joint in self.joints]
        for link in self.links:
            origins = [("inertial", link.inertial.origin)] if link.inertial is not None else []
            origins += [("collision", shape.origin) for shape in link.collisions]
            origins += [("visual", shape.origin) for shape in link.visuals]
            places += [(f"the {kind} of link '{link.name}'", origin, "the link's frame")
                       for kind, origin in origins]
        for what, origin, reference in places:
            if math.isnan(origin.offset_m):  # a number urdfdom cannot read, or nan
                raise DescriptionError(
                    f"{self.display}: {what} has an <origin xyz> that is not three finite "
                    f"numbers {check_hint(self.display, self.xacro_args)}")
            if not origin.offset_m <= el.FARTHEST_M:
                raise DescriptionError(
                    f"{self.display}: {what} is placed {origin.offset_m:g} m from {reference}, "
                    f"beyond the {el.FARTHEST_M:g} m of any robot; write its <origin xyz> in "
                    f"metres {check_hint(self.display, self.xacro_args)}")

    def refuse_unmovable_joints(self) -> None:
        """Refuse joints no command can move, each in one line that names it.

        Limits in the wrong order (check's SB203), and a ``<mimic>`` of itself or of a joint
        that is not there (SB210, SB209). No position lies between a lower limit above the
        upper one (pybullet reads them as no limit, every other tool as a range nothing
        satisfies).

        No joint drives the follower: MoveIt refuses the robot, yourdfpy sets it to the
        offset, Pinocchio and this tool's kinematics would move it freely. The commands
        that move the robot refuse it (:func:`~servicebot_cli.description.loader.load`);
        ``inspect``, which shows what a file holds (RViz draws such a robot), does not.
        A loop of mimics (SB211) keeps one of its joints free, as check explains.

        Raises:
            DescriptionError: Naming the joint.
        """
        for joint in self.joints:
            limits = joint.limits
            if joint.type in ("revolute", "prismatic") and limits is not None \
                    and limits.lower is not None and limits.upper is not None \
                    and limits.lower > limits.upper:
                raise DescriptionError(  # check's SB203 is a warning (pybullet: no limit)
                    f"{self.display}: joint '{joint.name}' has lower limit {limits.lower:g} "
                    f"above its upper limit {limits.upper:g}: no position lies between them "
                    "(pybullet reads it as no limit, and check only warns: SB203); write them "
                    "in order, or make the joint continuous if it turns without limit")
        names = {joint.name for joint in self.joints}
        for joint in self.joints:
            if joint.mimic is None or (joint.mimic.joint in names
                                       and joint.mimic.joint != joint.name):
                continue
            leader = joint.mimic.joint
            if leader is None:
                what = "no joint (its <mimic> has no joint attribute)"
            else:
                what = "itself" if leader == joint.name else f"'{leader}', which does not exist"
            raise DescriptionError(
                f"{self.display}: joint '{joint.name}' mimics {what}: nothing drives it; "
                "name its leader in <mimic joint=...>, or remove the <mimic> "
                f"{check_hint(self.display, self.xacro_args)}")
        for joint in self.joints:
            self._refuse_far_follower(joint)

    def _refuse_far_follower(self, joint: el.Joint) -> None:
        """Refuse a sliding follower its ``<mimic>`` places beyond any robot (or nowhere).

        ``multiplier="1e308" offset="1e308"`` put a finger 1e308 m out: every distance to it
        overflowed.

        Raises:
            DescriptionError: Naming the joint and how far.
        """
        mimic = joint.mimic
        if mimic is None or joint.type != "prismatic" or mimic.joint is None:
            return
        leader = self.joints_by_name.get(mimic.joint)
        limits = leader.limits if leader is not None else None
        ends = [value for value in ((limits.lower, limits.upper) if limits else ())
                if value is not None and math.isfinite(value)] or [0.0]
        far = max(abs(mimic.multiplier * value + mimic.offset) for value in ends)  # inf, nan
        if not far <= el.FARTHEST_M:
            how = (f"slides it {far:g} m, beyond the {el.FARTHEST_M:g} m of any robot"
                   if math.isfinite(far) else "slides it out of a number's range"
                   if math.isinf(far) else "places it at no number")
            raise DescriptionError(
                f"{self.display}: joint '{joint.name}' mimics '{mimic.joint}' times "
                f"{mimic.multiplier:g} plus {mimic.offset:g}, which {how}; write the "
                "multiplier and offset in metres per unit of its leader "
                f"{check_hint(self.display, self.xacro_args)}")

    def _refuse_negative_friction(self) -> None:
        """A negative ``<dynamics friction>`` (check's SB216), in the file's words.

        Pinocchio refuses it as "Some components of min_dry_friction are greater than
        max_dry_friction", naming neither the joint nor the attribute.

        Raises:
            DescriptionError: Naming the joint.
        """
        for joint in self.joints:
            if joint.type not in el.ONE_AXIS_TYPES:
                continue
            dynamics = joint.element.find("dynamics") if joint.element is not None else None
            friction = el.parse_float(dynamics.get("friction")) if dynamics is not None else None
            if friction is not None and friction < 0:
                raise DescriptionError(
                    f"{self.display}: joint '{joint.name}' has <dynamics friction="
                    f"\"{friction:g}\">, which Pinocchio refuses; write its magnitude "
                    f"{check_hint(self.display, self.xacro_args)}")

    @property
    def model(self) -> pin.Model:
        """The fixed-base Pinocchio model: the root link is the world frame."""
        return self.model_with_base("fixed")

    @cached_property
    def data(self) -> pin.Data:
        """Pinocchio data for :attr:`model`, shared; commands recompute what they read."""
        return new_data(self.model, self.display)

    @cached_property
    def joint_space(self) -> JointSpace:
        """Joint names, limits and configuration vectors for :attr:`model`."""
        from servicebot_cli.description.joint_space import JointSpace

        return JointSpace.of(self.model, self.movable_joints)


_Named = TypeVar("_Named", el.Link, el.Joint)


def _first_by_name(items: tuple[_Named, ...]) -> dict[str, _Named]:
    """``items`` by name, the first of a name written twice kept."""
    found: dict[str, _Named] = {}
    for item in items:
        found.setdefault(item.name, item)
    return found
