"""A joint naming a link that does not exist is SB103, whatever the joint turns.

A continuous joint (a wheel, a caster's swivel) with a misspelt child link stopped the whole
check with 'Error: no link ...' and exit 2: the drive rules looked the link up. A directory
run lost every other file's report with it.
"""

from __future__ import annotations

import json

import pytest

from tests.check.helpers import findings

WHEEL = ('<robot name="r"><link name="base_link"/><joint name="wheel_joint" type="continuous">'
         '<parent link="base_link"/><child link="wheel"/><axis xyz="0 1 0"/></joint></robot>')
CASTER = ('<robot name="r"><link name="base_link"/><link name="wheel"><collision><geometry>'
          '<cylinder radius="0.05" length="0.02"/></geometry></collision></link>'
          '<joint name="swivel_joint" type="continuous"><parent link="base_link"/>'
          '<child link="swivl"/><axis xyz="0 0 1"/></joint>'
          '<joint name="caster_joint" type="continuous"><parent link="swivl"/>'
          '<child link="wheel"/><axis xyz="0 1 0"/></joint></robot>')


@pytest.mark.parametrize("text", [WHEEL, CASTER], ids=["wheel", "caster swivel"])
def test_a_turning_joint_with_a_missing_link_is_sb103(run, tmp_path, text):
    path = tmp_path / "r.urdf"
    path.write_text(text)
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    assert result.exit_code == 1, result.output
    assert "SB103" in {f["code"] for f in findings(result.stdout)}


def test_the_other_files_of_a_directory_are_still_reported(run, tmp_path):
    (tmp_path / "a.urdf").write_text(WHEEL)
    (tmp_path / "b.urdf").write_text('<robot name="b"><link name="base_link"/></robot>')
    result = run("check", "urdf", tmp_path, "--format", "json", "--isolated")
    assert result.exit_code == 1, result.output
    files = json.loads(result.stdout)["files"]
    assert [f["file"].rsplit("/", 1)[-1] for f in files] == ["a.urdf", "b.urdf"]
