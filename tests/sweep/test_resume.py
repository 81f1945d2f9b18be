"""A re-run with the same --out skips finished runs; Ctrl-C and SIGTERM keep what finished."""

from __future__ import annotations

import csv
import os
import signal
import subprocess
import sys
import time

import pytest

SWEEP = {"scenario": "default", "seeds": 3, "set": {"duration_s": 5},
         "grid": {"slip.track_factor": [0.9, 1.1]}, "expect": ["collisions == 0"]}


def _rows(out):
    with open(out / "runs.csv", newline="") as f:
        return list(csv.DictReader(f))


def test_a_rerun_skips_what_is_done_and_runs_what_is_new(run, write_sweep, tmp_path):
    out = tmp_path / "out"
    first = run("sweep", write_sweep(SWEEP), "--out", out, "--jobs", "2")
    assert first.exit_code == 0, first.stderr
    assert "finished 6, 6 passed" in first.stdout
    records = {p: p.stat().st_mtime_ns for p in out.glob("runs/*/run.json")}
    assert len(records) == 6

    again = run("sweep", write_sweep(SWEEP), "--out", out, "--jobs", "2")
    assert "finished 6 (6 found done)" in again.stdout
    assert "ran 0 runs" in again.stderr
    assert {p: p.stat().st_mtime_ns for p in out.glob("runs/*/run.json")} == records

    grown = {**SWEEP, "seeds": 4, "grid": {"slip.track_factor": [0.9, 1.1, 1.3]}}
    third = run("sweep", write_sweep(grown), "--out", out, "--jobs", "2")
    assert "finished 12 (6 found done)" in third.stdout
    assert "ran 6 runs" in third.stderr
    rows = _rows(out)
    assert [int(r["run"]) for r in rows] == list(range(12))
    assert {r["key"] for r in rows} >= {p.parent.name for p in records}


def test_another_robot_is_another_run(run, write_sweep, tmp_path):
    out = tmp_path / "out"
    assert run("sweep", write_sweep(SWEEP), "--out", out).exit_code == 0
    result = run("sweep", write_sweep(SWEEP), "--robot", "real", "--out", out)
    assert result.exit_code == 0, result.stderr
    assert "found done" not in result.stdout
    assert len(list(out.glob("runs/*/run.json"))) == 12


def test_a_missing_kept_output_runs_again(run, write_sweep, tmp_path):
    out = tmp_path / "out"
    assert run("sweep", write_sweep(SWEEP), "--out", out).exit_code == 0
    result = run("sweep", write_sweep(SWEEP), "--out", out, "--keep", "csv")
    assert "found done" not in result.stdout
    assert len(list(out.glob("runs/*/csv/ground_truth.csv"))) == 6
    assert "(6 found done)" in run("sweep", write_sweep(SWEEP), "--out", out,
                                   "--keep", "csv").stdout


@pytest.mark.parametrize(("signum", "code"), [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_an_interrupted_sweep_keeps_finished_runs(write_sweep, tmp_path, signum, code):
    long = {**SWEEP, "seeds": 40, "set": {"duration_s": 60}}
    path = write_sweep(long)
    out = tmp_path / "out"
    args = [sys.executable, "-m", "servicebot_cli", "sweep", path, "--out", out, "--jobs", "2",
            "--keep", "csv"]
    process = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               start_new_session=True)
    deadline = time.monotonic() + 60
    while len(list(out.glob("runs/*/run.json"))) < 3 and time.monotonic() < deadline:
        time.sleep(0.05)
    # Ctrl-C in a terminal reaches the whole process group, workers included.
    os.killpg(process.pid, signum) if signum == signal.SIGINT else process.send_signal(signum)
    stdout, stderr = process.communicate(timeout=60)
    assert process.returncode == code, stderr
    assert stderr.strip().splitlines()[-1].startswith("Error: ")
    assert "Traceback" not in stderr
    finished = {p.parent.name for p in out.glob("runs/*/run.json")}
    assert 3 <= len(finished) < 80
    assert {r["key"] for r in _rows(out)} == finished
    assert [p for p in out.rglob("*") if ".tmp" in p.name] == []
    assert all((out / "runs" / key / "csv" / "summary.json").exists() for key in finished)

    # The first 4 seeds of each grid value again: those that finished are found done.
    args[args.index(path)] = write_sweep({**long, "seeds": 4}, name="first4.yaml")
    done = sum(int(r["seed"]) < 4 for r in _rows(out))
    result = subprocess.run(args, capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    assert f"finished 8 ({done} found done)" in result.stdout
    assert f"ran {8 - done} run" in result.stderr
