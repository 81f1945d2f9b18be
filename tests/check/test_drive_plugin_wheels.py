"""SB516: a Gazebo diff-drive plugin's wheel numbers against the URDF's wheels.

sam_bot (Nav2's tutorial) writes wheel_separation 0.4 on wheels 0.36 m apart, and bcr_bot a
gz DiffDrive wheel_radius of 0.11 on wheels of 0.1: Gazebo turns and drives them other than
commanded. The same numbers in a controllers file were SB603/SB604; here check said nothing.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings

_WHEEL = ('<link name="{name}"><collision><origin rpy="1.5708 0 0"/><geometry><cylinder '
          'radius="0.1" length="0.04"/></geometry></collision></link>'
          '<joint name="{name}_joint" type="continuous"><parent link="base_link"/>'
          '<child link="{name}"/><origin xyz="{x} {y} 0"/><axis xyz="0 1 0"/></joint>')


def _base(tmp_path, plugin: str, wheels=(("wheel_l", 0, 0.18), ("wheel_r", 0, -0.18))):
    parts = "".join(_WHEEL.format(name=n, x=x, y=y) for n, x, y in wheels)
    path = tmp_path / "base.urdf"
    path.write_text(f'<robot name="base"><link name="base_link"/>{parts}'
                    f"<gazebo>{plugin}</gazebo></robot>")
    return path


def _sb516(run, path):
    result = run("check", "urdf", path, "--format", "json", "--isolated", "--select", "SB516")
    return [(f["severity"], f["message"], f["fix"]) for f in findings(result.stdout)]


def _classic(body: str) -> str:
    return ('<plugin name="d" filename="libgazebo_ros_diff_drive.so"><left_joint>wheel_l_joint'
            f"</left_joint><right_joint>wheel_r_joint</right_joint>{body}</plugin>")


def test_the_urdfs_own_numbers_pass(run, tmp_path):
    path = _base(tmp_path, _classic("<wheel_separation>0.36</wheel_separation>"
                                    "<wheel_diameter>0.2</wheel_diameter>"))
    assert _sb516(run, path) == []


def test_a_separation_and_diameter_not_the_wheels_are_errors(run, tmp_path):
    path = _base(tmp_path, _classic("<wheel_separation>0.4</wheel_separation>"
                                    "<wheel_diameter>0.25</wheel_diameter>"))
    (separation, diameter) = _sb516(run, path)
    assert separation[0] == "error" and "<wheel_separation> 0.4 m, where the URDF's wheels " \
        "are 0.36 m apart: the robot turns at another rate" in separation[1]
    assert separation[2] == "<wheel_separation>0.36</wheel_separation>"
    assert "<wheel_diameter> 0.25 m, where the URDF's wheel diameter is 0.2 m" in diameter[1]
    assert diameter[2] == "<wheel_diameter>0.2</wheel_diameter>"


def test_numbers_left_out_are_the_plugins_defaults(run, tmp_path):
    """gazebo_ros_diff_drive drives with 0.34 m and a 0.15 m diameter when not told."""
    path = _base(tmp_path, _classic(""))
    messages = [m for _, m, _ in _sb516(run, path)]
    assert any("<wheel_separation> is not written: the plugin's default 0.34 m" in m
               for m in messages)
    assert any("<wheel_diameter> is not written: the plugin's default 0.15 m" in m
               for m in messages)


def test_a_few_per_cent_is_a_calibration_warning(run, tmp_path):
    path = _base(tmp_path, _classic("<wheel_separation>0.37</wheel_separation>"
                                    "<wheel_diameter>0.2</wheel_diameter>"))
    ((severity, message, _),) = _sb516(run, path)
    assert severity == "warning" and "(a calibration to the floor, if on purpose)" in message


def test_gz_sims_diff_drive_and_ros1_keys(run, tmp_path):
    gz = _base(tmp_path, '<plugin filename="gz-sim-diff-drive-system" name="gz::sim::systems::'
               'DiffDrive"><left_joint>wheel_l_joint</left_joint><right_joint>wheel_r_joint'
               '</right_joint><wheel_separation>0.36</wheel_separation><wheel_radius>0.11'
               "</wheel_radius></plugin>")
    ((_, message, fix),) = _sb516(run, gz)
    assert "<wheel_radius> 0.11 m, where the URDF's wheel radius is 0.1 m" in message
    assert fix == "<wheel_radius>0.1</wheel_radius>"
    ros1 = _base(tmp_path, '<plugin name="d" filename="libgazebo_ros_diff_drive.so">'
                 "<leftJoint>wheel_l_joint</leftJoint><rightJoint>wheel_r_joint</rightJoint>"
                 "<wheelSeparation>0.36</wheelSeparation><wheelDiameter>0.3</wheelDiameter>"
                 "</plugin>")
    ((_, message, _),) = _sb516(run, ros1)
    assert "<wheelDiameter> 0.3 m" in message


@pytest.mark.parametrize("separation", ["0.36", "0.6"])
def test_a_skid_steer_base_may_drive_with_a_wider_track(run, tmp_path, separation):
    """Four wheels skid as the base turns: a wider effective track is a warning."""
    wheels = (("wheel_l", 0.2, 0.18), ("wheel_r", 0.2, -0.18),
              ("rear_l", -0.2, 0.18), ("rear_r", -0.2, -0.18))
    path = _base(tmp_path, '<plugin name="d" filename="libgazebo_ros_skid_steer_drive.so">'
                 "<leftFrontJoint>wheel_l_joint</leftFrontJoint><wheelSeparation>"
                 f"{separation}</wheelSeparation></plugin>", wheels)
    found = _sb516(run, path)  # its own defaults are not judged: no diameter finding
    assert [severity for severity, _, _ in found] == ([] if separation == "0.36"
                                                     else ["warning"])


@pytest.mark.parametrize(("written", "shown"), [("abc", "abc"), ("nan", "nan"), ("", "")])
def test_a_number_that_is_no_number_is_an_error(run, tmp_path, written, shown):
    """'abc' and 'nan' passed (SB513 reads <gazebo> settings, not a plugin's); an empty
    element was 'not written: the plugin's default', though sdformat converts its text."""
    path = _base(tmp_path, _classic("<wheel_separation>0.36</wheel_separation>"
                                    f"<wheel_diameter>{written}</wheel_diameter>"))
    ((severity, message, fix),) = _sb516(run, path)
    assert severity == "error"
    assert f"<wheel_diameter>{shown}</wheel_diameter> is no number: sdformat cannot " \
        "convert it" in message
    assert fix == "<wheel_diameter>0.2</wheel_diameter>"


@pytest.mark.parametrize(("written", "said"), [
    ("<wheel_diameter>0</wheel_diameter>", "is no size a wheel has"),
    ("<wheel_diameter>1e-300</wheel_diameter>", "is no size a wheel has"),
    ("<wheel_separation>-0.3</wheel_separation>", "is no size a wheel has"),
    ("<wheel_diameter>abc</wheel_diameter>", "is no number")])
def test_simulate_refuses_wheel_numbers_no_wheel_has(run, tmp_path, written, said):
    """A diameter of 0 stopped simulate with a division by zero (exit 3); 1e-300 drove the
    robot 2.8e298 m in a second; 'abc' was driven with the URDF's wheels, silently."""
    path = _base(tmp_path, _classic(written))
    result = run("simulate", path, "--headless", "--duration-s", "1")
    assert result.exit_code == 2, result.output
    key = written.split(">")[0] + ">"
    assert f"{key}{written.split('>')[1].split('<')[0]}</{key[1:]} {said}" in result.stderr
    assert "(check reports it as SB516)" in result.stderr
