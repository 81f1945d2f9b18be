"""Real description packages, with no ROS variables set: packages found as ROS finds them.

rtb-data's robots are laid out as a colcon workspace here: each package copied into
``ws/src/NAME`` with a package.xml, then checked from the workspace, from a package and from
elsewhere. pybullet_data's ``package://meshes/`` resolves beside the file, with a warning.
"""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

import pytest

from tests.check.corpus import pybullet_urdfs
from tests.check.helpers import findings

rtbdata = pytest.importorskip("rtbdata")
RTB = Path(rtbdata.__file__).resolve().parent / "xacro"
# rtb-data keeps these packages under other directory names; ROS names them by package.xml
PACKAGES = {
    "kuka_kr10_support": "kuka_description/kuka_kr10",
    "kuka_kr6_support": "kuka_description/kuka_kr6",
    "kuka_resources": "kuka_description/kuka_resources",
    "abb_irb140": "abb_irb140_description",
    "abb_irb140_support": "abb_irb140_description",
}
NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}


@pytest.fixture(scope="module")
def workspace(tmp_path_factory) -> Path:
    ws = tmp_path_factory.mktemp("ws")
    for name, relative in PACKAGES.items():
        package = ws / "src" / name
        shutil.copytree(RTB / relative, package)
        (package / "package.xml").write_text(
            f"<package format=\"3\"><name>{name}</name><version>0.0.0</version></package>\n")
    (ws / "build" / "ignored").mkdir(parents=True)
    return ws


def _json(run, *args, env=None):
    result = run("check", *args, "--format", "json", "--isolated", env={**NO_ROS, **(env or {})})
    return result, json.loads(result.stdout)


def test_a_workspace_of_real_packages_has_no_error_and_no_missing_package(run, workspace,
                                                                          monkeypatch):
    monkeypatch.chdir(workspace)
    result, document = _json(run, "src")
    assert result.exit_code == 0, result.stdout
    assert document["summary"]["files"] >= 6
    assert not {f["code"] for f in findings(result.stdout)} & {"SB007", "SB401", "SB408"}
    kr10 = next(f for f in document["files"] if f["file"].endswith("kr10r1100sixx.xacro"))
    support = kr10["packages"]["kuka_kr10_support"]
    assert support["ros_finds_it"] and support["how"].startswith("the package holding the file")
    assert kr10["packages"]["kuka_resources"]["how"].startswith("workspace")


def test_checked_from_a_package_and_from_elsewhere_the_answer_is_the_same(run, workspace,
                                                                          monkeypatch, tmp_path):
    target = workspace / "src" / "kuka_kr6_support" / "urdf" / "kr6r700sixx.xacro"
    monkeypatch.chdir(target.parent)
    _, inside = _json(run, target.name)
    monkeypatch.chdir(tmp_path)
    _, outside = _json(run, target)
    assert inside["summary"]["errors"] == outside["summary"]["errors"] == 0
    assert inside["files"][0]["packages"].keys() == outside["files"][0]["packages"].keys() == {
        "kuka_kr6_support", "kuka_resources"}


def test_a_missing_package_is_one_warning_per_file_and_package(run, tmp_path):
    urdf = tmp_path / "irb140.urdf"
    shutil.copy(RTB / "abb_irb140_description" / "urdf" / "irb140.urdf", urdf)
    result, document = _json(run, urdf)
    missing = [f for f in findings(result.stdout) if f["code"] == "SB408"]
    assert result.exit_code == 0
    assert len(missing) == 1 and missing[0]["severity"] == "warning"
    assert "'abb_irb140_support' not found: 14 meshes not checked" in missing[0]["message"]
    assert document["files"][0]["packages"]["abb_irb140_support"]["path"] is None


def test_pybullet_meshes_beside_the_file_are_found_with_one_warning_per_package(run):
    with_meshes = [p for p in pybullet_urdfs() if "package://meshes/" in p.read_text()]
    if not with_meshes:
        pytest.skip("pybullet_data is not installed")
    result, document = _json(run, *with_meshes[:5])
    for file in document["files"]:
        warned = [f for f in file["findings"] if f["code"] == "SB409"]
        assert len(warned) == 1, file["file"]
        assert file["packages"]["meshes"]["ros_finds_it"] is False
    assert "SB408" not in {f["code"] for f in findings(result.stdout)}


def test_a_file_missing_beside_the_others_is_a_missing_file_not_a_missing_package(
        run, tmp_path):
    """onshape-to-robot's dog: package://assets/... found beside the file for every mesh
    but one, whose file is absent; that one made 'package not found' (a warning, passed)."""
    with_meshes = [p for p in pybullet_urdfs() if "package://meshes/" in p.read_text()]
    if not with_meshes:
        pytest.skip("pybullet_data is not installed")
    def uris_of(path: Path) -> list[str]:
        return sorted(set(re.findall(r'"(package://meshes/[^"]+)"', path.read_text())))

    source = next(p for p in with_meshes if len(uris_of(p)) >= 2)
    text, uris = source.read_text(), uris_of(source)
    shutil.copytree(source.parent / "meshes", tmp_path / "meshes")
    urdf = tmp_path / source.name
    urdf.write_text(text.replace(f'"{uris[0]}"', '"package://meshes/absent.stl"'))
    result = run("check", "urdf", urdf, "--format", "json", "--isolated")
    found = findings(result.stdout)
    missing = [f for f in found if f["code"] == "SB401"]
    assert result.exit_code == 1 and missing and "SB408" not in {f["code"] for f in found}
    assert all(f"{tmp_path / 'meshes' / 'absent.stl'} does not exist" in f["message"]
               for f in missing)
    assert [f["code"] for f in found].count("SB409") == 1


def test_the_text_report_says_where_and_how_each_package_was_found(run, workspace,
                                                                   monkeypatch):
    monkeypatch.chdir(workspace / "src" / "kuka_kr10_support")
    result = run("check", "urdf", "urdf/kr10r1100sixx.xacro", "--isolated", "--show-packages",
                 env=NO_ROS)
    lines = [line for line in result.stdout.splitlines() if ": package " in line]
    assert any(line.startswith("urdf/kr10r1100sixx.xacro: package kuka_resources at ")
               and str(workspace / "src" / "kuka_resources") in line
               and "found as workspace" in line for line in lines), result.stdout
    assert any(f"package kuka_kr10_support at {workspace / 'src' / 'kuka_kr10_support'}, found "
               "as the package holding the file" in line for line in lines), result.stdout
    plain = run("check", "urdf", "urdf/kr10r1100sixx.xacro", "--isolated", env=NO_ROS)
    assert ": package " not in plain.stdout
