"""What a library says on its own (a log record, a Python warning), kept off the terminal.

trimesh logs ``unable to load bumpmap`` with a whole traceback when a COLLADA file names a
texture image that is not there (urdf_tutorial's 07-physics robot), and numpy warns on
overflowing values. Neither is servicebot's voice: :func:`captured` collects them as short
lines for the caller to report as one warning each, or to ignore.
"""

from __future__ import annotations

import contextlib
import logging
import warnings
from collections.abc import Iterator

LIBRARIES = ("trimesh", "pycollada", "collada", "PIL")
"""Loggers of the mesh-reading libraries."""


class _Collector(logging.Handler):
    def __init__(self, lines: list[str]) -> None:
        super().__init__(logging.WARNING)
        self.lines = lines

    def emit(self, record: logging.LogRecord) -> None:
        message = record.getMessage()
        if record.exc_info and record.exc_info[1] is not None:
            error = record.exc_info[1]
            message = f"{message}: {type(error).__name__}: {error}"
        self.lines.append(" ".join(message.split()))


@contextlib.contextmanager
def captured(names: tuple[str, ...] = LIBRARIES) -> Iterator[list[str]]:
    """Within the block, the named loggers and Python warnings go into the yielded list.

    Each entry is one line: the message, and the exception it carried (without traceback).
    """
    lines: list[str] = []
    handler = _Collector(lines)
    loggers = [logging.getLogger(name) for name in names]
    saved = [(logger.propagate, logger.handlers[:]) for logger in loggers]
    for logger in loggers:
        logger.propagate = False
        logger.handlers = [handler]
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            yield lines
        lines.extend(" ".join(str(w.message).split()) for w in caught)
    finally:
        for logger, (propagate, handlers) in zip(loggers, saved, strict=True):
            logger.propagate = propagate
            logger.handlers = handlers
