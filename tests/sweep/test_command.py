"""sweep's help is light; its tables and statistics agree with its runs; the progress bar."""

from __future__ import annotations

import csv
import io
import json
import statistics

from servicebot_cli.sweep.progress import SweepProgress
from tests.foundation.test_cli_shape import HEAVY, _imported


def test_help_imports_nothing_heavy():
    modules, stdout = _imported(["sweep", "--help"])
    assert "SWEEP.yaml" in stdout and "--scheduler" in stdout
    assert not HEAVY & modules, HEAVY & modules
    assert not {"distributed", "dask"} & modules


def test_summary_statistics_are_those_of_the_runs(run, write_sweep, tmp_path):
    sweep = write_sweep({"seeds": 3, "set": {"duration_s": 6},
                         "grid": {"slip.longitudinal": [0.0, 0.2]},
                         "sample": {"n": 2, "seed": 5,
                                    "initial_pose.x_m": {"uniform": [-0.6, -0.4]}}})
    out = tmp_path / "out"
    plot = tmp_path / "sweep.png"
    result = run("sweep", sweep, "--out", out, "--plot", plot, "--format", "json")
    assert result.exit_code == 0, result.stderr
    printed = json.loads(result.stdout)
    assert printed == json.loads((out / "summary.json").read_text())
    assert printed["runs"] == printed["finished"] == printed["passed"] == 12
    rows = list(csv.DictReader((out / "runs.csv").open()))
    assert len({r["initial_pose.x_m"] for r in rows}) == 2   # two draws, shared by both points
    for point in printed["points"]:
        mine = [float(r["distance_m"]) for r in rows if int(r["point"]) == point["point"]]
        assert len(mine) == point["runs"] == 6
        stats = point["metrics"]["distance_m"]
        assert stats["median"] == statistics.median(mine)
        assert stats["max"] == max(mine) and stats["min"] == min(mine)
        assert abs(stats["std"] - statistics.stdev(mine)) < 1e-12
    slow, fast = (p["metrics"]["distance_m"]["mean"] for p in printed["points"])
    assert fast < slow  # longitudinal slip: the wheels turn, the robot goes less far
    assert plot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


class _Terminal(io.StringIO):
    def isatty(self):
        return True


def test_progress_shows_count_and_time_left(monkeypatch):
    monkeypatch.delenv("CI", raising=False)  # a person's terminal, also when CI runs the test
    now = [0.0]
    stream = _Terminal()
    bar = SweepProgress(10, stream, done=2, clock=lambda: now[0])
    assert bar.enabled
    now[0] = 4.0
    bar.advance()  # 1 run in 4 s, 7 to go
    assert stream.getvalue().endswith("sweep  3/10 [#######-----------------] 28s left")
    bar.close()
    assert stream.getvalue().endswith("\r")


def test_progress_is_silent_in_pipes_and_ci(monkeypatch):
    stream = io.StringIO()
    bar = SweepProgress(3, stream)
    bar.advance()
    bar.close()
    monkeypatch.setenv("CI", "true")
    assert not SweepProgress(3, _Terminal()).enabled
    assert stream.getvalue() == ""
