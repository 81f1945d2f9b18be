"""Every run of a sweep is byte for byte the `servicebot simulate` of the same values."""

from __future__ import annotations

import json

import yaml

from servicebot_cli.simulate.scenario.definition import DEFAULT_SCENARIO
from tests.conftest import run_servicebot


def _files(directory):
    return {p.relative_to(directory).as_posix(): p.read_bytes()
            for p in sorted(directory.rglob("*")) if p.is_file()}


def test_a_run_equals_simulate_with_its_values_in_a_scenario_file(tmp_path, write_sweep):
    # The sweep's scenario is a copy of the default one, so both summaries name it "loop".
    (tmp_path / "sweep").mkdir()
    (tmp_path / "sweep" / "loop.yaml").write_text(DEFAULT_SCENARIO.read_text())
    sweep = write_sweep({
        "scenario": "loop.yaml", "seeds": [0, 7], "set": {"duration_s": 20},
        "grid": {"slip.track_factor": [0.95, 1.2]},
        "sample": {"n": 1, "seed": 3, "initial_pose.yaw_rad": {"uniform": [-0.2, 0.2]}},
    }, name="sweep/sweep.yaml")
    out = tmp_path / "out"
    result = run_servicebot("sweep", sweep, "--out", out, "--keep", "csv,bag", "--jobs", "2")
    assert result.returncode == 0, result.stderr
    rows = list(json.loads(p.read_text()) for p in (out / "runs").glob("*/run.json"))
    assert len(rows) == 4
    record = next(r for r in rows if r["seed"] == 7 and r["values"]["slip.track_factor"] == 1.2)
    yaw = record["values"]["initial_pose.yaw_rad"]
    assert -0.2 <= yaw <= 0.2

    scenario = yaml.safe_load(DEFAULT_SCENARIO.read_text())
    scenario["slip"]["track_factor"] = 1.2  # duration_s: cut short by --duration-s, as set: does
    scenario["initial_pose"]["yaw_rad"] = yaw
    alone = tmp_path / "alone"
    alone.mkdir()
    (alone / "loop.yaml").write_text(yaml.safe_dump(scenario))
    result = run_servicebot("simulate", "--headless", "-s", alone / "loop.yaml", "--seed", 7,
                            "--duration-s", 20, "--out", alone / "csv", "--bag", alone / "bag")
    assert result.returncode == 0, result.stderr

    kept = out / "runs" / record["key"]
    assert _files(kept / "csv") == _files(alone / "csv")
    assert len(_files(kept / "csv")) >= 9
    assert json.loads((kept / "csv" / "summary.json").read_text()) == record["summary"]
    assert _files(kept / "bag").keys() == {"bag_0.mcap", "metadata.yaml"}
    assert _files(kept / "bag") == _files(alone / "bag")


def test_the_built_in_scenario_fits_another_robot_as_simulate_fits_it(tmp_path, write_sweep):
    """A robot without the bundled arm: its joints hold still in both, with the same note."""
    from tests.simulate.plugin_robots import TURTLEBOT3

    sweep = write_sweep({"scenario": "default", "seeds": [3], "set": {"duration_s": 4}})
    out = tmp_path / "out"
    result = run_servicebot("sweep", sweep, TURTLEBOT3, "--out", out, "--keep", "bag",
                            "--jobs", "1")
    assert result.returncode == 0, result.stderr
    notes = [line for line in result.stderr.splitlines() if line.startswith("note:")]
    alone = run_servicebot("simulate", "--headless", TURTLEBOT3, "--seed", 3, "--duration-s", 4,
                           "--bag", tmp_path / "bag")
    assert alone.returncode == 0, alone.stderr
    assert len(notes) == 1 and "arm_base_to_link1" in notes[0]
    assert notes == [line for line in alone.stderr.splitlines() if line.startswith("note:")]
    (record,) = (json.loads(p.read_text()) for p in (out / "runs").glob("*/run.json"))
    assert _files(out / "runs" / record["key"] / "bag") == _files(tmp_path / "bag")
