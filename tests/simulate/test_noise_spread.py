"""Gazebo's noise on values written oddly: a negative spread draws as its magnitude."""

from __future__ import annotations

from tests.conftest import run_servicebot
from tests.simulate.plugin_robots import SAM_BOT, edited


def test_a_negative_noise_spread_draws_as_its_magnitude(tmp_path):
    """sam_bot's IMU with its gyro's stddev and bias stddev written negative: Gazebo draws
    mean + stddev * z, the same spread; the run's IMU samples are those of the positive
    values, bit for bit (it ended in an internal error)."""
    outputs = {}
    for sign in ("", "-"):
        robot = edited(SAM_BOT, tmp_path / f"robot{sign}", (
            "<stddev>2e-4</stddev>", f"<stddev>{sign}2e-4</stddev>"), (
            "<bias_stddev>0.0000008</bias_stddev>", f"<bias_stddev>{sign}0.0000008</bias_stddev>"))
        out = tmp_path / f"out{sign}"
        result = run_servicebot("simulate", robot, "--headless", "--duration-s", "1",
                                "--out", out)
        assert result.returncode == 0, result.stderr
        outputs[sign] = (out / "imu.csv").read_bytes()
    assert outputs[""] == outputs["-"]
