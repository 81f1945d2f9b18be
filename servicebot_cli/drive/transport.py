"""The serial port: the only module that imports pyserial, and only when a port is opened.

:func:`open_port` turns every way opening can fail into one :class:`~servicebot_cli.common.errors.
LinkError` line that says what to do. :class:`Port` is what the drive loop is given (the
pySerial way: the caller opens, the logic uses); once open, any failure of the port becomes
:class:`~servicebot_cli.common.errors.LinkLost`.
"""

from __future__ import annotations

import errno
import glob
import grp
import os
import select
from collections.abc import Sequence
from typing import Protocol

from servicebot_cli.common.errors import LinkError, LinkLost, ServicebotError
from servicebot_cli.common.listing import some_of

WRITE_TIMEOUT_S = 0.5  # a write that cannot leave in this long means the port is dead
_MAX_LISTED = 8


class PortMissing(LinkError):
    """The port's device file does not exist."""


class PortPermission(LinkError):
    """The user may not open the port."""


class PortBusy(LinkError):
    """Another program holds the port."""


class SerialDevice(Protocol):
    """What :class:`Port` uses of an open ``serial.Serial`` (pyserial ships no types)."""

    @property
    def in_waiting(self) -> int:
        """Bytes received and not yet read."""

    def write(self, data: bytes) -> int | None:
        """Send ``data``."""

    def read(self, size: int = 1) -> bytes:
        """Up to ``size`` bytes."""

    def flush(self) -> None:
        """Wait until written bytes have left."""

    def fileno(self) -> int:
        """The file descriptor, for select."""

    def close(self) -> None:
        """Close the device."""


class Port:
    """An open serial port as the drive loop uses it.

    Args:
        serial: An open ``serial.Serial`` with ``timeout=0`` (reads never block).
        name: The path it was opened as, for messages.
    """

    def __init__(self, serial: SerialDevice, name: str) -> None:
        self._serial = serial
        self.name = name

    def write(self, data: bytes) -> None:
        """Send ``data``; a port that fails or stalls raises LinkLost."""
        try:
            self._serial.write(data)
        except ServicebotError:  # Ctrl-C or a signal raised mid-call: not the port
            raise
        except Exception as exc:  # pyserial raises SerialException, OSError and timeouts
            raise LinkLost(f"link lost: writing to {self.name} failed ({_reason(exc)}): "
                           "the device is gone (unplugged, or its firmware died)") from None

    def drain(self) -> None:
        """Wait until written bytes have left (tcdrain)."""
        try:
            self._serial.flush()
        except ServicebotError:  # Ctrl-C or a signal raised mid-call: not the port
            raise
        except Exception as exc:
            raise LinkLost(f"link lost: {self.name} failed ({_reason(exc)})") from None

    def read_available(self) -> bytes:
        """Whatever has arrived, without waiting (may be empty)."""
        try:
            waiting = self._serial.in_waiting
            return self._serial.read(waiting) if waiting else b""
        except ServicebotError:  # Ctrl-C or a signal raised mid-call: not the port
            raise
        except Exception as exc:
            raise LinkLost(f"link lost: reading {self.name} failed ({_reason(exc)}): "
                           "the device is gone (unplugged, or its firmware died)") from None

    def wait(self, timeout_s: float, extra_fds: Sequence[int] = ()) -> list[int]:
        """Sleep until bytes arrive, one of ``extra_fds`` is readable, or ``timeout_s`` passes.

        Returns:
            The readable ``extra_fds``.
        """
        fds = [self._serial.fileno(), *extra_fds]
        try:
            ready, _, _ = select.select(fds, [], [], max(0.0, timeout_s))
        except (OSError, ValueError) as exc:
            raise LinkLost(f"link lost: {self.name} failed ({_reason(exc)})") from None
        return [fd for fd in ready if fd in extra_fds]

    def close(self) -> None:
        """Close the port; never raises."""
        try:
            self._serial.close()
        except Exception:  # noqa: S110 -- closing a dead port may fail; nothing to do
            pass


def open_port(path: str, baud: int) -> Port:
    """Open ``path`` at ``baud`` (8N1), exclusively, with non-blocking reads.

    Raises:
        PortMissing: No such device; the message lists the ports that exist.
        PortPermission: Not allowed; the message says which group to join.
        PortBusy: Another program has it.
        LinkError: Not a serial port, or another failure, named.
    """
    import serial  # pyserial, only here and only now

    try:
        port = serial.Serial(path, baud, timeout=0, write_timeout=WRITE_TIMEOUT_S,
                             exclusive=True)
    except serial.SerialException as exc:
        raise explain_open_error(path, exc) from None
    except ValueError as exc:
        raise LinkError(f"cannot open {path} at {baud} baud: {exc}") from None
    return Port(port, path)


def explain_open_error(path: str, exc: Exception) -> LinkError:
    """One line for why ``path`` did not open, with what to do."""
    code = getattr(exc, "errno", None)
    text = str(exc)
    if code == errno.ENOENT or (code is None and not os.path.exists(path)):
        return PortMissing(f"port {path} does not exist; {describe_ports()}")
    if code in (errno.EACCES, errno.EPERM):
        group = _group_of(path)
        return PortPermission(
            f"permission denied opening {path}" + (f" (group '{group}')" if group else "")
            + f"; add yourself to that group: sudo usermod -aG {group or 'dialout'} $USER, "
            "then log out and back in"
        )
    if code in (errno.EAGAIN, errno.EWOULDBLOCK, errno.EBUSY):
        return PortBusy(
            f"port {path} is busy: another program has it open (another servicebot drive, a "
            "serial monitor, ModemManager?); close that program and try again"
        )
    if code in (errno.EISDIR, errno.ENOTTY) or "Inappropriate ioctl" in text:
        return LinkError(f"{path} is not a serial port; {describe_ports()}")
    if code in (errno.ENXIO, errno.EIO, errno.ENODEV):
        return PortMissing(f"port {path} exists but no device answers there (unplugged?); "
                           f"{describe_ports()}")
    return LinkError(f"cannot open {path}: {_reason(exc)}")


def available_ports() -> tuple[list[str], list[str]]:
    """Serial devices pyserial finds, and the pseudo-terminals (emulators) that exist."""
    try:
        from serial.tools import list_ports

        serial_ports = sorted(p.device for p in list_ports.comports())
    except Exception:  # listing is a courtesy in an error message; never fail because of it
        serial_ports = []
    ptys = sorted((p for p in glob.glob("/dev/pts/*") if os.path.basename(p).isdigit()),
                  key=lambda p: int(os.path.basename(p)))
    return serial_ports, ptys


def describe_ports() -> str:
    """The ports that exist, as a clause for an error message."""
    serial_ports, ptys = available_ports()
    parts = [f"serial ports here: {_listed(serial_ports) or 'none'}"]
    if ptys:
        parts.append(f"pseudo-terminals: {_listed(ptys)}")
    return "; ".join(parts) + " (plug the board in, or give --port; `servicebot emulate` " \
        "makes a test port)"


def _listed(names: list[str]) -> str:
    return some_of(names, _MAX_LISTED)


def _group_of(path: str) -> str:
    try:
        return grp.getgrgid(os.stat(path).st_gid).gr_name
    except (OSError, KeyError):
        return ""


def _reason(exc: Exception) -> str:
    text = str(exc) or type(exc).__name__
    return text.replace("\n", " ")
