"""A wheel radius written with a unit ("50mm") is no number: said so, not 'nan m'.

simulate and inspect said the wheel 'rolls on a radius of nan m, which no wheel has'.
"""

from __future__ import annotations

from tests.conftest import SIM_URDF, assert_one_line_error


def test_a_radius_with_a_unit_is_named_as_no_number(run, tmp_path):
    text = SIM_URDF.read_text()
    wheel = '<cylinder length="0.04" radius="0.07"/>'
    assert wheel in text
    path = tmp_path / "robot.urdf"
    path.write_text(text.replace(wheel, '<cylinder length="0.04" radius="70mm"/>'))
    result = run("simulate", path, "--headless", "--duration-s", "0.1", "--out",
                 tmp_path / "run.csv")
    line = assert_one_line_error(result, 2)
    assert "rolls on a radius that is no number as written" in line and "nan m" not in line
