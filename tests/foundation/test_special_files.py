"""Outputs and inputs that are not regular files: devices, named pipes, symbolic links to them.

An output that is a device or a FIFO (``/dev/null``, ``/dev/full``, a named pipe) is written
as a shell's ``>`` writes it; renaming a temporary file over it would replace the device
itself (as root, ``/dev/full`` became a regular file holding a check report).
"""

from __future__ import annotations

import json
import os
import resource
import stat
from pathlib import Path

import pytest

from tests.conftest import assert_one_line_error, run_servicebot


def test_an_output_that_is_a_named_pipe_is_written_into_not_replaced(tmp_path: Path) -> None:
    fifo = tmp_path / "report.json"
    os.mkfifo(fifo)
    reader = os.open(fifo, os.O_RDONLY | os.O_NONBLOCK)  # a reader, so the writer's open returns
    try:
        result = run_servicebot("check", "--format", "json", "--output", fifo)
        assert result.returncode == 0, result.stderr
        assert stat.S_ISFIFO(fifo.lstat().st_mode), "the named pipe was replaced"
        assert b'"format_version"' in os.read(reader, 1 << 16)
    finally:
        os.close(reader)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report.json"]


def test_an_output_linked_to_a_device_writes_to_the_device(tmp_path: Path) -> None:
    link = tmp_path / "report.json"
    link.symlink_to(os.devnull)
    result = run_servicebot("check", "--output", link)
    assert result.returncode == 0, result.stderr
    assert link.is_symlink() and stat.S_ISCHR(link.stat().st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["report.json"]


@pytest.mark.skipif(not Path("/dev/full").is_char_device(), reason="no /dev/full")
def test_a_full_disk_is_one_error_line(tmp_path: Path) -> None:
    link = tmp_path / "report.json"
    link.symlink_to("/dev/full")
    result = run_servicebot("check", "--output", link)
    assert_one_line_error(result, 2, "report.json: cannot write: No space left on device",
                          "free some space")
    assert stat.S_ISCHR(Path("/dev/full").stat().st_mode)


def _memory_capped() -> None:
    """Run the child with 3 GB of address space: an endless read fails instead of the machine."""
    resource.setrlimit(resource.RLIMIT_AS, (3 << 30, 3 << 30))


@pytest.mark.parametrize(("args", "needle"), [
    (["fk", "/dev/zero"], "/dev/zero: holds more, over the 34 MB limit"),
    (["simulate", "--headless", "-s", "/dev/zero"], "/dev/zero: holds more, over the 10 MB"),
    (["sweep", "/dev/zero"], "/dev/zero: holds more, over the 1 MB limit"),
])
@pytest.mark.skipif(not Path("/dev/zero").is_char_device(), reason="no /dev/zero")
def test_an_input_without_end_is_read_to_the_limit_only(args: list[str], needle: str) -> None:
    result = run_servicebot(*args, timeout=60, preexec_fn=_memory_capped)
    assert_one_line_error(result, 2, needle, "is it the right file?")


def test_standard_input_without_end_is_read_to_the_limit_only() -> None:
    with open("/dev/zero", "rb") as zeros:
        result = run_servicebot("simulate", "--headless", "-s", "-", stdin=zeros, timeout=60,
                                preexec_fn=_memory_capped)
    assert_one_line_error(result, 2, "<stdin>: holds more, over the 10 MB limit")


def test_a_named_pipe_nothing_writes_into_ends_at_once(tmp_path):
    """A stale pipe named like a robot blocked every command forever, and a walk of its
    directory too. Named, it reads as empty; in a walk it is no robot file; a pipe that is
    written into (a shell's <(xacro ...)) is read as before."""
    import os
    import threading

    from tests.conftest import SIM_URDF, run_servicebot

    stale = tmp_path / "stale.urdf"
    os.mkfifo(stale)
    (tmp_path / "good.urdf").write_text(Path(SIM_URDF).read_text())
    named = run_servicebot("fk", stale, timeout=20)
    assert named.returncode == 2 and "file is empty" in named.stderr
    walked = run_servicebot("check", "urdf", tmp_path, "--isolated", timeout=20)
    assert walked.returncode == 0 and "1 file checked" in walked.stdout
    fed = tmp_path / "fed.urdf"
    os.mkfifo(fed)

    def feed() -> None:
        with fed.open("w") as pipe:
            pipe.write(Path(SIM_URDF).read_text())

    writer = threading.Thread(target=feed)
    writer.start()
    result = run_servicebot("fk", fed, "--format", "json", timeout=20)
    writer.join(timeout=20)
    assert result.returncode == 0, result.stderr


def test_a_xacro_include_that_is_a_stale_named_pipe_ends_at_once(tmp_path):
    import os

    os.mkfifo(tmp_path / "part.xacro")
    robot = tmp_path / "robot.urdf.xacro"
    robot.write_text('<robot xmlns:xacro="http://wiki.ros.org/xacro" name="r"><link name="a"/>'
                     '<xacro:include filename="part.xacro"/></robot>')
    result = run_servicebot("expand", robot, timeout=20)
    # named as what it is, at the include that names it
    line = assert_one_line_error(result, 2, "cannot include '", "part.xacro': it is a named pipe")
    assert line.startswith(f"Error: {robot}:1:")


def test_a_xacro_source_through_a_pipe_is_expanded_once_read(tmp_path):
    """``servicebot check <(cat robot.urdf.xacro)``: the bytes read to tell xacro from URDF
    used the pipe up, and xacro, opening it again, read an empty file (SB002, 'file is
    empty'). The real xacro expands it. No advice to rename a pipe, either."""
    import subprocess
    import sys

    text = ('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
            '<xacro:property name="w" value="0.5"/><link name="base"><visual><geometry>'
            '<box size="${w} 1 1"/></geometry></visual></link></robot>')
    for command in (["expand", "/dev/stdin"], ["check", "urdf", "--isolated", "/dev/stdin"]):
        result = subprocess.run([sys.executable, "-m", "servicebot_cli", *command], input=text,
                                capture_output=True, text=True, timeout=60)
        assert result.returncode == 0, result.stderr
        assert "empty" not in result.stdout + result.stderr
        assert ".urdf.xacro" not in result.stdout + result.stderr
    assert '<box size="0.5 1 1"/>' in subprocess.run(
        [sys.executable, "-m", "servicebot_cli", "expand", "/dev/stdin"], input=text,
        capture_output=True, text=True, timeout=60).stdout


def test_rules_that_read_a_piped_xacro_again_see_what_it_gave(tmp_path):
    """The optional-part rule reads the sources again: a piped xacro read as empty, and a
    reference to a part its arguments leave out was an error, a warning from the file."""
    import subprocess
    import sys

    text = ('<robot name="r" xmlns:xacro="http://www.ros.org/wiki/xacro">'
            '<xacro:property name="with_cam" value="false"/><link name="base"/>'
            '<xacro:if value="${with_cam}"><link name="cam_link"/><joint name="cam" '
            'type="fixed"><parent link="base"/><child link="cam_link"/></joint></xacro:if>'
            '<gazebo reference="cam_link"><material>Gazebo/Red</material></gazebo></robot>')
    (tmp_path / "r.urdf.xacro").write_text(text)
    severities = []
    for source, stdin in ((str(tmp_path / "r.urdf.xacro"), None), ("/dev/stdin", text)):
        result = subprocess.run(
            [sys.executable, "-m", "servicebot_cli", "check", "urdf", "--isolated", "--format",
             "json", "--select", "SB501", source], input=stdin, capture_output=True, text=True,
            timeout=60)
        (found,) = [f for file in json.loads(result.stdout)["files"] for f in file["findings"]]
        severities.append(found["severity"])
    assert severities == ["warning", "warning"]
