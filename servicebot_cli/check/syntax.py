"""Parse-level rules on the parsed XML: root, name, version, elements, attributes, numbers.

SB008-SB016. Walks the tree iteratively against :mod:`urdf_schema`; extension elements
(``gazebo``, ``ros2_control``, namespaced ones...) are not entered.
"""

from __future__ import annotations

import dataclasses
import difflib
import functools
import math
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterator

from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.check.urdf_schema import EXTENSIONS, SPEC, TOP_LEVEL
from servicebot_cli.check.values import NON_FINITE, NUMBER  # ASCII digits only, as urdfdom
from servicebot_cli.description.elements import FARTHEST_M, escaped_blanks

URDF_VERSION = re.compile(r"[ \t\n\r\f\v]*\+?(\d+)\.(\d+)")  # as urdfdom reads two unsigned
_C_SPACES = " \t\n\r\f\v"  # what istringstream skips; not NBSP or other Unicode blanks
_OTHER_BLANKS = re.compile(r"[\t\n\r\f\v]")
_BLANK_IN_VALUE = re.compile(r"""=[ \t\n\r]*(?:"[^"]*[\t\n\r]|'[^']*[\t\n\r])""")
_VECTOR_ATTRIBUTE = re.compile(
    r"""(?<![\w:.-])(xyz|rpy|size|scale|rgba)[ \t\n\r]*=[ \t\n\r]*(?:"([^"]*)"|'([^']*)')""")
_COMMENT = re.compile(r"<!--.*?-->", re.DOTALL)
_TAG_NAME = re.compile(r"[A-Za-z_][\w:.-]*")
MAX_LINKS = 20_000
"""Most links (or joints) checked; more is refused (SB015)."""


def check(root: ET.Element) -> Iterator[Issue]:
    """Every parse-level issue of the document under ``root``."""
    if root.tag != "robot":
        yield not_a_robot(root)
        return
    yield from _robot_attributes(root)
    counts = {tag: len(root.findall(tag)) for tag in ("link", "joint")}
    for tag, count in counts.items():
        if count > MAX_LINKS:
            yield Issue("SB015", f"{count} <{tag}> elements, over the limit of {MAX_LINKS}; "
                        "refused", root)
            return
    newer = (urdf_version(root) or (0, 0)) >= (1, 2)
    for child in root:
        if not isinstance(child.tag, str):
            continue
        if child.tag in TOP_LEVEL:
            yield from _element_tree(child, newer)
        elif not _is_extension(child.tag):
            close = _close(child.tag, TOP_LEVEL)
            if close:
                yield Issue("SB010", f"<{child.tag}> is not a URDF element; did you mean "
                            f"<{close[0]}>?", child, fix=f"rename it <{close[0]}>")


def not_a_robot(root: ET.Element) -> Issue:
    """SB008, saying what the file is where its root tells: SDF, or a URDF world."""
    if root.tag == "world":  # DART's parseWorld reads it (urdfdom's urdf_world)
        return Issue("SB008", "root element is <world>: a URDF world (DART's), which places "
                     "robots it includes, is not a robot", root, severity=Severity.WARNING,
                     fix="check the robots it includes")
    return Issue("SB008", f"root element is <{root.tag}>, not <robot>; is this a URDF?", root,
                 fix="for SDF use gz sdf --check" if root.tag == "sdf" else None)


def _robot_attributes(root: ET.Element) -> Iterator[Issue]:
    if root.get("name") is None:
        yield Issue("SB009", "<robot> has no name", root, fix='add name="my_robot"')
    elif not root.get("name", "").strip():  # urdfdom wants the attribute, not a value
        yield Issue("SB009", "<robot> has an empty name: urdfdom loads it, but what goes by "
                    "the robot's name (MoveIt's SRDF <robot name>, a spawned model's name) "
                    "gets none", root, fix='write name="my_robot"', severity=Severity.WARNING)
    version = root.get("version")
    if version is not None:
        match = URDF_VERSION.fullmatch(version)
        if not match:
            yield Issue("SB016", f"version '{version}' is not in the form x.y", root)
        elif not (int(match.group(1)) == 1 and int(match.group(2)) <= 2):
            yield Issue("SB016", f"version '{version}': only 1.0 to 1.2 are supported", root)


def urdf_version(root: ET.Element) -> tuple[int, int] | None:
    """``<robot version>`` as urdfdom reads it (1.0 where it is not written); None: unread."""
    version = URDF_VERSION.fullmatch(root.get("version") or "1.0")
    return None if version is None else (int(version[1]), int(version[2]))


def _is_extension(tag: str) -> bool:
    return tag in EXTENSIONS or ":" in tag or tag.startswith("{")


_FROM_1_2 = {"acceleration": 1, "deceleration": 1, "jerk": 1}
"""<limit> attributes urdfdom reads from URDF 1.2 on (it ignores them, with a note, before)."""


def _element_tree(top: ET.Element, urdf_1_2: bool = False) -> Iterator[Issue]:
    stack = [top]
    while stack:  # iterative: depth is bounded by the parser, but stay uniform
        element = stack.pop()
        spec = SPEC[element.tag]
        if element.tag == "limit":
            yield from _limit_attributes(element, spec.attributes, spec.required, urdf_1_2)
        else:
            yield from _attributes(element, spec.attributes, spec.required)
        present = set()
        once = _READ_ONCE.get(element.tag, ())
        for child in _read_children(element):
            if child.tag == "gazebo" and element.tag in ("link", "joint"):
                yield _nested_gazebo(child, element)
                continue
            if _is_extension(child.tag):
                continue
            if element.tag == "joint" and child.tag in _UNREAD.get(element.get("type", ""), ()):
                yield from _unread_axis(child, element)  # urdfdom does not read it; MuJoCo does
                continue
            if child.tag in present and child.tag in once:
                refused = child.tag in _MUJOCO_ONCE.get(element.tag, ())
                yield Issue("SB020", f"<{element.tag}>{_named(element)} has a second "
                            f"<{child.tag}>: urdfdom, and Gazebo, Pinocchio and "
                            "robot_state_publisher through it, read the first and ignore this "
                            "one" + ("; MuJoCo refuses the file ('repeated element')"
                                     if refused else ""), child,
                            fix="merge the two, or remove the one you do not mean",
                            severity=Severity.ERROR if refused else None)
                continue  # not read, so not judged
            present.add(child.tag)
            if child.tag in spec.children:
                stack.append(child)
            elif child.tag not in spec.extensions and element.tag != "geometry":  # SB406
                yield _unknown(child, element, spec.children)
        for needed in spec.required_children:
            if needed not in present:
                yield Issue("SB012", f"<{element.tag}>{_named(element)} has no <{needed}>",
                            element, fix=f"add a <{needed}> element")
        yield from _empty_reference(element)
        if element.tag == "origin":
            yield from _far_origin(element)
            yield from _degrees_origin(element)
        elif element.tag == "joint":
            yield from _empty_links(element)
        if element.tag == "dynamics" and not element.attrib.keys() & {"damping", "friction"}:
            yield Issue("SB012", "<dynamics> has neither damping nor friction", element,
                        fix="add damping=\"...\" or friction=\"...\", or remove <dynamics>")


_UNREAD = {"fixed": ("axis",), "floating": ("axis",)}  # its <limit> it reads, for any type
"""A joint's children urdfdom does not read for its type."""
_READ_ONCE = {
    "joint": ("origin", "parent", "child", "axis", "limit", "dynamics", "mimic",
              "safety_controller", "calibration"),
    "link": ("inertial",),
    "inertial": ("origin", "mass", "inertia"),
    "visual": ("origin", "geometry", "material"),
    "collision": ("origin", "geometry"),
    "material": ("color", "texture"),
}
"""Children urdfdom reads once (its FirstChildElement): a second one is ignored (SB020)."""
_MUJOCO_ONCE = {
    "joint": ("origin", "parent", "child", "axis", "limit", "dynamics", "mimic"),
    "link": ("inertial",),
    "inertial": ("origin", "mass", "inertia"),
    "visual": ("material",),
    "collision": ("origin", "geometry"),
    "material": ("color",),
}
"""Of those, the ones MuJoCo's URDF import refuses twice ('repeated element'), as measured
with MuJoCo 3; a visual's origin or geometry it does not read (it drops visuals)."""
_FLOAT32_MAX = 3.4028234663852886e38  # past it, single-precision renderers hold infinity


def _empty_links(joint: ET.Element) -> Iterator[Issue]:
    """SB012 for a joint's ``<parent link="">`` or ``<child link="">``: urdfdom refuses it."""
    for end in ("parent", "child"):
        element = joint.find(end)
        link = element.get("link") if element is not None else None
        if element is not None and link is not None and not link:  # " " names a link " "
            yield Issue("SB012", f"joint{_named(joint)} has <{end} link=\"{link}\">: it names no "
                        "link, and urdfdom refuses the joint", element,
                        fix=f"name the {end} link")


def _degrees_origin(origin: ET.Element) -> Iterator[Issue]:
    """SB021: an ``<origin rpy>`` written in degrees (``rpy="0 0 90"``).

    Every angle that is not 0 a whole multiple of 5 from 15 to 360, one beyond 2 pi: no
    radian value is written so, and urdfdom takes 90 for 90 rad, a turn of 116.6 degrees.
    """
    value = origin.get("rpy")
    if value is None or not _plain(value, 3):
        return  # SB013/SB014 say what is wrong with it
    angles = [float(part) for part in value.split()]
    turned = [abs(a) for a in angles if a != 0]
    if not turned or max(turned) <= 2 * math.pi or not all(
            15 <= a <= 360 and a % 5 == 0 for a in turned):
        return
    radians = " ".join(f"{math.radians(a):.6g}" for a in angles)
    most = max((a for a in angles if a != 0), key=abs)  # with its sign: -90 turns the other way
    turn_deg = math.degrees(math.remainder(most, math.tau))
    yield Issue("SB021", f"<origin rpy=\"{value}\"> looks like degrees: URDF angles are "
                f"radians, so {most:g} is a turn of {turn_deg:.1f} degrees", origin,
                fix=f'rpy="{radians}"')


def _far_origin(origin: ET.Element) -> Iterator[Issue]:
    """SB019: an ``<origin xyz>`` beyond :data:`FARTHEST_M`, plain numbers otherwise."""
    value = origin.get("xyz")
    if value is None or not _plain(value, 3):
        return  # SB013/SB014 say what is wrong with it
    offset = max(abs(float(part)) for part in value.split())
    if offset <= FARTHEST_M:
        return
    past_float32 = offset > _FLOAT32_MAX
    yield Issue("SB019", f"<origin xyz=\"{value}\"> is {offset:g} m from its frame, beyond the "
                f"{FARTHEST_M:g} m of any robot"
                + (": RViz and Gazebo, which draw in single precision, get infinity"
                   if past_float32 else ""), origin, fix="write it in metres",
                severity=None if past_float32 else Severity.WARNING)


def _read_children(element: ET.Element) -> list[ET.Element]:
    """The child elements urdfdom reads: of a ``<geometry>``, only the first.

    urdfdom (and sdformat's copy of it) builds the shape from the first child and ignores
    the rest, so a second shape is never read (diffbot's wheel macro leaves a
    ``<mesh scale="">`` after the mesh it means).
    """
    children = [child for child in element if isinstance(child.tag, str)]
    return children[:1] if element.tag == "geometry" else children


def _empty_reference(element: ET.Element) -> Iterator[Issue]:
    """A ``<mesh>`` or ``<texture>`` whose filename is empty or missing."""
    filename = element.get("filename")
    if element.tag == "mesh" and filename is not None and not filename.strip():
        yield Issue("SB012", "<mesh> has an empty filename", element,
                    fix="name the mesh file, e.g. filename=\"package://my_robot/meshes/base.stl\"")
    elif element.tag == "texture" and not (filename or "").strip():
        yield Issue("SB112", "<texture> has no filename, so it gives the material nothing",
                    element, fix="add filename=\"...\" or remove the <texture>")


def _nested_gazebo(gazebo: ET.Element, parent: ET.Element) -> Issue:
    """SB010 for a ``<gazebo>`` inside a link or joint.

    sdformat reads those under <robot> only (parser_urdf.cc), so Gazebo never sees its
    plugins, sensors or materials.
    """
    name = parent.get("name", "")
    return Issue("SB010", f"<gazebo> inside <{parent.tag}>{_named(parent)}: sdformat reads "
                 "<gazebo> only directly under <robot>, so Gazebo never sees what it holds",
                 gazebo, fix=f"move it under <robot> as <gazebo reference=\"{name}\">")


def _unknown(child: ET.Element, parent: ET.Element, allowed: tuple[str, ...]) -> Issue:
    close = _close(child.tag, allowed)
    hint = f"; did you mean <{close[0]}>?" if close else f" (allowed: {', '.join(allowed)})"
    return Issue("SB010", f"<{child.tag}> is not a URDF element inside <{parent.tag}>{hint}",
                 child, fix=f"rename it <{close[0]}>" if close else "remove it")


@functools.lru_cache(maxsize=1024)
def _close(name: str, allowed: tuple[str, ...]) -> tuple[str, ...]:
    """The allowed names most like ``name``, the likeliest first: up to three.

    The same unknown names come back in file after file (pybullet's ``<contact>``), and
    difflib takes a third of a millisecond.
    """
    return tuple(difflib.get_close_matches(name, allowed, n=3, cutoff=0.6))


def _named(element: ET.Element) -> str:
    name = element.get("name")
    return f" '{name}'" if name else ""


_SYMMETRIC_TWINS = {"iyx": "ixy", "izx": "ixz", "izy": "iyz"}
"""The lower half of an inertia tensor, and the attribute URDF reads each from."""


def _attributes(element: ET.Element, allowed: dict[str, int], required: tuple[str, ...],
                skip: frozenset[str] = frozenset()) -> Iterator[Issue]:
    for key, value in element.attrib.items():
        if ":" in key or key.startswith("{") or key in skip:
            continue
        if key not in allowed:
            twin = _SYMMETRIC_TWINS.get(key) if element.tag == "inertia" else None
            if twin is not None:  # a full tensor written out: URDF reads its upper half
                yield Issue("SB011", f"<inertia> has no attribute '{key}': URDF reads the "
                            f"upper half of the symmetric tensor, and '{twin}' is its value",
                            element, fix="remove it" if twin in element.attrib
                            else f"rename it '{twin}'")
                continue
            close = tuple(c for c in _close(key, tuple(allowed)) if c not in element.attrib)
            hint = f"; did you mean '{close[0]}'?" if close else ""
            yield Issue("SB011", f"<{element.tag}> has no attribute '{key}'{hint}", element,
                        fix=f"rename it '{close[0]}'" if close else "remove it")
        elif allowed[key]:
            for issue in _number(element, key, value, allowed[key]):
                yield dataclasses.replace(issue, attribute=key)
    for key in required:
        if key not in element.attrib:
            yield Issue("SB012", f"<{element.tag}>{_named(element)} has no '{key}' attribute",
                        element, fix=f"add {key}=\"...\"")


def _limit_attributes(element: ET.Element, allowed: dict[str, int], required: tuple[str, ...],
                      urdf_1_2: bool) -> Iterator[Issue]:
    """A ``<limit>``'s attributes: URDF 1.2's acceleration, deceleration and jerk too.

    urdfdom reads them in a ``<robot version="1.2">`` file and ignores them before; they are
    no misspelling either way.
    """
    if urdf_1_2:
        yield from _attributes(element, {**allowed, **_FROM_1_2}, required)
        for key in _FROM_1_2:
            text = (element.get(key) or "").strip()
            if NUMBER.fullmatch(text) is None:
                continue  # not written, or no number (SB013 above)
            if float(text) < 0:  # urdfdom: "deceleration value (-2) is negative": no joint
                yield Issue("SB205", f"<limit {key}=\"{text}\">: a negative limit, which urdfdom "
                            "refuses (the joint, and so the file, fails to load)", element,
                            fix=f"{key}=\"{text.lstrip('-')}\"")
        return
    newer = [key for key in element.attrib if key in _FROM_1_2]
    if newer:
        listed = ", ".join(f"'{key}'" for key in newer)
        yield Issue("SB011", f"<limit> {listed}: urdfdom reads "
                    f"{'it' if len(newer) == 1 else 'them'} only from URDF 1.2 on, and this "
                    "file is older (no <robot version=\"1.2\">): ignored", element,
                    fix='<robot version="1.2"> if it is meant')
    yield from _attributes(element, allowed, required, skip=frozenset(newer))


def _unread_axis(axis: ET.Element, joint: ET.Element) -> Iterator[Issue]:
    """SB013 for the <axis> of a fixed or floating joint that is no three numbers.

    urdfdom skips it, so check_urdf, ROS and Pinocchio never see it; MuJoCo's URDF reader
    does, and refuses the file ("attribute 'xyz' does not have enough data", "has too much
    data", "bad format").
    """
    xyz = axis.get("xyz")
    parts = (xyz or "").split()
    if xyz is None or len(parts) == 3 and all(NUMBER.fullmatch(part) for part in parts):
        return
    said = ("bad format in attribute 'xyz'" if len(parts) == 3 else "attribute 'xyz' "
            + ("does not have enough data" if len(parts) < 3 else "has too much data"))
    yield Issue("SB013", f"<axis xyz=\"{xyz}\"> of {joint.get('type')} joint{_named(joint)} is "
                f"not three numbers: urdfdom skips a {joint.get('type')} joint's axis, but MuJoCo "
                f"reads it and refuses the file ('{said}')", axis,
                fix="remove the <axis>, or write three numbers")


@functools.lru_cache(maxsize=8192)  # "0 0 0", "1": the same values in file after file
def _plain(value: str, count: int) -> bool:
    """Whether ``value`` is ``count`` finite numbers as urdfdom reads them."""
    if count > 1 and _OTHER_BLANKS.search(value):
        return False  # a tab or line break: see _split_by_urdfdom
    parts = [value.lstrip(_C_SPACES)] if count == 1 else _ascii_split(value)
    return len(parts) == count and all(NUMBER.fullmatch(part) is not None
                                       and math.isfinite(float(part)) for part in parts)


_UNICODE_BLANK = re.compile(r"[^\S \t\n\r\f\v]")  # a blank to Python, not to istringstream


def _ascii_split(value: str) -> list[str]:
    """``value`` split at the blanks istringstream skips (str.split() also splits at NBSP)."""
    return [part for part in re.split(r"[ \t\n\r\f\v]+", value) if part]


def _blank_name(char: str) -> str:
    """``non-breaking space (U+00A0)``: a blank that does not show."""
    import unicodedata

    return f"{unicodedata.name(char, 'blank').lower()} (U+{ord(char):04X})"


def _split_by_urdfdom(value: str) -> str | None:
    """The first piece of a vector urdfdom cannot read for the blank in it, or None.

    urdfdom splits ``xyz``, ``rpy``, ``size``, ``scale`` and ``rgba`` at spaces only, and
    reads each piece as one number, blanks before it skipped, none after it allowed:
    ``0<tab>0<tab>0.1`` is one piece, and ``0.1<line break>`` a number with a blank after it.
    Gazebo, Pinocchio and robot_state_publisher then drop the element, or refuse a joint.
    """
    for piece in value.split(" "):
        if piece and _OTHER_BLANKS.search(piece) and \
                NUMBER.fullmatch(piece.lstrip(_C_SPACES)) is None:
            return piece
    return None


def _split_wrong(attribute: str, piece: str, element: ET.Element | None = None,
                 where: tuple[str, int, int] | None = None) -> Issue:
    """SB013 for ``piece`` of the vector ``attribute`` (as shown), split by urdfdom."""
    kind = "a tab" if "\t" in piece else "a line break"
    return Issue("SB013", f"{attribute}: {kind} inside '{escaped_blanks(piece)}': urdfdom "
                 "separates numbers by spaces only, so it cannot read them", element,
                 where=where, fix="put single spaces between the numbers")


def vectors_split_wrong(text: str, display: str) -> Iterator[Issue]:
    """SB013 for each vector attribute whose tab or line break urdfdom reads in a number.

    Read from the file's text: an XML parser turns a tab or line break written inside an
    attribute into a space, as the XML standard says; urdfdom's does not. A file with no
    blank but a space inside an attribute value costs one search.
    """
    if _BLANK_IN_VALUE.search(text) is None:
        return
    text = _COMMENT.sub(lambda c: re.sub(r"[^\n]", " ", c[0]), text)  # offsets kept
    for found in _VECTOR_ATTRIBUTE.finditer(text):
        value = found[2] if found[2] is not None else found[3]
        piece = _split_by_urdfdom(value)
        if piece is None:
            continue
        line = text.count("\n", 0, found.start()) + 1
        column = found.start() - text.rfind("\n", 0, found.start())
        tag = _TAG_NAME.match(text, text.rfind("<", 0, found.start()) + 1)
        name = tag[0] if tag is not None else "element"
        yield _split_wrong(f"<{name} {found[1]}=\"{escaped_blanks(value)}\">", piece,
                           where=(display, line, column))


def _number(element: ET.Element, key: str, value: str, count: int) -> Iterator[Issue]:
    """SB013/SB014 for an attribute of ``count`` numbers.

    A single number may have blanks before it, not after: urdfdom reads it with
    ``istringstream >> double`` and then wants the stream at its end (unitree's R1.urdf has
    ``izz=" 9e-06"``, which it loads).
    """
    if _plain(value, count):
        return  # the common case, without building the message's text
    parts = [value.lstrip(_C_SPACES)] if count == 1 else _ascii_split(value)
    where = f"<{element.tag}{_named(element)} {key}=\"{escaped_blanks(value)}\">"
    piece = _split_by_urdfdom(value) if count > 1 else None
    if piece is not None:  # written as &#9; or &#10;, which XML keeps
        yield _split_wrong(where, piece, element)
        return
    odd = _UNICODE_BLANK.search(value)
    if odd is not None and count > 1:
        shown = next(part for part in parts if odd[0] in part)
        yield Issue("SB013", f"{where}: a {_blank_name(odd[0])} inside '{shown}': urdfdom "
                    "separates numbers by plain spaces only, so it cannot read them", element,
                    fix="retype the blank between the numbers as a plain space")
        return
    if len(parts) != count:
        yield Issue("SB013", f"{where}: expected {count} numbers, found {len(parts)}", element,
                    fix=f"write {count} numbers separated by spaces")
        return
    for part in parts:
        if NON_FINITE.fullmatch(part.strip()):
            yield Issue("SB014", f"{where}: '{part.strip()}' is not a finite number", element)
        elif not NUMBER.fullmatch(part):
            yield Issue("SB013", f"{where}: '{part}' is not a number", element,
                        fix="write a plain decimal number without spaces or units")
        elif not math.isfinite(float(part)):
            yield Issue("SB014", f"{where}: '{part}' overflows a double", element)
        else:
            continue
        return
