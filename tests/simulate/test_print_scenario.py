"""simulate --print-scenario: the built-in scenario as a starting point that runs as it is."""

from __future__ import annotations

import json


def test_the_printed_scenario_runs_as_the_built_in_one(run, tmp_path):
    printed = run("simulate", "--print-scenario")
    assert printed.exit_code == 0 and printed.stdout.startswith("# The built-in scenario")
    assert 'color: "#d77828"' in printed.stdout  # the camera's colours, as a field to edit
    (tmp_path / "default.yaml").write_text(printed.stdout)
    own = run("simulate", "--headless", "--duration-s", "30", "--format", "json")
    copied = run("simulate", "--headless", "-s", tmp_path / "default.yaml", "--duration-s", "30",
                 "--format", "json")
    assert own.exit_code == copied.exit_code == 0, own.stderr + copied.stderr
    mine, theirs = json.loads(own.stdout), json.loads(copied.stdout)
    assert mine["scenario"] == "default" and theirs["scenario"] == "default"
    assert mine == theirs


def test_print_scenario_runs_nothing_and_writes_nothing(run, tmp_path):
    result = run("simulate", "--print-scenario", "--out", tmp_path / "out")
    assert result.exit_code == 0 and not (tmp_path / "out").exists()
