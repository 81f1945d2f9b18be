"""The live window keeps a thinned run: what it stores does not grow with the duration."""

from __future__ import annotations

import dataclasses

import numpy as np
from matplotlib.figure import Figure

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.simulate import simulator
from servicebot_cli.simulate.files import live, plot
from servicebot_cli.simulate.scenario.definition import load_scenario
from servicebot_cli.simulate.session import Outputs, run_and_write
from servicebot_cli.simulate.world.solids import world_solids
from tests.simulate.helpers import body

BODY = body()


def _gathered(duration_s: float, piece_s: float) -> live.LiveTrack:
    """The live window's track of the built-in scenario, gathered piece by piece."""
    scenario = dataclasses.replace(load_scenario(None), duration_s=duration_s)
    writer: live.LiveWriter | None = None
    for piece in simulator.pieces(BODY, scenario, seed=0, solids=world_solids(scenario.world),
                                  piece_s=piece_s):
        writer = writer or live.LiveWriter(piece)
        writer.add(piece)
    assert writer is not None
    writer.finish(None)
    return writer.track


def test_points_kept_do_not_grow_with_the_simulated_duration(monkeypatch):
    monkeypatch.setattr(plot, "MAX_POINTS", 300)
    monkeypatch.setattr(live, "MAX_SCANS", 20)
    short, long = _gathered(20.0, 7.0), _gathered(80.0, 7.0)
    assert len(np.vstack(long.track.truth)) <= 301  # 8,001 boundaries, thinned
    assert len(long.scans) <= 20  # of 800 scans
    assert long.stored_points() <= 1.1 * short.stored_points()
    # a bound that does not depend on the duration: three series and 20 scans of 360 returns
    assert long.stored_points() <= 3 * 301 + 20 * 360


def test_a_frame_shows_the_kept_pose_and_the_last_kept_scan(monkeypatch):
    monkeypatch.setattr(plot, "MAX_POINTS", 300)
    monkeypatch.setattr(live, "MAX_SCANS", 20)
    track = _gathered(30.0, 4.0)
    scenario = dataclasses.replace(load_scenario(None), duration_s=30.0)
    whole = simulator.run(BODY, scenario, seed=0, solids=world_solids(scenario.world))
    series = live._Series.of(track)
    artists = live._artists(Figure().add_subplot())
    t = 17.3
    live._update(artists, track, series, t)
    xs, ys = (np.asarray(v, dtype=float) for v in artists.truth.get_data())
    stride = track.track.tick_stride
    k = int(t / whole.truth.dt_s + 1e-9) // stride * stride  # the last kept boundary
    assert (xs[-1], ys[-1]) == (whole.truth.x_m[k], whole.truth.y_m[k])
    assert len(xs) == k // stride + 1
    # the scan drawn is the first of the run's stretch of 1.5 s that holds t (20 stretches)
    stretches = np.floor(whole.scans[0].times_s / (30.0 / 20))
    index = int(np.flatnonzero(stretches == int(t // 1.5))[0])
    assert whole.scans[0].times_s[index] <= t
    drawn = np.column_stack([np.asarray(v, dtype=float) for v in artists.scan.get_data()])
    np.testing.assert_array_equal(drawn, plot.scan_points(whole.scans[0], index))


def test_the_live_window_gathers_a_track_not_the_whole_run(tmp_path):
    robot = load(RobotSource.bundled("sim"))
    report = run_and_write(robot, load_scenario(None), seed=0, outputs=Outputs(),
                           scenario_dir=tmp_path, live=True, piece_s=7.0)
    assert report.result is None and report.live_track is not None
    track = report.live_track
    assert track.duration_s == 180.0
    assert track.track.truth and track.scans  # every piece went to it
