"""A file named from its own directory finds the package that holds it.

``inspect r.urdf`` run in ``pkg_a/urdf`` looked for package.xml files above ".", which has
no parents: 'package pkg_a not found', no bounding box, where ``check`` (and inspect run
from the package root) found it.
"""

from __future__ import annotations

import json
import shutil

from tests.check.helpers import FIXTURES, findings

URDF = ('<robot name="r"><link name="body"><visual><geometry><mesh '
        'filename="package://pkg_a/meshes/part.stl"/></geometry></visual></link></robot>')


def test_inspect_and_check_from_the_files_own_directory(run, tmp_path, monkeypatch):
    package = tmp_path / "pkg_a"
    (package / "urdf").mkdir(parents=True)
    (package / "meshes").mkdir()
    shutil.copy(FIXTURES / "meshes" / "cube.stl", package / "meshes" / "part.stl")
    (package / "package.xml").write_text('<package format="3"><name>pkg_a</name></package>')
    (package / "urdf" / "r.urdf").write_text(URDF)
    monkeypatch.chdir(package / "urdf")
    result = run("inspect", "r.urdf", "--section", "totals", "--format", "json")
    assert result.exit_code == 0, result.output
    box = json.loads(result.stdout)["totals"]["bounding_box_m"]
    assert box is not None and box["max_m"][0] > 0.04
    checked = run("check", "urdf", "r.urdf", "--format", "json", "--isolated")
    assert not {"SB401", "SB408"} & {f["code"] for f in findings(checked.stdout)}
