"""The OBJ reader gives one mesh however its lines are written.

A random mesh is written in the forms OBJ files take (CRLF or LF, blanks and tabs, indented
lines, corners with texture and normal indices, objects whose lines interleave, comments and
other keywords, polygons, a vertex weight, a byte order mark). The reader, which cuts vertex
and face lines out of the file in runs, must give what Python's own float() and int() give
line by line from the plain form of the same mesh.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from servicebot_cli.description.mesh_arrays import MeshFormatError
from servicebot_cli.description.mesh_obj import read_obj_indexed

_COORDINATES = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False, width=64)
_OTHER_LINES = [b"vt 0.5 0.25", b"vn 0 0 1", b"# v 1 2 3 f 1 2 3", b"o part", b"g group",
                b"s off", b"usemtl steel", b"", b"mtllib parts.mtl", b"l 1 2"]


@st.composite
def _objects(draw: st.DrawFn) -> list[tuple[list[tuple[float, float, float]], list[list[int]]]]:
    """Objects, each its vertices then faces naming any vertex given so far (from 1)."""
    objects, total = [], 0
    for _ in range(draw(st.integers(1, 4))):
        vertices = draw(st.lists(st.tuples(_COORDINATES, _COORDINATES, _COORDINATES),
                                 min_size=1 if total else 3, max_size=12))
        total += len(vertices)
        corner = st.integers(1, total)
        faces = draw(st.lists(st.lists(corner, min_size=3, max_size=5), max_size=10))
        objects.append((vertices, faces))
    return objects


def _number(value: float, style: int) -> bytes:
    return (repr(value), f"{value:.17g}", f"{value:.17e}")[style].encode()


@st.composite
def _written(draw: st.DrawFn, objects: list) -> bytes:
    """``objects`` in an OBJ file, each line in a form drawn for it."""
    end = draw(st.sampled_from([b"\n", b"\r\n", None]))  # None: each line its own
    lines: list[bytes] = [draw(st.sampled_from(_OTHER_LINES))
                          for _ in range(draw(st.integers(0, 2)))]
    indented = draw(st.integers(0, 4)) == 0  # some lines start with a blank

    def line(keyword: bytes, items: list[bytes]) -> bytes:
        indent = draw(st.sampled_from([b"", b" ", b"\t"])) if indented else b""
        after = draw(st.sampled_from([b" ", b" ", b"\t", b"  ", b" \t"]))
        between = draw(st.sampled_from([b" ", b" ", b"\t", b"   "]))
        trailing = draw(st.sampled_from([b"", b"", b" ", b"\t"]))
        return indent + keyword + after + between.join(items) + trailing

    for vertices, faces in objects:
        style = draw(st.integers(0, 2))
        weighted = draw(st.booleans())
        for vertex in vertices:
            items = [_number(c, style) for c in vertex] + ([b"1.0"] if weighted else [])
            lines.append(line(b"v", items))
            if draw(st.integers(0, 9)) == 0:
                lines.append(draw(st.sampled_from(_OTHER_LINES)))
        form = draw(st.sampled_from([b"%d", b"%d/1", b"%d//1", b"%d/1/1"]))
        for face in faces:
            lines.append(line(b"f", [form % index for index in face]))
            if draw(st.integers(0, 9)) == 0:
                lines.append(draw(st.sampled_from(_OTHER_LINES)))
    ends = [end or draw(st.sampled_from([b"\n", b"\r\n"])) for _ in lines]
    text = b"".join(text + ending for text, ending in zip(lines, ends, strict=True))
    if draw(st.booleans()):
        text = text.removesuffix(ends[-1]) if lines else text  # no line end after the last
    return (b"\xef\xbb\xbf" if draw(st.integers(0, 9)) == 0 else b"") + text


def _plain(objects: list) -> tuple[np.ndarray, np.ndarray]:
    """The mesh read line by line from its plain form, by Python's float() and int()."""
    table = [vertex for vertices, _ in objects for vertex in vertices]
    triangles = [(face[0] - 1, face[k] - 1, face[k + 1] - 1)
                 for _, faces in objects for face in faces for k in range(1, len(face) - 1)]
    plain = "".join(f"v {' '.join(repr(c) for c in v)}\n" for v in table).encode()
    parsed = np.array([[float(x) for x in line.split()[1:]] for line in plain.splitlines()])
    return parsed.reshape(-1, 3), np.array(triangles, dtype=np.int64).reshape(-1, 3)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_every_written_form_reads_as_the_plain_mesh(data):
    objects = data.draw(_objects())
    text = data.draw(_written(objects))
    vertices, faces = read_obj_indexed(text)
    expected_vertices, expected_faces = _plain(objects)
    assert vertices.tobytes() == expected_vertices.tobytes()  # the same bits: -0.0 too
    assert np.array_equal(faces, expected_faces)


@pytest.mark.parametrize("text", [
    b"v 0 0 0\nv 1 0 0\nv v 1 0\nf 1 2 3\n",  # a keyword in a vertex's numbers
    b"v 0 0 0\nv\t1 0 0\nv v\t1 0\nf 1 2 3\n",
    b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 f\n",  # and in a face's corners
    b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf\t1 2 3\nf f\t1 2 3\n",
])
def test_a_keyword_inside_a_line_is_no_number(text):
    with pytest.raises((MeshFormatError, ValueError)):
        read_obj_indexed(text)


def test_a_carriage_return_inside_a_line_ends_it():
    """As Assimp and the regular expressions read it: what follows the CR is not the line's."""
    text = b"v 0 0 0\nv 1 0 0\r 5\nv 0 1 0\nf 1 2 3\n"
    vertices, faces = read_obj_indexed(text)
    assert vertices.tolist() == [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    assert faces.tolist() == [[0, 1, 2]]


def test_many_objects_of_one_line_each():
    """More runs of vertex and face lines than the reader cuts one by one."""
    text = b"".join(b"v %d 0 0\nv %d 1 0\nv %d 0 1\nf %d %d %d\n"
                    % (k, k, k, 3 * k + 1, 3 * k + 2, 3 * k + 3) for k in range(500))
    vertices, faces = read_obj_indexed(text)
    assert len(vertices) == 1500 and faces.tolist()[-1] == [1497, 1498, 1499]
    assert vertices[faces[-1]].tolist() == [[499, 0, 0], [499, 1, 0], [499, 0, 1]]


@pytest.mark.parametrize(("text", "counts"), [
    (b"o a\r\nv 0 0 0\r\nv\t1 0 0\r\nv 0 1 0\r\nvn 0 0 1\r\nf 1//1 2//1 3//1\r\n"
     b"o b\r\nv 0 0 1\r\nf\t1/1/1 2/1/1  4/1/1\r\nf 1 2 3 4", (4, 3)),
    (b"v 0 0 0\n" * 8 + b"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 9 10 11 12\nf 9 10 11\n",
     (12, 2)),
], ids=["CRLF, tabs, objects, texture and normal indices", "a quad and a triangle"])
def test_exporters_forms_take_the_one_pass_path(text, counts):
    """What exporters write is cut out in runs and its corners read in a few passes: the
    slower readers are only for what they do not write."""
    from servicebot_cli.description import mesh_obj, mesh_obj_faces

    found = mesh_obj._in_runs(text)
    assert found is not None
    ((_, vertex_count), (face_text, face_count)), dotted_textures = found
    assert (vertex_count, face_count, dotted_textures) == (*counts, False)
    assert mesh_obj_faces._plain_corners(face_text, face_count) is not None
