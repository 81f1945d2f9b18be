"""Expand xacro without ROS, and remember which xacro line produced each URDF element.

The only importer of ``xacro``. xacro keeps its state in module globals, so an expansion
runs under a lock with a few of its functions wrapped:

* ``parse`` reads every file (the top one and each include) through :mod:`safe_xml` first,
  then builds xacro's DOM while tagging each element with its line and column;
* ``handle_macro_call`` tags what a macro produced with the call site;
* ``eval_all`` and friends track the element being expanded, so an error names its line;
* ``$(find pkg)`` resolves through :class:`PackageResolver` instead of ament.

The tags are attributes removed before serialising, so the output is plain URDF.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import sys
import threading
import xml.dom
import xml.dom.minidom
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any
from xml.dom import expatbuilder
from xml.parsers import expat

from servicebot_cli.common.errors import DescriptionError, PackageNotFound, XacroError, XmlError
from servicebot_cli.common.inputs import as_typed, not_a_file, open_binary
from servicebot_cli.description.install_layout import (
    included_when_installed,
    installed_source,
    lands_outside,
)
from servicebot_cli.description.load_warnings import LoadWarning, said_by_xacro
from servicebot_cli.description.packages import PackageResolver
from servicebot_cli.description.safe_xml import MAX_BYTES, parse_xml
from servicebot_cli.description.sources import SourceRef
from servicebot_cli.description.xacro_calls import (
    bare_definition,
    bare_directives,
    bare_macro_calls,
)
from servicebot_cli.description.xacro_limits import (
    GUARDS,
    ExpansionTooLarge,
    MacroBudget,
    bounded_eval_text,
    guarded_safe_eval,
)
from servicebot_cli.description.yaml_size import AliasBomb, bounded_document

_SRC_ATTR = "servicebot-src"
_VIA_ATTR = "servicebot-via"
_REF_KEY = "servicebot-ref"  # minidom user data: a xacro element's index into the positions
_ARG_USE_RE = re.compile(r"\$\(arg\s+([A-Za-z_][\w]*)\s*\)")
_EXPRESSION_RE = re.compile(r"when evaluating expression '(.*)' *$", re.MULTILINE)
_LOCK = threading.Lock()
# Python frames one expansion may use. xacro itself runs under Python's default of 1,000 and
# so expands a recursive macro (a chain of segments, a track) to about 230 levels; the
# position tracking here costs about twice its frames per level, so 3,000 reaches past that.
_RECURSION_LIMIT = 3000


def _template_hint(filename: object) -> str:
    """What to do when ``filename`` is missing but its template ``filename.in`` is there.

    The build makes the file (hector_quadrotor's CMake ``configure_file``). Empty otherwise.
    """
    if not isinstance(filename, str) or not os.path.isfile(filename + ".in"):
        return ""
    return (f"; '{os.path.basename(filename)}.in' beside it is the template the package's "
            "build makes it from: build the package, or check the installed copy")


@dataclass(frozen=True)
class Expansion:
    """The result of expanding a xacro file.

    Attributes:
        xml_text: The URDF, serialised as xacro's own command does (two-space indent).
        origins: For each element of ``xml_text`` in document order, the xacro position
            that produced it, or None for elements xacro created itself.
        files: Every file read, the top one first.
        warnings: What xacro printed (warnings, a file's errors and messages), and a warning
            per bare macro call and per argument the file does not read.
    """

    xml_text: str
    origins: tuple[SourceRef | None, ...]
    files: tuple[str, ...]
    warnings: tuple[LoadWarning, ...]


def expand(
    path: str | os.PathLike[str],
    args: Mapping[str, str] | None = None,
    resolver: PackageResolver | None = None,
    data: bytes | None = None,
) -> Expansion:
    """Expand the xacro file at ``path`` with ``name:=value`` arguments.

    ``data``: the file's bytes, when the caller read them already: a pipe
    (``<(cat robot.urdf.xacro)``) gives its bytes once.

    Raises:
        XmlError: A file is not well-formed or unsafe (with its line and column).
        XacroError: xacro failed (with the line being expanded).
        PackageNotFound: ``$(find pkg)`` names a package that is nowhere.
    """
    display = str(path)
    tracer = _Tracer(resolver or PackageResolver.from_environment(), data)
    given = dict(args or {})
    with _LOCK, tracer.patched():
        import xacro

        xacro.all_includes.clear()
        xacro.init_stacks(display)
        try:
            with _recursion_limit(_RECURSION_LIMIT):
                doc = xacro.parse(None, display)
                xacro.process_doc(doc, mappings=_ReadArguments(given, tracer.known_args))
        except DescriptionError as exc:
            exc.said_before = said_by_xacro(tracer.said)
            raise
        except Exception as exc:  # xacro raises bare Python errors from expressions, too
            error = tracer.error(exc, xacro.filestack)
            error.said_before = said_by_xacro(tracer.said)  # xacro printed them before failing
            raise error from None
    _refuse_unwritable(doc, display, tracer)
    _refuse_bad_names(doc, display, tracer)
    bare = bare_macro_calls(doc, tracer.macros, tracer.ref_of) + bare_directives(
        doc, tracer.ref_of)
    origins = tracer.take_origins(doc)
    _add_banner(doc, Path(display).name, given)
    return Expansion(
        xml_text=doc.toprettyxml(indent="  "),
        origins=tuple(origins),
        files=tuple(tracer.files),
        warnings=(said_by_xacro(tracer.said) + bare + tuple(tracer.installed_only)
                  + _unread_args(display, given, tracer)),
    )


@contextlib.contextmanager
def _recursion_limit(frames: int) -> Iterator[None]:
    """Allow at least ``frames`` Python frames inside the block."""
    saved = sys.getrecursionlimit()
    sys.setrecursionlimit(max(saved, frames))
    try:
        yield
    finally:
        sys.setrecursionlimit(saved)


_INCLUDE_DEPTH = 64
"""How often a file may be on the include stack: recursion through an include that a condition
ends (``<xacro:if value="${level > 0}">``, xacro's own tests go 16 deep) is xacro, one that
nothing ends never stops."""
_INCLUDES = 10_000
"""Files a description may read: a robot including ``*`` from its own directory includes
every file there, which include ``*`` again; a real robot reads a few hundred."""


def _installed_spec(spec: str, joined: str, filestack: list[str | None]) -> str:
    """Where an include or YAML file ``spec`` (``joined`` to its includer's directory) is read.

    What exists is read where it is. A missing absolute path (``$(find PKG)/...``) is read
    from the source file the package's install rules put there; a missing relative one from
    where it lands once its includer is installed, and only there: an include that names no
    file in the sources nor in the install space stays missing, as for xacro.
    """
    if os.path.exists(joined):
        return joined
    if os.path.isabs(spec):
        return installed_source(joined)
    includer = filestack[-1] if filestack else None
    found = included_when_installed(Path(includer), spec) if includer else None
    return joined if found is None else str(found)


def _refuse_include_cycle(filestack: list[str | None], read: int,
                          error: Callable[[str], Exception]) -> None:
    """Refuse a file included in itself too deep, or too many files read (``read``).

    A file included in itself :data:`_INCLUDE_DEPTH` deep, or over :data:`_INCLUDES` files.
    Such a file includes itself again and again: xacro gives up only when Python's stack
    runs out, after expanding everything on the way (a robot including ``*`` from its own
    directory took minutes). Named with its cycle, from the include on the stack.
    """
    if read > _INCLUDES:
        raise error(f"over {_INCLUDES} files included; does a file include itself, or '*' "
                    "from its own directory?")
    if len(filestack) < 2 or not filestack[-1]:
        return
    real = [os.path.realpath(f) if f else None for f in filestack]
    if real[:-1].count(real[-1]) >= _INCLUDE_DEPTH:
        start = len(real) - 2 - real[-2::-1].index(real[-1])  # its last time before this
        cycle = " -> ".join(os.path.basename(f or "") for f in filestack[start:])
        raise error(f"'{filestack[-1]}' includes itself ({cycle}) {_INCLUDE_DEPTH} deep, "
                    "where servicebot stops: an include cycle that no condition ends, or a "
                    f"recursion deeper than {_INCLUDE_DEPTH} levels")


def _refuse_unwritable(doc: xml.dom.minidom.Document, display: str, tracer: _Tracer) -> None:
    """Refuse an attribute whose value is a number, not text, as xacro fails to write it.

    ``<xacro:attribute name="size" value="${0.5}"/>`` sets the float 0.5, which xacro's
    writer cannot escape (AttributeError): xacro itself stops there.
    """
    for node in doc.getElementsByTagName("*"):
        for name, value in node.attributes.items():
            if not isinstance(value, str):
                ref = tracer.ref_of(node)
                where = ref.location() if ref is not None else display
                raise XacroError(
                    f"{where}: xacro: attribute '{name}' of <{node.tagName}> is the "
                    f"{type(value).__name__} {value!r}, not text, which xacro cannot write; "
                    f"write it as text (value=\"{value}\")")


_NAME_START = (":A-Z_a-z\u00c0-\u00d6\u00d8-\u00f6\u00f8-\u02ff\u0370-\u037d\u037f-\u1fff"
               "\u200c-\u200d\u2070-\u218f\u2c00-\u2fef\u3001-\ud7ff\uf900-\ufdcf"
               "\ufdf0-\ufffd\U00010000-\U000effff")
_XML_NAME = re.compile(f"[{_NAME_START}][{_NAME_START}\\-.0-9\u00b7\u0300-\u036f\u203f-\u2040]*")
"""An XML name, as XML 1.0 (fifth edition) writes NameStartChar and NameChar: letters, '_'
or ':' first (and most characters beyond Latin), then also digits, '-', '.', U+00B7, the
combining marks U+0300-036F and U+203F-2040."""


def _refuse_bad_names(doc: xml.dom.minidom.Document, display: str, tracer: _Tracer) -> None:
    """Refuse an element or attribute name that is no XML name, where xacro made it.

    ``<xacro:element xacro:name="${x}">`` with x = '1bad name', or ``<xacro:attribute
    name="bad name">``: xacro writes XML no reader parses, and the parse error pointed into
    the expanded text, at a line of the source that was fine.
    """
    for node in doc.getElementsByTagName("*"):
        bad = [(f"element name '{node.tagName}'", "xacro:element")] \
            if not _XML_NAME.fullmatch(node.tagName) else []
        bad += [(f"attribute name '{name}' of <{node.tagName}>", "xacro:attribute")
                for name in node.attributes.keys() if not _XML_NAME.fullmatch(name)]
        if bad:
            what, made_by = bad[0]
            ref = tracer.ref_of(node)
            where = ref.location() if ref is not None else display
            raise XacroError(f"{where}: xacro: {what} is no XML name, so the expanded URDF "
                             f"would not parse (a {made_by} named it); give a name of "
                             "letters, digits, '_', '-' and '.', starting with a letter")


class _ReadArguments(dict[str, str]):
    """xacro's ``$(arg)`` values, noting in ``read`` each name the expansion looks up.

    A file may read an argument under a computed name (``$(arg ${'v' + 'ar'})``, from xacro's
    own tests) that no scan of its text sees.
    """

    def __init__(self, given: Mapping[str, str], read: set[str]) -> None:
        super().__init__(given)
        self.read = read

    def __getitem__(self, name: str) -> str:
        self.read.add(name)
        return super().__getitem__(name)


def _unread_args(display: str, given: Mapping[str, str],
                 tracer: _Tracer) -> tuple[LoadWarning, ...]:
    """A warning per argument the file neither declares nor reads (on any path it took).

    Not an error: ROS xacro accepts any argument, and a branch not taken with these
    arguments may read it.
    """
    declared = ", ".join(sorted(tracer.known_args)) or "none"
    return tuple(
        LoadWarning(f"xacro argument '{name}' is not declared or read by this file (its "
                    f"arguments: {declared}); xacro ignores it", display,
                    fix=f"drop {name}:=VALUE, or declare it with <xacro:arg name=...> where "
                    "the file reads it")
        for name in sorted(set(given) - tracer.known_args))


def _add_banner(doc: xml.dom.minidom.Document, name: str, args: Mapping[str, str]) -> None:
    argv = " ".join([name, *(f"{k}:={v}" for k, v in sorted(args.items()))])
    text = f" Generated by `servicebot expand {argv}`: edit the xacro source, not this file. "
    doc.insertBefore(doc.createComment(text.replace("--", "-")), doc.documentElement)


_ATTRIBUTE_READERS = ("check_attrs", "reqd_attrs", "replace_node")
"""xacro's functions that read a directive's attributes (xacro:if, xacro:attribute,
xacro:element), and the one that ends its work."""


class _Tracer:
    """Positions of xacro's DOM nodes, and the patches that record them."""

    def __init__(self, resolver: PackageResolver, top_data: bytes | None = None) -> None:
        self.resolver = resolver
        self.top_data = top_data  # the top file's bytes, read already
        self.refs: list[SourceRef] = []
        self.node_refs: dict[int, int] = {}  # id(xacro:* node) -> index into refs
        self.keep: list[object] = []  # keeps nodes alive so their ids stay unique
        self.current: list[int] = []
        self.failed_at: int | None = None
        self.failed_calls: list[tuple[str, int | None]] = []  # macro, call: the innermost first
        self.docs: list[xml.dom.minidom.Document] = []  # each file read, as xacro parsed it
        self.files: list[str] = []
        self.known_args: set[str] = set()
        self.macros: dict[str, SourceRef] = {}  # where each macro is defined, by name
        self.reading: tuple[int, int] | None = None  # the directive whose attributes are read
        self.said: list[tuple[str, SourceRef | None]] = []  # what xacro printed, and where
        self.installed_only: list[LoadWarning] = []  # includes that hold in the sources only

    def record(self, node: xml.dom.minidom.Element, file: str, line: int, column: int) -> None:
        self.refs.append(SourceRef(file, line, column))
        index = len(self.refs) - 1
        if node.tagName.startswith("xacro:"):
            self.node_refs[id(node)] = index
            self.keep.append(node)
            # xacro clones a macro's body at each call: the clone of a call or an <xacro:if>
            # in it is known by the same position (an attribute would be a macro parameter)
            node.setUserData(_REF_KEY, index, self)
            if node.tagName == "xacro:arg" and node.getAttribute("name"):
                self.known_args.add(node.getAttribute("name"))
            elif node.tagName == "xacro:macro" and node.getAttribute("name"):
                self.macros.setdefault(node.getAttribute("name"), self.refs[index])
        else:
            node.setAttribute(_SRC_ATTR, str(index))

    def handle(self, operation: int, key: str, index: int, _source: object,
               clone: xml.dom.minidom.Node | None) -> None:
        """The DOM's user-data hook: a cloned xacro element keeps its original's position."""
        if key == _REF_KEY and clone is not None and operation in (
                xml.dom.UserDataHandler.NODE_CLONED, xml.dom.UserDataHandler.NODE_IMPORTED):
            self.node_refs[id(clone)] = index
            self.keep.append(clone)
            clone.setUserData(_REF_KEY, index, self)

    def ref_of(self, node: object) -> SourceRef | None:
        """Where ``node`` was written, if it was read from a file."""
        index = self.index_of(node)
        return None if index is None else self.refs[index]

    def _spec(self, spec: str, joined: str, filestack: list[str | None]) -> str:
        """:func:`_installed_spec`, noting a relative include that holds in the sources only."""
        read = _installed_spec(spec, joined, filestack)
        includer = filestack[-1] if filestack else None
        if includer and read == joined and not os.path.isabs(spec) and os.path.exists(read):
            lands = lands_outside(Path(includer), spec)
            if lands is not None and not self._installed_share(lands, includer):
                where = self.refs[self.current[-1]] if self.current else None
                self.installed_only.append(LoadWarning(
                    f"'{spec}' is read from the sources only: from where the install rules put "
                    f"{os.path.basename(includer)}, it names <install prefix>/{lands}, which no "
                    "package installs, so xacro fails on the installed file that launch files "
                    "load (FindPackageShare)", where.file if where else None,
                    where.line if where else 0, where.column if where else 0,
                    fix="name it through its package: $(find PACKAGE)/path/in/its/share",
                    said_as="installed"))
        return read

    def _installed_share(self, lands: str, includer: str) -> bool:
        """Whether ``lands`` (under the install prefix) is in the share of a package ROS finds."""
        parts = lands.split("/")
        if len(parts) < 3 or parts[0] != "share":
            return False
        try:
            return self.resolver.probe().locate(parts[1], Path(includer).parent).ros_finds_it
        except PackageNotFound:
            return False

    def _said(self, *parts: object, sep: str | None = " ", **_: object) -> None:
        """xacro.color's print: the text, and the element being processed.

        A directive whose attributes are being read at this depth (xacro:if, xacro:arg:
        their parent is what is processed) is the element, as for an error.
        """
        reading = self.reading
        if reading is not None and reading[1] == len(self.current):
            where: SourceRef | None = self.refs[reading[0]]
        else:
            where = self.refs[self.current[-1]] if self.current else None
        self.said.append(((" " if sep is None else sep).join(map(str, parts)), where))

    def index_of(self, node: object) -> int | None:
        if isinstance(node, xml.dom.minidom.Element):
            if node.hasAttribute(_SRC_ATTR):
                return int(node.getAttribute(_SRC_ATTR))
            return self.node_refs.get(id(node))
        return None

    @contextlib.contextmanager
    def patched(self) -> Iterator[io.StringIO]:
        import xacro
        import xacro.substitution_args as subst

        names = ("parse", "eval_all", "handle_macro_call", "grab_property", "grab_macro",
                 "process_include")
        saved = {name: getattr(xacro, name) for name in names}
        saved_find = subst._eval_find
        saved_spec = xacro.abs_filename_spec
        saved_eval = xacro.safe_eval, xacro.eval_text
        xacro.parse = self._parse
        # bounded: a file cannot ask for more than a machine has (see xacro_limits)
        xacro.safe_eval = guarded_safe_eval(xacro.XacroException)
        xacro.eval_text = bounded_eval_text(xacro.eval_text)
        xacro._global_symbols.update(GUARDS)
        # includes and load_yaml open what abs_filename_spec names: a file of a source
        # package found where the package's install rules put it
        xacro.abs_filename_spec = lambda spec: self._spec(spec, saved_spec(spec),
                                                          xacro.filestack)
        import yaml  # type: ignore[import-untyped]  # PyYAML ships no types

        saved_load = yaml.safe_load  # what xacro's load_yaml reads with
        yaml.safe_load = _bounded_safe_load(xacro.XacroException)
        for name in names[1:]:
            setattr(xacro, name, self._tracking(saved[name]))
        xacro.handle_macro_call = self._tracking(
            self._macro_call(MacroBudget().wrap(saved["handle_macro_call"])))
        attrs = {name: getattr(xacro, name) for name in _ATTRIBUTE_READERS}
        for name, fn in attrs.items():
            setattr(xacro, name, self._reading(fn, clears=name == "replace_node"))
        saved.update(attrs)
        subst._eval_find = lambda pkg: str(self.resolver.find(pkg))
        import xacro.color

        # every warning, error and message xacro prints (its own, and a file's xacro.warning()
        # and the like) goes through xacro.color's print: each is kept with its element
        xacro.color.print = self._said
        captured = io.StringIO()  # the rest (print_location's trail of files): dropped
        try:
            with contextlib.redirect_stderr(captured), contextlib.redirect_stdout(captured):
                yield captured
        finally:
            del xacro.color.print
            for name, fn in saved.items():
                setattr(xacro, name, fn)
            subst._eval_find = saved_find
            xacro.abs_filename_spec = saved_spec
            xacro.safe_eval, xacro.eval_text = saved_eval
            yaml.safe_load = saved_load
            for name in GUARDS:
                xacro._global_symbols.pop(name, None)

    def _parse(self, inp: str | xml.dom.minidom.Document | None,
               filename: str | None = None) -> xml.dom.minidom.Document:
        import xacro

        if inp is not None:
            return xml.dom.minidom.parseString(inp) if isinstance(inp, str) else inp
        path = os.path.join(xacro.root_dir, filename or "")  # mapped by abs_filename_spec
        _refuse_include_cycle(xacro.filestack, len(self.files), xacro.XacroException)
        data = self.top_data if not self.files else None
        why = not_a_file(path) if data is None else None
        if why is not None and why != "does not exist" and not why.startswith("cannot"):
            xacro.filestack.pop()  # a pipe or a device: no file to include
            raise xacro.XacroException(f"cannot include '{filename}': it {why}")
        try:
            if data is None:
                with open_binary(path) as handle:  # a device: read to the limit only; a
                    # named pipe nothing writes into: empty at once
                    data = handle.read(MAX_BYTES + 1)
        except OSError as exc:
            xacro.filestack.pop()  # as xacro does: the failing file is not "being processed"
            raise xacro.XacroException(f"{exc.strerror}: {filename}", exc=exc) from None
        if len(data) > MAX_BYTES:
            xacro.filestack.pop()
            raise xacro.XacroException(f"'{filename}' holds over {MAX_BYTES >> 20} MiB, the "
                                       "limit for a description; is it the right file?")
        display = filename or path
        if self.files:  # an include: $(find)'s absolute path shown as a relative include's
            display = as_typed(display)  # (the file checked stays as the user named it)
        try:
            text = parse_xml(data, display, blanks_before_declaration=False).text
        except XmlError as exc:  # an include's: say which xacro:include reads it
            if not self.files or not self.current or type(exc) is not XmlError:
                raise
            raise XmlError(exc.file, f"{exc.reason} (included at "
                           f"{self.refs[self.current[-1]].location()})", exc.line,
                           exc.column) from None
        self.files.append(display)
        self.known_args.update(_ARG_USE_RE.findall(text))
        builder = _PositionBuilder(self, display)
        try:
            parsed: xml.dom.minidom.Document = builder.parseString(text)
            self.docs.append(parsed)
            return parsed
        except expat.ExpatError as exc:  # namespace errors: safe_xml does not track prefixes
            raise XmlError(
                display, f"XML namespace error: {expat.ErrorString(exc.code)} (is xmlns:xacro "
                'declared as "http://www.ros.org/wiki/xacro"?)', exc.lineno, exc.offset + 1
            ) from None

    def _tracking(self, fn: Callable[..., object]) -> Callable[..., object]:
        def wrapper(node: object, *args: object, **kwargs: object) -> object:
            index = self.index_of(node)
            if index is not None:
                self.current.append(index)
            try:
                return fn(node, *args, **kwargs)
            except Exception:
                if self.failed_at is None and self.current:
                    # a directive's attributes (xacro:if's value) are read while its parent
                    # is processed: the directive read last at this depth failed
                    reading = self.reading
                    self.failed_at = reading[0] if reading is not None \
                        and reading[1] == len(self.current) else self.current[-1]
                raise
            finally:
                if index is not None:
                    self.current.pop()

        return wrapper

    def _reading(self, fn: Callable[..., object], clears: bool) -> Callable[..., object]:
        """``fn`` (xacro's attribute readers, or replace_node), noting the directive it reads.

        replace_node ends a directive's work: what fails after it is its parent's.
        """
        def wrapper(node: object, *args: object, **kwargs: object) -> object:
            if clears:
                self.reading = None
            else:
                index = self.index_of(node)
                self.reading = None if index is None else (index, len(self.current))
            return fn(node, *args, **kwargs)

        return wrapper

    def _macro_call(self, fn: Callable[..., bool]) -> Callable[..., bool]:
        def wrapper(node: xml.dom.minidom.Element, *args: object) -> bool:
            call_site = self.node_refs.get(id(node))
            parent, before, after = node.parentNode, node.previousSibling, node.nextSibling
            try:
                handled = fn(node, *args)
            except Exception:  # unwinding from the innermost call out
                if node.tagName.startswith("xacro:"):
                    name = node.getAttribute("macro") if node.tagName == "xacro:call" \
                        else node.tagName.removeprefix("xacro:")
                    if not self.failed_calls or self.failed_calls[-1] != (name, call_site):
                        self.failed_calls.append((name, call_site))  # xacro:call comes twice
                raise
            if handled and call_site is not None and parent is not None:
                child = before.nextSibling if before is not None else parent.firstChild
                while child is not None and child is not after:
                    if child.nodeType == child.ELEMENT_NODE:
                        for element in (child, *child.getElementsByTagName("*")):
                            _add_call(element, call_site)
                    child = child.nextSibling
            return handled

        return wrapper

    def error(self, exc: Exception, filestack: list[str | None] | None) -> DescriptionError:
        if self.failed_at is not None:
            where = self.refs[self.failed_at].location()
        else:
            where = next((f for f in reversed(filestack or []) if f), "xacro")
        inner: BaseException = exc
        while isinstance(getattr(inner, "exc", None), BaseException):  # xacro wraps errors
            inner = inner.exc  # type: ignore[attr-defined]
        if isinstance(inner, PackageNotFound):
            return PackageNotFound(f"{where}: {inner}")
        if isinstance(inner, OSError):
            expression = _EXPRESSION_RE.search(str(exc))
            if expression is None:
                return XacroError(f"{where}: cannot read included file '{inner.filename}': "
                                  f"{inner.strerror}{_template_hint(inner.filename)}")
            # load_yaml(name) of an argument left empty reads the directory (motoman's
            # joint_velocities_file:=): name the expression, not an include
            return XacroError(f"{where}: cannot read file '{inner.filename}' that "
                              f"'{expression[1]}' names: {inner.strerror}")
        import xacro

        # A deliberate error (xacro.fatal in the file, or xacro's own checks) says it all;
        # the "when evaluating expression" context only helps for Python errors.
        deliberate = isinstance(inner, xacro.XacroException) and inner.exc is None
        if isinstance(inner, RecursionError):
            return XacroError(f"{where}: xacro: macros or includes nest without end: a macro "
                              "that calls itself, or a file that includes itself")
        from xacro.substitution_args import SubstitutionException

        own = deliberate or isinstance(inner, ExpansionTooLarge) or (
            isinstance(inner, SubstitutionException) and str(exc).startswith("<class "))
        if not own and str(exc).startswith(f"{type(inner)}: "):  # a Python error in $(eval)
            return XacroError(f"{where}: xacro: a $(...) substitution failed: "
                              f"{type(inner).__name__}: {' '.join(str(inner).split())}")
        shown = inner if own else exc
        message = " ".join(str(shown).split()) or type(exc).__name__
        macros = getattr(inner, "macros", None) or [None]  # the innermost first
        body = getattr(macros[0], "body", None)
        if message.startswith(("Undefined parameters", "Invalid parameter")) and isinstance(
                body, xml.dom.minidom.Element) and body.getAttribute("name"):
            message = f"{message} of macro '{body.getAttribute('name')}'"
            if message.startswith("Invalid parameter"):
                params = body.getAttribute("params").split()
                message += (f" (its parameters: {', '.join(params)})" if params
                            else " (it takes no parameters)")
        elif message.endswith("when evaluating expression ''"):  # ${}: Python's parser text
            message = "an empty expression ${}: write what it should compute"
        elif "object has no attribute '_setitem'" in message:  # xacro's words, an internal slip
            message = ("a property with scope=\"parent\" at the top of the file, where there is "
                       "no parent scope (xacro stops on it): drop scope=\"parent\"")
        else:
            message += self._in_macros(where) + self._bare_definition(message)
        if not own and not str(inner).strip():  # "when evaluating expression '...'" alone
            reason = "out of memory" if isinstance(inner, MemoryError) else \
                type(inner).__name__
            message = f"{message}: {reason}"
        return XacroError(f"{where}: xacro: {message}")

    def _bare_definition(self, message: str) -> str:
        """What a bare directive written to define an undefined name says about it.

        `` (<property name="x"> at f.xacro:3:3 has no xacro: prefix ...)``; else nothing.
        """
        undefined = _UNDEFINED_RE.search(message)
        if undefined is None:
            return ""
        name = undefined[1] or undefined[2]
        for doc in self.docs:
            node = bare_definition(doc, name)
            if node is not None:
                ref = self.ref_of(node)
                at = f" at {ref.location()}" if ref is not None else ""
                return (f" (<{node.tagName} name=\"{node.getAttribute('name')}\">{at} has no "
                        f"xacro: prefix, which xacro requires since 1.14 and 2.0.8: it defines "
                        "nothing)")
        return ""

    def _in_macros(self, where: str) -> str:
        """`` (in macro 'wheel', called at r.urdf.xacro:4:3)``: the calls an error came through.

        The innermost call, and the calls around it out to the first written outside any
        macro (at most three); nothing where the error is at the call itself.
        """
        calls = [(name, self.refs[site].location() if site is not None else None)
                 for name, site in self.failed_calls if name]
        if not calls or calls[0][1] == where:
            return ""
        shown = [f"macro '{name}'" + (f", called at {site}" if site else "")
                 for name, site in calls[:3]]
        more = " ..." if len(calls) > 3 else ""
        return f" (in {', in '.join(shown)}{more})"

    def take_origins(self, doc: xml.dom.minidom.Document) -> list[SourceRef | None]:
        """Strip the position tags, returning them per element in document order."""
        origins: list[SourceRef | None] = []
        for element in doc.getElementsByTagName("*"):
            src = element.getAttribute(_SRC_ATTR)
            via = element.getAttribute(_VIA_ATTR)
            for attr in (_SRC_ATTR, _VIA_ATTR):
                if element.hasAttribute(attr):
                    element.removeAttribute(attr)
            if not src:
                origins.append(None)
                continue
            ref = self.refs[int(src)]
            if via:
                calls = tuple(self.refs[int(index)] for index in via.split(","))
                ref = SourceRef(ref.file, ref.line, ref.column, calls=calls)
            origins.append(ref)
        return origins


_UNDEFINED_RE = re.compile(r"name '([^']+)' is not defined|Undefined substitution argument "
                           r"(\S+)")


def _add_call(element: xml.dom.minidom.Element, call_site: int) -> None:
    """Record that the macro call at ``call_site`` produced ``element``.

    Calls nest: the call inside a macro's body records first, the call of that macro next,
    so the list runs from the innermost call out.
    """
    calls = element.getAttribute(_VIA_ATTR)
    element.setAttribute(_VIA_ATTR, f"{calls},{call_site}" if calls else str(call_site))


def _bounded_safe_load(error: type[Exception]) -> Callable[[Any], Any]:
    """``yaml.safe_load`` refusing a document whose aliases unfold past a million items.

    xacro's ``load_yaml`` of a 500-byte alias bomb built a 2.3-billion-character string in
    35 s and 4.3 GB when an expression printed it.
    """
    import yaml

    def safe_load(stream: Any) -> Any:
        try:  # SafeLoader: with the unit constructors xacro adds to it
            return bounded_document(yaml.SafeLoader(stream))
        except AliasBomb as exc:
            raise error(f"load_yaml: {exc}") from None

    return safe_load


class _PositionBuilder(expatbuilder.ExpatBuilderNS):
    """xacro's DOM builder (minidom, namespace-aware) that records element positions."""

    def __init__(self, tracer: _Tracer, filename: str) -> None:
        super().__init__()
        self._tracer = tracer
        self._filename = filename

    def start_element_handler(self, name: str, attributes: list[str]) -> None:
        parser = self._parser  # type: ignore[attr-defined]  # typeshed omits ExpatBuilder._parser
        line, column = parser.CurrentLineNumber, parser.CurrentColumnNumber + 1
        super().start_element_handler(name, attributes)
        if isinstance(self.curNode, xml.dom.minidom.Element):
            self._tracer.record(self.curNode, self._filename, line, column)
