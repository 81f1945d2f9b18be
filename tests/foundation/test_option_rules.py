"""One rule for every option of every command, checked by walking the whole command tree.

Every numeric option refuses NaN and infinities; a single-valued option given twice is refused;
``--debug`` keeps the documented exit codes; every output option is checked before any work.
"""

from __future__ import annotations

import click
import pytest

from servicebot_cli.cli import main
from servicebot_cli.commands.options import Number, OutputPath
from tests.conftest import assert_one_line_error


def _commands(group: click.Group = main, path: tuple[str, ...] = ()):
    ctx = click.Context(group)
    for name in group.list_commands(ctx):
        command = group.get_command(ctx, name)
        assert command is not None
        yield (*path, name), command
        if isinstance(command, click.Group):
            yield from _commands(command, (*path, name))


COMMANDS = list(_commands())
OPTIONS = [(path, option) for path, command in COMMANDS for option in command.params
           if isinstance(option, click.Option)]


def _ids(item):
    path, option = item
    return f"{' '.join(path)} {max(option.opts, key=len)}"


NUMERIC = [item for item in OPTIONS
           if isinstance(item[1].type, (Number, click.types.FloatParamType))]
SINGLE = [item for item in OPTIONS if not (item[1].multiple or item[1].count or item[1].is_flag)]


@pytest.mark.parametrize("item", OPTIONS, ids=_ids)
def test_no_float_option_accepts_nan(item):
    """Floats go through Number, which refuses NaN and infinities (click's float does not)."""
    _, option = item
    assert not isinstance(option.type, click.types.FloatParamType), \
        "use commands.options.Number: click's float and FloatRange accept nan and inf"


@pytest.mark.parametrize("bad", ["nan", "inf", "-inf"])
@pytest.mark.parametrize("item", NUMERIC, ids=_ids)
def test_numeric_options_refuse_non_finite_values(run, item, bad):
    path, option = item
    flag = max(option.opts, key=len)
    result = run(*path, flag, *[bad] * option.nargs)
    assert_one_line_error(result, 2, flag)


@pytest.mark.parametrize("item", SINGLE, ids=_ids)
def test_single_valued_options_are_refused_twice(run, item):
    path, option = item
    if isinstance(option.type, click.Choice):
        value = str(option.type.choices[0])
    elif isinstance(option.type, OutputPath) and option.type.suffixes:
        value = "out" + option.type.suffixes[0]
    elif isinstance(option.type, click.IntRange | click.types.IntParamType | Number):
        value = "1"
    else:
        value = "x"
    flag = max(option.opts, key=len)
    values = [value] * option.nargs
    result = run(*path, flag, *values, flag, *values)
    assert_one_line_error(result, 2, f"{flag} given 2 times")


def test_xacro_argument_twice_is_refused(run):
    result = run("expand", "robots/service_robot.urdf.xacro", "hardware:=real", "hardware:=sim")
    assert_one_line_error(result, 2, "hardware:= given twice")


def test_the_same_xacro_argument_for_two_files_is_fine(run):
    result = run("check", "robots/service_robot.urdf.xacro", "hardware:=real",
                 "robots/service_robot.urdf.xacro", "hardware:=sim")
    assert result.exit_code == 0, result.stderr


@pytest.mark.parametrize(("args", "code"), [
    (["fk", "no_such_robot.urdf"], 2),
    (["ik", "--position", "5", "5", "5"], 1),
    (["check", "tests/check/fixtures/SB107_kinematic_loop.urdf"], 1),
])
def test_debug_adds_the_traceback_and_keeps_the_exit_code(run, args, code):
    plain = run(*args)
    debug = run("--debug", *args)
    assert plain.exit_code == debug.exit_code == code
    if plain.stderr.startswith("Error:"):
        assert "Traceback" in debug.stderr
        assert plain.stderr.splitlines()[-1] == debug.stderr.splitlines()[-1]
