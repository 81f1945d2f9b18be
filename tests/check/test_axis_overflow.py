"""An axis so long its square overflows: Pinocchio normalises it to 0 0 0 (urdfdom keeps it).

Eigen's normalize() divides by the square root of the squared length: from about 1e154 on
that is infinite, and the joint turns about nothing. An axis of 1e100 still normalises.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings
from tests.conftest import assert_one_line_error

ROBOT = ('<robot name="r"><link name="base_link"/><link name="arm"><inertial><mass value="1"/>'
         '<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>'
         '<joint name="j" type="revolute"><parent link="base_link"/><child link="arm"/>'
         '<axis xyz="{axis}"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint>'
         '</robot>')


@pytest.mark.parametrize(("axis", "severity"), [("1e160 0 0", "error"), ("0 -3e200 0", "error"),
                                                ("1e100 0 0", "warning"),
                                                ("1e-170 0 0", "error"),  # squared: 0
                                                ("1e-100 0 0", "warning")])
def test_an_axis_too_long_or_short_to_normalise_is_an_error(run, tmp_path, axis, severity):
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(axis=axis))
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB208"]
    assert found["severity"] == severity
    assert ("to normalise" in found["message"]) is (severity == "error")


def test_fk_refuses_an_axis_too_short_to_normalise(run, tmp_path):
    """Pinocchio leaves an axis of 1e-170 as it is: fk at 0.5 rad gave no rotation matrix."""
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(axis="1e-170 0 0"))
    assert_one_line_error(run("fk", path, "-j", "j=0.5", "-f", "arm"), 2,
                          "joint 'j' has an axis too short to normalise")


def test_fk_refuses_it_in_one_line_instead_of_a_scaled_identity(run, tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(axis="1e160 0 0"))
    assert_one_line_error(run("fk", path, "-j", "j=0.5", "-f", "arm"), 2,
                          "joint 'j' has an axis too long to normalise")
    path.write_text(ROBOT.format(axis="1e100 0 0"))
    result = run("fk", path, "-j", "j=0.5", "-f", "arm")
    assert result.exit_code == 0 and "roll pitch yaw [rad]  0.5  0  0" in result.stdout
