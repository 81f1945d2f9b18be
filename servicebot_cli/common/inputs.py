"""Reading the user's input files: one policy, one-line errors.

Robot descriptions, scenarios, batch files, drive scripts and controller YAML files all fail
the same ways (missing, a directory, unreadable, too big, empty, not UTF-8: UTF-16, binary or
Latin-1); each failure becomes one line that names the file and says what to give instead.
``-`` means standard input where a command allows it. Text is decoded by
:mod:`~servicebot_cli.common.text_decoding`.
"""

from __future__ import annotations

import contextlib
import errno
import io
import os
import stat
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import IO, BinaryIO

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.common.text_decoding import NotUtf8, decode_utf8

STDIN = "-"


def display_path(path: Path) -> str:
    """``path`` relative to the working directory when inside it, else absolute.

    A real path, so editors and CI annotations can open what a message points at.
    """
    try:
        return str(path.resolve().relative_to(Path.cwd().resolve()))
    except ValueError:
        return str(path.resolve())


def as_typed(path: str) -> str:
    """``path`` relative to the working directory when it lies under it, else as it is.

    A file reached through ``$(find pkg)`` comes as an absolute path, the same file reached
    by a relative include as a relative one; shown the same way, a finding points at one
    file, and GitHub annotations (which want paths in the repository) attach to it.
    Symbolic links are not followed: the path stays the one the user's tools name. A ``..``
    is taken out (realsense's ``tests/../urdf/_d415.urdf.xacro`` is ``urdf/_d415.urdf.xacro``)
    where the shorter path is the same file: a symbolic link before it may lead elsewhere.
    """
    if ".." in Path(path).parts:
        shorter = os.path.normpath(path)
        try:
            if not os.path.samefile(path, shorter):
                return path
        except OSError:  # either is missing: what the text says is all there is
            return path
        path = shorter
    if not os.path.isabs(path):
        return path
    try:
        here = os.getcwd()
    except OSError:  # no working directory any more
        return path
    inside = here.rstrip(os.sep) + os.sep
    if not path.startswith(inside):
        return path
    return os.path.normpath(path[len(inside):])


@contextlib.contextmanager
def _reading(display: str, kind: str, error: type[ServicebotError]) -> Iterator[None]:
    """Turn the OS's reasons for not reading a file into one ``error`` line."""
    try:
        yield
    except FileNotFoundError:
        raise error(f"{display}: no such file; give {kind}") from None
    except IsADirectoryError:
        raise error(f"{display}: is a directory; give {kind}") from None
    except PermissionError:
        raise error(
            f"{display}: permission denied; make it readable (chmod +r) or run as its owner"
        ) from None
    except OSError as exc:
        raise error(f"{display}: cannot read: {exc.strerror or exc}") from None


def printable_name(name: str) -> str:
    """``name`` with the bytes a non-UTF-8 file name carries written as ``\xff``."""
    try:
        name.encode("utf-8")
    except UnicodeEncodeError:
        return name.encode("utf-8", "surrogateescape").decode("utf-8", "backslashreplace")
    return name


def not_a_file(path: str | os.PathLike[str]) -> str | None:
    """Why ``path`` is no file to read, as a sentence's end (``is a named pipe``).

    None: it is a regular file (symbolic links followed).
    """
    try:
        mode = os.stat(path).st_mode
    except OSError as exc:
        if exc.errno == errno.ELOOP:
            return "is a loop of symbolic links"
        if exc.errno == errno.ENAMETOOLONG:
            return "is a name too long for the file system"
        return "does not exist" if exc.errno in (errno.ENOENT, errno.ENOTDIR) \
            else f"cannot be read: {exc.strerror}"
    if stat.S_ISREG(mode):
        return None
    if stat.S_ISDIR(mode):
        return "is a directory"
    return "is a named pipe" if stat.S_ISFIFO(mode) else "is a device, not a file"


def read_input_bytes(path: Path, display: str, *, kind: str,
                     error: type[ServicebotError] = ServicebotError,
                     max_bytes: int | None = None) -> bytes:
    """The content of the user's file ``path``.

    Args:
        path: The file.
        display: How messages name it.
        kind: What the user should give instead, e.g. ``"a URDF or xacro file"``.
        error: The error class raised.
        max_bytes: Refuse larger files without reading them [bytes].

    Raises:
        error: Missing, a directory, unreadable, or over ``max_bytes``.
    """
    with _reading(display, kind, error), open_binary(path) as handle:
        mode = os.fstat(handle.fileno())  # a device or a pipe has no size: read to the limit
        if max_bytes is not None and stat.S_ISREG(mode.st_mode) and mode.st_size > max_bytes:
            raise _too_large(display, mode.st_size, max_bytes, error)
        data = handle.read() if max_bytes is None else handle.read(max_bytes + 1)
        if max_bytes is not None and len(data) > max_bytes:
            raise _too_large(display, None, max_bytes, error)
        if not stat.S_ISREG(mode.st_mode):
            _READ_ONCE[os.path.abspath(path)] = data
        return data


_READ_ONCE: dict[str, bytes] = {}
"""What a pipe or a device the user named gave, by absolute path: it gives it once."""


def read_again(path: str | os.PathLike[str], most: int | None = None) -> bytes | None:
    """What the user's pipe ``path`` gave when it was read (up to ``most`` bytes).

    None for anything else, which the caller reads as it is: ``<(cat robot.urdf.xacro)``
    read again is empty.
    """
    data = _READ_ONCE.get(os.path.abspath(path))
    return data if data is None or most is None else data[:most]


def open_binary(path: str | os.PathLike[str]) -> BinaryIO:
    """``path`` open for reading; a named pipe without a writer reads as empty.

    ``servicebot check <(xacro robot.xacro)`` reads a pipe its shell writes into; a named
    pipe that nothing writes into (left over on a disk) would block the run forever when
    opened. It is opened without waiting for a writer, then read as usual: with none, it
    ends at once.
    """
    # opened first, then asked what it is: a check of a thousand files opens each of them,
    # and a stat before each step took three system calls where one does
    descriptor = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
    try:
        if stat.S_ISDIR(os.fstat(descriptor).st_mode):
            raise IsADirectoryError(errno.EISDIR, os.strerror(errno.EISDIR), os.fspath(path))
        os.set_blocking(descriptor, True)  # a named pipe without a writer reads as empty
        return os.fdopen(descriptor, "rb")
    except BaseException:
        os.close(descriptor)
        raise


def _too_large(display: str, size: int | None, max_bytes: int,
               error: type[ServicebotError]) -> ServicebotError:
    what = f"file is {size / 1e6:.1f} MB" if size is not None else "holds more"
    return error(f"{display}: {what}, over the {max_bytes / 1e6:.0f} MB limit; is it the "
                 "right file?")


def read_input_text(path: str, *, kind: str, error: type[ServicebotError] = ServicebotError,
                    max_bytes: int | None = None, allow_empty: bool = True) -> str:
    """The UTF-8 text of the user's file ``path``, or of standard input for ``-``.

    Args:
        path: The file, or ``-``.
        kind: What the user should give instead, e.g. ``"a ros2_control controllers YAML"``.
        error: The error class raised.
        max_bytes: Refuse larger files without reading them [bytes].
        allow_empty: False to refuse a file that holds nothing but blanks.

    Raises:
        error: As :func:`read_input_bytes`, or the bytes are not UTF-8 text (UTF-16, binary,
            Latin-1...), or the file is empty and ``allow_empty`` is False.
    """
    display = "<stdin>" if path == STDIN else path
    if path == STDIN:
        data = sys.stdin.buffer.read(-1 if max_bytes is None else max_bytes + 1)
        if max_bytes is not None and len(data) > max_bytes:
            raise _too_large(display, None, max_bytes, error)
    else:
        data = read_input_bytes(Path(path), display, kind=kind, error=error, max_bytes=max_bytes)
    try:
        text = decode_utf8(data)
    except NotUtf8 as exc:
        raise error(not_text_message(display, exc, kind)) from None
    if not allow_empty and not text.strip():
        raise error(f"{display}: file is empty; give {kind}")
    return text


def not_text_message(display: str, problem: NotUtf8, kind: str) -> str:
    """One line for a file ``display`` that is not UTF-8 text: what it is and what to do."""
    if problem.binary:
        return f"{display}: {problem.what}, not text; give {kind}"
    if problem.line:
        return (f"{display}:{problem.line}:{problem.column}: not UTF-8 text ({problem.what}); "
                "save it as UTF-8")
    return f"{display}: {problem.what}, not UTF-8; save it as UTF-8"


def open_input_text(path: str, *, kind: str,
                    error: type[ServicebotError] = ServicebotError) -> IO[str]:
    """A text handle on the user's file ``path`` (``-``: standard input), for streaming.

    Bytes that are not UTF-8 read as U+FFFD, so a bad line is reported by the line's parser
    instead of stopping the stream. The caller closes the handle.

    Raises:
        error: Missing, a directory or unreadable.
    """
    if path == STDIN:
        return io.TextIOWrapper(sys.stdin.buffer, encoding="utf-8", errors="replace")
    with _reading(path, kind, error):
        if os.path.isdir(Path(path)):
            raise IsADirectoryError
        return open(path, encoding="utf-8", errors="replace", newline="")  # noqa: SIM115
