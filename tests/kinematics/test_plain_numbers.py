"""Numbers as CSV and ROS write them: Python's float() reads '0_1' as 1 and '٣' as 3.

fk's batch cell 0_1 set a joint to 1 rad, fk -j j1=0_1 did the same and ik --position
0_3 0 0_5 aimed 3 m out: a typo became another value, exit 0. Every such number is now
refused as 0x10 was.
"""

from __future__ import annotations

import pytest

from tests.conftest import SIM_URDF, assert_one_line_error, run_servicebot

JOINT = "arm_base_to_link1"


@pytest.mark.parametrize("text", ["0_1", "1_0", "٣", "０.１"])
def test_a_batch_cell_float_reads_and_no_writer_writes_is_refused(tmp_path, text):
    configs = tmp_path / "configs.csv"
    configs.write_text(f"{JOINT}\n0.1\n{text}\n", encoding="utf-8")
    result = run_servicebot("fk", SIM_URDF, "--configs", configs, cwd=tmp_path)
    assert_one_line_error(result, 2, f"configs.csv:3: joint '{JOINT}' is '{text}', not a number")


def test_a_jsonl_string_number_is_refused_alike(tmp_path):
    configs = tmp_path / "configs.jsonl"
    configs.write_text(f'{{"{JOINT}": "0_1"}}\n')
    result = run_servicebot("fk", SIM_URDF, "--configs", configs, cwd=tmp_path)
    assert_one_line_error(result, 2, f"joint '{JOINT}' is '0_1', not a number")


@pytest.mark.parametrize(("args", "expected"), [
    (("fk", "-j", f"{JOINT}=0_1"), "'0_1' for joint 'arm_base_to_link1' is not a number"),
    (("ik", "--position", "0_3", "0", "0.5"), "'0_3' is not a number"),
    (("simulate", "--headless", "--duration-s", "1_0"), "'1_0' is not a number")])
def test_an_option_refuses_it(args, expected):
    assert_one_line_error(run_servicebot(*args), 2, expected)
