"""A signal delivered to another thread still waits for a clean-up to own its temporary file.

The kernel delivers a process-directed signal to any thread that does not block it (numpy's
BLAS threads among them); CPython then runs the Python handler in the main thread at once,
whatever the main thread's own signal mask says. A run signalled between creating a
temporary file and registering its removal left the file behind (a flaky SIGTERM test of
simulate). Here the signal is sent to a second thread, as the kernel may choose to.
"""

from __future__ import annotations

import subprocess
import sys

import pytest

from tests.conftest import REPO

SCRIPT = """
import signal, threading, time
from servicebot_cli.common.signals import EndedBySignal, SignalsHeld, signals_as_exceptions
idle = threading.Event()
other = threading.Thread(target=idle.wait, daemon=True)
other.start()
with signals_as_exceptions():
    try:
        hold = SignalsHeld()
        signal.pthread_kill(other.ident, signal.SIG)
        time.sleep(0.3)  # the handler has run by now, in the main thread
        print("held", flush=True)
        hold.release()
        print("not raised")
    except (EndedBySignal, KeyboardInterrupt) as exc:
        print("raised at release:", type(exc).__name__)
"""


@pytest.mark.parametrize("name", ["SIGTERM", "SIGHUP", "SIGINT"])
def test_a_signal_to_another_thread_waits_for_the_hold(name):
    done = subprocess.run([sys.executable, "-c", SCRIPT.replace("signal.SIG)", f"signal.{name})")],
                          capture_output=True, text=True, cwd=REPO, timeout=30)
    expected = "KeyboardInterrupt" if name == "SIGINT" else "EndedBySignal"
    assert done.stdout.splitlines() == ["held", f"raised at release: {expected}"], done.stderr


def test_a_file_written_atomically_is_gone_when_a_signal_comes_at_its_creation(tmp_path):
    """The same, through atomic_output: the signal arrives while the temporary is made."""
    script = f"""
import os, signal, threading, tempfile
from servicebot_cli.common import files
from servicebot_cli.common.signals import EndedBySignal, signals_as_exceptions
idle = threading.Event()
other = threading.Thread(target=idle.wait, daemon=True)
other.start()
made = tempfile.mkstemp
def mkstemp(*args, **kwargs):
    found = made(*args, **kwargs)
    signal.pthread_kill(other.ident, signal.SIGTERM)
    import time; time.sleep(0.2)
    return found
files.tempfile.mkstemp = mkstemp
with signals_as_exceptions():
    try:
        with files.atomic_output({str(tmp_path / "out.csv")!r}) as handle:
            handle.write("never")
    except EndedBySignal:
        print("ended")
"""
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          cwd=REPO, timeout=30)
    assert done.stdout.split() == ["ended"], done.stderr
    assert list(tmp_path.iterdir()) == []


def test_the_signal_exception_crosses_a_process_boundary():
    """A sweep worker sends EndedBySignal back to its parent: unpickling it called
    __init__ with its message (TypeError), which broke the pool and left sweep hanging."""
    import pickle
    import signal

    from servicebot_cli.common.signals import EndedBySignal

    back = pickle.loads(pickle.dumps(EndedBySignal(signal.SIGTERM)))
    assert (back.signum, back.exit_code, back.description) == (
        signal.SIGTERM, 143, "terminated (SIGTERM)")
