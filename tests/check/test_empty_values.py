"""A joint's type="" and a <mimic joint="">: judged, not skipped as if left out.

check_urdf ('has no known type []'), Pinocchio and MuJoCo refuse type=""; Pinocchio refuses a
mimic of "" as of any joint not in the tree. check said nothing of either (a falsy string
skipped the rule), or only SB701 at <robot>.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings
from tests.conftest import run_servicebot

ROBOT = """<robot name="r">
  <link name="a"/><link name="b"/><link name="c"/>
  <joint name="j1" {kind}><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="b"/><child link="c"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>{mimic}</joint>
</robot>
"""


@pytest.mark.parametrize(("kind", "mimic", "expected"), [
    ('type="revolute"', "", []),
    ('type=""', "", [("SB201", 3, "joint 'j1' has type '', which URDF does not have")]),
    ('type="revolute"', '<mimic joint=""/>',
     [("SB209", 5, "joint 'j2' has <mimic joint=\"\">, which names no joint")]),
])
def test_empty_values_are_judged_where_they_are(tmp_path, kind, mimic, expected):
    robot = tmp_path / "r.urdf"
    robot.write_text(ROBOT.format(kind=kind, mimic=mimic))
    result = run_servicebot("check", "urdf", robot, "--isolated", "--format", "json",
                            "--select", "SB2")
    found = [(f["code"], f["line"], f["message"].split(";")[0]) for f in findings(result.stdout)
             if f["severity"] == "error"]
    assert found == expected
