"""A COLLADA file's XML tree, read by lxml when it can: four times faster than ElementTree.

COLLADA files are large XML (megabytes of number lists), and parsing them was a fifth of a
check's time. lxml (libxml2; installed with yourdfpy) builds the same tree in a quarter of
the time. ElementTree stays the reader of record: a file that declares a DOCTYPE (entities),
that lxml refuses, or about which libxml2 logs anything at all goes to it, so an error says
what it said before, and entity expansion keeps expat's limits.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from typing import cast

_ROOT_END = b"</COLLADA>"
# an attribute value holding a raw "<" (each quote kind): "=" and the quoted value
_RAW_LT_VALUE = re.compile(rb'=[ \t]*"[^"<>]*<[^"]*"|=[ \t]*\'[^\'<>]*<[^\']*\'')


class ColladaXmlError(ValueError):
    """The file is not well-formed XML; the message is ElementTree's."""


def parse_collada(data: bytes) -> ET.Element:
    """The root element of ``data``; children may include comments (skip non-str tags).

    Two defects Assimp (Gazebo's and RViz's reader) reads past are read past here too:
    bytes after the root's end, and a raw ``<`` in an attribute value.

    Raises:
        ColladaXmlError: Not well-formed XML.
    """
    try:
        return _parsed(data)
    except ColladaXmlError as exc:
        first = exc
    end = data.find(_ROOT_END)
    if end >= 0 and data[end + len(_ROOT_END):].strip():
        # bytes after the root's end (NULs and the rest of an older, longer file written
        # over): left out
        data = data[:end + len(_ROOT_END)]
    # velodyne_simulator's meshes: <geometry name="<STL_BINARY>">, as an exporter wrote it
    data = _RAW_LT_VALUE.sub(lambda m: m[0].replace(b"<", b"&lt;"), data)
    try:
        return _parsed(data)
    except ColladaXmlError:
        raise first from None


def _parsed(data: bytes) -> ET.Element:
    root = _with_lxml(data)
    if root is not None:
        return root
    try:
        return ET.fromstring(data)
    except ET.ParseError as exc:
        raise ColladaXmlError(str(exc)) from None


def _declares_doctype(data: bytes) -> bool:
    """Whether the prolog (declarations, comments and blanks before the root) holds a DOCTYPE.

    A prolog that does not end as XML says is taken to hold one (ElementTree then judges).
    """
    at = 3 if data.startswith(b"\xef\xbb\xbf") else 0  # a UTF-8 byte order mark
    while True:
        while at < len(data) and data[at] in b" \t\r\n":
            at += 1
        if data.startswith(b"<!DOCTYPE", at):
            return True
        for opening, closing in ((b"<?", b"?>"), (b"<!--", b"-->")):
            if data.startswith(opening, at):
                end = data.find(closing, at + len(opening))
                if end < 0:
                    return True
                at = end + len(closing)
                break
        else:
            return not data.startswith(b"<", at)  # the root element starts: no DOCTYPE


def _with_lxml(data: bytes) -> ET.Element | None:
    """The tree lxml builds (ElementTree's interface), or None when it is not sure of it."""
    if _declares_doctype(data):
        return None
    try:
        from lxml import etree
    except ImportError:  # pragma: no cover - yourdfpy depends on lxml
        return None
    # huge_tree: number lists beyond 10 MB; no DTD is read, so no entity is ever expanded
    parser = etree.XMLParser(resolve_entities=False, huge_tree=True, no_network=True,
                             load_dtd=False)
    try:
        root = etree.fromstring(data, parser)
    except (etree.LxmlError, ValueError):
        return None
    if len(parser.error_log):
        return None
    return cast(ET.Element, root)
