"""Load a robot description from a file: the one entry point every command uses.

``read_description`` reads, expands (xacro) and parses, and stops there: ``check`` wants
the defects of a file, not a refusal. ``load`` also insists on a ``<robot>`` that Pinocchio
accepts, and memoises per source, so all commands in a process share one object.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path

from servicebot_cli.common.errors import DescriptionError, PackageNotFound, split_location
from servicebot_cli.common.inputs import (
    display_path,
    not_a_file,
    printable_name,
    read_input_bytes,
)
from servicebot_cli.description import resources
from servicebot_cli.description.load_warnings import LoadWarning
from servicebot_cli.description.model import check_hint
from servicebot_cli.description.packages import PackageResolver
from servicebot_cli.description.parents import second_parents
from servicebot_cli.description.robot import RobotDescription, is_xacro_name
from servicebot_cli.description.safe_xml import (
    ENTITY_FIX,
    MAX_BYTES,
    parse_xml,
    read_as_written,
)

_COMMENT = re.compile(rb"<!--.*?-->", re.DOTALL)
_FIND = re.compile(rb"\$\(find\s")
_FIND_IN_FILENAME = re.compile(rb"""filename\s*=\s*(?:"[^"]*|'[^']*)\$\(find\s""")
"""A package's directory, which only xacro substitutes (as it does ``${...}`` expressions).

Not ``$(optenv NAME default)``: pybullet_data's husky.urdf holds it in an ``<origin>``, and
pybullet and check_urdf read that file as it is (and refuse the origin).
"""


@dataclass(frozen=True)
class RobotSource:
    """What to load: a file, its xacro arguments and package directories.

    Attributes:
        path: The file.
        display: How messages name it.
        xacro_args: ``name:=value`` pairs, in the order given.
        packages: ``--package NAME=DIR`` pairs.
    """

    path: Path
    display: str
    xacro_args: tuple[tuple[str, str], ...] = ()
    packages: tuple[tuple[str, str], ...] = ()

    def __post_init__(self) -> None:
        # a file name that is not UTF-8 (a Latin-1 byte from an old archive) is shown with
        # the byte escaped (bad\xff.urdf): every report is UTF-8 text
        object.__setattr__(self, "display", printable_name(self.display))

    @classmethod
    def bundled(cls, name: str = resources.DEFAULT_ROBOT) -> RobotSource:
        """The bundled robot called ``name``."""
        path = resources.bundled_robot(name)
        return cls(path=path, display=display_path(path))

    @classmethod
    def of(cls, path: str | os.PathLike[str], *, xacro_args: tuple[tuple[str, str], ...] = (),
           packages: tuple[tuple[str, str], ...] = ()) -> RobotSource:
        """A source for a path given by the user."""
        return cls(path=Path(path), display=str(path), xacro_args=xacro_args,
                   packages=packages)

    def resolver(self) -> PackageResolver:
        """Package search for this source.

        ``--package`` first, then the file's own package and workspace, then the environment
        (see :mod:`~servicebot_cli.description.packages`).
        """
        return PackageResolver.from_environment({k: Path(v) for k, v in self.packages},
                                                context=self.path.parent)


def read_bytes(path: Path, display: str, max_bytes: int = MAX_BYTES) -> bytes:
    """The content of a description file, or one DescriptionError that says what to do.

    Raises:
        DescriptionError: Missing, a directory, unreadable, or larger than ``max_bytes``.
    """
    return read_input_bytes(path, display, kind="a URDF or xacro file, or --robot sim|real",
                            error=DescriptionError, max_bytes=max_bytes)


def is_xacro(path: Path, data: bytes) -> bool:
    """True for ``.xacro`` and ``.xacro.urdf`` files, and for what only xacro can read.

    Another ``.urdf`` file is URDF even when it holds xacro elements (ros/urdf's
    ``pr2_desc.urdf``): robot_state_publisher and check_urdf read it as it is, and so does
    servicebot, with a warning (see :func:`uses_xacro`). But one that also holds ``${...}``
    expressions is xacro input whatever its name (see :func:`needs_xacro`).
    """
    return is_xacro_name(path) or needs_xacro(data)


def needs_xacro(data: bytes) -> bool:
    """Whether the bytes hold what only xacro reads, outside comments.

    No URDF reader takes ``${base_length}`` for a number, or ``$(find pkg)`` for a
    directory, so such a file is only ever given to xacro (navigation2_tutorials'
    ``sam_bot_description.urdf``, which its launch file expands with
    ``Command(['xacro ', model])``; roverrobotics_ros2's ``rplidar_s2.urdf``, whose mesh is
    ``file://$(find ...)``). An expression needs xacro beside it: its elements, or its
    namespace declared (turtlebot3_simulations' ``common_properties.urdf``: ``${255/255}`` in
    colours, no xacro element); a package path is xacro's alone (ocs2's ``quadrotor.urdf``,
    which its launch file expands, declares nothing).
    """
    def xacro(text: bytes) -> bool:
        return _xacro_words(text) or b"xmlns:xacro" in text

    def xacro_input(text: bytes) -> bool:
        # a package path needs no xacro namespace to be xacro's: ocs2's quadrotor.urdf has
        # none, and its launch file expands it with xacro
        return _FIND.search(text) is not None or (b"${" in text and xacro(text))

    return b"$" in data and xacro_input(data) and xacro_input(without_comments(data))


def uses_xacro(data: bytes) -> bool:
    """Whether the bytes hold xacro elements or substitutions outside comments.

    A URDF xacro wrote keeps the comments of its source, and those may hold commented-out
    xacro (unitree_ros' ``a1.urdf``: ``<!-- <xacro:property name="trunk_mass" ...``).
    """
    return _xacro_words(data) and _xacro_words(without_comments(data))


def _xacro_words(data: bytes) -> bool:
    return b"<xacro:" in data or b"$(arg " in data


def without_comments(data: bytes) -> bytes:
    """``data`` with its XML comments left out."""
    return _COMMENT.sub(b"", data)


def comments_blanked(data: bytes) -> bytes:
    """``data`` with each XML comment replaced by its line breaks: lines keep their numbers."""
    return _COMMENT.sub(lambda comment: b"\n" * comment[0].count(b"\n"), data)


def read_description(source: RobotSource, max_bytes: int = MAX_BYTES) -> RobotDescription:
    """Read, expand and parse ``source`` without judging its content.

    Raises:
        DescriptionError: The file cannot be read, is not well-formed XML, is unsafe, or
            xacro fails. Each message names the file (and line) and the problem.
    """
    data = read_bytes(source.path, source.display, max_bytes)
    if not is_xacro(source.path, data):
        if source.xacro_args:
            names = ", ".join(name for name, _ in source.xacro_args)
            raise DescriptionError(
                f"{source.display}: not a xacro file, so xacro arguments ({names}) mean nothing"
            )
        document = parse_xml(data, source.display, max_bytes=max_bytes)
        warnings = (LoadWarning("holds xacro elements, but is not a .xacro file: read as "
                                "plain URDF, as ROS tools read it", source.display,
                                fix="name it .urdf.xacro to expand it"),
                    ) if uses_xacro(data) else ()
        return RobotDescription(
            display=source.display, path=source.path, xml_text=document.text,
            root=document.root, doctype=document.doctype, external_dtd=document.external_dtd,
            entities_used=document.entities_used, files=(source.display,),
            warnings=warnings,
        )
    from servicebot_cli.description.xacro_expand import expand

    try:
        expansion = expand(source.path, dict(source.xacro_args), source.resolver(), data)
    except PackageNotFound as exc:
        if source.xacro_args or not _finds_outside_geometry(source.path, data):
            raise  # arguments given: the user means it expanded
        return _as_written(source, data, max_bytes, str(exc))
    document = parse_xml(expansion.xml_text.encode("utf-8"), source.display, max_bytes=max_bytes)
    for element, origin in zip(document.root.iter(), expansion.origins, strict=True):
        element.origin = origin  # type: ignore[attr-defined]
    what = "expressions (${...})" if b"${" in without_comments(data) else \
        "package paths ($(find ...))"
    renamable = not is_xacro_name(source.path) and not_a_file(source.path) is None
    named = () if not renamable else (LoadWarning(
        f"holds xacro {what}, but is not a .xacro file: expanded with xacro, as only xacro "
        "can read it", source.display, fix="name it .urdf.xacro"),)
    return RobotDescription(
        display=source.display, path=source.path, xml_text=expansion.xml_text,
        root=document.root, files=expansion.files, xacro_args=source.xacro_args,
        doctype=document.doctype, external_dtd=document.external_dtd,
        warnings=(*named, *expansion.warnings), from_xacro=True,
    )


def _finds_outside_geometry(path: Path, data: bytes) -> bool:
    """Whether ``data``, a ``.urdf`` whose only xacro is ``$(find)``, has none in a file name.

    JAKA's ``jaka_zu7.urdf``, which its launch file gives robot_state_publisher as it is,
    names a MoveIt package in a Gazebo plugin's ``<parameters>``: what builds the robot never
    reads the text, and urdfdom keeps it as written.
    """
    text = without_comments(data)
    return not is_xacro_name(path) and b"${" not in text and not _xacro_words(text) \
        and _FIND_IN_FILENAME.search(text) is None


def _as_written(source: RobotSource, data: bytes, max_bytes: int,
                not_found: str) -> RobotDescription:
    """``source`` read as plain URDF, its ``$(find)`` as written: its package is nowhere."""
    document = parse_xml(data, source.display, max_bytes=max_bytes)
    file, line, column, text = split_location(not_found, source.display)
    return RobotDescription(
        display=source.display, path=source.path, xml_text=document.text,
        root=document.root, doctype=document.doctype, external_dtd=document.external_dtd,
        entities_used=document.entities_used, files=(source.display,),
        warnings=(LoadWarning(
            "$(find ...) read as written, as robot_state_publisher reads a plain URDF "
            f"(xacro would stop here): {text}", file, line, column,
            fix="pass --package NAME=DIR, or source the workspace that holds it",
            said_as="package"),),
    )


_LOADED: dict[tuple[object, ...], RobotDescription] = {}


def load(source: RobotSource, *, build_model: bool = True,
         as_written: bool = False) -> RobotDescription:
    """The validated description for ``source``, loaded once per process.

    Without ``build_model`` the description is checked up to Pinocchio, which the caller
    then builds (``simulate`` in a forked process meanwhile). With ``as_written``, joints
    no command could move (a ``<mimic>`` of no joint, limits in the wrong order) and origins
    no robot has (1e308 m) are let through: ``inspect`` shows such files.

    Raises:
        DescriptionError: Anything :func:`read_description` raises, a root that is not a
            named ``<robot>``, or a description Pinocchio cannot build.
    """
    search_path = (os.environ.get("ROS_PACKAGE_PATH"), os.environ.get("AMENT_PREFIX_PATH"))
    key = (source, _mtime(source.path), search_path)
    if key not in _LOADED:
        robot = read_description(source)
        if robot.root.tag != "robot":
            raise DescriptionError(
                f"{source.display}: root element is <{robot.root.tag}>, not <robot>; "
                "is this a URDF?"
            )
        if not robot.name:
            raise DescriptionError(f"{source.display}: <robot> has no name attribute; add one")
        _refuse_entities(robot)
        _refuse_second_parents(robot)
        _LOADED[key] = robot
    robot = _LOADED[key]
    if not as_written:
        robot.refuse_far_origins()
        robot.refuse_unmovable_joints()
    if build_model:
        robot.model  # noqa: B018 -- building the model is the validation (once: it is kept)
    return robot


def _refuse_entities(robot: RobotDescription) -> None:
    """Refuse a plain URDF that refers to an entity its DOCTYPE declares.

    Read here, the entity is expanded (as xacro expands it); urdfdom, and Pinocchio on it,
    read the reference as written: a link an entity holds is no link of theirs, and an
    entity in a name is another name. The two readings are not one robot.

    Raises:
        DescriptionError: Naming the first entity used, and where.
    """
    if not robot.entities_used:
        return
    name, line, column = robot.entities_used[0]
    raise DescriptionError(
        f"{robot.display}:{line}:{column}: {read_as_written(name)}; {ENTITY_FIX}")


def _refuse_second_parents(robot: RobotDescription) -> None:
    """Refuse a link that is the child of two joints (:mod:`.parents`).

    Raises:
        DescriptionError: The first such link.
    """
    links = {link.name for link in robot.links}
    tree = (j for j in robot.joints  # a missing link is urdfdom's own error
            if j.child in links and j.parent in links)
    found = next(second_parents(tree), None)
    if found is not None:
        first, joint = found
        raise DescriptionError(
            f"{robot.display}: not a valid URDF: link '{joint.child}' is the child of joints "
            f"'{first.name}' and '{joint.name}'; a URDF is a tree, each link with one "
            f"parent joint {check_hint(robot.display, robot.xacro_args)}")


def _mtime(path: Path) -> float:
    try:
        return path.stat().st_mtime
    except OSError:
        return 0.0
