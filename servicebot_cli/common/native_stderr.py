"""What native code (urdfdom inside Pinocchio) writes to file descriptor 2, kept off it.

urdfdom prints ``Error: Mesh scale was specified, but could not be parsed`` through
console_bridge straight to fd 2, and carries on without the shape; Python's ``sys.stderr``
never sees it. The lines are collected so the caller can drop them or report them.
"""

from __future__ import annotations

import contextlib
import os
import sys
import tempfile
from collections.abc import Iterator


@contextlib.contextmanager
def captured_fd2() -> Iterator[list[str]]:
    """Within the block, fd 2 goes into the yielded list of lines (filled when it ends)."""
    lines: list[str] = []
    sys.stderr.flush()
    with tempfile.TemporaryFile() as sink:
        saved = os.dup(2)
        os.dup2(sink.fileno(), 2)
        try:
            yield lines
        finally:
            os.dup2(saved, 2)
            os.close(saved)
            sink.seek(0)
            lines.extend(sink.read().decode("utf-8", "replace").splitlines())
