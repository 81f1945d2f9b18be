"""SB011's fix never renames an attribute to one the element already has.

crazyswarm2's crazyflie2.urdf writes the inertia tensor whole (ixx iyy izz ixy ixz iyz iyx izx
izy): 'iyx' was 'did you mean iyz? rename it', which the element has; following it made a
duplicate attribute that check_urdf refuses. The lower half's names are said as the twins of
the upper half, which is what URDF reads.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings

_ROBOT = ('<robot name="r"><link name="base"><inertial><mass value="1"/><inertia ixx="0.1" '
          'iyy="0.1" izz="0.1" ixy="0" ixz="0" {extra}/></inertial></link></robot>')


def _sb011(run, tmp_path, extra: str):
    path = tmp_path / "r.urdf"
    path.write_text(_ROBOT.format(extra=extra))
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB011")
    return [(f["message"], f["fix"]) for f in findings(result.stdout)]


def test_the_lower_half_of_a_written_out_tensor_is_removed(run, tmp_path):
    found = _sb011(run, tmp_path, 'iyz="0" iyx="0" izx="0" izy="0"')
    assert [fix for _, fix in found] == ["remove it"] * 3
    assert "'iyx': URDF reads the upper half of the symmetric tensor, and 'ixy' is its value" \
        in found[0][0]


def test_a_lower_half_name_whose_twin_is_missing_is_renamed_to_it(run, tmp_path):
    assert _sb011(run, tmp_path, 'izy="0"') == [
        ("<inertia> has no attribute 'izy': URDF reads the upper half of the symmetric tensor, "
         "and 'iyz' is its value", "rename it 'iyz'")]


@pytest.mark.parametrize(("extra", "fix"), [('iyz="0" iyzz="0"', "remove it"),
                                            ('iyzz="0"', "rename it 'iyz'")])
def test_a_typo_is_renamed_only_to_a_name_not_there(run, tmp_path, extra, fix):
    [(_, got)] = _sb011(run, tmp_path, extra)
    assert got == fix
