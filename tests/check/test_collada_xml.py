"""COLLADA through lxml reads as through ElementTree, which keeps the last word."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest
import trimesh

from servicebot_cli.check.meshes import MeshError, load_mesh
from servicebot_cli.description.collada_xml import parse_collada
from tests.check.corpus import erd_root


def _sample() -> list:
    """Every 6th COLLADA file of example-robot-data."""
    return sorted(p for p in (erd_root() / "robots").rglob("*") if p.suffix.lower() == ".dae")[::6]


def _shape(element: ET.Element) -> tuple:
    """Tag, attributes and text of the element and every element below it."""
    children = tuple(_shape(c) for c in element if isinstance(c.tag, str))
    return element.tag, dict(element.attrib), element.text, children


@pytest.mark.parametrize("path", _sample(), ids=lambda p: p.name)
def test_the_tree_is_elementtrees(path):
    data = path.read_bytes()
    assert _shape(parse_collada(data)) == _shape(ET.fromstring(data))


@pytest.fixture
def box_dae(tmp_path):
    """A 0.3 x 0.2 x 0.1 m box exported by trimesh, as COLLADA text."""
    path = tmp_path / "box.dae"
    trimesh.creation.box(extents=(0.3, 0.2, 0.1)).export(path)
    return path.read_text()


def test_comments_between_elements_change_nothing(tmp_path, box_dae):
    """lxml keeps comments as children (ElementTree drops them): the readers skip them."""
    commented = (box_dae.replace("<triangles", "<!-- faces --><triangles")  # in <mesh>
                 .replace("<instance_geometry", "<!-- box --><instance_geometry"))  # in <node>
    assert commented.count("<!--") == 2
    path = tmp_path / "commented.dae"
    path.write_text(commented)
    plain = tmp_path / "plain.dae"
    plain.write_text(box_dae)
    for with_mass in (False, True):
        assert _summary(load_mesh(path, with_mass)) == _summary(load_mesh(plain, with_mass))
    assert _summary(load_mesh(path, True))[-1][0] == pytest.approx(0.006)


def _summary(info) -> tuple:
    mass = info.mass and (info.mass.volume, info.mass.centroid, info.mass.second_moment.tolist())
    return info.triangles, info.lower, info.upper, info.closed, mass


def test_an_entity_is_expanded_as_elementtree_does(tmp_path):
    """A DOCTYPE goes to ElementTree, which expands internal entities (within expat's limits)."""
    text = ('<?xml version="1.0"?>\n<!DOCTYPE COLLADA [<!ENTITY corners "0 0 0 2 0 0 0 3 0">]>\n'
            '<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema"><library_geometries>'
            '<geometry id="g"><mesh><source id="p"><float_array id="a" count="9">&corners;'
            '</float_array><technique_common><accessor source="#a" count="3" stride="3"/>'
            '</technique_common></source><vertices id="v"><input semantic="POSITION" source="#p"/>'
            '</vertices><triangles count="1"><input semantic="VERTEX" source="#v" offset="0"/>'
            '<p>0 1 2</p></triangles></mesh></geometry></library_geometries></COLLADA>')
    path = tmp_path / "entity.dae"
    path.write_text(text)
    info = load_mesh(path)
    assert (info.triangles, info.lower, info.upper) == (1, (0, 0, 0), (2, 3, 0))


def test_malformed_collada_says_what_elementtree_says(tmp_path):
    path = tmp_path / "broken.dae"
    path.write_text("<COLLADA><library_geometries></COLLADA>")
    with pytest.raises(MeshError, match=r"not well-formed XML: mismatched tag: line 1, column 31"):
        load_mesh(path)


@pytest.mark.parametrize("before", ["", "<!-- <a> -->\n", "<!-- a comment -->\n"])
def test_a_doctype_after_a_comment_still_goes_to_elementtree(before):
    """Only the prolog is searched for a DOCTYPE; an element-like comment there widens it."""
    from servicebot_cli.description.collada_xml import _with_lxml

    text = (f'<?xml version="1.0"?>\n{before}<!DOCTYPE COLLADA [<!ENTITY n "1 2 3">]>\n'
            '<COLLADA><float_array>&n;</float_array></COLLADA>').encode()
    assert _with_lxml(text) is None
    assert _with_lxml(text.replace(b"<!DOCTYPE COLLADA [<!ENTITY n \"1 2 3\">]>\n", b"")
                      .replace(b"&n;", b"1 2 3")) is not None


def test_a_processing_instruction_holding_an_element_start_hides_no_doctype():
    from servicebot_cli.description.collada_xml import _with_lxml

    text = (b'<?note <a?><!DOCTYPE COLLADA [<!ENTITY n "0 0 0 1 0 0 0 1 0">]>'
            b"<COLLADA><x>&n;</x></COLLADA>")
    assert _with_lxml(text) is None
    assert parse_collada(text).find("x").text == "0 0 0 1 0 0 0 1 0"
    assert _with_lxml(b"\xef\xbb\xbf<?xml version='1.0'?>\n<!-- c -->\n<COLLADA/>") is not None
