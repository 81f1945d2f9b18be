"""What comes back from the firmware: replies matched to what was sent, and what they say.

The inbox reads whatever the port has, turns it into protocol events, and keeps the run's
picture of the firmware: who it is (the hello), its last reading, how many replies came, the
round trips of acknowledged commands, and how far the encoders say each wheel turned. A reply
to a command this run never sent (left over from an earlier run) is ignored.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable

from servicebot_cli.drive.protocols.events import Ack, Event, Hello, Reading, Refused
from servicebot_cli.drive.session.commander import HostLink
from servicebot_cli.drive.session.contracts import FirmwareRefuses
from servicebot_cli.drive.transport import Port

REFUSALS_TO_FAIL = 5  # refusals in a row, nothing accepted between: the firmware cannot
_SENT_KEPT = 256  # commands remembered for matching replies


class Inbox:
    """Replies from the firmware, matched to the commands sent.

    Args:
        link: The protocol adapter that turns bytes into events.
        wheel_count: How many wheels the readings report.
        where: The port and baud, for messages.
        now_s: The time the run starts [s].
        log: Where event lines go (the first refusal, new fault flags).
        on_reading: Called with ``(now_s, reading)`` for each telemetry reading.
    """

    def __init__(self, link: HostLink, wheel_count: int, where: str, now_s: float, *,
                 log: Callable[[str], None],
                 on_reading: Callable[[float, Reading], None]) -> None:
        self.link, self.where, self.log, self.on_reading = link, where, log, on_reading
        self.hello: Hello | None = None  # the last answer to a handshake, kept for the summary
        self.greeted = False  # whether the firmware answered the handshake on this open
        self.reading: Reading | None = None
        self.replies = self.received_bytes = self.stale = self.refused_in_a_row = 0
        self.last_rx_s = now_s
        self.rtt_s: float | None = None
        self.rtts_s: deque[float] = deque(maxlen=4096)
        self.measured_travel_rad = [0.0] * wheel_count
        self._sent: dict[int, float | None] = {}  # token -> sent at; None once timed
        self._reply_times: deque[float] = deque(maxlen=256)
        self._faults: tuple[str, ...] = ()
        self._last_positions: tuple[float, ...] | None = None

    def sent(self, token: int, now_s: float) -> None:
        """Remember that the command ``token`` left at ``now_s``, to match its reply."""
        self._sent[token] = now_s
        if len(self._sent) > _SENT_KEPT:
            self._sent.pop(next(iter(self._sent)))

    def forget_stream(self) -> None:
        """The port was reopened: nothing sent before can be answered, encoders may restart."""
        self._sent.clear()
        self._last_positions = None

    def receive(self, port: Port, now_s: float) -> None:
        """Read what ``port`` has and handle every event in it.

        Raises:
            LinkLost: The port failed.
            FirmwareRefuses: The firmware refused :data:`REFUSALS_TO_FAIL` commands in a row.
        """
        data = port.read_available()
        if data:
            self.received_bytes += len(data)
            for event in self.link.feed(data, now_s):
                self._on_event(event, now_s)

    def reply_rate_hz(self, now_s: float) -> float:
        """Replies in the second before ``now_s`` [Hz]."""
        return float(sum(1 for t in self._reply_times if now_s - t <= 1.0))

    def _on_event(self, event: Event, now_s: float) -> None:
        token = event.token if isinstance(event, Ack) else getattr(event, "ack", None)
        if token is not None and token not in self._sent:
            self.stale += 1  # a reply to nothing this run sent (left over from an earlier one)
            return
        self.last_rx_s = now_s
        if isinstance(event, Refused):
            self._refused(event)
            return
        self.refused_in_a_row = 0
        if isinstance(event, Hello):
            self.hello, self.greeted = event, True
        elif isinstance(event, Ack):
            self._acknowledged(event.token, now_s)
        elif isinstance(event, Reading):
            self._on_reading(event, now_s)

    def _refused(self, event: Refused) -> None:
        self.refused_in_a_row += 1
        if self.refused_in_a_row == 1:
            self.log(event.reason)
        if self.refused_in_a_row >= REFUSALS_TO_FAIL and self.greeted:
            raise FirmwareRefuses(self.link.refusal_advice(self.where))

    def _acknowledged(self, token: int, now_s: float) -> None:
        """Time the first reply to ``token``; it stays known, for the replies after it.

        ROSArduinoBridge answers one command twice (``OK`` to ``m``, then the counts to
        ``e``): forgetting the token at the first would make the counts a stale reply.
        """
        sent_s = self._sent.get(token)
        if sent_s is not None:
            self._sent[token] = None
            self.rtt_s = now_s - sent_s
            self.rtts_s.append(self.rtt_s)

    def _on_reading(self, reading: Reading, now_s: float) -> None:
        if self._last_positions is not None:  # encoders may restart with the firmware: add steps
            for i, (new, old) in enumerate(zip(reading.wheel_position_rad, self._last_positions,
                                               strict=True)):
                self.measured_travel_rad[i] += new - old
        self._last_positions = reading.wheel_position_rad
        self.reading = reading
        self.replies += 1
        self._reply_times.append(now_s)
        if reading.ack is not None:
            self._acknowledged(reading.ack, now_s)
        news = tuple(f for f in reading.faults if f not in self._faults and f != "RESET")
        if news:
            self.log(f"firmware reports {', '.join(news)}")
        self._faults = reading.faults
        self.on_reading(now_s, reading)
