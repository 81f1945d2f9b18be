"""The click-free ``simulate`` entry point: a request in, a typed report out."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.common.jsonable import dumps
from servicebot_cli.description.loader import RobotSource
from servicebot_cli.output.simulate_text import speed_line, summary_lines
from servicebot_cli.simulate import session
from servicebot_cli.simulate.session import Outputs, Overrides, SimulateReport, SimulateRequest


def _ticks(*values: float):
    """A clock that returns ``values`` in turn: the wall time is known exactly."""
    it = iter(values)
    return lambda: next(it)


def test_run_returns_the_summary_and_the_wall_time_of_the_run(tmp_path):
    request = SimulateRequest(RobotSource.bundled("sim"), overrides=Overrides(duration_s=5.0),
                              seed=3, outputs=Outputs(out_dir=str(tmp_path / "out")))
    report = session.run(request, clock=_ticks(10.0, 10.5))
    assert isinstance(report, SimulateReport)
    assert report.wall_s == 0.5 and report.real_time_factor == pytest.approx(10.0)
    assert report.summary["duration_s"] == 5.0 and report.summary["seed"] == 3
    assert report.result is None  # streamed to the outputs, not kept
    assert json.loads((tmp_path / "out" / "summary.json").read_text()) == json.loads(
        dumps(report.summary))
    assert speed_line(report) == "simulated 5 s in 0.50 s (real-time factor 10)"
    lines = list(summary_lines(report.summary))
    assert lines[0] == "service_robot, scenario default, 5 s, seed 3"


def test_overrides_replace_only_what_they_name(tmp_path):
    scenario = tmp_path / "s.yaml"
    scenario.write_text("duration_s: 2\ncontroller: {cmd_vel_timeout_s: 0.25, "
                        "saturation: per-wheel}\n")
    request = SimulateRequest(RobotSource.bundled("sim"), str(scenario),
                              Overrides(wheel_separation_multiplier=1.2))
    controller = session.run(request).summary["controller"]
    assert (controller["wheel_separation_multiplier"], controller["cmd_vel_timeout_s"],
            controller["saturation"]) == ({"value": 1.2, "source": "command line"},
                                          {"value": 0.25, "source": "scenario"},
                                          {"value": "per-wheel", "source": "scenario"})
    changed = session.run(dataclasses.replace(
        request, overrides=Overrides(duration_s=1.0, saturation="keep-curvature")))
    assert changed.summary["duration_s"] == 1.0
    assert changed.summary["controller"]["saturation"]["value"] == "keep-curvature"


def test_live_window_without_a_display_is_refused_before_any_work(tmp_path, monkeypatch):
    monkeypatch.setenv("DISPLAY", "")
    monkeypatch.setenv("WAYLAND_DISPLAY", "")
    request = SimulateRequest(RobotSource.bundled("sim"), live_window=True,
                              outputs=Outputs(out_dir=str(tmp_path / "out")))
    with pytest.raises(ServicebotError, match="--headless"):
        session.run(request)
    assert list(tmp_path.iterdir()) == []


def test_live_window_frame_draws_the_path_up_to_its_time():
    from matplotlib.figure import Figure

    from servicebot_cli.description.loader import load
    from servicebot_cli.simulate.files import live
    from servicebot_cli.simulate.scenario.definition import load_scenario

    scenario = dataclasses.replace(load_scenario(None), duration_s=4.0)
    result = session.run_and_write(load(RobotSource.bundled("sim")), scenario, seed=0,
                                   outputs=Outputs(), scenario_dir=Path.cwd(),
                                   keep_run=True).result  # a run kept whole
    assert result is not None and result.first and result.last
    ax = Figure().add_subplot()
    artists = live._artists(ax)
    track = live.LiveTrack.of_run(result)
    live._update(artists, track, live._Series.of(track), 2.0)
    xs, _ = artists.truth.get_data()
    assert len(xs) == round(2.0 / result.truth.dt_s) + 1
    outline = np.asarray(artists.body.get_data()[0], dtype=float)
    # one closed outline per collision part, separated by NaN breaks
    assert np.isnan(outline).sum() == len(result.body.shape.parts)
    assert artists.clock.get_text().endswith("t =    2.0 s")


_CLOCK_SEES = """
import sys, time
from servicebot_cli.description.loader import RobotSource
from servicebot_cli.simulate import session
seen = []
def clock():
    seen.append(("numba" in sys.modules, "servicebot_cli.simulate.bag.rosbag" in sys.modules))
    return time.perf_counter()
request = session.SimulateRequest(
    RobotSource.bundled("sim"), seed=0, outputs=session.Outputs(bag=sys.argv[1]),
    overrides=session.Overrides(duration_s=2.0, camera_scale=0.05 if sys.argv[2] else None))
session.run(request, clock=clock)
print(seen[0])
"""


@pytest.mark.parametrize("camera", [True, False])
def test_the_run_clock_starts_once_the_writers_and_the_camera_renderer_are_loaded(tmp_path,
                                                                                    camera):
    """Importing is loading: numba (0.3 s) for the camera, the bag's modules, before the clock."""
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-c", _CLOCK_SEES, str(tmp_path / "bag"),
                           "1" if camera else ""], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == f"({camera}, True)"
