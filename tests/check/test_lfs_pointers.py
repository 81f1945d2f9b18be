"""A mesh that is a Git LFS pointer (a clone without git-lfs) says so, and how to fetch it.

NVIDIA's urdf-importer-extension holds 168 such files; they were 'no triangles' (export the
mesh again), 'not an STL file' or 'not well-formed XML'.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings
from tests.conftest import run_servicebot

POINTER = ("version https://git-lfs.github.com/spec/v1\n"
           "oid sha256:4d7a214614ab2935c943f9e0ff69d22eadbb8f32b1258daaa5e2ca24d17e2393\n"
           "size 184332\n")


@pytest.mark.parametrize("suffix", [".stl", ".obj", ".dae", ".ply"])
def test_a_git_lfs_pointer_mesh_is_named_as_one(run, tmp_path, suffix):
    (tmp_path / f"part{suffix}").write_text(POINTER)
    path = tmp_path / "r.urdf"
    path.write_text(f'<robot name="r"><link name="a"><visual><geometry><mesh filename="part'
                    f'{suffix}"/></geometry></visual></link></robot>')
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    (found,) = [f for f in findings(result.stdout) if f["code"] == "SB402"]
    assert "a Git LFS pointer, not the mesh" in found["message"]
    assert found["fix"] == "run 'git lfs pull' in the repository that holds it"
    if suffix != ".ply":  # inspect reads .ply with trimesh
        shown = run_servicebot("inspect", path, "--section", "totals")
        assert "a Git LFS pointer, not the mesh" in shown.stdout + shown.stderr
