"""Writing output files atomically: a reader sees the old file or the whole new one.

Data goes to a temporary file beside the target, then ``os.replace`` puts it in place.
An error or an interruption (Ctrl-C, SIGTERM turned into an exception) removes the
temporary file, so nothing half-written is ever left behind.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import IO, Any

from servicebot_cli.errors import ServicebotError


class OutputError(ServicebotError):
    """An output file cannot be written: missing directory, no permission, disk full."""


@contextlib.contextmanager
def atomic_output(
    path: str | os.PathLike[str], mode: str = "w", **open_kwargs: Any
) -> Iterator[IO[Any]]:
    """Open a temporary file beside ``path``; on success it replaces ``path``.

    Args:
        path: The file to create or replace.
        mode: ``"w"`` for text (UTF-8, Unix newlines) or ``"wb"`` for bytes.
        **open_kwargs: Passed to :func:`open`.

    Raises:
        OutputError: The directory is missing or not writable, or writing failed.
    """
    target = Path(path)
    directory = target.parent if str(target.parent) else Path(".")
    if target.is_dir():
        raise OutputError(f"{target}: is a directory; give a file name to write")
    if not directory.is_dir():
        raise OutputError(f"{target}: directory '{directory}' does not exist; create it first")
    try:
        fd, tmp_name = tempfile.mkstemp(dir=directory, prefix=f".{target.name}.", suffix=".tmp")
    except PermissionError:
        raise OutputError(f"{target}: permission denied writing in '{directory}'") from None
    except OSError as exc:
        raise OutputError(f"{target}: cannot write: {exc.strerror or exc}") from None
    if "b" not in mode:
        open_kwargs.setdefault("encoding", "utf-8")
        open_kwargs.setdefault("newline", "\n")
    try:
        with os.fdopen(fd, mode, **open_kwargs) as handle:
            yield handle
        os.chmod(tmp_name, 0o644 & ~_umask())
        os.replace(tmp_name, target)
    except OSError as exc:
        raise OutputError(f"{target}: cannot write: {exc.strerror or exc}") from None
    finally:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp_name)


def write_atomic(path: str | os.PathLike[str], content: str | bytes) -> None:
    """Write ``content`` to ``path`` atomically (see :func:`atomic_output`)."""
    with atomic_output(path, "wb" if isinstance(content, bytes) else "w") as handle:
        handle.write(content)


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
