"""Inertias MuJoCo refuses: a point mass a joint moves alone, a triangle inequality missed by
a rounding. Each case was checked in MuJoCo (mujoco.MjModel.from_xml_path), here too.

laikago's hip motors (mass 1.095, inertia all zero) passed with a warning, and MuJoCo refuses
all four laikago files; moments 0.1, 0.1, 0.2000002 passed, and MuJoCo refuses them.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings

_LINK = ('<link name="{name}"><inertial><mass value="1"/><inertia ixx="{i[0]}" iyy="{i[1]}" '
         'izz="{i[2]}" ixy="0" ixz="0" iyz="0"/></inertial></link>')
_BODY = (0.01, 0.01, 0.01)


def _robot(tmp_path, rod, tip=None):
    tip_part = "" if tip is None else (
        _LINK.format(name="tip", i=tip) + '<joint name="f" type="fixed"><parent link="rod"/>'
        '<child link="tip"/><origin xyz="0.1 0 0"/></joint>')
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r">' + _LINK.format(name="base", i=_BODY)
                    + _LINK.format(name="rod", i=rod) + '<joint name="j" type="revolute">'
                    '<parent link="base"/><child link="rod"/><axis xyz="0 0 1"/><limit '
                    'lower="-1" upper="1" effort="1" velocity="1"/></joint>'
                    + tip_part + "</robot>")
    return path


def _verdict(run, path):
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select",
                 "SB307,SB308")
    return [(f["code"], f["severity"]) for f in findings(result.stdout)]


def _mujoco_loads(path) -> bool:
    mujoco = pytest.importorskip("mujoco")
    try:
        mujoco.MjModel.from_xml_path(str(path))
    except ValueError:
        return False
    return True


@pytest.mark.parametrize(("rod", "tip", "expected"), [
    ((0, 0, 0), None, [("SB307", "error")]),  # a point mass a joint moves
    ((0, 0, 0), _BODY, [("SB307", "warning")]),  # lumped with its fixed tip: a body
    ((0.1, 0.1, 0.2000002), None, [("SB308", "warning")]),  # by a rounding
    ((0.1, 0.1, 0.3), None, [("SB308", "error")]),
    (_BODY, None, []),
])
def test_verdicts_follow_mujoco(run, tmp_path, rod, tip, expected):
    path = _robot(tmp_path, rod, tip)
    assert _verdict(run, path) == expected
    assert _mujoco_loads(path) == (not expected or expected == [("SB307", "warning")])
