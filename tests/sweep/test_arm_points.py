"""A swept arm point that puts the robot through itself is refused as simulate refuses it."""

from __future__ import annotations

from tests.conftest import assert_one_line_error

SWEEP = """\
scenario: default
seeds: 1
set: {duration_s: 3}
grid:
  arm.points[0].positions: [[0.8, 0.4, -0.6, 0.3], [0.0, 0.5, 0.5, 0.5]]
"""
SRDF = """<robot name="service_robot">
  <disable_collisions link1="arm_link4" link2="camera_link" reason="Never"/>
</robot>
"""


def test_a_point_in_collision_is_refused_before_any_run(run, write_sweep, tmp_path):
    path = write_sweep(SWEEP)
    result = run("sweep", path, "--jobs", "1", "--out", tmp_path / "out")
    assert_one_line_error(result, 2, "arm.points[0]",
                          "'arm_link4' and 'camera_link' would intersect",
                          "--allow-collisions accepts it, or --srdf FILE can disable the pair")
    assert not (tmp_path / "out").exists()  # nothing ran


def test_allow_collisions_or_an_srdf_lets_the_runs_go(run, write_sweep, tmp_path):
    path = write_sweep(SWEEP)
    srdf = tmp_path / "robot.srdf"
    srdf.write_text(SRDF)
    for options in (("--allow-collisions",), ("--srdf", srdf)):
        result = run("sweep", path, "--jobs", "1", *options)
        assert result.exit_code == 0, result.stderr
