"""Controllers files as rcl reads them: several documents as one file; tabs named.

simulate refused a valid file of two YAML documents ('not valid YAML', which check called a
warning), and said 'not valid YAML' with no reason for an indentation by tabs.
"""

from __future__ import annotations

import json

from tests.check.helpers import findings
from tests.conftest import REPO, SIM_URDF, assert_one_line_error

BUNDLED = (REPO / "robots" / "controllers.yaml").read_text()


def test_two_documents_are_read_as_one_file(run, tmp_path):
    cut = BUNDLED.index("\n", BUNDLED.index("diff_controller:\n  ros__parameters") - 1)
    path = tmp_path / "controllers.yaml"
    path.write_text(BUNDLED[:cut] + "\n---\n" + BUNDLED[cut:])
    result = run("simulate", SIM_URDF, "--headless", "--format", "json", "--duration-s",
                 "0.2", "--controllers", path)
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["odometry_published_on"] == ["/diff_controller/odom", "/tf"]


def test_a_tab_in_the_indentation_is_named(run, tmp_path):
    path = tmp_path / "controllers.yaml"
    path.write_text(BUNDLED.replace("\n  ros__parameters:", "\n\tros__parameters:", 1))
    result = run("simulate", SIM_URDF, "--headless", "--duration-s", "0.2", "--controllers",
                 path)
    assert "YAML indents with spaces, never tabs" in assert_one_line_error(result, 2)
    checked = run("check", "controllers", path, "--robot", "sim", "--format", "json",
                  "--isolated")
    (found,) = findings(checked.stdout)
    assert found["fix"] == "indent with spaces"
