"""An opening ``<?xml ...?>`` is read as tinyxml2 (urdfdom, Gazebo, MuJoCo) reads it."""

from __future__ import annotations

from pathlib import Path

from tests.check.corpus import check_urdf_rejects
from tests.check.helpers import findings

BODY = '<robot name="one_link">\n  <link name="link1"/>\n</robot>\n'


def _check(run, tmp_path: Path, text: str) -> tuple[bool, list[str]]:
    path = tmp_path / "robot.urdf"
    path.write_text(text)
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB0")
    return check_urdf_rejects(path), [str(f["code"]) for f in findings(result.stdout)]


def test_a_misspelt_declaration_is_not_judged(run, tmp_path):
    # ros/urdf's test/one_link.urdf: <?xml verison="1.0"?>, which urdf's own tests load
    assert _check(run, tmp_path, '<?xml verison="1.0"?>\n' + BODY) == (False, [])


def test_what_follows_a_misspelt_declaration_is_still_judged(run, tmp_path):
    # ros/urdf's test/fail_three_links_one_joint.urdf: a misspelt declaration and a bad tag
    text = '<?xml verison="1.0"?>\n' + BODY.replace("</robot>", "</robt>")
    rejected, codes = _check(run, tmp_path, text)
    assert rejected and codes == ["SB004"]


def test_a_declaration_after_other_text_is_still_malformed(run, tmp_path):
    # navigation2_tutorials' turtlebot3_waffle_gps.urdf: comment lines, then <?xml ...?>
    rejected, codes = _check(run, tmp_path, '<!-- a comment -->\n<?xml version="1.0"?>\n' + BODY)
    assert rejected and codes == ["SB004"]
