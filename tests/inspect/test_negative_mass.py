"""A negative mass is counted as written, and inspect says so.

A base of 1 kg and an arm of -0.5 kg at x = 1: 'total mass 0.5 kg', centre of mass at
x = -1, outside the robot, with no word that the file is wrong (check says SB302).
"""

from __future__ import annotations

import json


def test_a_negative_mass_is_named_beside_the_totals(run, tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(
        '<robot name="r"><link name="base"><inertial><mass value="1"/><inertia ixx="1" '
        'ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link><link name="arm">'
        '<inertial><mass value="-0.5"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" '
        'izz="1"/></inertial></link><joint name="j1" type="fixed"><origin xyz="1 0 0"/>'
        '<parent link="base"/><child link="arm"/></joint></robot>')
    result = run("inspect", path, "--section", "totals", "--format", "json")
    totals = json.loads(result.stdout)["totals"]
    assert totals["mass_kg"] == 0.5
    assert any("arm (-0.5 kg)" in note and "SB302" in note for note in totals["notes"])
