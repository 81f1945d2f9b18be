"""A bad number is placed at its attribute, not at the tag that holds it.

The SolidWorks exporter writes one attribute a line (double_pendulum_continuous): a bad
iyz was reported at the <inertia> five lines above it, and GitHub's annotation landed there.
"""

from __future__ import annotations

from tests.check.helpers import findings

INERTIAL = """<robot name="r">
  <link name="a">
    <inertial>
      <mass value="1"/>
      <inertia
        ixx="0.1"
        ixy="0" ixz="0"
        iyy="0.1"
        iyz="0,0"
        izz="0.1" />
    </inertial>
  </link>
</robot>
"""


def _places(run, path) -> list[tuple[str, int, int]]:
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB013")
    return [(f["file"].rsplit("/", 1)[-1], f["line"], f["column"])
            for f in findings(result.stdout)]


def test_a_bad_number_is_placed_at_its_attribute(run, tmp_path):
    path = tmp_path / "r.urdf"
    path.write_text(INERTIAL)
    assert _places(run, path) == [("r.urdf", 9, 9)]
    path.write_text(INERTIAL.replace('ixy="0" ixz="0"', 'ixy="0" ixz="x"'))
    assert _places(run, path) == [("r.urdf", 7, 17), ("r.urdf", 9, 9)]


def test_in_a_xacro_include_too(run, tmp_path):
    (tmp_path / "part.xacro").write_text(
        '<robot xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        + INERTIAL.split("\n", 1)[1].rsplit("</robot>", 1)[0] + "</robot>\n")
    path = tmp_path / "r.urdf.xacro"
    path.write_text('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
                    '  <xacro:include filename="part.xacro"/>\n</robot>\n')
    assert _places(run, path) == [("part.xacro", 9, 9)]
