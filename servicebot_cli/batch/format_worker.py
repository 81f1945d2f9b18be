"""The child side of :mod:`servicebot_cli.batch.formatting`: numbers in, text out.

Run as ``python -c "from servicebot_cli.batch.format_worker import main; main()"``; it
imports nothing but the standard library. On stdin: a template (``%``-format of one row,
length-prefixed UTF-8), then frames of ``rows, width`` (two little-endian uint32), ``rows``
int64 line numbers and ``rows * width`` float64 values. For each frame it writes back,
length-prefixed, ``(template * rows) % (line, values..., line, values...)``: each number
as ``%d``/``%r`` writes it, so the text is what the parent would have made itself. It ends
at the end of stdin. Ctrl-C and hang-ups are the parent's to handle: the child ignores them
and ends when the parent closes the pipe.
"""

from __future__ import annotations

import array
import signal
import struct
import sys
from typing import BinaryIO

_HEADER = struct.Struct("<II")
_LENGTH = struct.Struct("<Q")


def read_exact(stream: BinaryIO, size: int) -> bytes | None:
    """``size`` bytes from ``stream``; None at its end."""
    data = stream.read(size)
    if len(data) < size:
        return None
    return data


def format_frame(template: str, lines: array.array[int], values: list[float],
                 width: int) -> str:
    """``template`` once per row, filled with the row's line number and values."""
    flat: list[int | float] = []
    for k, line in enumerate(lines):
        flat.append(line)
        flat.extend(values[k * width:(k + 1) * width])
    return (template * len(lines)) % tuple(flat)


def serve(source: BinaryIO, sink: BinaryIO) -> None:
    """Answer frames from ``source`` on ``sink`` until ``source`` ends."""
    prefix = read_exact(source, _LENGTH.size)
    if prefix is None:
        return
    raw = read_exact(source, _LENGTH.unpack(prefix)[0])
    if raw is None:
        return
    template = raw.decode()
    while (header := read_exact(source, _HEADER.size)) is not None:
        rows, width = _HEADER.unpack(header)
        lines, values = array.array("q"), array.array("d")
        body = read_exact(source, rows * 8 * (1 + width))
        if body is None:
            return
        lines.frombytes(body[:rows * 8])
        values.frombytes(body[rows * 8:])
        text = format_frame(template, lines, values.tolist(), width).encode()
        sink.write(_LENGTH.pack(len(text)) + text)
        sink.flush()


def main() -> None:
    """Serve stdin to stdout; quietly end when the parent goes."""
    for name in ("SIGINT", "SIGHUP", "SIGQUIT"):
        if hasattr(signal, name):
            signal.signal(getattr(signal, name), signal.SIG_IGN)
    try:
        serve(sys.stdin.buffer, sys.stdout.buffer)
    except (BrokenPipeError, ConnectionResetError):
        pass
