"""A run ends on a control tick: a duration between two ticks is refused, not overrun.

At update_rate_hz 30 a run of 1.05 s ran to 1.0667 s (ground_truth.csv and the bag past
the duration its summary gave), at 0.7 Hz a run of 2 s to 2.857 s, and --duration-s
0.005 at 100 Hz ran a whole 0.01 s tick.
"""

from __future__ import annotations

import pytest

from tests.conftest import assert_one_line_error, run_servicebot


@pytest.mark.parametrize(("rate", "duration", "message"), [
    (30, "1.05", "duration_s 1.05 s is not a whole number of control ticks at 30 Hz (one "
                 "every 0.0333333 s): give 1.03333 s or 1.06667 s"),
    (100, "0.005", "duration_s 0.005 s is not a whole number of control ticks at 100 Hz "
                   "(one every 0.01 s): give 0.01 s")])
def test_a_duration_between_ticks_is_refused(tmp_path, rate, duration, message):
    scenario = tmp_path / "s.yaml"
    scenario.write_text(f"duration_s: {duration}\ncontroller: {{update_rate_hz: {rate}}}\n")
    assert_one_line_error(run_servicebot("simulate", "--headless", "-s", scenario), 2, message)


def test_a_duration_on_a_tick_runs_to_it(tmp_path):
    scenario = tmp_path / "s.yaml"
    scenario.write_text("duration_s: 1.0\ncontroller: {update_rate_hz: 30}\n")
    out = tmp_path / "out"
    assert run_servicebot("simulate", "--headless", "-s", scenario, "--out", out).returncode == 0
    last = (out / "ground_truth.csv").read_text().splitlines()[-1]
    assert float(last.split(",")[0]) == pytest.approx(1.0, abs=1e-9)
