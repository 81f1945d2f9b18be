"""A world mesh with a coordinate that is no number is refused, not drilled with holes.

trimesh drops every face that has a 'v nan nan nan' corner: a 0.5 m box lost two faces,
and the robot's arm went in through them, where the box without the NaN stopped it.
"""

from __future__ import annotations

from tests.conftest import assert_one_line_error, run_servicebot

BOX = """v -0.25 -0.25 0.0
v -0.25 -0.25 1.0
v -0.25 0.25 0.0
v -0.25 0.25 1.0
v 0.25 -0.25 0.0
v 0.25 -0.25 1.0
v 0.25 0.25 0.0
v 0.25 0.25 1.0
f 1 3 2
f 2 3 4
f 5 6 7
f 6 8 7
f 1 2 5
f 2 6 5
f 3 7 4
f 4 7 8
f 1 5 3
f 3 5 7
f 2 4 6
f 4 8 6
"""


def test_a_mesh_with_a_nan_corner_is_refused(tmp_path):
    (tmp_path / "box.obj").write_text(BOX.replace("v -0.25 -0.25 0.0", "v nan nan nan", 1))
    scenario = tmp_path / "s.yaml"
    scenario.write_text("duration_s: 1\nworld:\n  meshes: [{file: box.obj, xyz_m: [2, 0, 0]}]\n")
    assert_one_line_error(run_servicebot("simulate", "--headless", "-s", scenario), 2,
                          "s.yaml:3: world.meshes[0].file: 'box.obj' has coordinates that are "
                          "not finite")
    (tmp_path / "box.obj").write_text(BOX)
    assert run_servicebot("simulate", "--headless", "-s", scenario).returncode == 0
