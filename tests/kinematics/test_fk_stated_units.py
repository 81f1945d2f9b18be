"""``fk --configs`` reads joint values in the unit their file states, whatever its flags say.

fk read every joint column by its ``--deg`` flag alone: ``ik --deg``'s results, in degrees,
were taken for radians unless the user remembered ``--deg`` (a limit error about a number the
file never held or, with ``--clamp``, every joint clamped and a wrong pose with exit 0). A
column ``NAME_deg``/``NAME_rad`` or a line's ``"angle_unit"`` now says the unit; bare names
keep their meaning, and units that disagree are refused in one line that says what to do.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from servicebot_cli.batch.fk_chunks import CHUNK_LINES
from tests.conftest import assert_one_line_error

ARM = ["arm_base_to_link1", "arm_link1_to_link2", "arm_link2_to_link3", "arm_link3_to_link4"]
CONFIG_DEG = [10.0, -20.0, 30.0, 15.0]
"""An arm configuration [deg] inside the limits."""


def _poses(run, configs, *flags) -> list[float]:
    """Position [m] and quaternion of the tool, line after line of ``configs``, by ``fk``."""
    result = run("fk", "--configs", configs, "--format", "json", *flags)
    assert result.exit_code == 0, result.stderr
    poses = [json.loads(line)["poses"][0] for line in result.stdout.splitlines()]
    return [v for p in poses for v in (*p["position_m"], *p["quaternion_xyzw"])]


def _configs(tmp_path, header, values, name="configs.csv"):
    path = tmp_path / name
    path.write_text(",".join(header) + "\n" + ",".join(map(str, values)) + "\n")
    return path


def test_fk_reads_a_unit_a_file_states_whatever_its_flags_say(run, tmp_path):
    want = _poses(run, _configs(tmp_path, ARM, CONFIG_DEG, "bare.csv"), "--deg")
    stated = _configs(tmp_path, [f"{name}_deg" for name in ARM], CONFIG_DEG)
    assert _poses(run, stated) == _poses(run, stated, "--deg") == want
    radians = [v / 57.29577951308232 for v in CONFIG_DEG]
    in_rad = _configs(tmp_path, [f"{name}_rad" for name in ARM], radians, "rad.csv")
    assert _poses(run, in_rad, "--deg") == pytest.approx(want, abs=1e-12)
    lines = tmp_path / "configs.jsonl"
    lines.write_text(
        json.dumps({"angle_unit": "deg", "joints": dict(zip(ARM, CONFIG_DEG, strict=True))})
        + "\n" + json.dumps({"angle_unit": "rad", **dict(zip(ARM, radians, strict=True))}) + "\n")
    assert _poses(run, lines) == pytest.approx(want * 2, abs=1e-12)
    assert _poses(run, lines, "--deg") == pytest.approx(want * 2, abs=1e-12)


def test_bare_names_keep_the_meaning_they_had(run, tmp_path):
    bare = _configs(tmp_path, ARM, [0.1, -0.2, 0.3, 0.15])
    assert _poses(run, bare) == _poses(run, _configs(
        tmp_path, [f"{name}_rad" for name in ARM], [0.1, -0.2, 0.3, 0.15], "rad.csv"))
    assert _poses(run, bare, "--deg") == _poses(run, _configs(
        tmp_path, [f"{name}_deg" for name in ARM], [0.1, -0.2, 0.3, 0.15], "deg.csv"))


@pytest.mark.parametrize(("header", "flags", "message"), [
    ([f"{ARM[0]}_deg", *ARM[1:]], (), f"configs.csv:1: '{ARM[1]}' has no unit, so it is read "
     f"in radians without --deg, but '{ARM[0]}_deg' is in degrees; give --deg, or name it "
     f"'{ARM[1]}_deg'"),
    ([f"{ARM[0]}_rad", *ARM[1:]], ("--deg",), f"'{ARM[1]}' has no unit, so --deg reads it in "
     f"degrees, but '{ARM[0]}_rad' is in radians; drop --deg, or name it '{ARM[1]}_rad'"),
    ([f"{ARM[0]}_deg", f"{ARM[1]}_rad", *ARM[2:]], ("--deg",), f"joint angles in two units: "
     f"'{ARM[0]}_deg' is in degrees, '{ARM[1]}_rad' is in radians; give them all in one unit"),
    ([f"{ARM[0]}_m", *ARM[1:]], (), f"'{ARM[0]}_m': joint '{ARM[0]}' is revolute, an angle; "
     f"name the column '{ARM[0]}_deg' or '{ARM[0]}_rad'"),
    # what ik --deg --with-base wrote before its columns said their unit
    (["line", "success", *ARM, "base_x_m", "base_y_m", "base_yaw_deg"], (),
     f"'{ARM[0]}' has no unit, so it is read in radians without --deg, but 'base_yaw_deg' is "
     "in degrees; give --deg"),
])
def test_a_header_whose_units_disagree_is_refused_in_one_line(run, tmp_path, header, flags,
                                                               message):
    values = [*(["2", "true"] if "line" in header else []), *CONFIG_DEG,
              *(["1", "2", "30"] if "base_x_m" in header else [])]
    out = tmp_path / "poses.csv"
    result = run("fk", "--configs", _configs(tmp_path, header, values), "-o", out, *flags)
    assert_one_line_error(result, 2, message)
    assert not out.exists()


@pytest.mark.parametrize(("line", "message"), [
    ({"angle_unit": "grad", "joints": {ARM[0]: 10}},
     'configs.jsonl:1: angle_unit is "grad"; give "deg" or "rad"'),
    ({"angle_unit": "rad", f"{ARM[0]}_deg": 10}, "configs.jsonl:1: joint angles in two "
     f"units: angle_unit is \"rad\", '{ARM[0]}_deg' is in degrees; give them all in one unit"),
    ({"joints": {ARM[0]: 10}, "base": {"x_m": 1, "y_m": 2, "yaw_deg": 30}},
     f"configs.jsonl:1: '{ARM[0]}' has no unit, so it is read in radians without --deg, but "
     "base 'yaw_deg' is in degrees; give --deg"),
])
def test_a_json_line_whose_units_disagree_is_a_bad_line(run, tmp_path, line, message):
    configs = tmp_path / "configs.jsonl"
    inside = dict(zip(ARM, [0.1, 0.2, 0.3, 0.4], strict=True))
    configs.write_text(json.dumps(line) + "\n" + json.dumps(inside) + "\n")
    assert_one_line_error(run("fk", "--configs", configs), 2, message)
    skipped = run("fk", "--configs", configs, "--on-error", "skip")
    assert skipped.exit_code == 0 and len(skipped.stdout.splitlines()) == 2  # header, line 2
    assert skipped.stderr.startswith(f"skipped {configs}:1: ")


def test_chunks_of_a_header_in_degrees_write_what_the_per_line_path_does(run, tmp_path):
    """A CSV goes through fk's chunked path, JSON lines line by line: the same poses.

    Within +-1.5 degrees, so that the values would pass the limits taken as radians too:
    the chunked path cannot hand them to the per-line path.
    """
    rng = np.random.default_rng(7)
    values = rng.uniform(-1.5, 1.5, (CHUNK_LINES + 50, len(ARM))).tolist()
    stated = tmp_path / "q.csv"
    stated.write_text(",".join(f"{name}_deg" for name in ARM) + "\n"
                      + "".join(",".join(map(repr, row)) + "\n" for row in values))
    lines = tmp_path / "q.jsonl"
    lines.write_text("".join(json.dumps({"angle_unit": "deg", "joints": dict(
        zip(ARM, row, strict=True))}) + "\n" for row in values))
    fast, slow = (run("fk", "--configs", path, "--format", "json").stdout.splitlines()
                  for path in (stated, lines))
    assert len(fast) == len(values)
    assert [json.loads(r)["poses"] for r in fast] == [json.loads(r)["poses"] for r in slow]


def test_a_csv_angle_unit_column_says_each_line_s_unit(run, tmp_path):
    configs = tmp_path / "configs.csv"
    configs.write_text(f"angle_unit,{ARM[1]}\ndeg,11.459155902616464\nrad,0.2\n,0.2\n")
    result = run("fk", "--configs", configs, "--on-error", "skip", "--format", "json")
    first, second = (json.loads(line)["poses"][0] for line in result.stdout.splitlines())
    assert first["position_m"] == pytest.approx(second["position_m"], abs=1e-15)
    assert result.stderr.splitlines()[0] == f'skipped {configs}:4: angle_unit is ""; give ' \
        '"deg" or "rad" (or leave it out: --deg then says)'
