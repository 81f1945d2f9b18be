"""The drive loop: a steady command stream over an open port, telemetry back, and a stop.

The loop is given an open :class:`~servicebot_cli.drive.transport.Port` and a clock. It sends
one command per tick, reads whatever arrives, and raises LinkLost when no reply came for
``link_timeout_s``. :meth:`DriveLoop.stop_motors` sends the stop and waits briefly for the
firmware to confirm it; the caller calls it on every way out.
"""

from __future__ import annotations

import select
import time
from collections import deque
from collections.abc import Callable

from servicebot_cli.common.errors import LinkError, LinkLost
from servicebot_cli.drive.plan import Setpoint
from servicebot_cli.drive.protocols.events import Ack, Event, Hello, Reading, Refused
from servicebot_cli.drive.session.commander import Commander, HostLink
from servicebot_cli.drive.session.contracts import (
    FirmwareRefuses,
    LinkStatus,
    Source,
    Suspender,
)
from servicebot_cli.drive.session.probe import probe_other, silence_error
from servicebot_cli.drive.transport import Port

HELLO_PERIOD_S = 0.25  # handshake retry
RECONNECT_PERIOD_S = 0.5  # the first wait after a failed reconnect; it doubles from there
RECONNECT_MAX_PERIOD_S = 4.0  # ... up to this
REFUSALS_TO_FAIL = 5  # refusals in a row, nothing accepted between: the firmware cannot
_MAX_DT_PERIODS = 4  # a late tick ramps as if at most this many periods passed


class DriveLoop:
    """Streams commands from a source to the firmware.

    Args:
        port: The open port.
        link: The protocol adapter (also given to ``commander``).
        commander: Builds each tick's bytes.
        rate_hz: Commands per second.
        link_timeout_s: No reply for this long is a lost link [s].
        where: The port and baud, for messages.
        clock: Monotonic time [s].
        reopen: Opens the port again (``--reconnect``); None to give up on a lost link.
        log: Where event lines go.
        on_reading: Called with ``(t_s, reading, commanded_rad_s)`` for each telemetry.
        on_tick: Called with the status after each tick.
        boot_s: Time the board needs after the port opens before it answers (a board that
            resets on open) [s]; the handshake waits this long before it asks.
        connect_timeout_s: How long a reconnect's handshake may take, after ``boot_s`` [s].
        suspender: Teleop's job control, or None.
    """

    def __init__(self, port: Port, link: HostLink, commander: Commander, *, rate_hz: float,
                 link_timeout_s: float, where: str,
                 clock: Callable[[], float] = time.monotonic,
                 reopen: Callable[[], Port] | None = None,
                 log: Callable[[str], None] = lambda line: None,
                 on_reading: Callable[[float, Reading, tuple[float, ...]], None] | None = None,
                 on_tick: Callable[[LinkStatus], None] | None = None,
                 boot_s: float = 0.0, connect_timeout_s: float = 2.0,
                 suspender: Suspender | None = None) -> None:
        self.port: Port | None = port
        self.link = link
        self.commander = commander
        self.period_s = 1.0 / rate_hz
        self.link_timeout_s = link_timeout_s
        self.where, self.clock, self.reopen, self.log = where, clock, reopen, log
        self.on_reading, self.on_tick = on_reading, on_tick
        self.boot_s, self.suspender = boot_s, suspender
        self.connect_timeout_s = connect_timeout_s
        self.refused_in_a_row = 0
        self.stops_sent = 0
        self.hello: Hello | None = None
        self.reading: Reading | None = None
        self.commands = self.replies = self.reconnects = self.received_bytes = self.stale = 0
        self.rtt_s: float | None = None
        self.reconnecting = False
        self.t0_s = self.last_rx_s = self.end_s = clock()
        self._sent: dict[int, float] = {}
        self._acked: deque[int] = deque(maxlen=64)
        self._reply_times: deque[float] = deque(maxlen=256)
        self.rtts_s: deque[float] = deque(maxlen=4096)
        self._faults: tuple[str, ...] = ()
        self.measured_travel_rad = [0.0] * len(commander.motors.wheel_joints)
        self._last_positions: tuple[float, ...] | None = None
        self._next_tick_s = self._last_tick_s = 0.0

    # -- handshake ---------------------------------------------------------------------------

    def connect(self, timeout_s: float) -> Hello:
        """Ask the firmware who it is until it answers.

        Raises:
            LinkError: No answer within ``timeout_s``, an answer in another protocol, or a
                firmware speaking another version.
        """
        assert self.port is not None
        self._boot_wait()
        start = self.clock()
        received_before, errors_before = self.received_bytes, self.link.errors
        self.hello, next_hello = None, start
        while self.hello is None:
            now = self.clock()
            if now - start >= timeout_s:
                received = self.received_bytes - received_before
                raise silence_error(
                    self.where, self.link.name, timeout_s, received,
                    self.link.errors - errors_before,
                    None if received else probe_other(self.port, self.link.name))
            if now >= next_hello:
                self.port.write(self.link.hello())
                next_hello = now + HELLO_PERIOD_S
            self.port.wait(min(next_hello, start + timeout_s) - now)
            self._receive(self.clock())
        if not self.hello.compatible:
            raise LinkError(f"the firmware on {self.where} speaks {self.hello.description}; "
                            "this servicebot speaks protocol v1: update one of them")
        self.last_rx_s = self.clock()
        return self.hello

    def _boot_wait(self) -> None:
        """Let a board that resets on open boot; what its bootloader says is not a reply."""
        assert self.port is not None
        deadline = self.clock() + self.boot_s
        while (left := deadline - self.clock()) > 0:
            self.port.wait(left)
            self.port.read_available()

    # -- streaming ---------------------------------------------------------------------------

    def run(self, source: Source) -> None:
        """Stream setpoints until the source is done.

        Raises:
            LinkLost: No reply for ``link_timeout_s`` or the port failed (and no reconnect).
        """
        self.t0_s = self._next_tick_s = self.clock()
        self._last_tick_s = 0.0
        while True:
            try:
                self._stream(source)
                return
            except LinkLost as exc:
                if self.reopen is None:
                    raise
                self._reconnect(source, exc)

    def _stream(self, source: Source) -> None:
        while True:
            assert self.port is not None
            self._job_control(source)
            now = self.clock()
            self._receive(now)
            if now - self.last_rx_s > self.link_timeout_s:
                raise LinkLost(f"link lost: no reply from the firmware on {self.where} for "
                               f"{self.link_timeout_s:g} s")
            if now >= self._next_tick_s:
                setpoint = source.setpoint(now - self.t0_s)
                if setpoint is None:
                    return
                self._tick(setpoint, now)
            if self.port.wait(self._next_tick_s - self.clock(), source.fds):
                source.poll()

    def _job_control(self, source: Source) -> None:
        """Ctrl-Z: stop the wheels, then suspend; after SIGCONT, go on as after a pause."""
        if self.suspender is None:
            return
        if self.suspender.requested:
            self.suspender.requested = False
            confirmed = self.stop_motors()
            self.log("suspended (Ctrl-Z): motors stopped"
                     + (" (the firmware confirmed)" if confirmed else ", not confirmed")
                     + "; `fg` resumes at zero speed")
            self.suspender.suspend()
            self.suspender.resumed = True
        if self.suspender.resumed:
            self.suspender.resumed = False
            now = self.clock()
            self.last_rx_s = self._next_tick_s = now  # the pause was ours, not the link's
            self._last_tick_s = 0.0
            self.commander.link_lost(now)  # ramp from zero

    def _tick(self, setpoint: Setpoint, now: float) -> None:
        assert self.port is not None
        dt = now - self._last_tick_s if self._last_tick_s else self.period_s
        data, token, _ = self.commander.command(
            setpoint, now, min(dt, _MAX_DT_PERIODS * self.period_s))
        self.port.write(data)
        self._sent[token] = now
        if len(self._sent) > 256:
            self._sent.pop(next(iter(self._sent)))
        self.commands += 1
        self._last_tick_s = now
        self._next_tick_s += self.period_s
        if now - self._next_tick_s > self.period_s:  # fell behind: do not burst to catch up
            self._next_tick_s = now + self.period_s
        if self.on_tick is not None:
            self.on_tick(self.status(now))

    def _receive(self, now: float) -> None:
        assert self.port is not None
        data = self.port.read_available()
        if data:
            self.received_bytes += len(data)
            for event in self.link.feed(data, now):
                self._on_event(event, now)

    def _on_event(self, event: Event, now: float) -> None:
        token = event.token if isinstance(event, Ack) else getattr(event, "ack", None)
        if token is not None and token not in self._sent:
            self.stale += 1  # a reply to nothing this run sent (left over from an earlier one)
            return
        self.last_rx_s = now
        if isinstance(event, Refused):
            self._refused(event)
            return
        self.refused_in_a_row = 0
        if isinstance(event, Hello):
            self.hello = event
        elif isinstance(event, Ack):
            self._acknowledged(event.token, now)
        elif isinstance(event, Reading):
            self._on_reading(event, now)

    def _refused(self, event: Refused) -> None:
        self.refused_in_a_row += 1
        if self.refused_in_a_row == 1:
            self.log(event.reason)
        if self.refused_in_a_row >= REFUSALS_TO_FAIL and self.hello is not None:
            raise FirmwareRefuses(self.link.refusal_advice(self.where))

    def _acknowledged(self, token: int, now: float) -> None:
        self._acked.append(token)
        if token in self._sent:
            self.rtt_s = now - self._sent.pop(token)
            self.rtts_s.append(self.rtt_s)

    def _on_reading(self, reading: Reading, now: float) -> None:
        if self._last_positions is not None:  # encoders may restart with the firmware: add steps
            for i, (new, old) in enumerate(zip(reading.wheel_position_rad, self._last_positions,
                                               strict=True)):
                self.measured_travel_rad[i] += new - old
        self._last_positions = reading.wheel_position_rad
        self.reading = reading
        self.replies += 1
        self._reply_times.append(now)
        if reading.ack is not None:
            self._acknowledged(reading.ack, now)
        self.commander.observe_arm(reading.arm_position_rad)
        news = tuple(f for f in reading.faults if f not in self._faults and f != "RESET")
        if news:
            self.log(f"firmware reports {', '.join(news)}")
        self._faults = reading.faults
        if self.on_reading is not None:
            self.on_reading(now - self.t0_s, reading, self.commander.commanded_rad_s)

    # -- losing and finding the link ---------------------------------------------------------

    def _reconnect(self, source: Source, lost: LinkLost) -> None:
        self.log(f"{lost}; reconnecting (motors at zero; retries back off from "
                 f"{RECONNECT_PERIOD_S:g} s to {RECONNECT_MAX_PERIOD_S:g} s)")
        self.commander.link_lost(self.clock())
        self._drop_port()
        self.reconnecting = True
        reopen = self.reopen
        if reopen is None:
            raise lost
        pause_s = RECONNECT_PERIOD_S
        while self.port is None:
            if source.setpoint(self.clock() - self.t0_s) is None:
                raise LinkLost(f"{lost}; the run ended before the link came back")
            if self.on_tick is not None:
                self.on_tick(self.status(self.clock()))
            try:  # one open per attempt: a board that resets on open gets its boot time
                self.port = reopen()
                self.link.reset()
                self._sent.clear()
                self._last_positions = None
                self.connect(self.connect_timeout_s)
                self._send_stop()  # zero before anything
            except LinkError:
                self._drop_port()
                self._idle(source, pause_s)
                pause_s = min(RECONNECT_MAX_PERIOD_S, 2 * pause_s)
        self.reconnecting = False
        self.reconnects += 1
        self.log(f"link back on {self.where}: {self.hello.description if self.hello else ''}")
        self._next_tick_s, self._last_tick_s = self.clock(), 0.0

    @staticmethod
    def _idle(source: Source, duration_s: float) -> None:
        """Wait, still reading the source's input (teleop keys: q quits while reconnecting)."""
        if not source.fds:
            time.sleep(duration_s)
        elif select.select(list(source.fds), [], [], duration_s)[0]:
            source.poll()

    def _drop_port(self) -> None:
        if self.port is not None:
            self.port.close()
        self.port = None

    # -- stopping ----------------------------------------------------------------------------

    def stop_motors(self) -> bool:
        """Send the stop until the firmware reports the wheels stopped; True once it did.

        What counts as stopped is the protocol's (:meth:`HostLink.still`): telemetry with the
        wheels at zero, or encoder counts that stop changing. The stop is resent every
        ``link.stop_resend_s`` until then, for at most ``link.stop_timeout_s``.
        """
        self.end_s = self.clock()
        if self.port is None:
            return False
        try:
            tokens = {self._send_stop()}
            deadline = self.clock() + self.link.stop_timeout_s
            resend = self.clock() + self.link.stop_resend_s
            while (now := self.clock()) < deadline:
                self._receive(now)
                if self.link.still(tokens, now):
                    return True
                if now >= resend:
                    tokens.add(self._send_stop())
                    resend = now + self.link.stop_resend_s
                self.port.wait(min(resend, deadline) - self.clock())
            self._receive(self.clock())
            return self.link.still(tokens, self.clock())
        except LinkError:
            return False

    def _send_stop(self) -> int:
        assert self.port is not None
        data, token = self.commander.stop(self.clock())
        self.stops_sent += 1
        self._sent[token] = self.clock()
        self.port.write(data)
        self.port.drain()
        return token

    def status(self, now: float) -> LinkStatus:
        """The run as it stands at ``now``."""
        recent = [t for t in self._reply_times if now - t <= 1.0]
        return LinkStatus(
            t_s=now - self.t0_s, commanded_rad_s=self.commander.commanded_rad_s,
            reading=self.reading, reply_rate_hz=float(len(recent)), rtt_s=self.rtt_s,
            errors=self.link.errors, commands=self.commands, replies=self.replies,
            reconnecting=self.reconnecting, scaled=self.commander.shaper.scaled,
        )
