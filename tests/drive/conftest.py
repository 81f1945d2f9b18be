"""Helpers for drive tests: the emulator in another process, and waiting for its state."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest

from tests.conftest import REPO

PATIENCE_S = 20.0  # generous: a loaded CI machine is slow; a test never asserts a duration


def servicebot(*args: object, **kwargs: Any) -> subprocess.Popen[str]:
    """Start ``servicebot ARGS...`` as a real process (stdout and stderr piped)."""
    return subprocess.Popen([sys.executable, "-m", "servicebot_cli", *map(str, args)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            cwd=REPO, **kwargs)


def wait_for(condition: Callable[[], Any], what: str, patience_s: float = PATIENCE_S) -> Any:
    """Poll ``condition`` until it returns something true; fail naming ``what``."""
    deadline = time.monotonic() + patience_s
    while time.monotonic() < deadline:
        value = condition()
        if value:
            return value
        time.sleep(0.02)
    raise AssertionError(f"gave up waiting for {what}")


class Emulator:
    """``servicebot emulate`` running in another process."""

    def __init__(self, state_file: Path, *args: object) -> None:
        self.state_file = state_file
        self.proc = servicebot("emulate", "--state-file", state_file, *args)
        assert self.proc.stdout is not None
        self.path = self.proc.stdout.readline().strip()
        assert self.path, f"emulate printed no device: {self.proc.stderr.read()}"

    def state(self) -> dict[str, Any]:
        """The state the emulator last wrote."""
        return json.loads(self.state_file.read_text())

    def wheel_positions(self) -> list[float]:
        return [w["position_rad"] for w in self.state()["wheels"]]

    def stop(self, sig: int = signal.SIGTERM) -> tuple[int, str]:
        """Signal it, wait for it; ``(exit code, stderr)``."""
        if self.proc.poll() is None:
            self.proc.send_signal(sig)
        _, stderr = self.proc.communicate(timeout=PATIENCE_S)
        return self.proc.returncode, stderr


@pytest.fixture
def emulator(tmp_path: Path) -> Iterator[Callable[..., Emulator]]:
    """Start emulators (``emulator(*args)``); each is stopped at the end of the test."""
    started: list[Emulator] = []

    def start(*args: object) -> Emulator:
        emu = Emulator(tmp_path / f"state{len(started)}.json", *args)
        started.append(emu)
        return emu

    yield start
    for emu in started:
        if emu.proc.poll() is None:
            emu.proc.kill()
        emu.proc.communicate(timeout=PATIENCE_S)


def finish(proc: subprocess.Popen[str], sig: int | None = None) -> tuple[int, str, str]:
    """Optionally signal ``proc``; wait for it; ``(exit code, stdout, stderr)``."""
    if sig is not None:
        os.kill(proc.pid, sig)
    stdout, stderr = proc.communicate(timeout=PATIENCE_S)
    return proc.returncode, stdout, stderr


@pytest.fixture(scope="session")
def real_motors() -> Any:
    """The real robot's motors and limits, from its URDF."""
    from servicebot_cli.description.loader import RobotSource, load
    from servicebot_cli.drive.motors import motor_map

    return motor_map(load(RobotSource.bundled("real")))


class FakeDevice:
    """A device on a real pty that answers with ``respond(received) -> bytes`` (or stays mute)."""

    def __init__(self, respond: Callable[[bytes], bytes] | None = None) -> None:
        import pty
        import threading
        import tty

        self.master, self.slave = pty.openpty()
        tty.setraw(self.slave)
        self.path = os.ttyname(self.slave)
        self.received = bytearray()
        self._respond = respond
        self._running = True
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()

    def _serve(self) -> None:
        import select

        while self._running:
            ready, _, _ = select.select([self.master], [], [], 0.05)
            if not ready:
                continue
            try:
                data = os.read(self.master, 1024)
            except OSError:
                return
            self.received += data
            if self._respond is not None:
                os.write(self.master, self._respond(data))

    def close(self) -> None:
        self._running = False
        self._thread.join()
        os.close(self.master)
        os.close(self.slave)


@pytest.fixture
def fake_device() -> Iterator[Callable[..., FakeDevice]]:
    """Make fake devices on ptys; each is closed at the end of the test."""
    made: list[FakeDevice] = []

    def make(respond: Callable[[bytes], bytes] | None = None) -> FakeDevice:
        made.append(FakeDevice(respond))
        return made[-1]

    yield make
    for device in made:
        device.close()
