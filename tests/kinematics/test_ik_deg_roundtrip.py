"""``ik --deg`` batch results say their unit, and ``fk`` reads them back to the same poses.

``ik --deg`` wrote its batch results in degrees under bare joint names (CSV) and with no unit
in its JSON lines; ``fk --configs`` read them as radians unless it was given ``--deg`` too.
The columns now say ``NAME_deg`` (``NAME_m`` for a prismatic joint) and every JSON line its
``"angle_unit"``, so the degree path and the radian path give ``fk`` the same poses.
"""

from __future__ import annotations

import csv
import io
import json

import pyarrow.csv as pa_csv
import pytest

from tests.conftest import assert_one_line_error
from tests.kinematics.robots import PANDA

WHEELS = ["front_left_wheel_joint", "front_right_wheel_joint", "rear_left_wheel_joint",
          "rear_right_wheel_joint"]
ARM = ["arm_base_to_link1", "arm_link1_to_link2", "arm_link2_to_link3", "arm_link3_to_link4"]
TARGETS = "x_m,y_m,z_m\n0.6,0.1,0.5\n0.5,0.2,0.6\n2,1,0.5\n0.45,-0.15,0.55\n"
"""Three targets the arm reaches and one it does not (its best try is a line too)."""


def _poses(run, configs, *flags) -> list[float]:
    """Position [m] and quaternion of the tool, line after line of ``configs``, by ``fk``."""
    result = run("fk", "--configs", configs, "--format", "json", *flags)
    assert result.exit_code == 0, result.stderr
    poses = [json.loads(line)["poses"][0] for line in result.stdout.splitlines()]
    return [v for p in poses for v in (*p["position_m"], *p["quaternion_xyzw"])]


def _ik(run, tmp_path, name, *flags):
    """``ik --targets`` over :data:`TARGETS` to the file ``name``; the file."""
    targets = tmp_path / "targets.csv"
    targets.write_text(TARGETS)
    out = tmp_path / name
    result = run("ik", "--targets", targets, "--seed", "1", "-o", out, *flags)
    assert_one_line_error(result, 1, "1 of 4 targets not reached (line 4 of")
    return out


@pytest.mark.parametrize("suffix", [".csv", ".jsonl"])
@pytest.mark.parametrize("fk_flags", [(), ("--deg",), ("--clamp",)])
def test_ik_deg_results_read_by_fk_give_the_poses_of_the_radian_path(run, tmp_path, suffix,
                                                                      fk_flags):
    radians = _poses(run, _ik(run, tmp_path, f"rad{suffix}"))
    degrees = _poses(run, _ik(run, tmp_path, f"deg{suffix}", "--deg"), *fk_flags)
    assert degrees == pytest.approx(radians, abs=1e-9)
    reached = [degrees[7 * k:7 * k + 3] for k in (0, 1, 3)]  # the third is out of reach
    assert sum(reached, []) == pytest.approx([0.6, 0.1, 0.5, 0.5, 0.2, 0.6, 0.45, -0.15, 0.55],
                                             abs=1e-5)


def test_ik_results_say_their_unit_in_every_row_shape(run, tmp_path):
    header = next(csv.reader(_ik(run, tmp_path, "deg.csv", "--deg").open()))
    assert header[2:10] == [f"{name}_deg" for name in WHEELS + ARM]
    table = pa_csv.read_csv(str(tmp_path / "deg.csv")).to_pylist()  # as pandas-like tools see it
    assert "arm_base_to_link1" not in table[0] and -90 <= table[0]["arm_base_to_link1_deg"] <= 90
    lines = [json.loads(t) for t in _ik(run, tmp_path, "deg.jsonl", "--deg").read_text()
             .splitlines()]
    assert [line["angle_unit"] for line in lines] == ["deg"] * 4
    assert list(lines[0])[:3] == ["line", "angle_unit", "success"]
    # radians: the bare names of the files written before, and the unit in every JSON line
    assert next(csv.reader(_ik(run, tmp_path, "rad.csv").open()))[2:10] == WHEELS + ARM
    assert {json.loads(t)["angle_unit"] for t in _ik(run, tmp_path, "rad.jsonl").read_text()
            .splitlines()} == {"rad"}
    single = run("ik", "--position", "0.5", "0.1", "0.5", "--seed", "1", "--deg",
                 "--format", "csv")
    (row,) = pa_csv.read_csv(io.BytesIO(single.stdout.encode())).to_pylist()
    assert {f"{name}_deg" for name in ARM} <= set(row) and not set(ARM) & set(row)


def test_a_prismatic_joint_is_in_metres_and_says_so(run, tmp_path):
    targets = tmp_path / "targets.csv"
    targets.write_text("x_m,y_m,z_m\n0.4,0.1,0.5\n")
    out = tmp_path / "panda.csv"
    result = run("ik", PANDA, "--targets", targets, "--seed", "1", "--deg", "-o", out)
    assert result.exit_code == 0, result.stderr
    header = next(csv.reader(out.open()))
    assert "panda_finger_joint1_m" in header and "panda_joint4_deg" in header
    assert _poses(run, out, PANDA)[:3] == pytest.approx([0.4, 0.1, 0.5], abs=1e-5)
