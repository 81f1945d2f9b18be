"""A batch ended by SIGTERM or SIGHUP leaves no file behind, half-written or whole."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import pytest

from tests.conftest import REPO


def _temporary_files(directory):
    return sorted(p.name for p in directory.iterdir() if p.name.startswith(".out.csv."))


@pytest.mark.parametrize(("signum", "code", "words"), [
    (signal.SIGTERM, 143, "terminated (SIGTERM)"),
    (signal.SIGHUP, 129, "hung up (SIGHUP)"),
])
def test_a_signal_mid_stream_removes_the_temporary_file(tmp_path, signum, code, words):
    process = subprocess.Popen(
        [sys.executable, "-m", "servicebot_cli", "fk", "--configs", "-", "-o", "out.csv"],
        cwd=tmp_path, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
        text=True, env={**os.environ, "PYTHONPATH": str(REPO)})
    try:
        assert process.stdin is not None
        process.stdin.write("arm_base_to_link1,arm_link1_to_link2\n0.1,0.2\n0.3,-0.4\n")
        process.stdin.flush()  # the pipe stays open: the run waits for more lines
        deadline = time.monotonic() + 60
        while not _temporary_files(tmp_path):
            assert process.poll() is None, process.communicate()
            assert time.monotonic() < deadline, "the output's temporary file never appeared"
            time.sleep(0.05)
        process.send_signal(signum)
        _, stderr = process.communicate(timeout=60)
    finally:
        if process.poll() is None:
            process.kill()
            process.communicate()
    assert process.returncode == code, stderr
    assert stderr == f"Error: {words}\n"
    assert list(tmp_path.iterdir()) == []  # neither out.csv nor .out.csv.*.tmp
