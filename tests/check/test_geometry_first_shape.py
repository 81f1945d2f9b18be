"""urdfdom reads the first shape of a ``<geometry>``; what follows it is never read."""

from __future__ import annotations

from tests.check.corpus import check_urdf_drops
from tests.check.helpers import findings

ROBOT = """<robot name="r">
  <link name="base">
    <visual>
      <geometry>
        <box size="0.1 0.1 0.1"/>
        {second}
      </geometry>
    </visual>
  </link>
</robot>
"""


def _check(run, tmp_path, second: str) -> tuple[bool, list[str]]:
    path = tmp_path / "robot.urdf"
    path.write_text(ROBOT.format(second=second))
    result = run("check", path, "--format", "json", "--isolated", "--ignore", "SB309")
    return check_urdf_drops(path), [str(f["code"]) for f in findings(result.stdout)]


def test_a_shape_after_the_first_is_not_judged(run, tmp_path):
    # ros-mobile-robots/diffbot's wheel macro writes <mesh scale=""> after the mesh it means
    assert _check(run, tmp_path, '<box size=""/>') == (False, [])


def test_the_first_shape_is_still_judged(run, tmp_path):
    path = tmp_path / "robot.urdf"
    path.write_text(ROBOT.format(second="").replace('size="0.1 0.1 0.1"', 'size=""'))
    assert check_urdf_drops(path)
    result = run("check", path, "--format", "json", "--isolated", "--ignore", "SB309")
    assert "SB013" in {f["code"] for f in findings(result.stdout)}
