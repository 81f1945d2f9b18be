"""Gazebo's model://NAME/... meshes, and URI schemes no reader resolves.

Valkyrie's multisense_sl_remote.urdf names its head camera
``model://val_description/model/meshes/...``: the URI was joined onto the file's directory
(``urdf/model:/val_description/...``) and reported missing with that path, whatever
GAZEBO_MODEL_PATH said.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings, tetrahedron_stl


def _robot(directory, uri: str, inertial: str = ""):
    path = directory / "robot.urdf"
    path.write_text(f'<robot name="m"><link name="base">{inertial}<visual><geometry><mesh '
                    f'filename="{uri}"/></geometry></visual></link></robot>')
    return path


def _check(run, path, env=None):
    result = run("check", "urdf", path, "--isolated", "--format", "json",
                 env={"GAZEBO_MODEL_PATH": "", "GZ_SIM_RESOURCE_PATH": "",
                      "IGN_GAZEBO_RESOURCE_PATH": "", **(env or {})})
    return result.exit_code, {f["code"]: f for f in findings(result.stdout)}


@pytest.mark.parametrize("variable", ["GAZEBO_MODEL_PATH", "GZ_SIM_RESOURCE_PATH"])
def test_a_model_on_gazebos_model_path_is_read_with_a_warning(run, tmp_path, variable):
    models = tmp_path / "models"
    (models / "arm" / "meshes").mkdir(parents=True)
    (models / "arm" / "meshes" / "part.stl").write_bytes(tetrahedron_stl(2000.0))
    (tmp_path / "elsewhere").mkdir()
    path = _robot(tmp_path / "elsewhere", "model://arm/meshes/part.stl",
                  '<inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" '
                  'iyz="0"/></inertial>')
    exit_code, found = _check(run, path, {variable: f"/nowhere:{models}"})
    assert exit_code == 0
    assert found["SB409"]["message"].startswith("model://arm/... is resolved only by Gazebo")
    assert found["SB409"]["severity"] == "warning"
    assert "SB401" not in found
    assert "2000 m across" in found["SB404"]["message"]  # the mesh itself was read


def test_a_model_named_like_a_package_of_the_workspace_is_found_there(run, tmp_path):
    package = tmp_path / "ws" / "src" / "val_description"
    (package / "model" / "meshes").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>val_description</name></package>")
    (package / "model" / "meshes" / "cam.stl").write_bytes(tetrahedron_stl(0.1))
    (package / "model" / "urdf").mkdir()
    path = _robot(package / "model" / "urdf", "model://val_description/model/meshes/cam.stl")
    exit_code, found = _check(run, path)
    assert exit_code == 0 and set(found) == {"SB409"}
    assert "package val_description by the package holding the file" in \
        found["SB409"]["message"]
    assert found["SB409"]["fix"].startswith("write package://val_description/...")
    (package / "model" / "meshes" / "cam.stl").unlink()
    exit_code, found = _check(run, path)  # found, but not there: a missing file
    assert exit_code == 1
    assert found["SB401"]["message"].endswith(f"': {package}/model/meshes/cam.stl does not exist")


def test_a_model_that_is_nowhere_is_one_warning_saying_where_to_point(run, tmp_path):
    exit_code, found = _check(run, _robot(tmp_path, "model://arm/meshes/part.stl"))
    assert exit_code == 0 and set(found) == {"SB408"}
    assert found["SB408"]["message"].startswith(
        "model 'arm' not found: 1 mesh not checked; looked in Gazebo's model path "
        "(GAZEBO_MODEL_PATH, GZ_SIM_RESOURCE_PATH, IGN_GAZEBO_RESOURCE_PATH: unset)")
    assert found["SB408"]["fix"] == ("set GAZEBO_MODEL_PATH to the directory that holds model "
                                     "arm, or pass --package arm=DIR")


def test_a_scheme_no_reader_resolves_is_an_error_that_names_it(run, tmp_path):
    exit_code, found = _check(run, _robot(tmp_path, "foo://arm/meshes/part.stl"))
    assert exit_code == 1
    assert found["SB401"]["message"] == (
        "visual of link 'base': mesh 'foo://arm/meshes/part.stl': no robot description reader "
        "resolves 'foo://' (ROS reads package:// and file://, Gazebo model:// too)")


def test_a_model_and_a_package_of_one_name_are_told_apart(run, tmp_path):
    """Both missing, they were one SB408 ('2 meshes') whose fix said GAZEBO_MODEL_PATH for the
    package:// mesh too; model:/// (no name) took the model path's first directory."""
    path = tmp_path / "robot.urdf"
    path.write_text('<robot name="m"><link name="base"><visual><geometry><mesh filename='
                    '"model://arm/a.stl"/></geometry></visual><collision><geometry><mesh '
                    'filename="package://arm/b.stl"/></geometry></collision></link></robot>')
    result = run("check", "urdf", path, "--isolated", "--format", "json",
                 env={"GAZEBO_MODEL_PATH": "", "GZ_SIM_RESOURCE_PATH": "",
                      "IGN_GAZEBO_RESOURCE_PATH": ""})
    fixes = sorted(f["fix"] for f in findings(result.stdout) if f["code"] == "SB408")
    assert fixes == ["pass --package arm=DIR, or check from the workspace that holds the "
                     "package", "set GAZEBO_MODEL_PATH to the directory that holds model arm, "
                     "or pass --package arm=DIR"]
    exit_code, found = _check(run, _robot(tmp_path, "model:///tmp/a.stl"),
                              {"GAZEBO_MODEL_PATH": str(tmp_path)})
    assert exit_code == 1 and set(found) == {"SB401", "SB702"}
    assert "names no model: Gazebo reads model://NAME/PATH" in found["SB401"]["message"]
