"""Writing output files atomically: a reader sees the old file or the whole new one.

Data goes to a temporary file beside the target, then ``os.replace`` puts it in place.
An error or an interruption (Ctrl-C, SIGTERM turned into an exception) removes the
temporary file, so nothing half-written is ever left behind.

Targets that are not plain files are written in place, opened for writing as a shell's
``>`` opens them, because renaming a file over them would replace the thing itself (as
root, ``/dev/null`` or the ``/dev/stdout`` link would become a regular file): a device, a
FIFO or a socket; a path under ``/dev`` or ``/proc/*/fd``, or a symbolic link whose chain
passes through one (``--output /dev/stdout > out.txt``: the link resolves to the regular
file ``out.txt``, which the shell holds open, and its output lands there); and a symbolic
link to something that is not a regular file at the time (a device, a FIFO, nothing yet).

A symbolic link to a regular file (through ordinary links only) is followed: the file it
resolves to is replaced atomically, beside itself, and the link stays. ``xacro -o``,
``cp`` and ``>`` all write through such a link into the file it names; replacing the link
with a regular file of its own, as this module once did, left the linked file stale and
broke the link (a report kept in a shared directory, a dotfiles-style layout).

A file replaced keeps its mode and owner; another hard link to it keeps the old content.
"""

from __future__ import annotations

import contextlib
import errno
import os
import re
import shutil
import signal
import stat
import tempfile
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import IO, Any

from servicebot_cli.common.errors import NO_ROOM, ServicebotError, no_room
from servicebot_cli.common.signals import ENDING_SIGNALS, SignalsHeld, raise_lost


class OutputError(ServicebotError):
    """An output file cannot be written: missing directory, no permission, disk full."""


@contextlib.contextmanager
def atomic_output(
    path: str | os.PathLike[str], mode: str = "w", *, make_parents: bool = False,
    **open_kwargs: Any
) -> Iterator[IO[Any]]:
    """Open a temporary file beside ``path``; on success it replaces ``path``.

    Args:
        path: The file to create or replace.
        mode: ``"w"`` for text (UTF-8, Unix newlines) or ``"wb"`` for bytes.
        make_parents: Create missing directories above ``path`` first (as ``xacro -o``).
        **open_kwargs: Passed to :func:`open`.

    Raises:
        OutputError: The directory is missing or not writable, or writing failed.
    """
    target = Path(path)
    if os.path.isdir(target):
        raise OutputError(f"{target}: is a directory; give a file name to write")
    if _written_in_place(target):
        # A device, FIFO or socket (/dev/null, /dev/stdout, a named pipe), or a link to one:
        # written in place as a shell's ``>`` would. Renaming a file over it would replace
        # the device, or the link, itself.
        with _in_place(target, mode, open_kwargs) as handle:
            yield handle
        return
    if os.path.islink(target):
        target = Path(os.path.realpath(target))  # a regular file: replaced, the link kept
    if make_parents and str(target.parent):
        try:
            target.parent.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise _cannot_write(target, target.parent, exc) from None
    directory = _parent(target)
    if "b" not in mode:
        open_kwargs.setdefault("encoding", "utf-8")
        open_kwargs.setdefault("newline", "\n")
    held = _hold_signals()  # no signal between creating the file and owning its clean-up
    try:
        fd, tmp_name = tempfile.mkstemp(dir=directory, prefix=f".{target.name}.", suffix=".tmp")
    except OSError as exc:
        _release(held)
        raise _cannot_write(target, directory, exc) from None
    try:
        _release(held)  # a signal that came meanwhile raises here, inside the try
        with os.fdopen(fd, mode, **open_kwargs) as handle:
            yield handle
        raise_lost()  # a signal that numpy swallowed still keeps the file out
        _take_mode(tmp_name, target)
        os.replace(tmp_name, target)
    except OSError as exc:
        raise _cannot_write(target, directory, exc) from None
    finally:
        _remove(tmp_name)


def _take_mode(tmp_name: str, target: Path) -> None:
    """Give the new file the mode and owner of the one it replaces.

    As ``>`` and ``xacro -o`` keep them: a private 0600 report stays private. A new file
    gets 0644 under the umask. A hard link to the old file keeps the old content: the file
    is replaced, not rewritten.
    """
    try:
        old = os.stat(target)
    except OSError:
        os.chmod(tmp_name, 0o644 & ~_umask())
        return
    if (old.st_uid, old.st_gid) != (os.getuid(), os.getgid()):  # first: chown clears SUID
        try:
            os.chown(tmp_name, old.st_uid, old.st_gid)  # root only
        except OSError:
            with contextlib.suppress(OSError):  # a group one belongs to, at least
                os.chown(tmp_name, -1, old.st_gid)
    os.chmod(tmp_name, stat.S_IMODE(old.st_mode))


_FD_DIR = re.compile(r"^/proc/[^/]+/(?:task/[^/]+/)?fd(?:/|$)")
_MAX_HOPS = 40  # as the kernel's limit of links followed in one lookup


def _written_in_place(target: Path) -> bool:
    """Whether ``target`` is to be opened and written as it is, not replaced (module doc)."""
    if any(_special(hop) for hop in _link_chain(target)):
        return True
    if os.path.islink(target):
        return not os.path.isfile(target)  # to a device, a FIFO, nothing yet (or a loop)
    return os.path.exists(target) and not os.path.isfile(target)


def _link_chain(target: Path) -> list[str]:
    """``target`` and each path its symbolic links lead to, in order, absolute.

    Each hop is also given with its directory resolved, so that a link reached through a
    linked directory (``/dev/fd/1``, ``x/fds/1`` with ``fds -> /proc/self/fd``) is seen for
    where it is.
    """
    hops: list[str] = []
    current = os.path.abspath(target)
    for _ in range(_MAX_HOPS):
        hops += [current, os.path.join(os.path.realpath(os.path.dirname(current)),
                                       os.path.basename(current))]
        try:
            link = os.readlink(current)
        except OSError:
            break  # not a link (or nothing there): the chain ends
        current = os.path.normpath(os.path.join(os.path.dirname(current), link))
    return hops


def _special(path: str) -> bool:
    """A path under ``/dev`` or a ``/proc/*/fd`` directory: a device or an open file's link."""
    return path == "/dev" or path.startswith("/dev/") or _FD_DIR.match(path) is not None


@contextlib.contextmanager
def _in_place(target: Path, mode: str, open_kwargs: dict[str, Any]) -> Iterator[IO[Any]]:
    """``target``, a file that is not a regular one, opened for writing as it is."""
    if "b" not in mode:
        open_kwargs.setdefault("encoding", "utf-8")
        open_kwargs.setdefault("newline", "\n")
    try:
        with open(target, mode, **open_kwargs) as handle:
            yield handle
    except OSError as exc:
        raise _cannot_write(target, target.parent, exc) from None


@contextlib.contextmanager
def atomic_directory(path: str | os.PathLike[str]) -> Iterator[Path]:
    """A temporary directory beside ``path``, renamed to ``path`` when the block succeeds.

    For outputs made of several files (a rosbag2 directory): readers never see a partial one.

    Raises:
        OutputError: ``path`` exists, its parent is missing or not writable, or writing failed.
    """
    target = Path(path)
    if os.path.exists(target):
        raise OutputError(f"{target}: already exists; remove it or give another path")
    parent = _parent(target)
    held = _hold_signals()
    try:
        temporary = Path(tempfile.mkdtemp(dir=parent, prefix=f".{target.name}.", suffix=".tmp"))
    except OSError as exc:
        _release(held)
        raise _cannot_write(target, parent, exc) from None
    try:
        _release(held)
        yield temporary
        raise_lost()
        os.chmod(temporary, 0o755 & ~_umask())
        os.rename(temporary, target)
    except OSError as exc:
        raise OutputError(f"{target}: cannot write: {exc.strerror or exc}") from None
    finally:
        _remove(str(temporary))


def _remove(temporary: str) -> None:
    """Remove a temporary file or directory (already gone: nothing to do), signals held.

    A signal raised in the middle of a clean-up would leave the temporary behind; held, it
    is raised once the temporary is gone.
    """
    held = _hold_signals()
    try:
        if os.path.isdir(temporary):
            shutil.rmtree(temporary, ignore_errors=True)
        else:
            with contextlib.suppress(FileNotFoundError):
                os.unlink(temporary)
    finally:
        _release(held)


_DEFERRED = {signal.SIGINT, *ENDING_SIGNALS}  # Ctrl-C and the signals cli.py turns into errors


Held = tuple[SignalsHeld, "set[int | signal.Signals] | None"]


def _hold_signals() -> Held:
    """Hold back the signals that end a run; what :func:`_release` needs to let them through.

    The handlers ``cli.py`` installs wait for the hold (:class:`SignalsHeld`), whichever
    thread the kernel delivers a signal to; for code run without them (a library caller),
    the main thread's signal mask holds them back too.
    """
    mask = None
    if threading.current_thread() is threading.main_thread():
        mask = signal.pthread_sigmask(signal.SIG_BLOCK, _DEFERRED)
    return SignalsHeld(), mask


def _release(held: Held) -> None:
    """Let held signals through: one that came meanwhile raises here."""
    hold, mask = held
    if mask is not None:
        signal.pthread_sigmask(signal.SIG_SETMASK, mask)
    hold.release()


def _parent(target: Path) -> Path:
    directory = target.parent if str(target.parent) else Path(".")
    if not os.path.isdir(directory):
        raise OutputError(f"{target}: directory '{directory}' does not exist; create it first")
    return directory


def read_only_file_system(directory: str | os.PathLike[str]) -> bool:
    """Whether ``directory`` is on a file system mounted read-only (EROFS, not permissions)."""
    try:
        return bool(os.statvfs(directory).f_flag & os.ST_RDONLY)
    except (OSError, AttributeError):  # pragma: no cover - not POSIX
        return False


def _cannot_write(target: Path, directory: Path, exc: OSError) -> OutputError:
    if exc.errno == errno.EROFS or (isinstance(exc, PermissionError)
                                    and read_only_file_system(directory)):
        return OutputError(f"{target}: '{directory}' is on a read-only file system; write "
                           "somewhere else")
    if isinstance(exc, PermissionError):
        return OutputError(f"{target}: permission denied writing in '{directory}'")
    if exc.errno in NO_ROOM:
        return OutputError(no_room(target, exc))
    return OutputError(f"{target}: cannot write: {exc.strerror or exc}")


def write_atomic(path: str | os.PathLike[str], content: str | bytes, *,
                 make_parents: bool = False) -> None:
    """Write ``content`` to ``path`` atomically (see :func:`atomic_output`)."""
    with atomic_output(path, "wb" if isinstance(content, bytes) else "w",
                       make_parents=make_parents) as handle:
        handle.write(content)


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
