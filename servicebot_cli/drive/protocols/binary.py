"""Host side of the servicebot binary protocol: commands to bytes, replies to events.

Every command gets the next sequence number, which is also its token: the firmware's reply
carries it back, so a reply is matched to its command. Wheel positions arrive modulo 2**16
mrad and are unwrapped here into continuous angles.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Sequence

from servicebot_cli.drive.motors import MotorMap
from servicebot_cli.drive.protocols import messages as msg
from servicebot_cli.drive.protocols.events import Event, Hello, Reading, Refused
from servicebot_cli.drive.protocols.framing import Decoder, Frame, encode_frame

_WRAP_RAD = 65.536  # 2**16 mrad


class BinaryLink:
    """The ``servicebot`` protocol for one robot's motors.

    Attributes:
        command_bytes: Bytes of the largest frame streamed each tick.
        reply_bytes: Bytes of the reply to each streamed frame.
    """

    name = "servicebot"
    command_bytes = msg.COMMAND_FRAME_BYTES
    reply_bytes = msg.REPLY_FRAME_BYTES
    has_arm = True
    stop_timeout_s = 0.5  # docs/serial-protocol.md: wait up to 0.5 s, resend after 0.25 s
    stop_resend_s = 0.25
    count_rad = 0.0  # telemetry carries continuous angles

    def __init__(self, motors: MotorMap) -> None:
        if len(motors.wheel_joints) != msg.SLOTS or len(motors.arm_joints) != msg.SLOTS:
            from servicebot_cli.common.errors import DescriptionError

            raise DescriptionError(
                f"the servicebot protocol carries {msg.SLOTS} wheels and {msg.SLOTS} arm joints; "
                f"{motors.robot} has {len(motors.wheel_joints)} wheels and "
                f"{len(motors.arm_joints)} arm joints"
            )
        self.motors = motors
        self._seq = 0
        self._decoder = Decoder()
        self._raw: tuple[float, ...] | None = None
        self._unwrapped = [0.0] * msg.SLOTS
        self._speeds: deque[tuple[int, tuple[float, ...]]] = deque(maxlen=32)
        self.refused = 0
        self.malformed = 0

    def _next_seq(self) -> int:
        self._seq = (self._seq + 1) % 256
        return self._seq

    def hello(self) -> bytes:
        """A PING frame."""
        return encode_frame(Frame(self._next_seq(), msg.MsgType.PING))

    def wheels(self, speeds_rad_s: Sequence[float]) -> tuple[bytes, int]:
        """SET_WHEELS for joint velocities in wire order [rad/s]; ``(bytes, token)``."""
        seq = self._next_seq()
        return encode_frame(msg.set_wheels(seq, speeds_rad_s, self.motors)), seq

    def quantised(self, speeds_rad_s: Sequence[float]) -> tuple[float, ...]:
        """The wheel speeds SET_WHEELS really carries for ``speeds_rad_s`` [rad/s]."""
        return tuple(c / msg.SCALE for c in msg.wheel_counts(speeds_rad_s, self.motors))

    def arm(self, targets_rad: Sequence[float]) -> tuple[bytes, int]:
        """SET_ARM for arm targets in wire order [rad]; ``(bytes, token)``."""
        seq = self._next_seq()
        return encode_frame(msg.set_arm(seq, targets_rad, self.motors)), seq

    def stop(self) -> tuple[bytes, int]:
        """STOP; ``(bytes, token)``."""
        seq = self._next_seq()
        return encode_frame(Frame(seq, msg.MsgType.STOP)), seq

    def reset(self) -> None:
        """Forget the stream state after the port was reopened."""
        self._decoder = Decoder()
        self._raw = None

    def feed(self, data: bytes, now_s: float) -> list[Event]:
        """Events for the bytes received (``now_s`` is unused: replies carry what they need)."""
        events: list[Event] = []
        for frame in self._decoder.feed(data):
            try:
                events.append(self._event(frame))
            except msg.ProtocolError:
                self.malformed += 1
        return events

    def _event(self, frame: Frame) -> Event:
        if frame.type == msg.MsgType.TELEMETRY:
            return self._reading(frame.seq, msg.decode_telemetry(frame))
        if frame.type == msg.MsgType.VERSION:
            version = msg.decode_version(frame)
            return Hello(
                f"servicebot protocol v{version.protocol}, firmware "
                f"{version.firmware[0]}.{version.firmware[1]}, watchdog {version.watchdog_ms} ms",
                version.watchdog_ms, version.protocol == msg.PROTOCOL_VERSION,
            )
        if frame.type == msg.MsgType.NACK:
            refused, reason = msg.decode_nack(frame)
            self.refused += 1
            name = getattr(reason, "name", str(reason))
            return Refused(f"firmware refused type 0x{refused:02X} (seq {frame.seq}): {name}")
        raise msg.ProtocolError(f"unexpected message type 0x{frame.type:02X} from the firmware")

    def _reading(self, seq: int, telemetry: msg.Telemetry) -> Reading:
        raw = telemetry.wheel_position_rad
        if self._raw is None:
            self._unwrapped = list(raw)
        else:
            for i, (new, old) in enumerate(zip(raw, self._raw, strict=True)):
                step = (new - old + _WRAP_RAD / 2) % _WRAP_RAD - _WRAP_RAD / 2
                self._unwrapped[i] += step
        self._raw = raw
        faults = tuple(f.name or "" for f in msg.Fault if f in telemetry.faults)
        self._speeds.append((seq, telemetry.wheel_velocity_rad_s))
        return Reading(seq, tuple(self._unwrapped), telemetry.wheel_velocity_rad_s,
                       telemetry.arm_position_rad, faults)

    def still(self, stop_tokens: set[int], now_s: float) -> bool:
        """Whether the TELEMETRY answering a STOP reports every wheel at zero."""
        return any(seq in stop_tokens and not any(speeds) for seq, speeds in self._speeds)

    def refusal_advice(self, where: str) -> str:
        """What to update when the firmware refuses every command."""
        return (f"the firmware on {where} refuses the motion commands (NACK): it does not "
                "implement servicebot protocol v1's SET_WHEELS and STOP; update it "
                "(docs/serial-protocol.md, firmware/)")

    def auto_stop_note(self, hello: Hello | None) -> str:
        """Who stops the motors when drive could not."""
        watchdog = f"{hello.watchdog_ms} ms" if hello and hello.watchdog_ms else "its timeout"
        return f"the firmware's watchdog stops the motors within {watchdog}"

    @property
    def errors(self) -> int:
        """Rejected frames, malformed payloads and refusals so far."""
        return self._decoder.stats.errors + self.malformed + self.refused

    def describe(self, data: bytes) -> str:
        """The frames in ``data``, decoded, for ``--dry-run``."""
        return "; ".join(msg.describe(frame) for frame in Decoder().feed(data))
