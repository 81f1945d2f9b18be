"""Which protocol a device that ignores ours speaks: the other one's handshake, once.

A ROSArduinoBridge board never answers a servicebot PING (there is no CR in it), and a
servicebot firmware drops ``b`` as garbage, so a wrong ``--protocol`` looks like silence.
Before calling a device silent, drive asks once in the other protocol: the answer turns a
baud-rate hint into the right one.
"""

from __future__ import annotations

import re
import time

from servicebot_cli.common.errors import LinkError
from servicebot_cli.drive.protocols import messages as msg
from servicebot_cli.drive.protocols.framing import Decoder, Frame, encode_frame
from servicebot_cli.drive.transport import Port

PROBE_WAIT_S = 0.3  # the other handshake's answer is a few bytes: at 9600 baud, 20 ms
_ARDUINO_ANSWER = re.compile(rb"(^|[\r\n]) ?[0-9]{3,7}\r?\n|Invalid Command")


class NoAnswer(LinkError):
    """Nothing at all came back to the handshake (exit 4): no board, or one still booting.

    Attributes:
        timeout_s: How long drive waited for the answer [s], when known.
    """

    def __init__(self, message: str, timeout_s: float | None = None) -> None:
        super().__init__(message)
        self.timeout_s = timeout_s


def probe_other(port: Port, protocol: str) -> str | None:
    """Ask once in the protocol that is not ``protocol``; its name if the device answered.

    Never raises: a port that fails here is reported by the caller's own message.
    """
    try:
        if protocol == "servicebot":
            port.write(b"\rb\r")  # CR first ends whatever the PINGs left in its buffer
            return "the ROSArduinoBridge protocol" if _ARDUINO_ANSWER.search(
                _collect(port)) else None
        port.write(encode_frame(Frame(0, msg.MsgType.PING)))
        frames = Decoder().feed(_collect(port))
        return "the servicebot protocol" if any(
            f.type == msg.MsgType.VERSION for f in frames) else None
    except LinkError:
        return None


def _collect(port: Port) -> bytes:
    data = bytearray()
    deadline = time.monotonic() + PROBE_WAIT_S
    while (left := deadline - time.monotonic()) > 0:
        port.wait(left)
        data += port.read_available()
    return bytes(data)


def silence_error(where: str, protocol: str, timeout_s: float, received: int, errors: int,
                  other_answered: str | None) -> LinkError:
    """One line for a handshake that got no answer in ``protocol`` within ``timeout_s``.

    Args:
        where: The port and baud rate, for the message.
        protocol: The protocol asked in.
        timeout_s: How long drive waited [s].
        received: Bytes that came back meanwhile.
        errors: How many of them were rejected.
        other_answered: The protocol the device answered in when asked once in the other
            one (:func:`probe_other`), or None.
    """
    other = "arduino" if protocol == "servicebot" else "servicebot"
    if other_answered:
        return LinkError(
            f"the firmware on {where} speaks {other_answered}, not the {protocol} protocol: "
            f"give --protocol {other}" + (" --ticks-per-rev N" if other == "arduino" else "")
        )
    if received == 0:
        return NoAnswer(
            f"no answer from the firmware on {where} within {timeout_s:g} s: is the board "
            f"powered and running {protocol}-protocol firmware, and is the baud rate right "
            "(--baud)?", timeout_s
        )
    return LinkError(
        f"{where} answers, but not in the {protocol} protocol ({received} bytes, {errors} "
        f"rejected): check --baud, or try --protocol {other}"
    )
