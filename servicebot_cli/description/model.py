"""Build Pinocchio models from URDF text; the only place a ``pin.Model`` is made.

urdfdom, underneath Pinocchio, prints its complaints straight to file descriptor 2. They are
captured here and folded into one error line instead of spilling onto the terminal.
"""

from __future__ import annotations

import re
import shlex
from collections.abc import Sequence
from typing import TYPE_CHECKING

from servicebot_cli.common.errors import DescriptionError, ServicebotError
from servicebot_cli.common.listing import some_of
from servicebot_cli.common.native_stderr import captured_fd2
from servicebot_cli.description.elements import escaped_blanks, read_joint
from servicebot_cli.description.safe_xml import parse_xml

if TYPE_CHECKING:
    import pinocchio as pin

BASES = ("fixed", "planar", "free")
"""Root joints: ``fixed`` (the root link is the world), ``planar`` (x, y, yaw on the floor),
``free`` (a 6-DoF floating base)."""


MOST_JOINTS_DEEP = 3000
"""The deepest kinematic tree a model is built of. Pinocchio's URDF parser recurses once per
joint: a chain of 4,000 links overflows the stack (a segmentation fault), 3,500 do not."""

MOST_MOVING_JOINTS = 250
"""The most degrees of freedom a model's working data is made for: Pinocchio's ``Data`` for
n holds about n**3 numbers (38 MB at 100, 886 MB at 300; a 1,000-joint chain took fk to
24 GB). Real robots have far fewer: the corpus's largest, TIAGo dual with its hands, has 101.
The model alone (what ``inspect`` reads) stays small, and is built for any size."""
_JOINT = re.compile(r"<joint\b[^>]*>(.*?)</joint>", re.DOTALL)
_END = re.compile(r"<(parent|child)\b[^>]*\blink\s*=\s*[\"']([^\"']*)[\"']")


def tree_depth(xml_text: str) -> int:
    """The most joints on a path from a root link to a leaf (a loop counts as it goes round)."""
    parent_of: dict[str, str] = {}
    for body in _JOINT.findall(xml_text):
        ends = dict(_END.findall(body))
        if "parent" in ends and "child" in ends:
            parent_of.setdefault(ends["child"], ends["parent"])
    depth: dict[str, int] = {}
    for start in parent_of:
        path, on_path, link = [], set(), start
        while link in parent_of and link not in depth and link not in on_path:
            path.append(link)
            on_path.add(link)
            link = parent_of[link]
        below = depth.get(link, 0)
        for link in reversed(path):
            below += 1
            depth[link] = below
    return max(depth.values(), default=0)


def check_hint(display: str, xacro_args: Sequence[tuple[str, str]] = ()) -> str:
    """``(run 'servicebot check FILE NAME:=VALUE...' for details)``.

    A word a shell would split is put in double quotes (the hint's own are single).
    """
    words = [display, *(f"{name}:={value}" for name, value in xacro_args)]
    return f"(run 'servicebot check {' '.join(map(_shell_word, words))}' for details)"


def _shell_word(word: str) -> str:
    if shlex.quote(word) == word:
        return word
    return '"' + re.sub(r'(["\\$`])', r"\\\1", word) + '"'


_URDFDOM_ERROR = re.compile(r"Error:(.*?)(?:\n\s+at line \d|(?=\nError:)|\Z)", re.DOTALL)
# urdfdom splits a vector at spaces alone; a tab or line break stays inside a piece
_VECTOR_PIECE = re.compile(r"Unable to parse component \[(.*?[\t\n\r].*?)\] to a double "
                           r"\(while parsing a vector value\)", re.DOTALL)
_SPACES_ONLY = "urdfdom separates the numbers of xyz, rpy, scale and axis by spaces only"


def refused_for_blanks(message: str) -> bool:
    """Whether :func:`build_model` refused for a tab or line break inside a vector."""
    return _SPACES_ONLY in message


def _spaces_only(match: re.Match[str]) -> str:
    """The refusal of ``0<tab>0<tab>0.3`` by urdfdom, with the tab named and shown."""
    piece = match[1]
    kinds = [name for char, name in (("\t", "tab"), ("\n", "line break"), ("\r", "line break"))
             if char in piece]
    return (f"a vector value holds a {' and a '.join(dict.fromkeys(kinds))} "
            f"('{escaped_blanks(piece)}'): {_SPACES_ONLY}")


def build_model(xml_text: str, display: str, base: str = "fixed",
                xacro_args: Sequence[tuple[str, str]] = ()) -> pin.Model:
    """A Pinocchio model of the URDF in ``xml_text``.

    Args:
        xml_text: The URDF.
        display: File name used in error messages.
        base: One of :data:`BASES`.
        xacro_args: The arguments the URDF was expanded with, for the error's hint.

    Raises:
        DescriptionError: urdfdom or Pinocchio rejected the description.
    """
    depth = tree_depth(xml_text)
    if depth > MOST_JOINTS_DEEP:
        raise DescriptionError(
            f"{display}: its kinematic tree is {depth} joints deep, over the "
            f"{MOST_JOINTS_DEEP:,} that Pinocchio's URDF parser can load (it recurses once "
            f"per joint and would crash) {check_hint(display, xacro_args)}")
    import pinocchio as pin

    root_joint = {"fixed": None, "planar": pin.JointModelPlanar, "free": pin.JointModelFreeFlyer}[
        base
    ]
    with captured_fd2() as noise:
        try:
            model = pin.buildModelFromXML(xml_text) if root_joint is None else \
                pin.buildModelFromXML(xml_text, root_joint())
        except (ValueError, RuntimeError) as exc:
            failure: Exception = exc
        else:
            if _HUGE_EXPONENT.search(xml_text):  # rare: only then are the axes looked at
                _refuse_lost_axes(model, display, xml_text, xacro_args)
            return model
    # an error may span lines: urdfdom quotes a vector with its line break
    reasons = [found.strip() for found in _URDFDOM_ERROR.findall("\n".join(noise))]
    # urdfdom keeps a link whose part it cannot parse (model.cpp ignores parseLink's
    # verdict): what failed the model comes after the last of those links' errors
    last_link = max((k for k, r in enumerate(reasons) if "for Link [" in r), default=-1)
    reasons = reasons[last_link + 1:] or reasons
    if reasons:
        reason = _VECTOR_PIECE.sub(_spaces_only, reasons[0])
        raise DescriptionError(
            f"{display}: not a valid URDF: {reason} {check_hint(display, xacro_args)}")
    reason = " ".join(str(failure).split())  # urdfdom read it: Pinocchio's own refusal
    raise DescriptionError(f"{display}: Pinocchio cannot build its model: {reason}"
                           f"{_bound_culprits(xml_text, reason)} "
                           f"{check_hint(display, xacro_args)}")


_LIMIT_BOUNDS = {"min_velocity": "velocity", "min_effort": "effort"}
_HUGE_EXPONENT = re.compile(r"\d[eE][+-]?(?:1[5-9]\d|[2-9]\d\d)")
"""A number of 1e150 or more (or 1e-150 or less), whose square overflows (underflows): an
axis that long normalises to zero, one that short is not normalised at all."""


def _refuse_lost_axes(model: pin.Model, display: str, xml_text: str,
                      xacro_args: Sequence[tuple[str, str]]) -> None:
    """Refuse a joint whose axis Pinocchio normalised to zero (an axis of 1e160).

    Eigen's normalize() squares the axis: beyond about 1e154 the square is infinite and the
    axis becomes 0 0 0, so the joint turns about nothing (its rotation a scaled identity).
    """
    import numpy as np

    for joint, name in zip(model.joints, model.names, strict=True):
        axis = getattr(joint.extract(), "axis", None)
        if axis is not None and not np.isclose(np.linalg.norm(axis), 1.0):
            what = "long" if not np.any(axis) else "short"
            raise DescriptionError(
                f"{display}: joint '{name}' has an axis too {what} to normalise: Pinocchio "
                "squares its length out of a double's range and turns the joint by no "
                f"rotation; write the unit axis {check_hint(display, xacro_args)}")


def _bound_culprits(xml_text: str, reason: str) -> str:
    """``(joints 'a', 'b' have a negative velocity limit)`` for Pinocchio's bounds refusal.

    Pinocchio makes [-limit, limit] of a joint's velocity and effort limits, and refuses a
    model where a minimum is above its maximum (moveit_robots' Atlas: velocity="-1").
    """
    kind = next((key for name, key in _LIMIT_BOUNDS.items() if name in reason), None)
    if kind is None:
        return ""
    try:  # the text urdfdom just read: it parses
        root = parse_xml(xml_text.encode("utf-8"), "").root
    except ServicebotError:  # pragma: no cover - only a file read before comes here
        return ""
    joints = (read_joint(element) for element in root.findall("joint"))
    negative = [joint.name for joint in joints if joint.limits is not None
                and (getattr(joint.limits, kind) or 0.0) < 0]
    if not negative:
        return ""
    listed = some_of([f"'{name}'" for name in negative], 5)
    return f" (joint{'s' if len(negative) > 1 else ''} {listed}: a negative {kind} limit)"


def new_data(model: pin.Model, display: str) -> pin.Data:
    """``model.createData()``, refused for a model too large for its data to fit.

    Raises:
        DescriptionError: Over :data:`MOST_MOVING_JOINTS` degrees of freedom.
    """
    if model.nv > MOST_MOVING_JOINTS:
        raise DescriptionError(
            f"{display}: its model has {model.nv} degrees of freedom, over the "
            f"{MOST_MOVING_JOINTS} that servicebot computes with (Pinocchio's working memory "
            "grows as the cube of their number: about 0.5 GB at 250, 33 GB at 1,000)")
    return model.createData()
