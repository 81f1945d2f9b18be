"""Result text for chunks of numbers, made beside the computing: a worker process.

Writing every float as its shortest round-trip text (``repr``) takes about half a large
``fk --configs`` run; CPython does it one number at a time and holds the GIL. So a batch of
more than one chunk hands its chunks' numbers to a child process
(:mod:`~servicebot_cli.batch.format_worker`, standard library only) and goes on reading and
computing; a thread takes the text back, in order, and writes it. The text is what
:func:`format_rows` makes here, byte for byte. Memory stays bounded: a pipe holds at most a
chunk or two.

If the child cannot start or dies, the chunks it did not answer are formatted here. If
writing fails in the thread (a closed pipe, a full disk), the error is raised in the caller's
thread at its next submit or drain, and nothing more is written.
"""

from __future__ import annotations

import collections
import struct
import subprocess
import sys
import threading
from collections.abc import Callable, Sequence
from types import TracebackType
from typing import IO

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]

_HEADER = struct.Struct("<II")
_LENGTH = struct.Struct("<Q")
_CHILD = "from servicebot_cli.batch.format_worker import main; main()"


def format_rows(template: str, lines: Sequence[int], values: FloatArray) -> str:
    """``template`` once per row: the line number, then the row's values (``%r``)."""
    table = values.reshape(len(lines), -1).tolist()
    flat: list[int | float] = []
    for line, row in zip(lines, table, strict=True):
        flat.append(line)
        flat.extend(row)
    return (template * len(lines)) % tuple(flat)


class Formatter:
    """Formats chunks in order and writes them: in a worker from the second chunk on.

    Use as a context manager: the block's end writes what is left.
    """

    def __init__(self, template: str, write: Callable[[str], None]) -> None:
        """Rows as ``template`` (``%d`` for the line, ``%r`` per value) go to ``write``."""
        self._template, self._write = template, write
        self._submitted = 0
        self._process: subprocess.Popen[bytes] | None = None
        self._reader: threading.Thread | None = None
        self._pending: collections.deque[tuple[Sequence[int], FloatArray]] = \
            collections.deque()
        self._done = threading.Condition()
        self._failed = False
        self._error: BaseException | None = None  # the reader thread's write failed

    def __enter__(self) -> Formatter:
        """The formatter."""
        return self

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 trace: TracebackType | None) -> None:
        """Write what is left (unless the block failed), and end the worker."""
        if kind is None:
            self.drain()
        self._stop()

    def submit(self, lines: Sequence[int], values: FloatArray) -> None:
        """Format rows ``lines`` (their input line numbers) of ``values`` (one row each)."""
        self._raise_error()
        self._submitted += 1
        if self._submitted == 2 and not self._failed:
            self._start()
        process = self._process
        if process is None or self._failed:
            self._write_left_here()  # chunks the worker did not answer come first
            self._write(format_rows(self._template, lines, values))
            return
        data = np.ascontiguousarray(values, dtype=np.float64)
        with self._done:
            self._pending.append((lines, data))
        frame = _HEADER.pack(len(lines), data.size // max(1, len(lines)))
        try:
            assert process.stdin is not None
            process.stdin.write(frame + np.asarray(lines, dtype="<i8").tobytes()
                                + data.astype("<f8", copy=False).tobytes())
        except OSError:  # the worker is gone: what it did not answer is formatted here
            self._fail()

    def drain(self) -> None:
        """Wait until every chunk submitted is written (before writing anything else)."""
        if self._process is not None and not self._failed:
            assert self._process.stdin is not None
            try:
                self._process.stdin.flush()
            except OSError:
                self._fail()
            with self._done:
                self._done.wait_for(lambda: not self._pending or self._failed)
        self._raise_error()
        if self._failed:
            self._write_left_here()

    def _start(self) -> None:
        try:
            self._process = subprocess.Popen([sys.executable, "-c", _CHILD],
                                             stdin=subprocess.PIPE, stdout=subprocess.PIPE)
        except OSError:
            self._failed = True
            return
        assert self._process.stdin is not None and self._process.stdout is not None
        encoded = self._template.encode()
        self._process.stdin.write(_LENGTH.pack(len(encoded)) + encoded)
        self._reader = threading.Thread(target=self._read, args=(self._process.stdout,),
                                        daemon=True, name="batch-formatter")
        self._reader.start()

    def _read(self, stream: IO[bytes]) -> None:
        """The reader thread: text back from the worker, written in order."""
        while True:
            prefix = stream.read(_LENGTH.size)
            if len(prefix) < _LENGTH.size:
                break
            size = _LENGTH.unpack(prefix)[0]
            text = stream.read(size)
            if len(text) < size:
                break
            try:
                self._write(text.decode())
            except BaseException as exc:  # noqa: BLE001 -- handed to the caller's thread
                with self._done:
                    self._error, self._failed = exc, True
                    self._done.notify_all()
                return
            with self._done:
                self._pending.popleft()
                self._done.notify_all()
        with self._done:
            if self._pending:
                self._failed = True
            self._done.notify_all()

    def _raise_error(self) -> None:
        """Raise here what made the reader thread stop writing, once; the worker is ended."""
        if self._error is not None:
            error, self._error = self._error, None
            self._pending.clear()  # nothing more is written after a failed write
            self._stop()
            raise error

    def _fail(self) -> None:
        with self._done:
            self._failed = True
            self._done.notify_all()

    def _write_left_here(self) -> None:
        if self._reader is not None:
            self._stop()
        while self._pending:
            lines, values = self._pending.popleft()
            self._write(format_rows(self._template, lines, values))

    def _stop(self) -> None:
        """End the worker: its stdin closed, it ends; killed when not all was answered."""
        process, self._process = self._process, None
        if process is None:
            return
        try:
            if process.stdin is not None:
                process.stdin.close()
        except OSError:
            pass
        if self._pending and process.poll() is None:
            process.kill()
        if self._reader is not None and self._reader is not threading.current_thread():
            self._reader.join()
        if process.stdout is not None:
            process.stdout.close()
        process.wait()
