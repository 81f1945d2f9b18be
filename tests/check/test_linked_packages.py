"""A package linked into a workspace's ``src/`` is checked, as colcon builds it.

colcon's recursive crawl walks with ``followlinks`` and keeps each real directory once; a
directory run did not enter links, said the workspace held no robot files, and passed a
wheel joint of type 'continuos' that colcon would install.
"""

from __future__ import annotations

import json

from tests.check.helpers import findings

_BROKEN = ('<robot name="r"><link name="base"/><link name="wheel"/>'
           '<joint name="w" type="continuos"><parent link="base"/><child link="wheel"/>'
           '<axis xyz="0 1 0"/></joint></robot>')


def _package(directory, name: str, urdf: str):
    (directory / "urdf").mkdir(parents=True)
    (directory / "package.xml").write_text(f"<package><name>{name}</name></package>")
    (directory / "urdf" / "r.urdf").write_text(urdf)


def test_a_package_linked_into_src_is_walked_once_and_named_by_its_link(run, tmp_path):
    outside = tmp_path / "elsewhere" / "outside_pkg"
    _package(outside, "outside_pkg", _BROKEN)
    (outside / "urdf" / "up").symlink_to("..")  # a link back up the tree: no loop
    src = tmp_path / "ws" / "src"
    src.mkdir(parents=True)
    (src / "outside_pkg").symlink_to(outside)
    (src / "again").symlink_to(outside)  # the same package twice: checked once
    result = run("check", "urdf", tmp_path / "ws", "--format", "json", "--isolated")
    assert result.exit_code == 1, result.output
    files = [f["file"] for f in json.loads(result.stdout)["files"]]
    assert files == [str(src / "again" / "urdf" / "r.urdf")]
    assert "SB201" in {f["code"] for f in findings(result.stdout)}
