"""URDF 1.2's <limit acceleration deceleration jerk>: read by urdfdom from 1.2 on.

In a <robot version="1.2"> file they were 'no attribute acceleration' (SB011), where urdfdom
6 reads them; in an older file the message said they do not exist, where urdfdom ignores
them for the file's version. SB407 named a 1.2 file 'this URDF 1.1 file'.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings


def _robot(tmp_path, version: str, limit: str):
    path = tmp_path / "r.urdf"
    head = f'<robot name="r"{version}>' if version is not None else '<robot name="r">'
    path.write_text(head + '<link name="a"/><link name="b"/><joint name="j" type="revolute">'
                    '<parent link="a"/><child link="b"/><axis xyz="0 0 1"/><limit lower="-1" '
                    f'upper="1" effort="1" velocity="1" {limit}/></joint></robot>')
    return path


def _sb011(run, path):
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select",
                 "SB011,SB013")
    return [(f["code"], f["message"]) for f in findings(result.stdout)]


def test_a_1_2_file_reads_them(run, tmp_path):
    path = _robot(tmp_path, ' version="1.2"', 'acceleration="5" deceleration="5" jerk="50"')
    assert _sb011(run, path) == []


def test_a_1_2_file_still_wants_numbers_there(run, tmp_path):
    path = _robot(tmp_path, ' version="1.2"', 'jerk="fast"')
    assert [code for code, _ in _sb011(run, path)] == ["SB013"]


@pytest.mark.parametrize("version", ["", ' version="1.0"'])
def test_an_older_file_is_told_they_are_ignored_for_its_version(run, tmp_path, version):
    path = _robot(tmp_path, version, 'acceleration="5" jerk="50"')
    ((code, message),) = _sb011(run, path)
    assert code == "SB011"
    assert "'acceleration', 'jerk': urdfdom reads them only from URDF 1.2 on" in message


@pytest.mark.parametrize(("version", "expected"), [(' version="1.2"', ["SB205"]), ("", [])])
def test_a_negative_1_2_limit_is_sb205_where_urdfdom_reads_it(run, tmp_path, version, expected):
    """urdfdom: 'deceleration value (-2) is negative', and the joint fails: it was SB701 at
    <robot>, with 'Fix what the message says', and nothing at all beside another error."""
    path = _robot(tmp_path, version, 'deceleration="-2"')
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB2")
    found = [(f["code"], f["message"], f["fix"]) for f in findings(result.stdout)]
    assert [code for code, _, _ in found] == expected
    if expected:
        assert found[0][1] == ('<limit deceleration="-2">: a negative limit, which urdfdom '
                               "refuses (the joint, and so the file, fails to load)")
        assert found[0][2] == 'deceleration="2"'
