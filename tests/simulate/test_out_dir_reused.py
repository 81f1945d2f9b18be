"""--out into a directory an earlier run wrote holds this run's files, and the user's own.

A run with camera images, then one without, into the same --out: the first run's
camera.png stayed beside a summary.json that said nothing of a camera (and a boxer run's
scan_rear_scan.csv beside the bundled robot's). Files the user put there stay.
"""

from __future__ import annotations

from tests.conftest import run_servicebot


def test_an_earlier_runs_files_this_run_does_not_write_are_gone(tmp_path):
    out = tmp_path / "run"
    first = run_servicebot("simulate", "--headless", "--duration-s", "0.5", "--camera-scale",
                           "0.05", "--out", out)
    assert first.returncode == 0, first.stderr
    assert (out / "camera.png").exists()
    (out / "scan_old_sensor.csv").write_text("t_s\n0\n")  # as an earlier robot's sensor
    (out / "notes.txt").write_text("mine")
    second = run_servicebot("simulate", "--headless", "--duration-s", "0.5", "--out", out)
    assert second.returncode == 0, second.stderr
    names = sorted(p.name for p in out.iterdir())
    assert "camera.png" not in names and "scan_old_sensor.csv" not in names
    assert {"notes.txt", "summary.json", "ground_truth.csv", "scan.csv"} <= set(names)
