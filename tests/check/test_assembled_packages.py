"""A package assembled at build time, checked in its source tree with no ROS variables set.

robotology/icub-models keeps ``iCub_manual/package.xml`` (``<name>iCub</name>``) beside the
generated ``iCub/robots/*/model.urdf`` and ``iCub/meshes/``; CMake merges both into one
installed ``share/iCub``. In the source tree the workspace package ``iCub`` lacks the meshes,
while the directory ``iCub`` above each model holds them, as Gazebo's model paths and
yourdfpy find them (trying each candidate until the file is there). That is a warning that
ROS would not find them (SB409), not 1282 missing meshes.
"""

from __future__ import annotations

import json
from pathlib import Path

from tests.check.helpers import findings, tetrahedron_stl

NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}

MODEL = """<?xml version="1.0" ?>
<robot name="iCub">
  <link name="root_link">
    <visual>
      <geometry><mesh filename="package://iCub/meshes/simmechanics/{mesh}"/></geometry>
    </visual>
  </link>
</robot>
"""


def _icub_models(root: Path, mesh: str) -> Path:
    repo = root / "src" / "icub-models"
    (repo / "iCub_manual").mkdir(parents=True)
    (repo / "iCub_manual" / "package.xml").write_text(
        '<package format="2"><name>iCub</name><version>1.0.0</version></package>\n')
    meshes = repo / "iCub" / "meshes" / "simmechanics"
    meshes.mkdir(parents=True)
    (meshes / "sim_root_link.stl").write_bytes(tetrahedron_stl(0.1))
    model = repo / "iCub" / "robots" / "iCubGenova09" / "model.urdf"
    model.parent.mkdir(parents=True)
    model.write_text(MODEL.format(mesh=mesh))
    return model


def _check(run, path: Path) -> tuple[int, list[dict], dict]:
    result = run("check", path, "--format", "json", "--isolated", env=NO_ROS)
    document = json.loads(result.stdout)
    return result.exit_code, findings(result.stdout), document["files"][0]["packages"]


def test_a_mesh_the_workspace_package_lacks_is_found_in_the_directory_named_so(run, tmp_path):
    model = _icub_models(tmp_path, "sim_root_link.stl")
    exit_code, found, packages = _check(run, model)
    assert [f["code"] for f in found] == ["SB409"], found
    assert "icub-models/iCub above the file" in found[0]["message"]
    assert "iCub_manual/package.xml" in found[0]["message"]
    # robot_properties_solo read 'where the package found by the package holding the file'
    assert "sim_root_link.stl'; the one ROS finds, through workspace " in found[0]["message"]
    assert exit_code == 0
    assert packages["iCub"]["path"].endswith("icub-models/iCub")
    assert packages["iCub"]["ros_finds_it"] is False


def test_a_mesh_that_is_nowhere_is_still_missing_where_ros_looks(run, tmp_path):
    model = _icub_models(tmp_path, "sim_no_such_link.stl")
    exit_code, found, packages = _check(run, model)
    assert [f["code"] for f in found] == ["SB401", "SB702"]
    assert "iCub_manual/meshes/simmechanics/sim_no_such_link.stl" in found[0]["message"]
    assert exit_code == 1
    assert packages["iCub"]["ros_finds_it"] is True
