"""The code Python 3.11's ``@dataclass`` compiles for servicebot's classes, kept between runs.

``@dataclass`` writes each method of a class (``__init__``, ``__repr__``, ``__eq__``, a frozen
class's ``__setattr__`` and ``__delattr__``) as Python text and compiles that text every time
the class is defined, in every process: Python 3.11 keeps nothing of it. Importing the
modules of ``servicebot simulate`` (89 dataclasses) took 91 ms, 37 of them compiling; with
the code kept, 54 ms.

:func:`install` wraps ``dataclasses._create_fn`` so that, for servicebot's own modules, the
code compiled from each text is kept in a file beside the module's bytecode (where Python keeps
the module's own, under its bytecode prefix, with its version tag) and read from there next
time. The text is the key: the same text compiled the same way gives the same code, so a
method is the one ``@dataclass`` would make (annotations included), and any other text is
compiled as usual. A file holds the texts its module used when last written, so a changed
class's old methods leave it. Nothing is written where Python writes no bytecode
(``PYTHONDONTWRITEBYTECODE``) or cannot (a read-only install); a file that cannot be read is
ignored. Other modules' dataclasses, and other Python versions, are left to ``dataclasses``
as it is. ``pip uninstall`` removes the bytecode it installed, not these files (as it leaves
numba's caches): a ``__pycache__`` directory of them can stay behind.
"""

from __future__ import annotations

import dataclasses
import marshal
import os
import sys
from collections.abc import Callable
from types import CodeType
from typing import Any

_PACKAGE = "servicebot_cli."
_SUFFIX = ".dataclass-code"
_CREATE_FN_ARGS = ("name", "args", "body", "globals", "locals", "return_type")
_kept: dict[str, dict[str, CodeType]] = {}  # module -> text -> code, as read or compiled
_codes: dict[str, dict[str, CodeType]] = {}  # the texts of each module used in this process
_unwritten: set[str] = set()  # modules with code compiled since their file was written


def install() -> None:
    """Keep the code of servicebot's dataclasses' methods, on the Python it was written for.

    Only on CPython 3.11, whose ``dataclasses._create_fn`` this reproduces; elsewhere (or if
    that function is not the one expected) nothing changes. Installing twice is harmless.
    """
    original = getattr(dataclasses, "_create_fn", None)
    if (sys.version_info[:2] != (3, 11) or sys.implementation.name != "cpython"
            or original is None or getattr(original, "_servicebot", False)):
        return
    code = getattr(original, "__code__", None)
    if code is None or code.co_varnames[:len(_CREATE_FN_ARGS)] != _CREATE_FN_ARGS:
        return
    process_class = getattr(dataclasses, "_process_class", None)
    if process_class is None:
        return
    dataclasses._create_fn = _wrapped(original)  # type: ignore[attr-defined]
    dataclasses._process_class = _writing(process_class)  # type: ignore[attr-defined]


def _writing(process_class: Callable[..., Any]) -> Callable[..., Any]:
    """``process_class``, then the code it compiled for a module of ours kept in its file."""

    def wrapped(cls: type, *args: Any, **kwargs: Any) -> Any:
        made = process_class(cls, *args, **kwargs)
        while _unwritten:
            module = _unwritten.pop()
            _write(module, _codes[module])
        return made

    return wrapped


def _wrapped(original: Callable[..., Any]) -> Callable[..., Any]:
    missing = dataclasses.MISSING

    def create_fn(name: str, args: list[str], body: list[str], *,
                  globals: dict[str, Any] | None = None,  # noqa: A002 -- dataclasses' names
                  locals: dict[str, Any] | None = None,  # noqa: A002
                  return_type: Any = missing) -> Any:
        module = (globals or {}).get("__name__", "")
        if not isinstance(module, str) or not module.startswith(_PACKAGE):
            return original(name, args, body, globals=globals, locals=locals,
                            return_type=return_type)
        # the text exactly as dataclasses._create_fn of Python 3.11 writes it
        if locals is None:
            locals = {}
        return_annotation = ""
        if return_type is not missing:
            locals["_return_type"] = return_type
            return_annotation = "->_return_type"
        joined_args = ",".join(args)
        joined_body = "\n".join(f"  {b}" for b in body)
        text = f" def {name}({joined_args}){return_annotation}:\n{joined_body}"
        text = f"def __create_fn__({', '.join(locals.keys())}):\n{text}\n return {name}"
        namespace: dict[str, Any] = {}
        exec(_code(module, text), globals, namespace)  # noqa: S102 -- as dataclasses does
        return namespace["__create_fn__"](**locals)

    create_fn._servicebot = True  # type: ignore[attr-defined]
    return create_fn


def _code(module: str, text: str) -> CodeType:
    """The code of ``text`` (a ``__create_fn__`` of ``module``): kept, else compiled now.

    Compiled as ``exec(text)`` in ``dataclasses`` compiles it: with no ``__future__``
    import of this module's (its annotations are objects, not strings).
    """
    kept = _kept.get(module)
    if kept is None:
        kept = _kept[module] = _read(module)
    used = _codes.setdefault(module, {})
    code = kept.get(text)
    if code is None:
        code = kept[text] = compile(text, "<string>", "exec", dont_inherit=True)
        _unwritten.add(module)  # written once its class is made
    used[text] = code
    return code


def cache_path(module: str) -> str | None:
    """Where the code of ``module``'s dataclasses is kept; None for a module with no file."""
    found = sys.modules.get(module)
    source = getattr(found, "__file__", None)
    if not source or not source.endswith(".py"):
        return None
    from importlib.util import cache_from_source

    try:
        return cache_from_source(source).removesuffix(".pyc") + _SUFFIX
    except (NotImplementedError, ValueError):  # no cache tag: no bytecode kept either
        return None


def _read(module: str) -> dict[str, CodeType]:
    path = cache_path(module)
    if path is None:
        return {}
    from importlib.util import MAGIC_NUMBER

    try:
        with open(path, "rb") as stream:
            data = stream.read()
        if not data.startswith(MAGIC_NUMBER):
            return {}
        kept = marshal.loads(memoryview(data)[len(MAGIC_NUMBER):])
    except (OSError, EOFError, ValueError, TypeError):
        return {}
    if not isinstance(kept, dict):
        return {}
    return {text: code for text, code in kept.items()
            if isinstance(text, str) and isinstance(code, CodeType)}


def _write(module: str, codes: dict[str, CodeType]) -> None:
    """Keep ``codes`` for next time, whole or not at all (a new file moved in place).

    They are the texts this process used: those of classes changed since are left out, so
    the file holds the module's classes as they are (all of them once each is used again).
    """
    path = cache_path(module) if not sys.dont_write_bytecode else None
    if path is None:
        return
    from importlib.util import MAGIC_NUMBER

    partial = f"{path}.{os.getpid()}"
    try:
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(partial, "wb") as stream:
            stream.write(MAGIC_NUMBER + marshal.dumps(codes))
        os.replace(partial, path)
    except OSError:  # a read-only install, a full disk: compiled again next time
        try:
            os.unlink(partial)
        except OSError:
            pass
