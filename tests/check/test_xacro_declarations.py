"""A xacro file's XML declaration read as ROS's xacro (expat, given text) reads it.

xacro opens the file as UTF-8 text, so expat ignores the encoding its declaration names:
a UTF-8 file declaring ISO-8859-1 came out garbled here ('base_Ã©'), one declaring 'utf8',
US-ASCII or UTF-16 was refused (SB004, blamed on xmlns:xacro), where xacro expands them.
And a malformed declaration (<?xml verison="1.0"?>), which tinyxml2 reads past in a plain
URDF, passed in a xacro file that xacro refuses.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings
from tests.conftest import run_servicebot

BODY = ('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
        '<xacro:property name="n" value="base_é"/><link name="${n}"/></robot>\n')


@pytest.mark.parametrize("encoding", ["ISO-8859-1", "utf8", "US-ASCII", "UTF-16"])
def test_the_declared_encoding_of_a_utf8_xacro_is_not_read(tmp_path, encoding):
    path = tmp_path / "robot.urdf.xacro"
    path.write_bytes(f'<?xml version="1.0" encoding="{encoding}"?>\n{BODY}'.encode())
    expanded = run_servicebot("expand", path)
    assert expanded.returncode == 0, expanded.stderr
    assert '<link name="base_é"/>' in expanded.stdout
    checked = run_servicebot("check", "urdf", path, "--isolated", "--format", "json")
    assert [f["code"] for f in findings(checked.stdout) if f["severity"] == "error"] == []


def test_a_malformed_declaration_is_refused_in_xacro_and_read_past_in_a_urdf(tmp_path):
    xacro = tmp_path / "robot.urdf.xacro"
    xacro.write_text('<?xml verison="1.0"?>\n' + BODY, encoding="utf-8")
    (found,) = findings(run_servicebot("check", "urdf", xacro, "--isolated", "--format",
                                       "json").stdout)
    assert (found["code"], found["line"]) == ("SB004", 1)
    assert "XML declaration not well-formed" in found["message"]
    urdf = tmp_path / "robot.urdf"
    urdf.write_text('<?xml verison="1.0"?>\n<robot name="r"><link name="base"/></robot>\n')
    result = run_servicebot("check", "urdf", urdf, "--isolated", "--format", "json")
    assert result.returncode == 0, result.stdout  # tinyxml2 (check_urdf) reads it


def test_an_entity_whose_value_holds_a_predefined_entity_is_read(tmp_path):
    """<!ENTITY q "a &amp; b"> was refused ('its value refers to another entity'): XML's
    five predefined entities expand to nothing more, and xacro writes name="a &amp; b"."""
    path = tmp_path / "robot.urdf.xacro"
    path.write_text('<?xml version="1.0"?>\n<!DOCTYPE robot [\n  <!ENTITY q "a &amp; b">\n]>\n'
                    '<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="r">\n'
                    '  <link name="a"><visual name="&q;"/></link>\n</robot>\n')
    expanded = run_servicebot("expand", path)
    assert expanded.returncode == 0, expanded.stderr
    assert '<visual name="a &amp; b"/>' in expanded.stdout
    nested = tmp_path / "nested.urdf.xacro"
    nested.write_text(path.read_text().replace('<!ENTITY q "a &amp; b">',
                                               '<!ENTITY p "x"><!ENTITY q "&p;_b">'))
    refused = run_servicebot("expand", nested)
    assert refused.returncode == 2 and "its value refers to another entity" in refused.stderr


@pytest.mark.parametrize("name", ["gz\u00b7tag", "cafe\u0301"])
def test_a_name_xml_allows_is_no_bad_name(tmp_path, name):
    """XML 1.0's NameChars include U+00B7 and combining marks: a literal element so
    named was refused as 'no XML name ... (a xacro:element named it)'; xacro expands it."""
    path = tmp_path / "robot.urdf.xacro"
    path.write_text(f'<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="r"><link '
                    f'name="a"><{name}/></link></robot>\n', encoding="utf-8")
    expanded = run_servicebot("expand", path)
    assert expanded.returncode == 0, expanded.stderr
    assert f"<{name}/>" in expanded.stdout
