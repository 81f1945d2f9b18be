"""Seeing a host open the emulator's port, as a board sees DTR: every open, however quick.

An Arduino Uno resets when a host opens its port. A pseudo-terminal has no DTR line, so the
emulator watches the slave device itself with Linux's inotify (``IN_OPEN``): the kernel
queues one event per open of ``/dev/pts/N``, by path or through a symlink to it, so none is
missed. Polling the master for the hangup condition would not do: drive's reconnect closes
and reopens the port within microseconds, and a poll sees the port closed only if it looks
in that window (3 of 51 back-to-back reopens, measured with a 20 ms poll).
"""

from __future__ import annotations

import ctypes
import os
import struct

IN_OPEN = 0x00000020
IN_CLOSE = 0x00000008 | 0x00000010  # IN_CLOSE_WRITE | IN_CLOSE_NOWRITE
IN_NONBLOCK = os.O_NONBLOCK
IN_CLOEXEC = os.O_CLOEXEC
_EVENT = struct.Struct("iIII")  # wd, mask, cookie, len (then len bytes of name)


class PortOpens:
    """Counts the opens of a device file by any process.

    Args:
        path: The device to watch, e.g. ``/dev/pts/3``.

    Raises:
        OSError: inotify is not available here (not Linux), or the device cannot be watched.
    """

    def __init__(self, path: str) -> None:
        try:
            libc = ctypes.CDLL(None, use_errno=True)
            init, add_watch = libc.inotify_init1, libc.inotify_add_watch
        except (OSError, AttributeError) as exc:
            raise OSError(f"inotify is not available here ({exc})") from None
        self._fd: int = init(IN_NONBLOCK | IN_CLOEXEC)
        if self._fd < 0:
            raise _last_error("inotify_init1")
        # Closes are watched too, only so that two opens are never the same event twice in a
        # row: inotify merges identical consecutive events, and open, open, ... would be one.
        if add_watch(self._fd, os.fsencode(path), IN_OPEN | IN_CLOSE) < 0:
            error = _last_error(f"watching {path}")
            os.close(self._fd)
            raise error

    def fileno(self) -> int:
        """The descriptor that is readable when an open was seen (for select)."""
        return self._fd

    def take(self) -> int:
        """How many times the device was opened since the last call; never blocks."""
        opens = 0
        while True:
            try:
                data = os.read(self._fd, 4096)
            except (BlockingIOError, InterruptedError):
                return opens
            if not data:
                return opens
            offset = 0
            while offset + _EVENT.size <= len(data):
                _, mask, _, name_len = _EVENT.unpack_from(data, offset)
                opens += bool(mask & IN_OPEN)
                offset += _EVENT.size + name_len

    def close(self) -> None:
        """Stop watching."""
        if self._fd >= 0:
            os.close(self._fd)
            self._fd = -1


def _last_error(what: str) -> OSError:
    code = ctypes.get_errno()
    return OSError(code, f"{what}: {os.strerror(code)}")
