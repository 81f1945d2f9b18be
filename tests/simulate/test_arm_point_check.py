"""A trajectory point that puts the robot through itself is refused with ik's check and words.

`drive --arm` refuses the same configuration with the same sentence; `--allow-collisions`
runs it (the run logs the self collision) and an SRDF that disables the pair lets it through.
"""

from __future__ import annotations

import yaml

from tests.conftest import assert_one_line_error, run_servicebot

ARM = ["arm_base_to_link1", "arm_link1_to_link2", "arm_link2_to_link3", "arm_link3_to_link4"]
FOLDED = [0.0, 0.5, 0.5, 0.5]  # arm_link4 folds onto the camera
SRDF = """<robot name="service_robot">
  <disable_collisions link1="arm_link4" link2="camera_link" reason="Never"/>
</robot>
"""


def _scenario(tmp_path, points):
    path = tmp_path / "arm.yaml"
    path.write_text(yaml.safe_dump({"duration_s": 6, "arm": {"joint_names": ARM, "points": [
        {"time_from_start_s": 2 + 2 * k, "positions": p} for k, p in enumerate(points)]}}))
    return path


def test_a_point_in_collision_is_refused_with_the_words_drive_uses(tmp_path):
    path = _scenario(tmp_path, [[0.3, 0.0, 0.0, 0.0], FOLDED])
    result = run_servicebot("simulate", "--headless", "-s", path, cwd=tmp_path)
    line = assert_one_line_error(result, 2, "arm.points[1]", f"{path}:")
    arm = [f"--arm={name}={value:g}" for name, value in zip(ARM, FOLDED, strict=True)]
    drive = run_servicebot("drive", "--dry-run", "--linear", "0", "--angular", "0",
                           "--duration-s", "1", *arm, cwd=tmp_path)
    said = assert_one_line_error(drive, 2, "camera_link")
    reason = said[said.index("is reachable only through a collision"):]
    reason = reason.removesuffix(" (see 'servicebot drive --help')")  # an option's error
    assert line.endswith(reason)  # the same check, the same sentence
    assert "'arm_link4' and 'camera_link' would intersect" in reason
    assert "--allow-collisions accepts it, or --srdf FILE can disable the pair" in reason


def test_allow_collisions_runs_it_and_the_run_logs_the_self_collision(tmp_path):
    path = _scenario(tmp_path, [FOLDED])
    result = run_servicebot("simulate", "--headless", "-s", path, "--allow-collisions",
                            "--format", "json", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    summary = yaml.safe_load(result.stdout)
    assert [(c["first"], c["second"]) for c in summary["self_collisions"]] == [
        ("arm_link4", "camera_link")]


def test_an_srdf_that_disables_the_pair_lets_the_point_through(tmp_path):
    path = _scenario(tmp_path, [FOLDED])
    srdf = tmp_path / "robot.srdf"
    srdf.write_text(SRDF)
    result = run_servicebot("simulate", "--headless", "-s", path, "--srdf", srdf,
                            "--format", "json", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert yaml.safe_load(result.stdout)["self_collisions"] == []



def test_a_mesh_collision_link_given_relative_to_a_relative_urdf_path_is_checked(tmp_path):
    from tests.simulate.test_mesh_parts import _robot, _stl

    folder = tmp_path / "robot"
    folder.mkdir()
    _stl(folder)
    _robot(folder, "bumper.stl")  # filename="bumper.stl", beside robot.urdf
    for cwd, path in ((folder, "robot.urdf"), (tmp_path, "robot/robot.urdf")):
        result = run_servicebot("simulate", path, "--headless", "--duration-s", "20",
                                cwd=cwd)  # the default arm points are checked with the mesh
        assert_one_line_error(result, 2, "'arm_link4' and 'bumper' would intersect")
        ik = run_servicebot("ik", path, "--position", "0.5", "0", "0.4", cwd=cwd)
        assert ik.returncode in (0, 1) and "collision geometry" not in ik.stderr, ik.stderr


def test_a_mesh_collision_link_in_a_package_given_by_option_is_checked(tmp_path):
    from tests.simulate.test_mesh_parts import _robot, _stl

    meshes = tmp_path / "meshes"
    meshes.mkdir()
    _stl(meshes)
    _robot(tmp_path, "package://bumper_meshes/bumper.stl")
    result = run_servicebot("simulate", tmp_path / "robot.urdf", "--headless", "--duration-s",
                            "20", "--package", f"bumper_meshes={meshes}", cwd=tmp_path,
                            env={"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""})
    # the point check read the mesh through --package (once: "package not found")
    assert_one_line_error(result, 2, "'arm_link4' and 'bumper' would intersect")
