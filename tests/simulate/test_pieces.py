"""A run simulated a piece at a time: the same bytes whatever the pieces, and flat memory.

Every output (CSV, bag, picture, summary) of runs split into pieces of different lengths,
one tick long included, is compared byte for byte with the run computed in one piece.
"""

from __future__ import annotations

import dataclasses
import tracemalloc
from pathlib import Path

import numpy as np

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.simulate import session, simulator
from servicebot_cli.simulate.files import plot
from servicebot_cli.simulate.scenario.definition import load_scenario
from servicebot_cli.simulate.sensors.noise import Noise, apply, one_after_another
from servicebot_cli.simulate.sensors.sample import SampleClock, sample_times
from servicebot_cli.simulate.session import Outputs
from tests.simulate.helpers import scenario

# The arm swings into a wall and the base, held there, waits until it can back away; the
# floor slips; a cylinder is close by; every sensor is on, the camera's images too.
EVENTFUL = {
    "duration_s": 9.0,
    "slip": {"track_factor": 1.2, "longitudinal": 0.02},
    "controller": {"max_linear_acceleration_m_s2": 0.3, "publish_rate_hz": 30},
    "cmd_vel": [{"duration_s": 3, "linear_m_s": 0.02, "angular_rad_s": 0.03},
                {"duration_s": 3, "linear_m_s": 0.5},
                {"duration_s": 3, "linear_m_s": -0.3}],
    "arm": {"joint_names": ["arm_base_to_link1", "arm_link1_to_link2"],
            "points": [{"time_from_start_s": 2, "positions": [0.5, -0.3]},
                       {"time_from_start_s": 7, "positions": [-0.5, 0.3]}]},
    "world": {"walls": [{"from_m": [0.95, -1], "to_m": [0.95, 1]}],
              "cylinders": [{"center_m": [-0.6, 0.4], "radius_m": 0.1}]},
    # 38x22 images with noise and depth, in the bag and the last one as camera.png
    "camera": {"scale": 0.02, "rate_hz": 3, "depth": True},
}
ROBOT = load(RobotSource.bundled("sim"))


def _outputs(tmp_path: Path, name: str, piece_s: float | None,
             keep_run: bool = False) -> tuple[dict[str, bytes], session.SimulateReport]:
    base = tmp_path / name
    base.mkdir()
    report = session.run_and_write(
        ROBOT, scenario(EVENTFUL), seed=11, scenario_dir=base, piece_s=piece_s,
        keep_run=keep_run, outputs=Outputs(str(base / "out"), str(base / "bag"),
                                           str(base / "run.png")))
    files = {p.relative_to(base).as_posix(): p.read_bytes() for p in sorted(base.rglob("*"))
             if p.is_file()}
    return files, report


def test_the_piece_length_does_not_change_a_byte(tmp_path, monkeypatch):
    monkeypatch.setattr(plot, "MAX_POINTS", 97)  # the picture thins its lines too
    whole, report = _outputs(tmp_path, "whole", None, keep_run=True)
    assert report.result is not None and report.result.first and report.result.last
    assert report.summary["collisions"] and report.summary["self_collisions"] == []
    assert len(whole) == 13  # 9 CSV, summary.json, camera.png, the bag's two files, the picture
    assert len(report.result.frames) == 27
    for piece_s in (0.01, 0.37, 2.0, simulator.PIECE_S):
        pieces, _ = _outputs(tmp_path, f"pieces_{piece_s}", piece_s)
        assert sorted(pieces) == sorted(whole)
        for name, data in whole.items():
            assert pieces[name] == data, f"{name} differs in pieces of {piece_s} s"


def test_pieces_cover_every_tick_once():
    from servicebot_cli.simulate.body import sim_robot
    from servicebot_cli.simulate.world.solids import world_solids

    body = sim_robot(ROBOT)
    s = scenario({"duration_s": 1.005})
    parts = list(simulator.pieces(body, s, seed=0, solids=world_solids(s.world), piece_s=0.3))
    assert [(p.first_tick, p.plan.ticks) for p in parts] == [(0, 30), (30, 30), (60, 30),
                                                              (90, 11)]
    assert [p.last for p in parts] == [False, False, False, True]
    boundaries = [p.truth.x_m for p in parts]
    for before, after in zip(boundaries, boundaries[1:], strict=False):
        assert after[0] == before[-1]  # a piece starts where the one before ended


def test_pieces_of_many_rays_are_cut_to_keep_their_scans_within_bounds(monkeypatch):
    """A LIDAR of many rays at a high rate fills a 30 s piece with gigabytes of ranges:
    pieces are cut so their scans stay within SCAN_PIECE_BYTES (here 2 MB, for the bundled
    robot's 360 rays at 10 Hz, 115 kB a second)."""
    from servicebot_cli.simulate.body import sim_robot
    from servicebot_cli.simulate.world.solids import world_solids

    body = sim_robot(ROBOT)
    s = scenario({"duration_s": 60.0})
    monkeypatch.setattr(simulator, "SCAN_PIECE_BYTES", 2_000_000)
    parts = list(simulator.pieces(body, s, seed=0, solids=world_solids(s.world)))
    # 2e6 B / (32 B x 360 rays x 10 Hz) = 17.36 s: 1,736 ticks a piece, not 3,000
    assert [p.plan.ticks for p in parts] == [1736, 1736, 1736, 792]


def test_sample_clock_hands_out_the_whole_runs_times_in_pieces():
    rng = np.random.default_rng(2)
    for rate, duration, dt in ((30.0, 9.0, 0.01), (7.0, 3.33, 0.02), (100.0, 2.0, 0.01)):
        clock = SampleClock(rate, duration, dt)
        stops = np.cumsum(rng.integers(0, 40, 20))
        got = np.concatenate([clock.take(int(s)) for s in stops] + [clock.take(None)])
        assert got.tobytes() == sample_times(rate, duration).tobytes()


def test_noise_drawn_in_pieces_is_the_noise_drawn_whole():
    from servicebot_cli.description.sensors import NoiseSpec

    specs = [NoiseSpec("gaussian", 0.1, 0.2, 0.3, 0.4), None, NoiseSpec("gaussian", 0, 1)]
    whole_rng = np.random.default_rng([5, 7])
    whole = [apply(np.zeros(50), spec, whole_rng) for spec in specs]  # one after another
    noises = one_after_another(specs, np.random.default_rng([5, 7]), 50)
    for spec, noise, expected in zip(specs, noises, whole, strict=True):
        pieces = np.concatenate([noise.add(np.zeros(n)) for n in (0, 13, 1, 36)])
        assert pieces.tobytes() == expected.tobytes(), spec
    assert isinstance(noises[1], Noise) and noises[1].add(np.ones(2)).tolist() == [1, 1]


def _peak_traced_bytes(duration_s: float, tmp_path: Path) -> int:
    s = dataclasses.replace(load_scenario(None), duration_s=duration_s)
    out = tmp_path / f"run_{duration_s:g}"
    out.mkdir()
    tracemalloc.start()
    try:
        session.run_and_write(ROBOT, s, seed=0, scenario_dir=out, piece_s=2.0,
                              outputs=Outputs(str(out / "csv"), str(out / "bag")))
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def test_memory_does_not_grow_with_the_simulated_duration(tmp_path):
    """Peak memory (numpy's arrays included) of a run with CSV and bag, and of one 4x longer.

    In pieces of 2 s, so that short runs hold many pieces; ``simulate`` takes 30 s pieces.
    """
    short = _peak_traced_bytes(10.0, tmp_path)
    long = _peak_traced_bytes(40.0, tmp_path)
    assert long < 1.3 * short, f"{short / 1e6:.1f} MB, then {long / 1e6:.1f} MB"
