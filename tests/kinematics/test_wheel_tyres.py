"""A wheel rolls on its tyre: the largest cylinder about its axle, whatever the order.

Leo Rover's wheels (tests/fixtures/leo_description, MIT) collide as a hub (r 0.057 m,
listed first) and a tyre (r 0.0625 m): inspect, simulate and check took the hub, a radius
9 % short (top speed 0.342 m/s for 0.375), where Leo's own DiffDrive plugin says
<wheel_radius>0.0625</wheel_radius> and its wheel frames sit 0.0625 m above the ground.
"""

from __future__ import annotations

import json

import pytest

from tests.conftest import REPO, run_servicebot

LEO = REPO / "tests" / "fixtures" / "leo_description" / "urdf" / "leo_sim.urdf.xacro"
WHEEL = ('<link name="{side}_wheel"><collision><origin rpy="1.5708 0 0"/><geometry><cylinder '
         'radius="{first}" length="0.07"/></geometry></collision><collision><origin '
         'rpy="1.5708 0 0"/><geometry><cylinder radius="{second}" length="0.04"/></geometry>'
         '</collision><collision><geometry><cylinder radius="0.2" length="0.01"/></geometry>'
         '</collision></link><joint name="{side}_joint" type="continuous"><parent '
         'link="base_link"/><child link="{side}_wheel"/><origin xyz="0 {y} 0.0625"/><axis '
         'xyz="0 1 0"/><limit effort="1" velocity="6"/></joint>')


def _drive(path) -> dict:
    result = run_servicebot("inspect", path, "--section", "totals", "--format", "json")
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)["totals"]["drive"]


def test_leos_wheels_roll_on_their_tyres():
    drive = _drive(LEO)
    assert drive["wheel_radius_m"] == pytest.approx(0.0625)
    assert drive["top_speed_m_s"] == pytest.approx(0.375)


@pytest.mark.parametrize(("first", "second"), [(0.057, 0.0625), (0.0625, 0.057)])
def test_the_order_of_the_cylinders_does_not_matter(tmp_path, first, second):
    """A larger cylinder across the axle (the third, about z) is no tyre."""
    path = tmp_path / "r.urdf"
    path.write_text('<robot name="r"><link name="base_link"/>'
                    + WHEEL.format(side="left", y=0.18, first=first, second=second)
                    + WHEEL.format(side="right", y=-0.18, first=first, second=second)
                    + "</robot>")
    assert _drive(path)["wheel_radius_m"] == pytest.approx(0.0625)
