"""A link's collision mesh as the simulator reads it: the fast readers, COLLADA's unit
applied as Gazebo and RViz apply it, trimesh for other formats."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from servicebot_cli.simulate.shape import MeshUnreadable
from servicebot_cli.simulate.world.meshes import _load_triangles
from tests.check.test_meshes import _collada


def test_a_collada_mesh_in_millimetres_is_read_in_metres(tmp_path):
    path = tmp_path / "part.dae"
    path.write_bytes(_collada("0.001").replace(b"0 2 0", b"0 2000 0"))
    vertices, faces = _load_triangles(path)
    triangles = vertices[faces]
    assert len(triangles) == 2
    assert np.ptp(triangles.reshape(-1, 3), axis=0)[1] == pytest.approx(2.001)  # y: 2000 mm + 1


@pytest.mark.parametrize("suffix", [".stl", ".obj", ".ply"])
def test_every_format_gives_trimeshs_triangles(tmp_path, suffix):
    box = trimesh.creation.box((0.2, 0.4, 0.6))
    path = tmp_path / f"box{suffix}"
    box.export(path)
    vertices, faces = _load_triangles(path)
    ours = sorted(map(tuple, vertices[faces].reshape(-1, 3).round(6).tolist()))
    assert ours == sorted(map(tuple, box.triangles.reshape(-1, 3).round(6).tolist()))


@pytest.mark.parametrize("content, needle", [
    (b"solid x\nendsolid x\n", "no triangles"),
    (b"v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n", "not finite"),
    (b"v 0 0 0\nf 1 2 9\n", "cannot read"),
])
def test_unusable_meshes_say_why(tmp_path, content, needle):
    path = tmp_path / ("m.stl" if content.startswith(b"solid") else "m.obj")
    path.write_bytes(content)
    with pytest.raises(MeshUnreadable, match=needle):
        _load_triangles(path)
