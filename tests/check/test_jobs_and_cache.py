"""``check urdf --jobs N`` and ``--mesh-cache``: the same report, in the same order, faster.

Worker processes and the on-disk mesh summaries must never change what a run reports: the
JSON of a parallel run is compared byte for byte with a serial one, and a changed mesh is
read again however recent its cached summary.
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import time

import pytest

from tests.check.corpus import erd_root
from tests.check.helpers import FIXTURES
from tests.conftest import assert_one_line_error
from tests.processes import children

MESHES = FIXTURES / "meshes"


def report(run, *args, env=None):
    result = run("check", "urdf", "--isolated", "--format", "json", *args, env=env)
    assert result.exit_code in (0, 1), result.output
    return result.stdout


def test_workers_report_what_one_process_reports_in_the_same_order(run):
    serial = report(run, FIXTURES, "--jobs", "1")
    parallel = report(run, FIXTURES, "--jobs", "3")
    assert parallel == serial
    files = [f["file"] for f in json.loads(serial)["files"]]
    assert len(files) > 50 and files == sorted(files)  # every fixture, in the walk's order


def test_a_named_file_that_is_missing_is_the_runs_error_with_workers(run, tmp_path):
    result = run("check", "urdf", "--jobs", "2", FIXTURES / "SB404_mesh_scale.urdf",
                 tmp_path / "missing.urdf")
    assert_one_line_error(result, 2, "missing.urdf")


@pytest.fixture
def robot(tmp_path):
    """A copy of the SB404 fixture whose mesh is a cube of the right size."""
    shutil.copy(FIXTURES / "SB404_mesh_scale.urdf", tmp_path / "robot.urdf")
    (tmp_path / "meshes").mkdir()
    shutil.copy(MESHES / "cube.stl", tmp_path / "meshes" / "cube_mm.stl")
    return tmp_path / "robot.urdf"


def codes(text):
    return sorted(f["code"] for f in json.loads(text)["files"][0]["findings"])


def test_summaries_are_kept_and_used_and_a_changed_mesh_is_read_again(run, robot, tmp_path):
    env = {"XDG_CACHE_HOME": str(tmp_path / "cache")}
    first = report(run, robot, "--mesh-cache", env=env)
    stored = list((tmp_path / "cache" / "servicebot" / "meshes").rglob("*.json"))
    assert stored, "nothing kept"
    assert report(run, robot, "--mesh-cache", env=env) == first
    assert "SB404" not in codes(first)
    mesh = robot.parent / "meshes" / "cube_mm.stl"
    shutil.copy(MESHES / "cube_mm.stl", mesh)  # the same byte count: only the time tells
    later = os.stat(mesh).st_mtime_ns + 10**9
    os.utime(mesh, ns=(later, later))
    assert "SB404" in codes(report(run, robot, "--mesh-cache", env=env))


def test_an_unreadable_summary_is_read_again_from_the_mesh(run, robot, tmp_path):
    env = {"XDG_CACHE_HOME": str(tmp_path / "cache")}
    first = report(run, robot, "--mesh-cache", env=env)
    for entry in (tmp_path / "cache").rglob("*.json"):
        entry.write_text('{"triangles": "many"')
    assert report(run, robot, "--mesh-cache", env=env) == first


def test_without_the_option_nothing_is_kept(run, robot, tmp_path):
    report(run, robot, env={"XDG_CACHE_HOME": str(tmp_path / "cache")})
    assert not (tmp_path / "cache").exists()


@pytest.mark.parametrize("ending", [signal.SIGINT, signal.SIGTERM])
def test_a_signal_stops_the_workers_with_one_line(ending):
    """Workers are stopped with the run: no traceback, no process left behind."""
    corpus = sorted((erd_root() / "robots").rglob("*.urdf")) * 4  # each file four times:
    process = subprocess.Popen(  # seconds of work on any machine
        [sys.executable, "-m", "servicebot_cli", "check", "urdf", "--isolated", "--jobs", "2",
         "--package", f"example-robot-data={erd_root()}", *map(str, corpus)],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 30
    while len(children(process.pid)) < 2 and time.monotonic() < deadline:
        time.sleep(0.05)
    time.sleep(0.3)  # past the start: the workers are checking
    workers = children(process.pid)
    assert workers, "no worker processes"
    assert process.poll() is None, "the run ended before the signal"
    process.send_signal(ending)
    _, stderr = process.communicate(timeout=30)
    assert process.returncode == 128 + ending
    assert "Traceback" not in stderr
    assert len(stderr.strip().splitlines()) == 1, stderr
    time.sleep(0.2)
    assert not [pid for pid in workers if os.path.exists(f"/proc/{pid}")]


def test_a_worker_that_dies_ends_the_run_in_one_line_naming_its_files(run, tmp_path,
                                                                      monkeypatch):
    """A native library crashing in a worker (a segmentation fault) hung the run before:
    multiprocessing's pool waited for the lost task forever, and SIGTERM did not end it."""
    import faulthandler
    import os
    import signal

    from servicebot_cli.check import workers

    files = []
    for name in ("a", "b", "crash", "d"):
        path = tmp_path / f"{name}.urdf"
        path.write_text(f'<robot name="{name}"><link name="base"/></robot>')
        files.append(path)
    checked = workers.check_one

    def crashing(source, *args, **kwargs):
        if source.path.name == "crash.urdf":
            faulthandler.disable()  # pytest's would print the worker's stack in the log
            os.kill(os.getpid(), signal.SIGSEGV)  # in the forked worker, as a C++ crash would
        return checked(source, *args, **kwargs)

    monkeypatch.setattr(workers, "check_one", crashing)
    result = run("check", *files, "--jobs", "2", "--isolated")
    assert result.exit_code == 3
    (line,) = result.stderr.splitlines()
    assert line.startswith("Error: a worker process died while checking ") and "crash.urdf" in line
    assert "--jobs 1" in line
