"""The wire between host and firmware, as the emulator models it: baud-rate pacing and faults.

A UART sends one byte every ``10 / baud`` seconds (start bit, 8 data bits, stop bit), so at
9600 baud the wire carries 960 bytes a second each way. :class:`PacedQueue` releases bytes
no faster than that; :class:`FaultInjector` drops and corrupts bytes. Pure: time and the
random generator are passed in.
"""

from __future__ import annotations

import math
import random
from collections import deque
from dataclasses import dataclass

BITS_PER_BYTE = 10  # 8N1: start + 8 data + stop


def byte_time_s(baud: int) -> float:
    """Time one byte takes on the wire [s]."""
    return BITS_PER_BYTE / baud


class PacedQueue:
    """Bytes waiting for the wire; each leaves ``byte_time_s`` after the previous one.

    With ``byte_time_s == 0`` bytes leave as soon as they are ready.
    """

    def __init__(self, byte_time_s: float = 0.0) -> None:
        self.byte_time_s = byte_time_s
        self._queue: deque[tuple[float, bytearray]] = deque()
        self._wire_free_s = -math.inf

    def push(self, data: bytes, ready_s: float) -> None:
        """Queue ``data``, which may not leave before ``ready_s``."""
        if data:
            self._queue.append((ready_s, bytearray(data)))

    def pop(self, now_s: float) -> bytes:
        """The bytes that have gone over the wire by ``now_s``."""
        out = bytearray()
        while self._queue:
            ready_s, chunk = self._queue[0]
            if self.byte_time_s <= 0.0:
                if ready_s > now_s:
                    break
                out += chunk
                self._queue.popleft()
                continue
            start_s = max(ready_s, self._wire_free_s)
            count = min(len(chunk), math.floor((now_s - start_s) / self.byte_time_s))
            if count <= 0:
                break
            out += chunk[:count]
            del chunk[:count]
            self._wire_free_s = start_s + count * self.byte_time_s
            if chunk:
                break
            self._queue.popleft()
        return bytes(out)

    def next_due_s(self) -> float | None:
        """When the next byte will have gone over the wire, or None when empty."""
        if not self._queue:
            return None
        ready_s = self._queue[0][0]
        if self.byte_time_s <= 0.0:
            return ready_s
        return max(ready_s, self._wire_free_s) + self.byte_time_s

    def __len__(self) -> int:
        return sum(len(chunk) for _, chunk in self._queue)


@dataclass(frozen=True)
class Faults:
    """Faults the emulator injects.

    Attributes:
        drop: Probability that a byte is lost, each way.
        corrupt: Probability that a byte has one bit flipped, each way.
        latency_s: Extra delay before each reply leaves [s].
        die_after_s: Exit (the port disappears) this long after start [s].
        mute_after_s: Stop answering and reading, port still open, after this long [s].
        stall_after_s: The wheels stop turning this long after start, commands still
            accepted and answered (an encoder cable pulled, motor power off, a wheel
            blocked): the encoders stop counting [s].
    """

    drop: float = 0.0
    corrupt: float = 0.0
    latency_s: float = 0.0
    die_after_s: float | None = None
    mute_after_s: float | None = None
    stall_after_s: float | None = None


@dataclass
class FaultInjector:
    """Drops and corrupts bytes with the probabilities of ``faults``."""

    faults: Faults
    rng: random.Random
    dropped: int = 0
    corrupted: int = 0

    def apply(self, data: bytes) -> bytes:
        """``data`` after the line's faults."""
        if not (self.faults.drop or self.faults.corrupt):
            return data
        out = bytearray()
        for byte in data:
            if self.rng.random() < self.faults.drop:
                self.dropped += 1
                continue
            if self.rng.random() < self.faults.corrupt:
                byte ^= 1 << self.rng.randrange(8)
                self.corrupted += 1
            out.append(byte)
        return bytes(out)
