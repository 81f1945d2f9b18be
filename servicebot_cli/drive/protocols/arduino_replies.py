"""ROSArduinoBridge reply lines: split, classified strictly, and matched to their commands.

The text protocol has no checksum and no sequence numbers, and a noisy link flips, drops and
inserts bytes. So every line is parsed defensively (a garbled line is a counted link error,
never an exception), and replies are matched to commands by what they say and in order:

- ``OK`` answers an ``m``; a line of two integers answers an ``e``.
- A reply that matches a later command than the oldest one waiting means the replies in
  between were lost: they are dropped (and counted), so one lost line never shifts every
  following reply by one.
- ``Invalid Command`` answers the oldest command waiting (the firmware refused it).
"""

from __future__ import annotations

import re
from collections import deque
from dataclasses import dataclass
from typing import Literal, TypeAlias

MAX_LINE = 64  # longer lines are garbage: no reply of the protocol is that long
INT32 = 2**31
_COUNTS = re.compile(r"(-?[0-9]{1,10}) (-?[0-9]{1,10})")
_BAUD = re.compile(r"[0-9]{2,7}")
_EOL = re.compile(rb"[\r\n]")
REFUSAL = "Invalid Command"

Expected: TypeAlias = Literal["ok", "counts"]


@dataclass(frozen=True)
class Line:
    """One reply line, classified.

    Attributes:
        kind: ``ok``, ``counts`` (two encoder counts), ``baud`` (the handshake's answer),
            ``refused`` (``Invalid Command``) or ``garbled`` (anything else).
        values: The integers it carries (encoder counts or the baud rate).
        text: The line as received, for messages.
    """

    kind: Literal["ok", "counts", "baud", "refused", "garbled"]
    values: tuple[int, ...] = ()
    text: str = ""


def classify(raw: bytes) -> Line:
    """What one line (without its line ending) says; never raises."""
    text = raw.decode("ascii", errors="replace").strip(" ")
    if text == "OK":
        return Line("ok", text=text)
    if text == REFUSAL:
        return Line("refused", text=text)
    if (counts := _COUNTS.fullmatch(text)) is not None:
        values = (int(counts[1]), int(counts[2]))
        if all(-INT32 <= v < INT32 for v in values):
            return Line("counts", values, text)
    if _BAUD.fullmatch(text) is not None:
        return Line("baud", (int(text),), text)
    return Line("garbled", text=text)


class LineSplitter:
    """Splits received bytes into lines at CR or LF; drops overlong lines and counts them.

    Either end-of-line byte ends a line (the firmware sends both), so a lost CR or LF never
    glues two replies together; empty lines are skipped.
    """

    def __init__(self) -> None:
        self._buffer = bytearray()
        self.garbage = 0

    def feed(self, data: bytes) -> list[bytes]:
        """Complete, non-empty lines in ``data``, without their line endings."""
        *complete, tail = _EOL.split(bytes(self._buffer + data))
        lines = []
        for raw in complete:
            if len(raw) > MAX_LINE:
                self.garbage += 1
            elif raw:
                lines.append(raw)
        self._buffer = bytearray(tail)
        if len(self._buffer) > MAX_LINE:
            self.garbage += 1
            self._buffer.clear()
        return lines


class ReplyMatcher:
    """Which command each reply answers, re-aligned by content after a lost or extra line.

    Attributes:
        lost: Replies that never came (skipped over by a later reply).
        unmatched: Replies no waiting command asked for.
    """

    def __init__(self, depth: int = 64) -> None:
        self._waiting: deque[tuple[int, Expected]] = deque(maxlen=depth)
        self.lost = 0
        self.unmatched = 0

    def expect(self, token: int, *replies: Expected) -> None:
        """Command ``token`` was sent and will be answered by ``replies``, in order."""
        for reply in replies:
            self._waiting.append((token, reply))

    def match(self, kind: Expected) -> int | None:
        """The token of the oldest command waiting for a ``kind`` reply; None when none is.

        Replies of the other kind waiting before it are dropped as lost.
        """
        if not any(waiting == kind for _, waiting in self._waiting):
            self.unmatched += 1
            return None
        while True:
            token, waiting = self._waiting.popleft()
            if waiting == kind:
                return token
            self.lost += 1

    def refuse(self) -> tuple[int, Expected] | None:
        """The command an ``Invalid Command`` answers: the oldest one waiting."""
        return self._waiting.popleft() if self._waiting else None

    def clear(self) -> None:
        """Nothing is waiting any more (the port was reopened)."""
        self._waiting.clear()
