"""A Ctrl-C or SIGTERM that lands inside a port call ends the run as itself, not as a lost link."""

from __future__ import annotations

import pytest

from servicebot_cli.common.errors import LinkLost
from servicebot_cli.drive.session.signals import Interrupted, Terminated
from servicebot_cli.drive.transport import Port


class _Device:
    """A serial device whose every call is cut short by ``error`` (as a signal handler does)."""

    def __init__(self, error: BaseException) -> None:
        self.error = error

    @property
    def in_waiting(self) -> int:
        return 1

    def write(self, data: bytes) -> int | None:
        raise self.error

    def read(self, size: int = 1) -> bytes:
        raise self.error

    def flush(self) -> None:
        raise self.error

    def fileno(self) -> int:
        return -1

    def close(self) -> None:
        pass


@pytest.mark.parametrize("call", ["write", "drain", "read_available"])
@pytest.mark.parametrize("error", [Interrupted("interrupted (Ctrl-C)"),
                                   Terminated("terminated (SIGTERM)")])
def test_a_signal_mid_call_passes_through(call, error):
    port = Port(_Device(error), "/dev/ttyUSB0")
    with pytest.raises(type(error)):
        getattr(port, call)(*([b"x"] if call == "write" else []))


@pytest.mark.parametrize("call", ["write", "drain", "read_available"])
def test_a_failing_device_is_a_lost_link(call):
    port = Port(_Device(OSError(5, "Input/output error")), "/dev/ttyUSB0")
    with pytest.raises(LinkLost, match="Input/output error"):
        getattr(port, call)(*([b"x"] if call == "write" else []))
