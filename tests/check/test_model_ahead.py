"""SB701's model built by a forked worker while a one-file check runs its other rules.

The child's verdict must be Pinocchio's own (same finding, same text), a child that dies
must not lose the finding, and a stopped child must not be left behind. Whole runs compare
the forked path (two cores) with the serial one (the process held to one core).
"""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from servicebot_cli.check import model_ahead
from servicebot_cli.check.model import check as model_check
from servicebot_cli.check.model_ahead import ModelAhead
from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.common.forked import Worker, WorkerEnded
from servicebot_cli.description.loader import RobotSource, read_description
from servicebot_cli.description.model import build_model
from tests.check.helpers import findings, fixture
from tests.processes import reaped

REFUSED = fixture("SB701")


def _in_process_error(text: str, display: str) -> str:
    with pytest.raises(DescriptionError) as caught:
        build_model(text, display)
    return str(caught.value)


def test_verdict_is_pinocchios_refusal():
    text = REFUSED.read_text()
    ahead = model_ahead.start(text, "r.urdf")
    assert ahead is not None and ahead.pid is not None
    pid = ahead.pid
    assert ahead.result() == _in_process_error(text, "r.urdf")
    ahead.close(finished=True)
    assert reaped(pid)


def test_verdict_of_a_model_that_builds_is_none():
    robot = read_description(RobotSource.bundled())
    ahead = model_ahead.start(robot.xml_text, robot.display)
    assert ahead is not None
    assert ahead.result() is None
    ahead.close(finished=True)


def _end_at_once(_job: None) -> str | None:
    os._exit(0)


def _silent_child() -> ModelAhead:
    """A worker that ends without a verdict (as one killed, or crashed in a library, does)."""
    silent: ModelAhead = Worker(_end_at_once, forked=True)
    silent.submit(None)
    silent.no_more_jobs()
    return silent


def test_a_child_that_ends_without_a_verdict_leaves_the_finding_to_the_parent():
    robot = read_description(RobotSource(REFUSED, str(REFUSED)))
    silent = _silent_child()
    pid = silent.pid
    assert pid is not None
    with pytest.raises(WorkerEnded):
        silent.result()
    silent.close()
    assert reaped(pid)
    without_verdict = [(i.code, i.message) for i in model_check(robot, _silent_child())]
    assert without_verdict == [(i.code, i.message) for i in model_check(robot)]
    assert without_verdict and without_verdict[0][0] == "SB701"


def test_stop_ends_the_child_and_is_idempotent():
    ahead = model_ahead.start(REFUSED.read_text(), "r.urdf")
    assert ahead is not None and ahead.pid is not None
    pid = ahead.pid
    ahead.close()
    assert reaped(pid)
    ahead.close()  # a second close neither fails nor signals a reused process id


_RUN = """
import sys
from servicebot_cli.cli import main
try:
    main(sys.argv[1:])
except SystemExit as exc:
    code = exc.code
print("pinocchio imported:", "pinocchio" in sys.modules, file=sys.stderr)
sys.exit(code)
"""


def _check(path: str, cores: set[int], *more: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-c", _RUN, "check", "urdf", path, "--format", "json", "--isolated",
         *more],
        capture_output=True, text=True, timeout=120,
        preexec_fn=lambda: os.sched_setaffinity(0, cores))


@pytest.mark.skipif(len(os.sched_getaffinity(0)) < 2,
                    reason="the model is built ahead only with a second core to run on")
@pytest.mark.parametrize("name", ["refused", "bundled"])
def test_forked_and_serial_runs_report_the_same(name):
    """Two cores: the parent never imports Pinocchio; one core: it builds the model itself."""
    path = str(REFUSED) if name == "refused" else ""
    args = path or str(RobotSource.bundled().path)
    two = sorted(os.sched_getaffinity(0))[:2]
    forked, serial = _check(args, set(two)), _check(args, {two[0]})
    assert forked.stdout == serial.stdout
    assert forked.returncode == serial.returncode == (1 if path else 0)
    assert "pinocchio imported: False" in forked.stderr, forked.stderr
    assert "pinocchio imported: True" in serial.stderr, serial.stderr
    found = {f["code"] for f in findings(forked.stdout)}
    assert ("SB701" in found) == bool(path)


@pytest.mark.skipif(len(os.sched_getaffinity(0)) < 2, reason="needs a second core to decline")
def test_jobs_1_keeps_the_run_in_one_process():
    two = set(sorted(os.sched_getaffinity(0))[:2])
    done = _check(str(RobotSource.bundled().path), two, "--jobs", "1")
    assert done.returncode == 0, done.stderr
    assert "pinocchio imported: True" in done.stderr
