"""A real ``servicebot simulate`` process ended by a signal: the exit code, and nothing left.

SIGTERM (a CI job cancelled) and SIGHUP (a terminal closed) end a run like Ctrl-C does: the
atomic writers' clean-up runs, so no temporary and no half-made output stays behind.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Callable
from pathlib import Path

import pytest

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="POSIX signals")


def _start(cwd: Path, *args: str) -> subprocess.Popen[bytes]:
    return subprocess.Popen([sys.executable, "-m", "servicebot_cli", "simulate", "--headless",
                             *args], cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            env={**os.environ, "CI": ""})


def _wait_for(process: subprocess.Popen[bytes], ready: Callable[[], bool],
              timeout_s: float = 120.0) -> None:
    deadline = time.monotonic() + timeout_s
    while not ready():
        assert process.poll() is None, "the run ended before the moment to signal it"
        assert time.monotonic() < deadline, "the moment to signal never came"
        time.sleep(0.002)


def _end(process: subprocess.Popen[bytes], signum: int) -> tuple[int, str]:
    process.send_signal(signum)
    _, stderr = process.communicate(timeout=60)
    return process.returncode, stderr.decode()


def _temporaries(directory: Path) -> list[str]:
    return sorted(p.name for p in directory.rglob("*.tmp"))


def test_sigterm_while_the_bag_is_written_leaves_no_bag(tmp_path):
    process = _start(tmp_path, "--duration-s", "600", "--bag", "B")
    _wait_for(process, lambda: bool(_temporaries(tmp_path)))
    assert _temporaries(tmp_path)[0].startswith(".B.")
    code, stderr = _end(process, signal.SIGTERM)
    assert code == 143, stderr
    assert stderr.splitlines() == ["Error: terminated (SIGTERM)"]
    assert list(tmp_path.iterdir()) == []  # no B, no .B.*.tmp


def test_sighup_while_a_new_out_directory_is_written_leaves_no_directory(tmp_path):
    process = _start(tmp_path, "--duration-s", "1800", "--out", "O")
    _wait_for(process, lambda: bool(_temporaries(tmp_path)))
    code, stderr = _end(process, signal.SIGHUP)
    assert code == 129, stderr
    assert stderr.splitlines() == ["Error: hung up (SIGHUP)"]
    assert list(tmp_path.iterdir()) == []  # no O, no .O.*.tmp


def test_sigterm_while_files_are_written_into_an_existing_out_directory(tmp_path):
    out = tmp_path / "O"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    process = _start(tmp_path, "--duration-s", "1800", "--out", "O")
    _wait_for(process, lambda: bool(_temporaries(out)))
    code, stderr = _end(process, signal.SIGTERM)
    assert code == 143, stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["O"]
    assert sorted(p.name for p in out.iterdir()) == ["notes.txt"]  # no new file, no temporary


def test_sigterm_while_simulating_writes_nothing(tmp_path):
    """Signalled mid-run (the progress bar is drawing): every output begun is removed."""
    process = _start(tmp_path, "--duration-s", "1800", "--bag", "B", "--out", "O",
                     "--plot", "p.png", "--progress")
    drawn = threading.Event()
    seen = bytearray()

    def read() -> None:
        assert process.stderr is not None
        while chunk := os.read(process.stderr.fileno(), 256):
            seen.extend(chunk)
            if b"simulating" in seen:
                drawn.set()
                return

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    _wait_for(process, drawn.is_set)
    reader.join(timeout=5)
    code, stderr = _end(process, signal.SIGTERM)
    assert code == 143, stderr
    # The bar is erased first, so the error line starts at the beginning of a line.
    assert stderr.endswith("\r" + " " * 60 + "\rError: terminated (SIGTERM)\n"), stderr
    assert list(tmp_path.iterdir()) == []
