"""sweep's help is light; its tables and statistics agree with its runs; the progress bar."""

from __future__ import annotations

import csv
import io
import json
import os
import pty
import statistics
import subprocess
import sys

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


def _screen(text: str) -> list[str]:
    """What a terminal shows for ``text``: each carriage return writes over its line."""
    lines = []
    for line in text.split("\n"):
        shown = ""
        for part in line.split("\r"):
            shown = part + shown[len(part):]
        lines.append(shown)
    return lines


def test_progress_is_drawn_at_once_and_a_shorter_line_leaves_nothing_behind(monkeypatch):
    monkeypatch.delenv("CI", raising=False)
    now = [0.0]
    stream = _Terminal()
    bar = SweepProgress(100, stream, clock=lambda: now[0])
    assert _screen(stream.getvalue()) == ["sweep   0/100 [------------------------]"]
    now[0] = 65 / 99
    bar.advance()  # 65/99 s per run, 99 to go: 1m05s
    assert _screen(stream.getvalue())[-1].endswith("] 1m05s left")
    now[0] = 100.0
    bar.advance()  # 50 s per run, 98 to go: over an hour; then 2 s per run: 2m36s
    now[0] = 200.0
    bar.advance()
    now[0] = 201.0
    for _ in range(96):
        now[0] += 0.2
        bar.advance()
    assert _screen(stream.getvalue())[-1].rstrip() == \
        "sweep  99/100 [#######################-] 2s left"  # not "2s leftleft"
    bar.close()
    assert _screen(stream.getvalue())[-1].strip() == ""


def test_progress_is_silent_in_pipes_and_ci(monkeypatch):
    stream = io.StringIO()
    bar = SweepProgress(3, stream)
    bar.advance()
    bar.close()
    monkeypatch.setenv("CI", "true")
    assert not SweepProgress(3, _Terminal()).enabled
    assert stream.getvalue() == ""


def test_the_command_draws_the_bar_on_a_terminal_and_keeps_stdout_clean(write_sweep):
    sweep = write_sweep({"seeds": 6, "set": {"duration_s": 2}})
    master, slave = pty.openpty()
    env = {k: v for k, v in os.environ.items() if k != "CI"}
    process = subprocess.Popen([sys.executable, "-m", "servicebot_cli", "sweep", sweep,
                                "--jobs", "2"], stdout=subprocess.PIPE, stderr=slave, env=env)
    os.close(slave)
    terminal = b""
    while True:
        try:
            chunk = os.read(master, 4096)
        except OSError:  # EIO: the command closed the terminal
            break
        if not chunk:
            break
        terminal += chunk
    os.close(master)
    stdout = process.stdout.read().decode()
    assert process.wait(timeout=60) == 0, terminal
    text = terminal.decode().replace("\r\n", "\n")
    assert text.startswith("\rsweep 0/6 [------------------------]")
    assert "\rsweep 6/6 [########################] " in text
    assert _screen(text)[0].startswith("ran 6 runs in ")  # the bar was erased, then this
    assert "\r" not in stdout and "finished 6, 6 passed, 0 failed" in stdout
