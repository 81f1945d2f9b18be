"""What native code (urdfdom inside Pinocchio) writes to file descriptor 2, kept off it.

urdfdom prints ``Error: Mesh scale was specified, but could not be parsed`` through
console_bridge straight to fd 2, and carries on without the shape; Python's ``sys.stderr``
never sees it. The lines are collected so the caller can drop them or report them.

``check`` builds a model of every file it is given, so the sink is cheap: an anonymous
in-memory file on Linux (``memfd_create``, 5 µs), where a named temporary file costs 0.2 ms
(a quarter of a second over a thousand files).
"""

from __future__ import annotations

import contextlib
import os
import sys
import tempfile
from collections.abc import Iterator
from typing import IO


@contextlib.contextmanager
def captured_fd2() -> Iterator[list[str]]:
    """Within the block, fd 2 goes into the yielded list of lines (filled when it ends)."""
    lines: list[str] = []
    sys.stderr.flush()
    with _sink() as sink:
        saved = os.dup(2)
        os.dup2(sink.fileno(), 2)
        try:
            yield lines
        finally:
            os.dup2(saved, 2)
            os.close(saved)
            sink.seek(0)
            lines.extend(sink.read().decode("utf-8", "replace").splitlines())


def _sink() -> IO[bytes]:
    """A new, empty file that nothing else can see, read and written in binary."""
    try:
        descriptor = os.memfd_create("servicebot-stderr", os.MFD_CLOEXEC)
    except (AttributeError, OSError):  # not Linux, or a kernel or sandbox without it
        return tempfile.TemporaryFile()
    return os.fdopen(descriptor, "w+b")
