"""A <capsule> is URDF 1.1: urdfdom drops it from any other file, and check says which."""

from __future__ import annotations

import pytest

from tests.check.corpus import check_urdf_drops
from tests.check.helpers import findings


@pytest.mark.parametrize(("version", "severity"), [("", "error"), (' version="1.0"', "error"),
                                                   (' version="1.1"', "warning"),
                                                   (' version="1.2"', "warning")])
def test_a_capsule_is_an_error_where_urdfdom_drops_it(run, tmp_path, version, severity):
    path = tmp_path / "r.urdf"
    path.write_text(f'<robot name="r"{version}><link name="a"><collision><geometry>'
                    '<capsule radius="0.1" length="0.5"/></geometry></collision></link></robot>')
    assert check_urdf_drops(path) is (severity == "error")
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB407")
    (found,) = findings(result.stdout)
    assert found["severity"] == severity
    assert ("only pybullet" not in found["message"])
