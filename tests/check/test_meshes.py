"""The fast mesh readers agree with trimesh, and mass properties are exact on solids."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh

from servicebot_cli.check.meshes import MeshError, load_mesh
from servicebot_cli.description.mesh_obj import read_obj_indexed
from tests.check.corpus import erd_root
from tests.check.helpers import FIXTURES


def _sample() -> list:
    """Every 8th mesh of example-robot-data, in each of the formats the fast path reads."""
    meshes = sorted(p for p in (erd_root() / "robots").rglob("*")
                    if p.suffix.lower() in (".stl", ".obj", ".dae"))
    return meshes[::8]


@pytest.mark.parametrize("path", _sample(), ids=lambda p: p.name)
def test_fast_readers_agree_with_trimesh(path):
    info = load_mesh(path, with_mass=True)
    reference = trimesh.load(path, force="mesh")
    if reference.is_empty:  # anymal_foot.dae: pycollada refuses a missing texture, trimesh
        assert path.suffix.lower() == ".dae" and info.triangles > 0  # then sees no geometry
        return
    size = float(np.abs(reference.bounds[1] - reference.bounds[0]).max())
    assert np.allclose(info.lower, reference.bounds[0], atol=1e-6 * size)
    assert np.allclose(info.upper, reference.bounds[1], atol=1e-6 * size)
    if info.mass is not None and reference.is_watertight:
        assert info.mass.volume == pytest.approx(abs(reference.volume), rel=1e-6)


@pytest.mark.parametrize("suffix", [".stl", ".obj", ".dae", ".ply"])
def test_box_mass_properties_in_every_format(tmp_path, suffix):
    box = trimesh.creation.box(extents=(0.3, 0.2, 0.1))
    box.apply_translation((1.0, 2.0, 3.0))
    path = tmp_path / f"box{suffix}"
    box.export(path)
    info = load_mesh(path, with_mass=True)  # .ply goes through trimesh itself
    assert info.triangles == 12 and info.closed
    assert info.mass.volume == pytest.approx(0.006, rel=1e-5)  # STL and PLY store float32
    assert info.mass.centroid == pytest.approx((1.0, 2.0, 3.0), rel=1e-6)
    expected = 0.006 / 12 * np.diag([0.09, 0.04, 0.01])  # integral of x x^T dV
    assert np.allclose(info.mass.second_moment, expected, rtol=1e-4, atol=1e-10)


def test_open_mesh_has_no_mass_properties(tmp_path):
    box = trimesh.creation.box()
    box.update_faces(np.arange(len(box.faces)) != 0)
    path = tmp_path / "open.stl"
    box.export(path)
    info = load_mesh(path, with_mass=True)
    assert info.closed is False and info.mass is None


@pytest.mark.parametrize(("name", "needle"), [("garbage.stl", "not an STL"),
                                              ("missing.stl", "cannot read")])
def test_bad_meshes_raise_mesh_error(name, needle):
    with pytest.raises(MeshError, match=needle):
        load_mesh(FIXTURES / "meshes" / name)


def test_ascii_stl_and_binary_stl_agree(tmp_path):
    binary = load_mesh(FIXTURES / "meshes" / "cube.stl", with_mass=True)
    ascii_path = tmp_path / "cube_ascii.stl"
    trimesh.load(FIXTURES / "meshes" / "cube.stl").export(ascii_path, file_type="stl_ascii")
    text = load_mesh(ascii_path, with_mass=True)
    assert text.mass.volume == pytest.approx(binary.mass.volume) == pytest.approx(0.001)


@pytest.mark.parametrize("path", [p for p in _sample() if p.suffix.lower() == ".dae"],
                         ids=lambda p: p.name)
def test_collada_bounds_only_path_agrees_with_the_full_read(path):
    """Same count; the box of every position holds the triangles' box (a file may carry
    vertices no triangle uses) and has the same size to well within SB404's factor 1000."""
    fast = load_mesh(path)
    full = load_mesh(path, with_mass=True)
    assert fast.triangles == full.triangles
    assert np.all(np.array(fast.lower) <= np.array(full.lower) + 1e-9)
    assert np.all(np.array(fast.upper) >= np.array(full.upper) - 1e-9)
    extent = max(np.subtract(fast.upper, fast.lower)) / max(np.subtract(full.upper, full.lower))
    assert extent < 3


OBJ_SHAPES = {
    "triangles": b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n",
    "quads, CRLF, comments": b"# a unit square\r\nv 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\n"
                             b"vn 0 0 1\r\nf 1//1 2//1 3//1 4//1\r\n",
    "vertex colours, texture indices": b"v 0 0 0 1 0 0\nv 2 0 0 0 1 0\nv 0 3 0 0 0 1\n"
                                       b"vt 0 0\nf 1/1 2/1 3/1\n",
    "a pentagon": b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0.5 2 0\nv 0 1 0\nf 1 2 3 4 5\n",
    "runs of blanks between corners": b"v 0 0 0\nv 1 0 0\nv 1 1 0\n"
        b"v 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1  3/1/1 \nf 1/1/1 3/1/1   4/1/1\n",
    "faces before vertices, a face on the first line": b"f 1/1 2/1 3/1\nf 1 3 4\n"
        b"v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\n",
}



def _obj_triangles(text: bytes) -> np.ndarray:
    """The OBJ's triangles (n, 3, 3), from its vertex table and faces."""

    vertices, faces = read_obj_indexed(text)
    return vertices[faces] if len(faces) else np.zeros((0, 3, 3))

@pytest.mark.parametrize("text", OBJ_SHAPES.values(), ids=OBJ_SHAPES.keys())
def test_obj_corners_and_vertices_are_trimeshs(tmp_path, text):
    """The one-pass OBJ reader, held against trimesh on the forms OBJ files take."""
    path = tmp_path / "shape.obj"
    path.write_bytes(text)
    ours = _obj_triangles(text)
    reference = trimesh.load(path, force="mesh", process=False)
    assert len(ours) == len(reference.faces)
    assert sorted(map(tuple, ours.reshape(-1, 3).round(9).tolist())) == \
        sorted(map(tuple, np.asarray(reference.triangles).reshape(-1, 3).round(9).tolist()))


def test_obj_negative_indices_count_back_from_the_vertices_read_so_far():
    """As the OBJ format says (trimesh counts back from the last vertex of the file)."""
    text = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 0 0 5\nf -4 -3 -1\n"
    assert _obj_triangles(text).tolist() == [[[0, 0, 0], [1, 0, 0], [0, 1, 0]],
                                       [[0, 0, 0], [1, 0, 0], [0, 0, 5]]]


def test_indented_obj_lines_count():
    flat = OBJ_SHAPES["a pentagon"]
    indented = b"".join(b"  " + line if k % 2 else b"\t" + line
                        for k, line in enumerate(flat.splitlines(keepends=True)))
    assert np.array_equal(_obj_triangles(indented), _obj_triangles(flat))


@pytest.mark.parametrize("text", [b"v 1 2\nf 1 1 1\n", b"v 1 2 3\nf 1 1 x\n",
                                  b"v 1 2 3\nf 0 1 1\n", b"v a b c\nf 1 1 1\n"])
def test_broken_obj_files_are_mesh_errors(tmp_path, text):
    path = tmp_path / "broken.obj"
    path.write_bytes(text)
    with pytest.raises(MeshError):
        load_mesh(path)


def _collada(meter: str) -> bytes:
    geometry = ('<geometry id="{0}"><mesh><source id="{0}-p"><float_array id="{0}-a" count="9">'
                '{1}</float_array><technique_common><accessor source="#{0}-a" count="3" '
                'stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param '
                'name="Z" type="float"/></accessor></technique_common></source><vertices '
                'id="{0}-v"><input semantic="POSITION" source="#{0}-p"/></vertices><triangles '
                'count="1"><input semantic="VERTEX" source="#{0}-v" offset="0"/><p>0 1 2</p>'
                '</triangles></mesh></geometry>')
    return (f'<?xml version="1.0"?><COLLADA xmlns="http://www.collada.org/2005/11/'
            f'COLLADASchema" version="1.4.1"><asset><unit meter="{meter}"/></asset>'
            '<library_geometries>' + geometry.format("a", "-0 0 0 1 0 0 0 2 0")
            + geometry.format("b", "0 0 0 0 0 3 -1 0 0") + '</library_geometries>'
            '<library_visual_scenes><visual_scene id="s"><node id="n1"><instance_geometry '
            'url="#a"/></node><node id="n2"><translate>5 0 0</translate><rotate>0 0 1 90'
            '</rotate><instance_geometry url="#b"/></node></visual_scene>'
            '</library_visual_scenes></COLLADA>').encode()


@pytest.mark.parametrize("meter", ["1", "0.001", "-2"])
def test_collada_bounds_of_placed_and_scaled_parts_are_the_triangles_bounds(meter):
    """An identity node, a moved and turned one, and units of any sign: the same box both ways."""
    from servicebot_cli.description.mesh_arrays import bounds
    from servicebot_cli.description.mesh_collada import read_dae, read_dae_bounds

    data = _collada(meter)
    count, lower, upper = read_dae_bounds(data)
    triangles = read_dae(data)
    assert count == len(triangles) == 2
    expected = bounds(triangles.reshape(-1, 3))
    assert np.allclose(lower, expected[0], atol=1e-12)
    assert np.allclose(upper, expected[1], atol=1e-12)
    assert np.allclose(expected[1] - expected[0], np.array([5, 3, 3]) * abs(float(meter)))


def _soup_and_indexed(text: bytes, with_mass: bool):
    from servicebot_cli.check.meshes import summarise, summarise_indexed

    return summarise(_obj_triangles(text), with_mass), \
        summarise_indexed(*read_obj_indexed(text), with_mass=with_mass)


CUBE_OBJ = (b"v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
            b"f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n")


@pytest.mark.parametrize("text", [
    CUBE_OBJ,
    CUBE_OBJ + b"v 9 9 9\n",
    CUBE_OBJ.replace(b"f 4 1 5 8\n", b""),  # one face left out: open
    CUBE_OBJ + b"v 0 0 0\nv 1 0 0\n",  # unused duplicates of used vertices
    # a mesh whose upper z is 0.0 among the corners and -0.0 in the vertex table
    (erd_root() / "robots" / "alex_description" / "meshes" / "PsyonicRight.obj").read_bytes(),
], ids=["closed cube", "an unused vertex outside", "an open box", "unused duplicates",
        "PsyonicRight.obj"])
def test_the_vertex_table_summary_is_the_triangles_summary(text):
    """Closedness welded on the vertex table, bounds over the used vertices: the same
    summary, to the bit, as from the triangles themselves."""
    for with_mass in (False, True):
        soup, indexed = _soup_and_indexed(text, with_mass)
        assert repr((soup.triangles, soup.lower, soup.upper, soup.closed)) == \
            repr((indexed.triangles, indexed.lower, indexed.upper, indexed.closed))  # -0.0
        assert (soup.mass is None) == (indexed.mass is None)
        if soup.mass is not None:
            assert soup.mass.volume == indexed.mass.volume
            assert np.array_equal(soup.mass.second_moment, indexed.mass.second_moment)


def test_a_vertex_no_face_uses_counts_for_nothing(tmp_path):
    """Outside the bounds, and a NaN there is no error (it is in no triangle)."""
    path = tmp_path / "cube.obj"
    path.write_bytes(b"v 50 50 50\nv nan 0 0\n" + _shifted(CUBE_OBJ, 2))
    info = load_mesh(path, with_mass=True)
    assert (info.lower, info.upper, info.closed) == ((0.0, 0.0, 0.0), (1.0, 1.0, 1.0), True)
    assert info.mass is not None and info.mass.volume == pytest.approx(1.0)


def _shifted(text: bytes, by: int) -> bytes:
    """An OBJ's face lines with every index raised by ``by``."""
    lines = []
    for line in text.splitlines():
        if line.startswith(b"f "):
            line = b"f " + b" ".join(str(int(i) + by).encode() for i in line.split()[1:])
        lines.append(line)
    return b"\n".join(lines) + b"\n"


def _library_collada(scene_nodes: str, library: str) -> bytes:
    """A one-triangle geometry 'a' (corners 0,0,0 1,0,0 0,2,0), placed through library nodes."""
    base = _collada("1")
    nodes = base[base.index(b'<node id="n1">'):base.index(b"</visual_scene>")]
    return base.replace(
        b'<library_visual_scenes><visual_scene id="s">',
        f'<library_nodes>{library}</library_nodes><library_visual_scenes>'
        '<visual_scene id="s">'.encode()).replace(nodes, scene_nodes.encode()).replace(
        b"</COLLADA>", b'<scene><instance_visual_scene url="#s"/></scene></COLLADA>')


def test_collada_library_nodes_are_placed_where_instance_node_puts_them(tmp_path):
    """SketchUp's layout: the scene instances library nodes, each with its own transform;
    trimesh (pycollada) reads the same triangles."""
    data = _library_collada(
        '<node id="i1"><translate>10 0 0</translate><instance_node url="#lib"/></node>'
        '<node id="i2"><translate>0 0 7</translate><instance_node url="#lib"/></node>',
        '<node id="lib"><translate>0 1 0</translate><instance_geometry url="#a"/></node>')
    path = tmp_path / "placed.dae"
    path.write_bytes(data)
    info = load_mesh(path)
    reference = trimesh.load(path, force="mesh", process=False)
    assert info.triangles == len(reference.faces) == 2
    assert np.allclose([info.lower, info.upper], reference.bounds)
    assert np.allclose([info.lower, info.upper], [[0, 1, 0], [11, 3, 7]])


def test_collada_library_nodes_placing_each_other_in_a_loop_are_a_mesh_error(tmp_path):
    path = tmp_path / "loop.dae"
    path.write_bytes(_library_collada(
        '<node id="i1"><instance_node url="#lib"/></node>',
        '<node id="lib"><instance_geometry url="#a"/><instance_node url="#lib"/></node>'))
    with pytest.raises(MeshError, match="loop"):
        load_mesh(path)


def test_collada_bytes_after_the_root_end_are_left_out(tmp_path):
    """kuka_experimental's iiwa meshes: NULs and an older file's tail after </COLLADA>."""
    whole = _collada("1")
    path = tmp_path / "tail.dae"
    path.write_bytes(whole + b"\x00" * 40 + b"      </polylist>\n</mesh>\n</COLLADA>\n")
    assert load_mesh(path) == load_mesh_of(tmp_path / "whole.dae", whole)
    path.write_bytes(whole[:-200])  # cut short: still not a mesh
    with pytest.raises(MeshError, match="not well-formed"):
        load_mesh(path)


def load_mesh_of(path, data: bytes):
    path.write_bytes(data)
    return load_mesh(path)


CUBE_VERTICES = CUBE_OBJ[:CUBE_OBJ.index(b"f ")]


def _cube_faces(offset: int) -> bytes:
    """The cube's faces, its vertices counted from ``offset`` + 1."""
    return _shifted(CUBE_OBJ[len(CUBE_VERTICES):], offset)


SECOND_CUBE = b"".join(b"v " + b" ".join(str(float(c) + dx).encode() for c, dx in
                                         zip(line.split()[1:], (1.0, 1.0, 0.0), strict=True))
                       + b"\n" for line in CUBE_VERTICES.splitlines())  # shares edge x=1, y=1


@pytest.mark.parametrize(("text", "closed"), [
    (CUBE_OBJ, True),
    (CUBE_VERTICES + b"v 5 5 5\nv 6 5 5\nv 6 6 5\nv 6 6 6\n" + _cube_faces(0)
     + b"f 9 10 11\nf 9 12 10\nf 10 12 11\nf 11 12 9\n", True),  # two solids apart
    (CUBE_OBJ + b"f 1 2 6\n", False),  # one edge in three triangles
    (CUBE_VERTICES + SECOND_CUBE + _cube_faces(0) + _cube_faces(8), False),  # edge in four
    (CUBE_OBJ.replace(b"f 4 1 5 8\n", b""), False),  # an open box
], ids=["cube", "cube and tetrahedron apart", "edge in three", "cubes sharing an edge",
        "open box"])
def test_closed_means_every_edge_in_exactly_two_triangles(text, closed):
    """A solid has every edge between two triangles: not one (open), not three or four
    (non-manifold), whatever the other solids of the file."""
    for soup_or_indexed in _soup_and_indexed(text, with_mass=True):
        assert soup_or_indexed.closed is closed
    reference = trimesh.Trimesh(*read_obj_indexed(text))
    edges = np.sort(reference.edges, axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    assert bool(np.all(counts == 2)) is closed  # the same count, done another way


@pytest.mark.parametrize("seed", range(20))
def test_each_twice_is_a_count_of_every_key(seed):
    """Keys that share low bits (one bucket) in every mix of counts: the bucket count and the
    sort of full buckets say what counting every key says."""
    from collections import Counter

    from servicebot_cli.check.meshes import _each_twice

    rng = np.random.default_rng(seed)
    low = rng.integers(0, (4, 64, 1024)[seed % 3], 40, dtype=np.uint64)  # full buckets, or pairs
    high = rng.integers(0, 2**20, 40, dtype=np.uint64) << np.uint64(40)
    distinct = np.unique(low | high)
    copies = rng.choice([2, 2, 2, 2, 1, 3, 4], len(distinct)) if seed % 4 in (1, 2) else \
        np.full(len(distinct), 2)
    keys = rng.permutation(np.repeat(distinct, copies))
    expected = bool(len(keys)) and all(n == 2 for n in Counter(keys.tolist()).values())
    assert _each_twice(keys) is expected


@pytest.mark.parametrize(("keys", "expected"), [
    ([5, 5 + 2**40, 9, 9], False),  # two keys once each, in one bucket of two
    ([5, 5 + 2**40, 5, 5 + 2**40], True),  # both twice: a bucket of four
    ([5, 5, 5, 5], False),  # one key four times
    ([5, 5, 7, 7, 7], False),
    ([], False),
])
def test_each_twice_in_shared_buckets(keys, expected):
    from servicebot_cli.check.meshes import _each_twice

    assert _each_twice(np.array(keys, dtype=np.uint64)) is expected


def test_a_mesh_named_in_another_case_says_so(run, tmp_path):
    """Left_Tire.STL exported on Windows, named left_tire.stl in the URDF: it loads there and
    not on Linux. SB401 said only 'does not exist'."""
    from tests.check.helpers import findings, tetrahedron_stl

    (tmp_path / "Left_Tire.STL").write_bytes(tetrahedron_stl(0.1))
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="base"><visual><geometry><mesh '
                    'filename="left_tire.stl"/></geometry></visual></link></robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB401")
    (found,) = findings(result.stdout)
    assert found["message"].endswith("does not exist; 'Left_Tire.STL' beside it differs only "
                                     "in case, which Windows and macOS ignore and Linux does not")
    assert found["fix"] == "write 'Left_Tire.STL' as the file is named, or rename the file"
