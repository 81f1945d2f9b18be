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


def _with_mujoco_block(path, compiler):
    text = path.read_text().replace('<robot name="r">', f'<robot name="r"><mujoco>{compiler}'
                                    '</mujoco>', 1)
    path.write_text(text)
    return path


@pytest.mark.parametrize("rod", [(0, 1e-4, 1e-4), (0, 0, 1e-4), (-2.9e-21, 1.2e-4, 1.2e-4),
                                 (5e-15, 1, 1), (1e-12, 1, 1)])
@pytest.mark.parametrize("compiler", [None, '<compiler angle="radian"/>',
                                      '<compiler boundinertia="1e-6"/>',
                                      '<compiler boundinertia="1e-6" balanceinertia="true"/>'])
@pytest.mark.parametrize("fixed", [False, True])
def test_a_zero_principal_moment_is_said_as_mujoco_reads_it(run, tmp_path, rod, compiler, fixed):
    """MuJoCo refuses an eigenvalue at zero (its mjMINVAL, past rounding) on any link, and
    a moment its boundinertia raises may then break A + B >= C: the message says MuJoCo
    refuses exactly where it does, and a file meant for MuJoCo (a <mujoco> block) makes
    that an error. The third rod is stretch_description's link_arm_l4.
    """  # noqa: D205
    path = _robot(tmp_path, rod, _BODY if fixed else None)
    if fixed:  # the rod fixed under the base: MuJoCo still reads its inertia
        path.write_text(path.read_text().replace('type="revolute"', 'type="fixed"'))
    if compiler is not None:
        _with_mujoco_block(path, compiler)
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select",
                 "SB307,SB308")
    found = [f for f in findings(result.stdout) if "'rod'" in f["message"]]
    loads = _mujoco_loads(path)
    if not fixed and rod[1] == 0:  # (0, 0, I) a joint moves: no body (SB308)
        assert [f["code"] for f in found] == ["SB308"]
        assert loads == ("balanceinertia" in (compiler or ""))  # MuJoCo, unless made one
        return
    assert [f["code"] for f in found] == ["SB307"], result.stdout
    assert ("MuJoCo refuses" in found[0]["message"]
            or "and then refuses" in found[0]["message"]) == (not loads)
    assert found[0]["severity"] == ("error" if compiler is not None and not loads else "warning")
