"""emulate's bad input: one line, exit 2, nothing left behind."""

from __future__ import annotations

import os

import pytest

from tests.conftest import assert_one_line_error


@pytest.mark.parametrize(("args", "needles"), [
    (("--drop", "2"), ("'--drop'", "give a number from 0 to 1")),
    (("--corrupt", "-0.1"), ("'--corrupt'",)),
    (("--latency-s", "-1"), ("must not be negative",)),
    (("--die-after-s", "0"), ("must be above 0",)),
    (("--protocol", "arduino"), ("--ticks-per-rev", "needed with --protocol arduino")),
    (("--watchdog-ms", "0"), ("'--watchdog-ms'",)),
])
def test_bad_options(run, args, needles):
    assert_one_line_error(run("emulate", *args), 2, *needles)


def test_a_state_file_in_a_missing_directory(run, tmp_path):
    result = run("emulate", "--state-file", tmp_path / "none" / "state.json")
    assert_one_line_error(result, 2, "does not exist")
    assert result.stdout == ""  # no device was announced


def test_a_link_that_cannot_be_made(run, tmp_path):
    assert_one_line_error(run("emulate", "--link", tmp_path / "none" / "tty"), 2,
                          "cannot make the link")
    assert_one_line_error(run("emulate", "--link", tmp_path), 2, "is a directory")


def test_an_existing_file_at_link_is_never_touched(run, tmp_path):
    notes = tmp_path / "notes.txt"
    notes.write_text("my notes\n")
    result = run("emulate", "--link", notes)
    assert_one_line_error(result, 2, f"--link {notes}: already exists", "give another path")
    assert result.stdout == ""  # no device was announced
    assert not notes.is_symlink() and notes.read_text() == "my notes\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["notes.txt"]


def test_a_symlink_that_is_not_an_emulators_is_never_touched(run, tmp_path):
    notes = tmp_path / "notes.txt"
    notes.write_text("my notes\n")
    link = tmp_path / "tty"
    link.symlink_to(notes)
    assert_one_line_error(run("emulate", "--link", link), 2, f"is a symlink to {notes}")
    assert os.readlink(link) == str(notes) and notes.read_text() == "my notes\n"


def test_a_link_to_a_pty_in_use_is_never_touched(run, tmp_path, fake_device):
    device = fake_device()  # another emulator's live pty
    link = tmp_path / "tty"
    link.symlink_to(device.path)
    assert_one_line_error(run("emulate", "--link", link), 2, f"links to {device.path}",
                          "in use")
    assert os.readlink(link) == device.path


def test_a_link_older_than_the_pty_it_names_is_a_dead_emulators(run, tmp_path, fake_device):
    """The pty number of a killed emulator, since taken by another program: replaced."""
    device = fake_device()  # made after the link, as a program that got the freed number
    link = tmp_path / "tty"
    link.symlink_to(device.path)
    made_s = os.stat(device.path).st_ctime
    os.utime(link, (made_s - 60, made_s - 60), follow_symlinks=False)  # the link: a minute older
    result = run("emulate", "--link", link, "--die-after-s", "0.3")
    assert result.exit_code == 0, result.output
    assert "in use" not in result.output
    assert str(link) in result.stdout  # announced as the emulator's device
    assert not link.is_symlink()  # and removed when it stopped
    assert os.path.exists(device.path)  # the other program's pty is left alone


def test_a_robot_the_binary_protocol_cannot_carry(run, tmp_path):
    from tests.conftest import REAL_URDF

    urdf = tmp_path / "three_arm_joints.urdf"
    text = REAL_URDF.read_text()
    text = text.replace('<joint name="arm_link3_to_link4" type="revolute">',
                        '<joint name="arm_link3_to_link4" type="fixed">')
    urdf.write_text(text)
    assert_one_line_error(run("emulate", urdf), 2, "carries 4 wheels and 4 arm joints",
                          "3 arm joints")
    assert_one_line_error(run("drive", urdf, "--dry-run", "--duration-s", "1"), 2,
                          "carries 4 wheels and 4 arm joints")
