"""Joint columns that say their unit (kinematics.joint_columns), without the CLI."""

from __future__ import annotations

from types import SimpleNamespace

import pytest

from servicebot_cli.kinematics.joint_columns import (
    UnitConflict,
    angle_unit,
    joint_column_names,
    joint_of,
    read_units,
)

SPACE = SimpleNamespace(names=("elbow", "elbow_deg", "slide"),
                        types=("revolute", "continuous", "prismatic"))
"""A joint named like another's column in degrees, and a prismatic one."""


def test_columns_are_bare_in_radians_and_name_the_unit_in_degrees():
    assert joint_column_names(SPACE, False) == {n: n for n in SPACE.names}
    assert joint_column_names(SPACE, True) == {"elbow": "elbow_deg",
                                               "elbow_deg": "elbow_deg_deg",
                                               "slide": "slide_m"}


def test_a_joint_s_own_name_wins_over_a_unit_suffix():
    assert joint_of("elbow_deg", SPACE) == ("elbow_deg", None)
    assert joint_of("elbow_deg_deg", SPACE) == ("elbow_deg", "deg")
    assert joint_of("elbow_rad", SPACE) == ("elbow", "rad")
    assert joint_of("slide_m", SPACE) == ("slide", "m")
    assert joint_of("nose_deg", SPACE) == ("nose_deg", None)  # unknown: the caller's to refuse


@pytest.mark.parametrize(("name", "message"), [
    ("slide_deg", "'slide_deg': joint 'slide' is prismatic, in metres; name the column "
     "'slide_m' or 'slide'"),
    ("elbow_m", "'elbow_m': joint 'elbow' is revolute, an angle; name the column 'elbow_deg' "
     "or 'elbow_rad'"),
])
def test_a_unit_that_does_not_fit_its_joint_is_refused(name, message):
    with pytest.raises(UnitConflict, match=f"^{message}$"):
        joint_of(name, SPACE)


def test_the_unit_a_line_states_wins_over_the_flags_and_bare_names_follow_it():
    stated = read_units(["elbow_deg_deg", "slide_m"], SPACE, deg=False)
    assert stated.deg and stated.joint("elbow_deg_deg") == "elbow_deg"
    assert stated.joint("slide_m") == "slide"
    assert not read_units(["elbow_rad"], SPACE, deg=True).deg
    assert read_units(["elbow"], SPACE, deg=False, line_unit="deg").deg
    assert not read_units(["elbow"], SPACE, deg=True, line_unit="rad").deg
    assert read_units(["elbow", "slide"], SPACE, deg=True).deg  # nothing stated: the flags
    assert read_units(["slide", "elbow_deg_deg"], SPACE, deg=False).deg  # metres: no angle


def test_units_that_disagree_are_refused():
    with pytest.raises(UnitConflict, match="two units"):
        read_units(["elbow_rad"], SPACE, deg=False, line_unit="deg")
    with pytest.raises(UnitConflict, match="two units: 'yaw' is in degrees, 'elbow_rad' is in "
                       "radians; give them all in one unit$"):
        read_units(["elbow_rad"], SPACE, deg=False, declared=[("'yaw'", "deg")])
    with pytest.raises(UnitConflict, match="'elbow' has no unit"):
        read_units(["elbow", "elbow_deg_deg"], SPACE, deg=False)


@pytest.mark.parametrize("value", ["grad", "DEG", "", None, 1, ["deg"]])
def test_an_angle_unit_is_deg_or_rad(value):
    assert angle_unit("deg") == "deg" and angle_unit("rad") == "rad"
    with pytest.raises(UnitConflict, match='give "deg" or "rad"'):
        angle_unit(value)


def test_a_joint_given_by_two_columns_is_refused_before_any_unit_is_weighed():
    with pytest.raises(UnitConflict, match="^'elbow' and 'elbow_rad' both give joint 'elbow'; "
                       "give it once$"):
        read_units(["elbow", "elbow_rad"], SPACE, deg=True)
