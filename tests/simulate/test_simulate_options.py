"""``simulate``'s options: bad values, output paths checked before any work, no-effect refusals."""

from __future__ import annotations

import time

import pytest

from tests.conftest import assert_one_line_error

LONG = "3600"  # a run that takes many seconds: a refusal must come long before it would end


@pytest.mark.parametrize(("option", "value", "needle"), [
    ("--wheel-separation-multiplier", "nan", "not a finite number"),
    ("--max-linear-acceleration", "nan", "not a finite number"),
    ("--max-angular-acceleration", "inf", "not a finite number"),
    ("--cmd-vel-timeout-s", "nan", "not a finite number"),
    ("--duration-s", "nan", "not a finite number"),
    ("--duration-s", "inf", "not a finite number"),
    ("--duration-s", "0", "must be above 0"),
    ("--speed", "nan", "not a finite number"),
    ("--seed", "-1", "not in the range"),
])
def test_bad_number_is_one_line(run, option, value, needle):
    line = assert_one_line_error(run("simulate", "--headless", option, value), 2, needle)
    assert option in line


def _refused_fast(run, *args):
    start = time.monotonic()
    result = run("simulate", "--headless", "--duration-s", LONG, *args)
    assert time.monotonic() - start < 5.0, "refused only after the run"
    return result


def test_out_under_a_regular_file_is_refused_before_the_run(run, tmp_path):
    (tmp_path / "file").write_text("x")
    line = assert_one_line_error(_refused_fast(run, "--out", tmp_path / "file" / "out"), 2,
                                 "--out")
    assert "is a file, not a directory" in line
    assert sorted(p.name for p in tmp_path.iterdir()) == ["file"]


def test_out_with_a_missing_parent_is_refused_before_the_run(run, tmp_path):
    assert_one_line_error(_refused_fast(run, "--out", tmp_path / "missing" / "out",
                                        "--bag", tmp_path / "bag"), 2, "--out",
                          "does not exist")
    assert list(tmp_path.iterdir()) == []


def test_bag_that_exists_or_cannot_be_made_is_refused_before_the_run(run, tmp_path):
    (tmp_path / "bag").mkdir()
    assert_one_line_error(_refused_fast(run, "--bag", tmp_path / "bag"), 2, "--bag",
                          "already exists")
    (tmp_path / "file").write_text("x")
    assert_one_line_error(_refused_fast(run, "--bag", tmp_path / "file"), 2, "--bag",
                          "is a file")
    assert_one_line_error(_refused_fast(run, "--bag", tmp_path / "file" / "bag"), 2, "--bag")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bag", "file"]
    assert list((tmp_path / "bag").iterdir()) == []


@pytest.mark.parametrize("name", ["run.txt", "run", "run.png.tmp", "run.jpg"])
def test_plot_with_an_extension_the_writer_does_not_make_is_refused(run, tmp_path, name):
    line = assert_one_line_error(_refused_fast(run, "--plot", tmp_path / name), 2, "--plot")
    assert ".png or .svg or .pdf" in line
    assert list(tmp_path.iterdir()) == []


def test_plot_that_is_a_directory_is_refused(run, tmp_path):
    (tmp_path / "p.png").mkdir()
    assert_one_line_error(_refused_fast(run, "--plot", tmp_path / "p.png"), 2, "--plot",
                          "is a directory")


def test_out_and_bag_in_one_directory_are_refused(run, tmp_path):
    assert_one_line_error(_refused_fast(run, "--out", tmp_path / "d", "--bag",
                                        tmp_path / "d"), 2, "--bag", "--out")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(("suffix", "magic"), [
    (".png", b"\x89PNG\r\n\x1a\n"), (".svg", b"<?xml"), (".pdf", b"%PDF-"), (".PNG", b"\x89PNG"),
])
def test_plot_is_written_in_the_format_its_extension_names(run, tmp_path, suffix, magic):
    for name in ("a", "b"):
        result = run("simulate", "--headless", "--duration-s", "4", "--plot",
                     tmp_path / f"{name}{suffix}")
        assert result.exit_code == 0, result.stderr
    first, second = (tmp_path / f"a{suffix}").read_bytes(), (tmp_path / f"b{suffix}").read_bytes()
    assert first.startswith(magic)
    assert first == second, "the same run gave different bytes"
    assert sorted(p.name for p in tmp_path.iterdir()) == [f"a{suffix}", f"b{suffix}"]


@pytest.mark.parametrize("speed", ["2", "1"])
def test_speed_with_headless_is_refused(run, speed):
    line = assert_one_line_error(run("simulate", "--headless", "--speed", speed), 2,
                                 "--speed", "--headless")
    assert "no effect" in line


def test_speed_without_headless_is_not_refused(run):
    result = run("simulate", "--speed", "2", env={"DISPLAY": "", "WAYLAND_DISPLAY": ""})
    line = assert_one_line_error(result, 2, "display")
    assert "--speed" not in line  # it reached the display check: --speed was accepted


def test_out_into_an_existing_directory_replaces_its_files_and_leaves_no_temporary(run,
                                                                                   tmp_path):
    out = tmp_path / "out"
    out.mkdir()
    (out / "summary.json").write_text("old")
    (out / "notes.txt").write_text("mine")
    result = run("simulate", "--headless", "--duration-s", "3", "--out", out)
    assert result.exit_code == 0, result.stderr
    names = sorted(p.name for p in out.iterdir())
    assert "notes.txt" in names and "ground_truth.csv" in names
    assert not [n for n in names if n.endswith(".tmp")]
    assert (out / "summary.json").read_text().startswith("{")
    assert (out / "notes.txt").read_text() == "mine"
