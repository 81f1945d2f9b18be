"""A noisy serial line between two pseudo-terminals: it flips, drops and inserts bytes.

One side opens a device (the emulator's pty, or the C++ firmware's) as a host would; the
other side is a new pty that ``servicebot drive`` opens. Two threads copy bytes across,
each byte independently dropped, bit-flipped or followed by a random byte with the given
probabilities (seeded), both ways. With no noise it is a clean line that can tap what the
host sends (``on_host``: the bytes, as they cross).
"""

from __future__ import annotations

import os
import pty
import random
import select
import termios
import threading
import tty
from collections.abc import Callable
from dataclasses import dataclass, field


@dataclass
class Noise:
    """Per-byte probabilities of each fault, and what was done."""

    flip: float = 0.0
    drop: float = 0.0
    insert: float = 0.0
    seed: int = 0
    counts: dict[str, int] = field(default_factory=lambda: {"flip": 0, "drop": 0, "insert": 0})

    def __post_init__(self) -> None:
        self.rng = random.Random(self.seed)

    def apply(self, data: bytes) -> bytes:
        out = bytearray()
        for byte in data:
            if self.rng.random() < self.drop:
                self.counts["drop"] += 1
                continue
            if self.rng.random() < self.flip:
                byte ^= 1 << self.rng.randrange(8)
                self.counts["flip"] += 1
            out.append(byte)
            if self.rng.random() < self.insert:
                out.append(self.rng.randrange(256))
                self.counts["insert"] += 1
        return bytes(out)


class Relay:
    """Copies bytes between ``device`` and a new pty (:attr:`path`), through ``noise``."""

    def __init__(self, device: str, noise: Noise,
                 on_host: Callable[[bytes], None] | None = None) -> None:
        self.noise, self.on_host = noise, on_host
        self.device = os.open(device, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
        tty.setraw(self.device)
        termios.tcflush(self.device, termios.TCIOFLUSH)
        self.master, self.slave = pty.openpty()
        tty.setraw(self.slave)
        os.set_blocking(self.master, False)
        self.path = os.ttyname(self.slave)
        self._running = True
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()

    def _serve(self) -> None:
        while self._running:
            ready, _, _ = select.select([self.device, self.master], [], [], 0.05)
            for fd in ready:
                other = self.master if fd == self.device else self.device
                try:
                    data = os.read(fd, 1024)
                except (BlockingIOError, OSError):
                    continue
                if fd == self.master and self.on_host is not None:
                    self.on_host(data)
                try:
                    os.write(other, self.noise.apply(data))
                except (BlockingIOError, OSError):
                    pass  # nobody reads that side: a UART drops the bytes too

    def close(self) -> None:
        self._running = False
        self._thread.join()
        for fd in (self.device, self.master, self.slave):
            os.close(fd)
