"""File names and values that are not what a program expects: one line, or escaped text.

A Latin-1 byte in a file name (an old archive) or a xacro argument (a Latin-1 terminal), a
JSON Lines batch with a 401-digit integer or 100,000 nested arrays: each ended in exit 3.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

from tests.conftest import SIM_URDF, assert_one_line_error, run_servicebot


def test_a_file_name_that_is_not_utf8_is_shown_escaped_in_every_report(tmp_path):
    folder = tmp_path / "d"
    folder.mkdir()
    name = os.fsencode(folder) + b"/bad\xff.urdf"
    with open(name, "wb") as handle:
        handle.write(Path(SIM_URDF).read_bytes())
    for fmt in ("json", "text", "sarif"):
        report = tmp_path / f"out.{fmt}"
        result = run_servicebot("check", "urdf", folder, "--isolated", "--format", fmt,
                                "-o", report)
        assert result.returncode == 0, result.stderr
        text = report.read_bytes().decode("utf-8")  # UTF-8, the byte escaped
        assert "xff.urdf" in text
    assert json.loads((tmp_path / "out.json").read_text())["files"][0]["file"].endswith(
        "bad\\xff.urdf")


def test_a_xacro_argument_that_is_not_utf8_is_one_line(tmp_path):
    xacro = Path(SIM_URDF).parent / "service_robot.urdf.xacro"
    result = run_servicebot("expand", xacro, os.fsdecode(b"hardware:=\xff"))
    assert_one_line_error(result, 2, "the value of 'hardware' is not UTF-8 text")


def test_batch_lines_beyond_what_json_numbers_hold_are_bad_lines(tmp_path):
    big = tmp_path / "big.jsonl"
    big.write_text('{"arm_base_to_link1": 1' + "0" * 400 + "}\n")
    deep = tmp_path / "deep.jsonl"
    deep.write_text('{"a": ' + "[" * 100_000 + "]" * 100_000 + "}\n")
    assert_one_line_error(run_servicebot("fk", "--configs", big), 2,
                          "big.jsonl:1: joint 'arm_base_to_link1' is an integer beyond any "
                          "double")
    assert_one_line_error(run_servicebot("fk", "--configs", deep), 2,
                          "deep.jsonl:1: not JSON this reads: nested too deep")
    big.write_text(big.read_text() + '{"arm_base_to_link1": 0.5}\n')  # and a usable line
    skipped = run_servicebot("fk", "--configs", big, "--on-error", "skip")
    assert skipped.returncode == 0 and "big.jsonl:1" in skipped.stderr
    assert skipped.stdout.startswith("line,") and "\n2," in skipped.stdout


def test_a_control_character_in_a_file_name_leaves_junit_well_formed(tmp_path):
    import xml.etree.ElementTree as ET

    folder = tmp_path / "d"
    folder.mkdir()
    (folder / "ctl\x01.urdf").write_text(Path(SIM_URDF).read_text())
    report = tmp_path / "junit.xml"
    result = run_servicebot("check", "urdf", folder, "--isolated", "--format", "junit",
                            "-o", report)
    assert result.returncode == 0, result.stderr
    case = ET.parse(report).getroot().find("testsuite/testcase")
    assert case is not None and case.get("name", "").endswith("ctl\\x01.urdf")


def test_a_batch_csv_with_excels_byte_order_mark_reads_its_header(tmp_path):
    configs = tmp_path / "configs.csv"
    configs.write_bytes(b"\xef\xbb\xbfarm_base_to_link1\n0.1\n")
    result = run_servicebot("fk", "--configs", configs)
    assert result.returncode == 0, result.stderr


def test_a_csv_header_of_200000_columns_is_refused_in_linear_time(tmp_path):
    """Each column was counted against the whole header: 200,000 ran over 40 s."""
    import time

    wide = tmp_path / "wide.csv"
    wide.write_text(",".join(f"c{i}" for i in range(200_000)) + "\n" + ",".join(
        ["0"] * 200_000) + "\n")
    start = time.monotonic()
    result = run_servicebot("fk", "--configs", wide)
    assert time.monotonic() - start < 20
    assert_one_line_error(result, 2, "no joint 'c0'")


def test_a_batch_file_saved_as_utf16_is_named_so(tmp_path):
    """Excel's 'Unicode text': the message printed its NUL bytes to the terminal."""
    configs = tmp_path / "configs.csv"
    configs.write_bytes("arm_base_to_link1\n0.1\n".encode("utf-16"))
    assert_one_line_error(run_servicebot("fk", "--configs", configs), 2,
                          "not UTF-8 text (it holds NUL bytes: UTF-16?); save it as UTF-8")
