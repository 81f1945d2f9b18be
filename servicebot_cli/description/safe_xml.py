"""A strict, safe XML parser that remembers where every element came from.

Expat, driven directly: never recovers from an error, never loads a DTD or an entity,
never touches the network. An entity the internal DTD subset declares is taken only as plain
text (no reference to another entity in it, at most :data:`MOST_ENTITY_BYTES` bytes, at most
:data:`MOST_ENTITIES` of them), as xacro expands it; others are refused, which rules out
"billion laughs" expansion. Which of them the text refers to is recorded: urdfdom does not
expand them. An external DTD is named only: never loaded, as no robot
description reader loads it; a reference to an entity it would declare is refused. Each
element records its 1-based line and column, and the comments just before it (``check``
reads suppression comments there).
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from typing import NoReturn
from xml.parsers import expat

from servicebot_cli.common.accidents import accident
from servicebot_cli.common.errors import UnsafeXmlError, XmlError
from servicebot_cli.common.text_decoding import NotUtf8, decode_utf8

_BAD_DECLARATION = expat.errors.XML_ERROR_XML_DECL
_MISPLACED_DECLARATION = expat.errors.XML_ERROR_MISPLACED_XML_PI

MAX_BYTES = 32 * 1024 * 1024
"""Largest description accepted [bytes]; real URDFs are well under 1 MB."""
MAX_ELEMENTS = 1_000_000
"""Most elements accepted in one document."""
MOST_ENTITIES = 256
"""Most entities an internal DTD subset may declare."""
MOST_ENTITY_BYTES = 4096
"""Longest entity value taken [characters]."""
MAX_DEPTH = 256
"""Deepest element nesting accepted; URDF nests about 6 deep."""


class PositionedElement(ET.Element):
    """An ElementTree element with its source position.

    Attributes:
        sourceline: 1-based line of the start tag.
        column: 1-based column of the start tag's ``<``.
        leading_comments: Text of the comments directly before the start tag.
    """

    sourceline: int = 0
    column: int = 0
    leading_comments: tuple[str, ...] = ()


@dataclass(frozen=True)
class XmlDocument:
    """A parsed document.

    Attributes:
        root: The root element.
        text: The decoded document text.
        doctype: Name in ``<!DOCTYPE name>`` if the document has one, else ``None``.
        external_dtd: The external DTD the DOCTYPE names (never loaded) and where, if any.
        entities_used: The internal DTD's entities the text refers to (expat expanded
            them; xacro does too, urdfdom does not), each with the line and column of its
            first reference.
    """

    root: PositionedElement
    text: str
    doctype: str | None
    external_dtd: ExternalDtd | None = None
    entities_used: tuple[tuple[str, int, int], ...] = ()


@dataclass(frozen=True)
class ExternalDtd:
    """An external DTD named by ``<!DOCTYPE name SYSTEM "...">``: its identifier and place."""

    identifier: str
    line: int
    column: int


_UNREAD = re.compile(r"<!--.*?-->|<!\[CDATA\[.*?\]\]>", re.DOTALL)
_ENTITY_REFERENCE = re.compile(r"&(?!(?:amp|lt|gt|quot|apos|#[0-9]+|#x[0-9a-fA-F]+);)"
                               r"([A-Za-z_:][\w.:-]*);")


def parse_xml(
    data: bytes, filename: str, *, max_bytes: int = MAX_BYTES, max_elements: int = MAX_ELEMENTS,
    blanks_before_declaration: bool = True,
) -> XmlDocument:
    """Parse ``data`` strictly and safely.

    Args:
        data: The raw file content; must be UTF-8 (a BOM is allowed).
        filename: Display name used in error messages.
        max_bytes: Refuse larger input [bytes].
        max_elements: Refuse documents with more elements.
        blanks_before_declaration: Accept blank lines or spaces before ``<?xml ...?>``, and a
            malformed declaration (``<?xml verison="1.0"?>``), as tinyxml2 (urdfdom, Gazebo,
            MuJoCo) does; False to refuse both, as expat (xacro) does.

    Raises:
        XmlError: Empty, too large, not UTF-8, or not well-formed; with line and column.
        UnsafeXmlError: The document declares entities, or refers to one that only an
            external DTD could declare.
    """
    if len(data) > max_bytes:
        raise XmlError(
            filename,
            f"file is {len(data) / 1e6:.1f} MB, over the {max_bytes / 1e6:.0f} MB limit "
            "for a robot description; is this really a URDF?",
        )
    text = _decode(data, filename)
    if not text.strip():
        raise XmlError(filename, "file is empty; a URDF needs a <robot> element")
    try:
        return _Builder(filename, max_elements).parse(text)
    except XmlError as exc:
        blanks = len(text) - len(text.lstrip(" \t\r\n"))
        if (blanks and blanks_before_declaration and exc.reason.endswith(_MISPLACED_DECLARATION)
                and _declaration_end(text[blanks:])):
            # tinyxml2 skips blanks before the declaration; expat refuses them (doosan's
            # H2017_2_2.dae, a URDF written with a blank first line)
            return _reparsed(text, blanks, filename, max_elements)
        declaration = _declaration_end(text) if blanks_before_declaration else 0
        if not (declaration and exc.line == 1 and exc.reason.endswith(_BAD_DECLARATION)):
            accident = download_accident(text)
            if accident is not None:
                raise XmlError(filename, accident[0], accident[1], 1) from None
            raise
        # tinyxml2 (urdfdom, Gazebo, MuJoCo) reads the opening <?xml ...?> without judging
        # what it says (ros/urdf's one_link.urdf: <?xml verison="1.0"?>); so does this,
        # with the declaration blanked out for expat
        return _Builder(filename, max_elements).parse(" " * declaration + text[declaration:])


def download_accident(text: str) -> tuple[str, int] | None:
    """What a file that is no XML is instead, and the line that shows it; None if not known.

    A Git LFS pointer or a merge conflict (:func:`~servicebot_cli.common.accidents.accident`),
    a web page saved instead of the raw file, or nothing but comments.
    """
    found = accident(text)
    if found is not None:
        return found
    head = text.lstrip()[:200].lower()
    if head.startswith(("<!doctype html", "<html")):
        return ("an HTML page, not a URDF (a web page saved instead of the raw file?): "
                "download the raw file"), 1
    if not _COMMENTS.sub("", _DECLARATION.sub("", text, count=1)).strip():
        return "file is empty but for comments; a URDF needs a <robot> element", 1
    return None


_COMMENTS = re.compile(r"<!--.*?(?:-->|$)", re.DOTALL)
_DECLARATION = re.compile(r"^\s*<\?xml[^>]*\?>")


def _reparsed(text: str, blanks: int, filename: str, max_elements: int) -> XmlDocument:
    """``text`` parsed with the declaration after its ``blanks`` leading blanks blanked out.

    Every other character keeps its line and column.
    """
    end = blanks + _declaration_end(text[blanks:])
    declaration = "".join(c if c in "\r\n" else " " for c in text[blanks:end])
    return _Builder(filename, max_elements).parse(text[:blanks] + declaration + text[end:])


def _declaration_end(text: str) -> int:
    """Where the ``<?xml ...?>`` that opens ``text`` ends, or 0 when it has none."""
    if not text.startswith("<?xml") or text[5:6] not in (" ", "\t", "\r", "\n"):
        return 0
    end = text.find("?>")
    return 0 if end < 0 or "<" in text[1:end] else end + 2


def declaration_first(data: bytes) -> bytes:
    """``data`` (a COLLADA file) with an ``<?xml ...?>`` that follows blank lines moved before them.

    Assimp (RViz, Gazebo, MoveIt) and tinyxml2 skip blanks before the declaration; expat and
    libxml2 refuse them (doosan-robot2's ``H2017_2_2.dae`` opens with a blank line). Moving
    the declaration keeps every later line and column where it was.
    """
    body = data.lstrip(b" \t\r\n")
    if len(body) == len(data) or not body.startswith(b"<?xml"):
        return data
    end = body.find(b"?>")
    if end < 0 or b"\n" in body[:end]:
        return data
    return body[:end + 2] + data[:len(data) - len(body)] + body[end + 2:]


def _decode(data: bytes, filename: str) -> str:
    """``data`` as text; every reason it is not starts with ``invalid UTF-8`` (SB003)."""
    try:
        return decode_utf8(data)
    except NotUtf8 as exc:
        if exc.binary:
            reason = f"invalid UTF-8: {exc.what}, not text; is it the right file?"
        elif exc.line:
            reason = f"invalid UTF-8 ({exc.what}); save the file as UTF-8"
        else:
            reason = f"invalid UTF-8: {exc.what}; save the file as UTF-8"
        raise XmlError(filename, reason, exc.line, exc.column) from None


ENTITY_FIX = "write its value there, or name the file .urdf.xacro (xacro expands it)"
"""What to do about an entity a plain URDF uses (:func:`read_as_written`)."""


def read_as_written(entity: str) -> str:
    """Why a plain URDF may not use ``entity``: what urdfdom reads where it stands."""
    return (f"entity '&{entity};' (its DOCTYPE declares it): urdfdom, under "
            "robot_state_publisher, Gazebo, MoveIt and Pinocchio, does not expand entities and "
            f"reads '&{entity};' as written")


def _references_only(text: str) -> str:
    """``text`` with its comments and CDATA sections blanked, lines and columns kept.

    They hold text, never an entity reference.
    """
    return _UNREAD.sub(lambda m: re.sub(r"[^\n]", " ", m[0]), text)


_PREDEFINED = re.compile(r"&(?:amp|lt|gt|quot|apos);")
"""XML's predefined entities: an entity's value may refer to them (``"a &amp; b"``)."""

class _Builder:
    """Feeds expat events into a TreeBuilder of PositionedElements."""

    def __init__(self, filename: str, max_elements: int) -> None:
        self.filename = filename
        self.max_elements = max_elements
        self.count = 0
        self.depth = 0
        self.doctype: str | None = None
        self.external_dtd: ExternalDtd | None = None
        self.entities: dict[str, str] = {}
        self.comments: list[str] = []
        self.tree = ET.TreeBuilder(element_factory=PositionedElement)
        self.parser = expat.ParserCreate()
        self.parser.buffer_text = True
        self.parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)
        self.parser.StartElementHandler = self._start
        self.parser.EndElementHandler = self._end
        self.parser.CharacterDataHandler = self.tree.data
        self.parser.CommentHandler = self.comments.append
        self.parser.StartDoctypeDeclHandler = self._doctype
        self.parser.EntityDeclHandler = self._entity
        self.parser.ExternalEntityRefHandler = self._external

    def parse(self, text: str) -> XmlDocument:
        try:
            self.parser.Parse(text, True)
        except expat.ExpatError as exc:
            raise XmlError(
                self.filename,
                f"XML is not well-formed: {expat.ErrorString(exc.code)}",
                exc.lineno,
                exc.offset + 1,
            ) from None
        root = self.tree.close()
        assert isinstance(root, PositionedElement)  # the element_factory makes every element
        if self.external_dtd is not None:
            self._entities_of_the_dtd(text, self.external_dtd)
        return XmlDocument(root=root, text=text, doctype=self.doctype,
                           external_dtd=self.external_dtd,
                           entities_used=self._entities_used(text))

    def _entities_used(self, text: str) -> tuple[tuple[str, int, int], ...]:
        """Each declared entity the text refers to, where first (comments and CDATA aside)."""
        if not self.entities:
            return ()
        text = _references_only(text)
        body = text.find("]>")  # after the internal subset, whose declarations refer to none
        used = []
        for name in self.entities:
            at = text.find(f"&{name};", max(body, 0))
            if at >= 0:
                line = text.count("\n", 0, at) + 1
                used.append((name, line, at - (text.rfind("\n", 0, at) + 1) + 1))
        return tuple(used)

    def _entities_of_the_dtd(self, text: str, dtd: ExternalDtd) -> None:
        """Refuse a reference to an entity the unloaded DTD would declare.

        With an external DTD, expat drops such a reference silently (from an attribute
        too), where tinyxml2 (urdfdom, Gazebo, MuJoCo) keeps the text ``&name;``.
        """
        text = _references_only(text)
        found = _ENTITY_REFERENCE.search(text)
        if found is not None:
            line = text.count("\n", 0, found.start()) + 1
            column = found.start() - (text.rfind("\n", 0, found.start()) + 1) + 1
            raise UnsafeXmlError(
                self.filename,
                f"entity '&{found[1]};' would come from the external DTD '{dtd.identifier}', "
                "which no robot description reader loads; write its value instead",
                line, column)

    def _where(self) -> tuple[int, int]:
        return self.parser.CurrentLineNumber, self.parser.CurrentColumnNumber + 1

    def _start(self, tag: str, attrs: dict[str, str]) -> None:
        # once per element of every file: the common path makes no call it can avoid
        self.count += 1
        self.depth += 1
        if self.count > self.max_elements or self.depth > MAX_DEPTH:
            self._refuse()
        element: PositionedElement = self.tree.start(tag, attrs)  # type: ignore[assignment]
        parser = self.parser  # (its element_factory makes every element a PositionedElement)
        element.sourceline = parser.CurrentLineNumber
        element.column = parser.CurrentColumnNumber + 1
        if self.comments:
            element.leading_comments = tuple(self.comments)
            self.comments.clear()

    def _refuse(self) -> NoReturn:
        if self.count > self.max_elements:
            raise XmlError(
                self.filename, f"more than {self.max_elements} elements; refused", *self._where()
            )
        raise XmlError(
            self.filename, f"elements nested over {MAX_DEPTH} deep; refused", *self._where()
        )

    def _end(self, tag: str) -> None:
        self.depth -= 1
        if self.comments:
            self.comments.clear()
        self.tree.end(tag)

    def _doctype(self, name: str, system_id: str | None, public_id: str | None, _: int) -> None:
        if system_id or public_id:
            self.external_dtd = ExternalDtd(system_id or public_id or "", *self._where())
        self.doctype = name

    def _entity(self, name: str, is_parameter: int, value: str | None, _base: str | None,
                system_id: str | None, public_id: str | None, notation: str | None) -> None:
        """Take a plain internal entity (xacro expands it); refuse any other."""
        if is_parameter or value is None or system_id or public_id or notation:
            why = "a parameter entity" if is_parameter else "an external entity"
        elif len(value) > MOST_ENTITY_BYTES or "&" in _PREDEFINED.sub("", value) \
                or "%" in value:  # XML's five predefined entities expand to no more
            why = (f"its value is over {MOST_ENTITY_BYTES} characters" if len(value) >
                   MOST_ENTITY_BYTES else "its value refers to another entity")
        elif len(self.entities) >= MOST_ENTITIES:
            why = f"over {MOST_ENTITIES} entities declared"
        else:
            self.entities[name] = value
            return
        raise UnsafeXmlError(
            self.filename,
            f"entity declaration '{name}' refused ({why}): only plain internal entities are "
            "read; use xacro properties instead",
            *self._where(),
        )

    def _external(self, *_: object) -> int:
        raise UnsafeXmlError(
            self.filename, "external entity reference refused; remove it", *self._where()
        )
