"""Macro calls and directives written without ``xacro:``, which xacro leaves as they are.

xacro expands ``<xacro:wheel .../>``. xacro before 1.14 (ROS 1 up to Melodic) and ROS 2's
before 2.0.8 (October 2022) also took a bare ``<wheel .../>``, with a deprecation warning;
later ones leave it untouched, and every URDF reader skips an element it does not know: the
wheel is silently missing. Descriptions written for those (Robotnik's rbkairos, velodyne_
simulator's dashing branch) still do this. So with the directives: a bare ``<include>``
(youbot_description, amr-ros-config) reads no file, and a bare ``<property>``, ``<macro>`` or
``<arg>`` defines nothing, so the name it was to define is undefined where it is used.
"""

from __future__ import annotations

import xml.dom.minidom
from collections.abc import Callable, Mapping

from servicebot_cli.description.load_warnings import LoadWarning
from servicebot_cli.description.sources import SourceRef

URDF_TOP_LEVEL = frozenset({"link", "joint", "material", "transmission", "gazebo",
                            "ros2_control"})
"""Elements a robot's readers know at the top: a macro of that name is not called by them."""


def bare_macro_calls(doc: xml.dom.minidom.Document, macros: Mapping[str, SourceRef],
                     origin: Callable[[xml.dom.minidom.Element], SourceRef | None]
                     ) -> tuple[LoadWarning, ...]:
    """A warning per element under ``<robot>`` named like one of ``macros`` without ``xacro:``.

    Args:
        doc: The expanded document.
        macros: Where each macro the files define is defined, by name.
        origin: Where an element of ``doc`` was written, when known.
    """
    warnings: list[LoadWarning] = []
    robot = doc.documentElement
    for node in robot.childNodes if robot is not None else ():
        if not isinstance(node, xml.dom.minidom.Element):
            continue
        name = node.tagName
        defined = macros.get(name)
        if defined is None or name in URDF_TOP_LEVEL:
            continue
        written = origin(node)
        place = (written.file, written.line, written.column) if written is not None \
            else (defined.file, 0, 0)
        warnings.append(LoadWarning(
            f"<{name}> is not a macro call: xacro expands <xacro:{name}> (macro "
            f"'{name}' of {defined.location()}), so it leaves <{name}> in the URDF, where every "
            f"reader skips it (xacro before 1.14 and 2.0.8 took the bare name)",
            *place, fix=f"write <xacro:{name} .../>"))
    return tuple(warnings)


BARE_DIRECTIVES = ("include", "property", "macro", "arg")
"""xacro's directives that it read without ``xacro:`` only before 1.14 and 2.0.8."""


def bare_directives(doc: xml.dom.minidom.Document,
                    origin: Callable[[xml.dom.minidom.Element], SourceRef | None]
                    ) -> tuple[LoadWarning, ...]:
    """A warning per ``<include>``, ``<property>``, ``<macro>`` or ``<arg>`` left in ``doc``."""
    warnings: list[LoadWarning] = []
    robot = doc.documentElement
    for node in robot.childNodes if robot is not None else ():
        if not isinstance(node, xml.dom.minidom.Element) or node.tagName not in BARE_DIRECTIVES:
            continue
        written = origin(node)
        place = (written.file, written.line, written.column) if written is not None \
            else ("", 0, 0)
        tag = node.tagName
        effect = (f"'{node.getAttribute('filename')}' is never read: what it defines is "
                  "missing from the robot" if tag == "include" else
                  f"'{node.getAttribute('name')}' is not defined by it")
        warnings.append(LoadWarning(
            f"<{tag}> is not <xacro:{tag}>: xacro leaves it in the URDF, where every reader "
            f"skips it, and {effect} (xacro before 1.14 and 2.0.8 took the bare name)",
            *place, fix=f"write <xacro:{tag} .../>"))
    return tuple(warnings)


def bare_definition(doc: xml.dom.minidom.Document, name: str) -> xml.dom.minidom.Element | None:
    """A bare ``<property>``, ``<arg>`` or ``<macro>`` of ``doc`` meant to define ``name``.

    A macro defines its parameters: a bare ``<macro params="name">`` leaves ``${name}``
    in its body undefined.
    """
    for node in doc.getElementsByTagName("*"):
        if node.tagName in ("property", "arg") and node.getAttribute("name") == name:
            return node
        if node.tagName == "macro" and name in {
                p.lstrip("*").partition(":=")[0] for p in node.getAttribute("params").split()}:
            return node
    return None
