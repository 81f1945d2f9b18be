"""How a ``servicebot`` process ends: the console script and ``python -m`` skip the teardown.

After the command returns, the process ends with :func:`os._exit` once atexit functions have
run and the standard streams are flushed; whatever stdout cannot take is one error line.
"""

from __future__ import annotations

import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

from tests.conftest import assert_one_line_error, run_servicebot

FULL = Path("/dev/full")


def test_every_line_of_a_large_stdout_reaches_the_reader() -> None:
    """A batch of 20,000 poses (about 2 MB, far over a pipe's buffer) arrives whole."""
    rows = "".join(f"{i * 5e-5:.5f},0.2,-0.3,0.1\n" for i in range(20_000))
    result = run_servicebot("fk", "--configs", "-", input=(
        "arm_base_to_link1,arm_link1_to_link2,arm_link2_to_link3,arm_link3_to_link4\n" + rows))
    assert result.returncode == 0, result.stderr
    lines = result.stdout.splitlines()
    assert len(lines) == 20_001, lines[-3:]  # the header and one line per configuration
    assert lines[-1].count(",") == lines[1].count(",") > 3


def test_atexit_functions_still_run() -> None:
    """A function registered with atexit (multiprocessing and tempfile rely on them) runs."""
    probe = ("import atexit, sys\n"
             "atexit.register(lambda: sys.stderr.write('atexit ran\\n'))\n"
             "sys.argv = ['servicebot', '--version']\n"
             "from servicebot_cli.cli import entry\n"
             "entry()\n")
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("servicebot")
    assert done.stderr == "atexit ran\n"


def test_the_console_script_is_the_fast_entry() -> None:
    """The installed ``servicebot`` script calls the same entry as ``python -m``."""
    script = Path(sysconfig.get_path("scripts")) / "servicebot"
    if not script.exists():
        pytest.skip(f"no console script at {script}: the package is not installed here")
    assert "from servicebot_cli.cli import entry" in script.read_text()
    done = subprocess.run([str(script), "--version"], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 0 and done.stdout.startswith("servicebot"), done.stderr


@pytest.mark.skipif(not FULL.is_char_device(), reason="no /dev/full")
@pytest.mark.parametrize("args", [
    ("inspect",),  # a subcommand's report
    ("fk", "--help"),  # a subcommand's help, printed while its options are parsed
    ("--help",),  # the group's own help
    ("--version",),
])
def test_a_full_stdout_is_one_error_line(args: tuple[str, ...]) -> None:
    with FULL.open("w") as full:
        result = subprocess.run([sys.executable, "-m", "servicebot_cli", *args], stdout=full,
                                stderr=subprocess.PIPE, text=True, timeout=60)
    result.stdout = ""  # it went to /dev/full
    assert_one_line_error(result, 2, "standard output: cannot write: No space left on device",
                          "free some space")


def test_a_standard_error_the_shell_closed_is_no_error() -> None:
    """``servicebot --version 2>&-``: Python sets the closed stream to None; nothing to flush."""
    done = subprocess.run(f"'{sys.executable}' -m servicebot_cli --version 2>&-", shell=True,
                          capture_output=False, stdout=subprocess.PIPE, text=True, timeout=60)
    assert done.returncode == 0 and done.stdout.startswith("servicebot")


@pytest.mark.parametrize("args", [("fk",), ("check", "urdf", "--isolated"), ("--version",),
                                  ("inspect", "--help")])
def test_a_closed_standard_output_is_a_usage_error_not_a_silent_success(args):
    """Started with fd 1 closed (`>&-`), Python has no sys.stdout and Click dropped every
    line: the command exited 0 with its answer lost."""
    import os

    result = subprocess.run([sys.executable, "-m", "servicebot_cli", *args],
                            preexec_fn=lambda: os.close(1),  # noqa: PLW1509 - in the child
                            stderr=subprocess.PIPE, text=True, timeout=60)
    assert result.returncode == 2, result.stderr
    assert result.stderr.splitlines() == [
        "Error: standard output is closed, so the output has nowhere to go; redirect it "
        "(> FILE, or > /dev/null to drop it)"]
