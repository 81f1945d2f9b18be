"""The drive loop: a steady command stream over an open port, telemetry back, and a stop.

The loop is given an open :class:`~servicebot_cli.drive.transport.Port` and a clock. It sends
one command per tick, hands whatever arrives to its :class:`~servicebot_cli.drive.session.
inbox.Inbox`, and raises LinkLost when no reply came for ``link_timeout_s``; with ``reopen``
it reconnects instead (:mod:`~servicebot_cli.drive.session.reconnect`). Every open, the
first and each reconnect, meets the firmware the same way (:mod:`~servicebot_cli.drive.
session.handshake`). :meth:`DriveLoop.stop_motors` sends the stop until the firmware
confirms it; the caller calls it on every way out.
"""

from __future__ import annotations

import select
import time
from collections.abc import Callable

from servicebot_cli.common.errors import LinkLost
from servicebot_cli.drive.plan import Setpoint
from servicebot_cli.drive.protocols.events import Hello, Reading
from servicebot_cli.drive.session.commander import Commander, HostLink
from servicebot_cli.drive.session.contracts import LinkStatus, Source, Suspender
from servicebot_cli.drive.session.handshake import boot_wait, handshake
from servicebot_cli.drive.session.inbox import Inbox
from servicebot_cli.drive.session.reconnect import ReconnectPolicy, reconnect
from servicebot_cli.drive.session.stall import StallWatch, WheelsStill
from servicebot_cli.drive.session.stopping import stop_until_still
from servicebot_cli.drive.transport import Port

_MAX_DT_PERIODS = 4  # a late tick ramps as if at most this many periods passed
DEFAULT_POLICY = ReconnectPolicy()


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
        policy: How many reconnect attempts, and the pauses between them.
        log: Where event lines go.
        on_reading: Called with ``(t_s, reading, commanded_rad_s)`` for each telemetry.
        on_tick: Called with the status after each tick.
        boot_s: Time the board needs after the port opens before it answers (a board that
            resets on open) [s]; every handshake, the first and each reconnect's, waits
            this long before it asks.
        connect_timeout_s: How long a reconnect's handshake may take, after ``boot_s`` [s].
        suspender: Teleop's job control, or None.
    """

    def __init__(self, port: Port, link: HostLink, commander: Commander, *, rate_hz: float,
                 link_timeout_s: float, where: str,
                 clock: Callable[[], float] = time.monotonic,
                 reopen: Callable[[], Port] | None = None,
                 policy: ReconnectPolicy = DEFAULT_POLICY,
                 log: Callable[[str], None] = lambda line: None,
                 on_reading: Callable[[float, Reading, tuple[float, ...]], None] | None = None,
                 on_tick: Callable[[LinkStatus], None] | None = None,
                 boot_s: float = 0.0, connect_timeout_s: float = 2.0,
                 suspender: Suspender | None = None) -> None:
        self.port: Port | None = port
        self.link, self.commander = link, commander
        self.period_s = 1.0 / rate_hz
        self.link_timeout_s = link_timeout_s
        self.where, self.clock, self.reopen, self.policy, self.log = (
            where, clock, reopen, policy, log)
        self.on_reading, self.on_tick = on_reading, on_tick
        self.boot_s, self.connect_timeout_s, self.suspender = boot_s, connect_timeout_s, suspender
        self.inbox = Inbox(link, len(commander.motors.wheel_joints), where, clock(), log=log,
                           on_reading=self._on_reading)
        self.stall = StallWatch(commander.motors.wheel_joints, link.count_rad)
        self.commands = self.reconnects = self.stops_sent = 0
        self.reconnecting = False
        self.t0_s = self.end_s = clock()
        self._next_tick_s = self._last_tick_s = 0.0
        self._source: Source | None = None

    def connect(self, timeout_s: float) -> Hello:
        """Let the board boot, then ask the firmware who it is until it answers.

        Raises:
            LinkError: No answer within ``timeout_s`` after the boot wait, an answer in
                another protocol, or a firmware speaking another version.
        """
        assert self.port is not None
        boot_wait(self.port, self.boot_s, self.clock)
        return handshake(self.port, self.inbox, timeout_s, self.clock)

    # -- streaming ---------------------------------------------------------------------------

    def run(self, source: Source) -> None:
        """Stream setpoints until the source is done.

        Raises:
            LinkLost: No reply for ``link_timeout_s`` or the port failed, and no reconnect
                (or every reconnect attempt failed).
        """
        self._source = source
        self.t0_s = self._next_tick_s = self.clock()
        self._last_tick_s = 0.0
        while True:
            try:
                self._stream(source)
                return
            except LinkLost as exc:
                if self.reopen is None:
                    raise
                self._reconnect(exc)

    def _stream(self, source: Source) -> None:
        while True:
            assert self.port is not None
            self._job_control()
            now = self.clock()
            self.inbox.receive(self.port, now)
            if self.stall.stalled is not None:
                raise WheelsStill(f"wheels stalled: {self.stall.stalled}")
            if now - self.inbox.last_rx_s > self.link_timeout_s:
                raise LinkLost(f"link lost: no reply from the firmware on {self.where} for "
                               f"{self.link_timeout_s:g} s")
            if now >= self._next_tick_s:
                setpoint = source.setpoint(now - self.t0_s)
                if setpoint is None:
                    return
                self._tick(setpoint, now)
            if self.port.wait(self._next_tick_s - self.clock(), source.fds):
                source.poll()

    def _job_control(self) -> None:
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
            self.inbox.last_rx_s = self._next_tick_s = now  # the pause was ours, not the link's
            self._last_tick_s = 0.0
            self.stall.restart()
            self.commander.link_lost(now)  # ramp from zero

    def _tick(self, setpoint: Setpoint, now: float) -> None:
        assert self.port is not None
        dt = now - self._last_tick_s if self._last_tick_s else self.period_s
        data, token, _ = self.commander.command(
            setpoint, now, min(dt, _MAX_DT_PERIODS * self.period_s))
        self.port.write(data)
        self.inbox.sent(token, now)
        self.commands += 1
        self._last_tick_s = now
        self._next_tick_s += self.period_s
        if now - self._next_tick_s > self.period_s:  # fell behind: do not burst to catch up
            self._next_tick_s = now + self.period_s
        if self.on_tick is not None:
            self.on_tick(self.status(now))

    def _on_reading(self, now: float, reading: Reading) -> None:
        self.commander.observe_arm(reading.arm_position_rad)
        self.stall.observe(now, reading.wheel_position_rad, self.commander.commanded_rad_s)
        if self.on_reading is not None:
            self.on_reading(now - self.t0_s, reading, self.commander.commanded_rad_s)

    # -- losing and finding the link ---------------------------------------------------------

    def _reconnect(self, lost: LinkLost) -> None:
        self.log(f"{lost}; reconnecting (motors at zero; {self.policy.describe()})")
        self.commander.link_lost(self.clock())
        self.drop_port()
        self.reconnecting = True
        reconnect(self, self.policy, lost, boot_s=self.boot_s, clock=self.clock)
        self.reconnecting = False
        self.reconnects += 1
        self.stall.restart()
        hello = self.inbox.hello
        self.log(f"link back on {self.where}: {hello.description if hello else ''}")
        self._next_tick_s, self._last_tick_s = self.clock(), 0.0

    def wanted(self) -> bool:
        """Whether the source still has setpoints; shows the status meanwhile."""
        if self.on_tick is not None:
            self.on_tick(self.status(self.clock()))
        return self._source is not None and (
            self._source.setpoint(self.clock() - self.t0_s) is not None)

    def reopen_port(self) -> None:
        """One reconnect attempt: open (a reset, on some boards), boot, handshake, stop.

        Raises:
            LinkError: The port did not open, or the firmware did not answer.
        """
        assert self.reopen is not None, "run() reconnects only with reopen"
        self.port = self.reopen()
        self.link.reset()
        self.inbox.forget_stream()
        self.connect(self.connect_timeout_s)
        self._send_stop()  # zero before anything

    def idle(self, duration_s: float) -> None:
        """Wait, still reading the source's input (teleop keys: q quits while reconnecting)."""
        fds = self._source.fds if self._source is not None else ()
        if not fds:
            time.sleep(duration_s)
        elif select.select(list(fds), [], [], duration_s)[0] and self._source is not None:
            self._source.poll()

    def drop_port(self) -> None:
        """Close the port, if one is open."""
        if self.port is not None:
            self.port.close()
        self.port = None

    # -- stopping ----------------------------------------------------------------------------

    def stop_motors(self) -> bool:
        """Send the stop until the firmware reports the wheels stopped; True once it did."""
        self.end_s = self.clock()
        if self.port is None:
            return False
        return stop_until_still(self.port, self.inbox, self._send_stop, self.clock)

    def _send_stop(self) -> int:
        assert self.port is not None
        data, token = self.commander.stop(self.clock())
        self.stops_sent += 1
        self.inbox.sent(token, self.clock())
        self.port.write(data)
        self.port.drain()
        return token

    def status(self, now: float) -> LinkStatus:
        """The run as it stands at ``now``."""
        return LinkStatus(
            t_s=now - self.t0_s, commanded_rad_s=self.commander.commanded_rad_s,
            reading=self.inbox.reading, reply_rate_hz=self.inbox.reply_rate_hz(now),
            rtt_s=self.inbox.rtt_s, errors=self.link.errors, commands=self.commands,
            replies=self.inbox.replies, reconnecting=self.reconnecting,
            scaled=self.commander.shaper.scaled,
        )
