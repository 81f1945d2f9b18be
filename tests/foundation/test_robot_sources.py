"""RobotArgs.sources(): every description a command line names, each with its own xacro args."""

from __future__ import annotations

import click
import pytest

from servicebot_cli.commands.options import RobotArgs, split_robot_args


def _args(*values: str, bundled: str | None = None) -> RobotArgs:
    files, xacro_args = split_robot_args(values)
    return RobotArgs(files, xacro_args, bundled, (), values)


def test_each_file_keeps_the_xacro_arguments_that_follow_it():
    a, b = _args("a.xacro", "hardware:=sim", "b.xacro", "hardware:=real", "x:=1").sources()
    assert (str(a.path), a.xacro_args) == ("a.xacro", (("hardware", "sim"),))
    assert (str(b.path), b.xacro_args) == ("b.xacro", (("hardware", "real"), ("x", "1")))


def test_the_bundled_robot_comes_first():
    bundled, other = _args("b.urdf", bundled="real").sources()
    assert bundled.path.name == "service_robot_real.urdf.xml"
    assert str(other.path) == "b.urdf"


def test_none_named_is_empty():
    assert _args().sources() == []


def test_an_argument_before_any_file_is_refused():
    with pytest.raises(click.UsageError, match="comes before any FILE"):
        _args("hardware:=real", "a.xacro").sources()
