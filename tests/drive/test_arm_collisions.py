"""drive refuses arm targets, and ways to them, that put the robot through itself.

The colliding and free configurations are found here by trying joint values on the real
robot and checking them with Pinocchio and coal directly (``arm_reference``), not with
servicebot's own check.
"""

from __future__ import annotations

import re

import numpy as np
import pytest

from tests.conftest import assert_one_line_error
from tests.drive.arm_reference import ARM, ArmReference
from tests.drive.conftest import finish, servicebot
from tests.drive.test_drive_pty import state_when

PAIR = re.compile(r"'(\w+)' and ('(\w+)'|the floor) would intersect")


@pytest.fixture(scope="module")
def reference():
    return ArmReference()


@pytest.fixture(scope="module")
def colliding(reference):
    """A value of arm_link1_to_link2 alone that puts links into each other, and which."""
    for value in np.arange(0.05, 1.57, 0.05):
        if reference.intersecting((0.0, value, 0.0, 0.0)):
            value = round(min(value + 0.15, 1.57), 2)  # well inside the contact
            found = reference.intersecting((0.0, value, 0.0, 0.0))
            assert found
            return value, found
    raise AssertionError("no value of arm_link1_to_link2 makes a contact")


def named_pair(line):
    """The two links a refusal names (the floor as ``floor``)."""
    match = PAIR.search(line)
    assert match, line
    return frozenset((match.group(1), match.group(3) or "floor"))


def arm_args(values):
    return [arg for name, value in zip(ARM, values, strict=True)
            for arg in ("--arm", f"{name}={value:g}")]


def test_a_colliding_target_is_refused_before_any_frame(run, colliding):
    from servicebot_cli.kinematics.collisions import Contact
    from servicebot_cli.kinematics.diagnosis import collision_hint

    value, found = colliding
    result = run("drive", "--dry-run", "--duration-s", "1", "--arm",
                 f"arm_link1_to_link2={value}")
    line = assert_one_line_error(result, 2, "Invalid value for",
                                 f"arm target arm_link1_to_link2={value:g} is reachable only "
                                 "through a collision")
    pair = PAIR.search(line)
    assert named_pair(line) in found
    assert line.endswith(f"is {collision_hint(Contact(pair[1], pair[3]))} "
                         "(see 'servicebot drive --help')")  # ik's words
    assert result.stdout == ""  # no frame printed


def test_the_floor_is_a_collision_no_srdf_can_disable(run, reference):
    pitch = next(p for p in np.arange(0.3, 1.57, 0.05)
                 if reference.below_floor_m((1.57, p, 0.0, 0.0)) > 0.02)  # arm out to the side
    assert not reference.intersecting((1.57, pitch, 0.0, 0.0))  # nothing but the floor
    line = assert_one_line_error(run("drive", "--dry-run", "--duration-s", "1",
                                     *arm_args((1.57, pitch, 0.0, 0.0))), 2)
    assert line.endswith(" and the floor would intersect; --allow-collisions accepts it "
                         "(see 'servicebot drive --help')")


def test_allow_collisions_lets_it_through(run, colliding):
    value, _ = colliding
    result = run("drive", "--dry-run", "--duration-s", "1", "--arm",
                 f"arm_link1_to_link2={value}", "--allow-collisions")
    assert result.exit_code == 0, result.stderr
    assert f"SET_ARM seq=2 [+0.000 +{value:.3f} +0.000 +0.000] rad" in result.stdout


def test_a_free_target_passes(run, reference):
    target = (0.5, 0.0, -0.3, 0.0)
    path = reference.firmware_path((0.0,) * 4, target, dt_s=0.005)
    assert all(reference.clear(arm) for arm in path)
    result = run("drive", "--dry-run", "--duration-s", "1", *arm_args(target))
    assert result.exit_code == 0, result.stderr
    assert "SET_ARM seq=2 [+0.500 +0.000 -0.300 +0.000] rad" in result.stdout


def test_a_script_line_is_named(run, tmp_path, colliding):
    value, found = colliding
    script = tmp_path / "tour.txt"
    script.write_text("twist 0.02 0 1\n# then the arm\narm arm_base_to_link1=0.2\nstop 0.5\n"
                      f"arm arm_link1_to_link2={value}\nstop 1\n")
    line = assert_one_line_error(run("drive", "--dry-run", "--script", script), 2,
                                 f"{script}:5: arm target arm_link1_to_link2={value:g}")
    assert named_pair(line) in found


def test_the_way_to_a_free_target_is_checked(run, reference):
    target = (-1.5, 0.0, 1.0, 1.0)
    assert reference.clear(target)
    touching = [reference.intersecting(arm) for arm in
                reference.firmware_path((0.0,) * 4, target, dt_s=0.005)]
    assert any(touching)  # the emulator's way there goes through the base
    line = assert_one_line_error(run("drive", "--dry-run", "--duration-s", "3",
                                     *arm_args(target)),
                                 2, "arm target arm_base_to_link1=-1.5 arm_link1_to_link2=0 "
                                 "arm_link2_to_link3=1 arm_link3_to_link4=1: on the way there, "
                                 "at arm_base_to_link1=")
    assert named_pair(line) in set().union(*touching)


def test_an_srdf_disables_the_pairs_it_names(run, tmp_path, colliding):
    value, found = colliding
    srdf, disabled = tmp_path / "robot.srdf", []
    args = ("drive", "--dry-run", "--duration-s", "1", "--arm", f"arm_link1_to_link2={value}",
            "--srdf", srdf)
    for _ in range(len(found) + 3):
        srdf.write_text("<robot name='service_robot'>" + "".join(
            f"<disable_collisions link1='{a}' link2='{b}' reason='test'/>"
            for a, b in disabled) + "</robot>")
        result = run(*args)
        if result.exit_code == 0:
            break
        pair = named_pair(assert_one_line_error(result, 2))
        if "floor" in pair:  # an SRDF names links; the floor is checked after every link
            break
        assert pair not in {frozenset(p) for p in disabled}
        disabled.append(sorted(pair))
    assert {frozenset(p) for p in disabled} == found


def test_collision_options_without_arm_targets_are_refused(run):
    assert_one_line_error(run("drive", "--dry-run", "--linear", "0", "--duration-s", "1",
                              "--allow-collisions"), 2,
                          "--allow-collisions has no effect without arm targets")


def test_a_run_on_a_port_sends_no_colliding_target(emulator, colliding):
    value, found = colliding
    emu = emulator()
    full = (0.0, value, 0.0, 0.0)  # every joint named: refused before the port opens
    code, _, stderr = finish(servicebot("drive", "--port", emu.path, "--duration-s", "1",
                                        *arm_args(full)))
    assert code == 2, stderr
    assert named_pair(stderr.splitlines()[-1]) in found
    assert "connected" not in stderr
    code, _, stderr = finish(servicebot("drive", "--port", emu.path, "--linear", "0",
                                        "--duration-s", "0.2"))
    assert code == 0, stderr
    state = state_when(emu, lambda s: s["counters"]["stops"] == 1, "the second run's stop")
    assert state["counters"]["first_command"] == "SET_WHEELS"  # the first run sent nothing
    assert [a["target_rad"] for a in state["arm"]] == [0.0] * 4


def test_a_run_checks_from_where_the_firmware_reports_the_arm(emulator, reference):
    """A joint left unnamed holds where it is: only the run knows, and checks before sending."""
    first, second = (0.0, 0.0, 0.8, 0.0), (0.0, 0.6, 0.8, 0.0)
    assert reference.clear(first) and reference.clear((0.0, 0.6, 0.0, 0.0))
    found = reference.intersecting(second)
    assert found
    emu = emulator()
    code, _, stderr = finish(servicebot("drive", "--port", emu.path, "--duration-s", "2",
                                        "--arm", "arm_link2_to_link3=0.8"))
    assert code == 0, stderr
    state_when(emu, lambda s: s["arm"][2]["position_rad"] == pytest.approx(0.8, abs=1e-3),
               "the arm at its first target")
    again = ("--duration-s", "1", "--arm", "arm_link1_to_link2=0.6")
    dry = finish(servicebot("drive", "--dry-run", *again))
    assert dry[0] == 0, dry[2]  # from where a dry run assumes the arm (0 rad), it is clear
    code, _, stderr = finish(servicebot("drive", "--port", emu.path, *again))
    assert code == 2, stderr
    line = stderr.splitlines()[-1]
    assert line.startswith("Error: --arm: arm target arm_link1_to_link2=0.6 is reachable only "
                           "through a collision: ")
    assert line.endswith("; motors stopped (the firmware confirmed)")
    assert named_pair(line) in found
    state = state_when(emu, lambda s: s["counters"]["stops"] == 2, "the second run's stop")
    assert [a["target_rad"] for a in state["arm"]] == pytest.approx(first, abs=1e-3)
