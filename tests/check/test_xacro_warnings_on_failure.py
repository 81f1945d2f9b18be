"""What xacro printed before it failed is shown, as xacro shows it.

A file's ${xacro.warning('...')} (or xacro's own deprecation warnings) before an expression
that fails is often the failure's explanation: xacro prints it, then the error; check and
expand printed the error alone.
"""

from __future__ import annotations

from tests.check.helpers import findings
from tests.conftest import run_servicebot

ROBOT = """<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">
  <link name="base"/>
  <link name="a_${xacro.warning('wheel_radius is now in metres')}"/>
  <link name="${undefined_name}"/>
</robot>
"""


def test_check_reports_the_warnings_before_the_failure(tmp_path):
    path = tmp_path / "robot.urdf.xacro"
    path.write_text(ROBOT)
    result = run_servicebot("check", "urdf", path, "--isolated", "--format", "json")
    found = [(f["code"], f["line"], f["severity"]) for f in findings(result.stdout)]
    assert found == [("SB017", 3, "warning"), ("SB006", 4, "error")]
    assert result.returncode == 1


def test_expand_prints_them_before_its_error(tmp_path):
    path = tmp_path / "robot.urdf.xacro"
    path.write_text(ROBOT)
    result = run_servicebot("expand", path)
    assert result.returncode == 2
    lines = result.stderr.splitlines()
    assert lines[0].startswith("warning: ") and lines[0].endswith(
        "robot.urdf.xacro:3:3: wheel_radius is now in metres")
    assert lines[1].startswith("Error: ") and "name 'undefined_name' is not defined" in lines[1]
    assert len(lines) == 2
