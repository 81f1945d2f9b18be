"""A signal whose exception a library swallowed still ends the run and keeps outputs out.

numpy can clear an exception raised by a signal handler while it runs Python code inside one
of its loops (``simulate --out``'s CSV rows, about 1 SIGTERM in 13): the run went on,
finished, and exited 0 with every output in place. Here a bare ``except`` stands for that
library: the signal comes, its exception is swallowed, and the outputs are written after.
"""

from __future__ import annotations

import subprocess
import sys

import pytest

from tests.conftest import REPO

SCRIPT = """
import os, signal, sys, time
from servicebot_cli.common.files import atomic_directory, atomic_output
from servicebot_cli.common.signals import EndedBySignal, signals_as_exceptions
target = sys.argv[1]
try:
    with signals_as_exceptions():
        try:
            os.kill(os.getpid(), signal.SIG)
            time.sleep(0.2)
        except BaseException:
            pass  # a library clears it
        with OUTPUT(target) as out:
            WRITE
        print("written")
except (EndedBySignal, KeyboardInterrupt) as exc:
    print("ended:", type(exc).__name__)
"""


@pytest.mark.parametrize("name", ["SIGTERM", "SIGINT"])
@pytest.mark.parametrize(("output", "write"), [
    ("atomic_output", "out.write('rows')"),
    ("atomic_directory", "(out / 'a.csv').write_text('rows')"),
])
def test_a_swallowed_signal_keeps_the_output_out_and_ends_the_run(tmp_path, name, output, write):
    script = SCRIPT.replace("signal.SIG)", f"signal.{name})").replace("OUTPUT", output) \
        .replace("WRITE", write)
    target = tmp_path / "result"
    done = subprocess.run([sys.executable, "-c", script, str(target)], cwd=REPO,
                          capture_output=True, text=True, timeout=60)
    expected = "KeyboardInterrupt" if name == "SIGINT" else "EndedBySignal"
    assert done.stdout.strip() == f"ended: {expected}", done.stdout + done.stderr
    assert list(tmp_path.iterdir()) == []  # neither the output nor a temporary


def test_a_swallowed_signal_ends_the_block_even_with_no_output(tmp_path):
    script = SCRIPT.replace("signal.SIG)", "signal.SIGTERM)").replace(
        "        with OUTPUT(target) as out:\n            WRITE\n", "")
    done = subprocess.run([sys.executable, "-c", script, str(tmp_path / "x")], cwd=REPO,
                          capture_output=True, text=True, timeout=60)
    assert done.stdout.strip() == "written\nended: EndedBySignal", done.stdout + done.stderr


def test_what_a_clean_up_writes_while_the_signal_goes_out_is_written(tmp_path):
    # sweep writes the table of its finished runs on its way out of a Ctrl-C
    script = SCRIPT.replace("signal.SIG)", "signal.SIGTERM)").replace(
        "        except BaseException:\n            pass  # a library clears it\n"
        "        with OUTPUT(target) as out:\n            WRITE\n",
        "        except BaseException:\n            with atomic_output(target) as out:\n"
        "                out.write('finished runs')\n            raise\n")
    done = subprocess.run([sys.executable, "-c", script, str(tmp_path / "runs.csv")], cwd=REPO,
                          capture_output=True, text=True, timeout=60)
    assert done.stdout.strip() == "ended: EndedBySignal", done.stdout + done.stderr
    assert (tmp_path / "runs.csv").read_text() == "finished runs"
