"""A bad sweep file, scenario value or expectation is one error line with file, line and field,
and nothing runs."""

from __future__ import annotations

import pytest

from tests.conftest import assert_one_line_error

SWEEP = """\
scenario: default
seeds: 2
set: {duration_s: 5}
grid:
  slip.track_factor: [0.9, 1.0]
expect:
  - collisions == 0
"""


@pytest.mark.parametrize(("change", "needles"), [
    (("slip.track_factor: [0.9, 1.0]", "slip.track_factor: [0.9, -1.0]"),
     ["sweep.yaml:5:", "slip.track_factor: must be positive, got -1"]),
    (("slip.track_factor", "slip.track_facter"),
     ["sweep.yaml:5:", "slip.track_facter: unknown field; did you mean 'track_factor'?"]),
    (("slip.track_factor", "slip..track"), ["sweep.yaml:5:", "is not a field path"]),
    (("slip.track_factor: [0.9, 1.0]", "cmd_vel[20].linear_m_s: [0.1]"),
     ["sweep.yaml:5:", "cmd_vel has 8 elements, no [20]"]),
    (("slip.track_factor: [0.9, 1.0]", "slip.track_factor: []"),
     ["sweep.yaml:5:", "grid.slip.track_factor: expected a non-empty list"]),
    (("seeds: 2", "seeds: -2"), ["sweep.yaml:2:", "seeds: expected a count of seeds"]),
    (("seeds: 2", "seeds: [1, 1]"), ["sweep.yaml:2:", "a seed is given twice"]),
    (("collisions == 0", "colisions == 0"),
     ["sweep.yaml:7:", "'colisions' is not a field of the summary; did you mean 'collisions'?"]),
    (("collisions == 0", "collisions = 0"), ["sweep.yaml:7:", "is not FIELD OP NUMBER"]),
    (("collisions == 0", "__import__('os').system('true') == 0"),
     ["sweep.yaml:7:", "is not a summary field"]),
    (("scenario: default", "scenario: nosuch.yaml"), ["nosuch.yaml: no such file"]),
    (("scenario: default", "scenaro: default"), ["sweep.yaml:1:", "did you mean 'scenario'?"]),
    (("set: {duration_s: 5}", "set: {duration_s: 5, arm.joint_names: [nosuch_joint]}"),
     ["default scenario:", "arm.points[0].positions: expected a list of 1 numbers",
      'with duration_s=5, arm.joint_names=["nosuch_joint"]']),
])
def test_bad_sweep_is_refused_before_any_run(run, write_sweep, tmp_path, change, needles):
    path = write_sweep(SWEEP.replace(*change))
    out = tmp_path / "out"
    result = run("sweep", path, "--out", out)
    assert_one_line_error(result, 2, *needles)
    assert not out.exists()


def test_a_value_the_robot_refuses_names_the_sweep_line(run, write_sweep, tmp_path):
    # The arm's first joint is limited by the URDF; 50 rad is outside any limit.
    path = write_sweep(SWEEP.replace(
        "slip.track_factor: [0.9, 1.0]", "arm.points[0].positions: [[0.1, 0, 0, 0], "
        "[50, 0, 0, 0]]"))
    result = run("sweep", path, "--out", tmp_path / "out")
    assert_one_line_error(result, 2, "sweep.yaml:5:", "arm.points[0].positions")
    assert not (tmp_path / "out").exists()


def test_sample_needs_a_known_distribution(run, write_sweep):
    path = write_sweep(SWEEP + "sample:\n  n: 3\n  initial_pose.yaw_rad: {normal: [0, 1]}\n")
    assert_one_line_error(run("sweep", path), 2, "sweep.yaml:10:", "{uniform: [LOW, HIGH]}")


def test_jobs_and_scheduler_together_are_refused(run, write_sweep):
    result = run("sweep", write_sweep(SWEEP), "--jobs", "2", "--scheduler", "tcp://x:8786")
    assert_one_line_error(result, 2, "--jobs has no effect with --scheduler")


def test_keep_needs_out(run, write_sweep):
    result = run("sweep", write_sweep(SWEEP), "--keep", "csv")
    assert_one_line_error(result, 2, "--keep has no effect without --out DIR")


def test_keep_names_known_outputs(run, write_sweep, tmp_path):
    result = run("sweep", write_sweep(SWEEP), "--out", tmp_path / "o", "--keep", "csv,mcap")
    assert_one_line_error(result, 2, "keep any of csv, bag, plot")


@pytest.mark.parametrize("address", ["tcp://127.0.0.1:9", "127.0.0.1:9", "tls://127.0.0.1:9"])
def test_no_scheduler_at_the_address_is_one_line(run, write_sweep, address):
    pytest.importorskip("distributed")
    result = run("sweep", write_sweep(SWEEP), "--scheduler", address)
    assert_one_line_error(result, 2, f"no Dask scheduler answers at {address}")


@pytest.mark.parametrize(("text", "got"), [("", "got nothing"), ("# all commented out\n",
                                                                  "got nothing"),
                                           ("{}", "got nothing"), ("- seeds: 2\n", "a list")])
def test_an_empty_sweep_file_is_refused_not_run_as_the_default(run, write_sweep, text, got):
    result = run("sweep", write_sweep(text))
    assert_one_line_error(result, 2, "sweep.yaml", "expected a sweep, a mapping of scenario",
                          got, "e.g. 'seeds: 10'")
