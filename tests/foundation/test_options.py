"""The shared option types and refusals, on a small command built with them."""

from __future__ import annotations

import click
import pytest
from click.testing import CliRunner

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.options import Number, OutputPath, refuse_with, refuse_without


@click.command(cls=Command)
@click.option("--plot", type=OutputPath((".png", ".svg")))
@click.option("--out", type=OutputPath(directory=True))
@click.option("--bag", type=OutputPath(directory=True, fresh=True))
@click.option("-o", "--output", type=OutputPath(parents=True, allow_dash=True))
@click.option("--speed", type=Number(positive=True, maximum=10.0))
@click.option("--headless", is_flag=True)
@click.option("--view", default="iso")
@click.option("--render")
@click.pass_context
def demo(ctx: click.Context, **values: object) -> None:
    refuse_with(ctx, "--speed", "--headless", present=bool(values["headless"]),
                why="which has no window")
    refuse_without(ctx, "--view", "--render FILE.png", present=values["render"] is not None)
    click.echo("ok")


def _run(*args: str) -> tuple[int, str]:
    result = CliRunner().invoke(demo, list(args))
    return result.exit_code, result.stdout + result.stderr


@pytest.mark.parametrize(("args", "needle"), [
    (["--plot", "run.txt"], "files end in .png or .svg; name it e.g. 'run.png'"),
    (["--plot", "no/such/dir/run.png"], "directory 'no/such/dir' does not exist"),
    (["--speed", "11"], "above the maximum 10"),
    (["--speed", "0"], "must be above 0"),
    (["--headless", "--speed", "2"], "--speed has no effect with --headless (which has no window)"),
    (["--view", "top"], "--view has no effect without --render FILE.png"),
])
def test_refused_before_any_work(args, needle):
    code, output = _run(*args)
    assert code == 2 and needle in output, output


def test_a_file_where_a_directory_is_needed(tmp_path):
    (tmp_path / "file").write_text("x")
    code, output = _run("--out", str(tmp_path / "file"))
    assert code == 2 and "is a file; give a directory" in output
    code, output = _run("--plot", str(tmp_path / "file" / "run.png"))
    assert code == 2 and "is a file, not a directory" in output


def test_fresh_directory_must_not_exist(tmp_path):
    code, output = _run("--bag", str(tmp_path))
    assert code == 2 and "already exists" in output
    assert _run("--bag", str(tmp_path / "new_bag")) == (0, "ok\n")


def test_parents_may_be_missing_but_not_a_file(tmp_path):
    assert _run("-o", str(tmp_path / "a" / "b" / "r.urdf")) == (0, "ok\n")
    (tmp_path / "f").write_text("x")
    code, output = _run("-o", str(tmp_path / "f" / "b" / "r.urdf"))
    assert code == 2 and "is a file, not a directory" in output
    assert not (tmp_path / "a").exists()  # checking creates nothing


def test_accepted_values_pass_through(tmp_path):
    assert _run("--plot", str(tmp_path / "RUN.PNG"), "--out", str(tmp_path), "-o", "-",
                "--speed", "2", "--view", "top", "--render", "x.png") == (0, "ok\n")


@pytest.mark.parametrize("option", ["--out", "--bag"])
def test_a_dash_is_no_directory_of_outputs(run, tmp_path, monkeypatch, option):
    """'-' means standard output for a file; for a directory of files it made a folder '-'."""
    from tests.conftest import assert_one_line_error

    monkeypatch.chdir(tmp_path)
    result = run("simulate", "--headless", "--duration-s", "0.1", option, "-")
    assert_one_line_error(result, 2, "'-' (standard output) cannot hold a directory of files")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("command", [("fk",), ("check", "urdf"), ("expand",)])
def test_a_package_given_twice_in_two_places_is_refused(run, tmp_path, command):
    """The last --package of a name won, unseen."""
    from tests.conftest import assert_one_line_error

    one, two = tmp_path / "one", tmp_path / "two"
    one.mkdir()
    two.mkdir()
    result = run(*command, "--package", f"desc={one}", "--package", f"desc={two}")
    assert_one_line_error(result, 2, f"package 'desc' is given twice ({one} and {two})")


def test_the_same_package_directory_twice_is_one(run, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "desc").mkdir()
    result = run("fk", "--package", "desc=desc", "--package", f"desc={tmp_path / 'desc'}")
    assert result.exit_code == 0, result.stderr
