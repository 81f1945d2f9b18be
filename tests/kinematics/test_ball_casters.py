"""Balls on continuous joints beside cylinder wheels are passive casters, not drive wheels.

A base with two cylinder drive wheels and four corner ball casters on continuous joints
had the casters' radii and positions averaged into the drive's: inspect's track and wheel
radius and simulate's base were the mean of all six.
"""

from __future__ import annotations

import json

import pytest

from tests.conftest import run_servicebot

_MASS = '<inertial><mass value="0.1"/><inertia ixx="1e-4" iyy="1e-4" izz="1e-4" ixy="0" ' \
        'ixz="0" iyz="0"/></inertial>'


def _wheel(name: str, x: float, y: float, shape: str) -> str:
    roll = ' rpy="1.5708 0 0"' if shape.startswith("<cylinder") else ""
    return (f'  <link name="{name}_link">{_MASS}<collision><origin xyz="0 0 0"{roll}/>'
            f"<geometry>{shape}</geometry></collision></link>\n"
            f'  <joint name="{name}" type="continuous"><parent link="base_link"/>'
            f'<child link="{name}_link"/><origin xyz="{x} {y} -0.05"/><axis xyz="0 1 0"/>'
            '<limit effort="5" velocity="10"/></joint>\n')


def _robot(casters: str) -> str:
    drive = '<cylinder radius="0.05" length="0.03"/>'
    wheels = _wheel("left_wheel", 0, 0.2, drive) + _wheel("right_wheel", 0, -0.2, drive)
    balls = "".join(_wheel(f"caster_{k}", x, y, casters) for k, (x, y) in enumerate(
        [(0.25, 0.15), (0.25, -0.15), (-0.25, 0.15), (-0.25, -0.15)])) if casters else ""
    return (f'<robot name="base">\n  <link name="base_link">{_MASS}</link>\n'
            f"{wheels}{balls}</robot>\n")


@pytest.mark.parametrize("casters", ["", '<sphere radius="0.02"/>'],
                         ids=["wheels alone", "with four ball casters"])
def test_the_drive_is_its_cylinder_wheels(tmp_path, casters):
    path = tmp_path / "base.urdf"
    path.write_text(_robot(casters))
    result = run_servicebot("inspect", path, "--section", "totals", "--format", "json")
    drive = json.loads(result.stdout)["totals"]["drive"]
    assert (drive["track_m"], drive["wheel_radius_m"]) == pytest.approx((0.4, 0.05))


def test_balls_alone_are_the_wheels(tmp_path):
    """Where every wheel is a ball (neobotix's collide as spheres), the balls drive."""
    path = tmp_path / "balls.urdf"
    ball = '<sphere radius="0.05"/>'
    path.write_text(_robot("").replace('<cylinder radius="0.05" length="0.03"/>', ball))
    result = run_servicebot("inspect", path, "--section", "totals", "--format", "json")
    drive = json.loads(result.stdout)["totals"]["drive"]
    assert (drive["track_m"], drive["wheel_radius_m"]) == pytest.approx((0.4, 0.05))
