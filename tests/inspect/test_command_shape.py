"""``inspect`` in one shape: a request, one click-free run, output renders, one way to say no.

Also: options that would do nothing are refused, and ``--clamp`` says what it clamped.
"""

from __future__ import annotations

import json

import pytest

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.inspect.run import DiffRequest, InspectRequest, JointValueError
from servicebot_cli.inspect.run import run as run_inspect
from tests.conftest import REAL_URDF, SIM_URDF, assert_one_line_error

SHOULDER = "arm_link1_to_link2"


def _limits(name: str) -> tuple[float, float]:
    space = load(RobotSource.bundled()).joint_space
    i = space.index(name)
    return float(space.lower[i]), float(space.upper[i])


def test_the_domain_run_needs_no_command_line():
    lower, upper = _limits(SHOULDER)
    request = InspectRequest(RobotSource.bundled(), ("totals",), ((SHOULDER, upper + 5),),
                             clamp=True)
    result = run_inspect(request)
    assert result.picture is None and result.inspection is not None
    assert result.inspection.sections() == ["totals"]
    assert result.inspection.totals.configuration_rad_or_m == {SHOULDER: upper}
    (clamped,) = result.clamped
    assert (clamped.joint, clamped.given, clamped.used, clamped.limit, clamped.unit) == (
        SHOULDER, upper + 5, upper, "upper", "rad")
    with pytest.raises(JointValueError, match="outside its limits"):
        run_inspect(InspectRequest(RobotSource.bundled(), ("totals",), ((SHOULDER, upper + 5),)))


def test_the_domain_run_poses_the_picture_only_when_asked():
    request = InspectRequest(RobotSource.bundled(), (), ((SHOULDER, 0.5),), picture=True)
    result = run_inspect(request)
    assert result.inspection is None and result.clamped == ()
    assert result.picture is not None and result.picture.values == {SHOULDER: 0.5}
    assert "base_link" in result.picture.labels and result.picture.visuals


def test_the_domain_diff():
    assert run_inspect(DiffRequest(RobotSource.of(SIM_URDF), RobotSource.of(SIM_URDF))).equal
    assert not run_inspect(DiffRequest(RobotSource.of(SIM_URDF), RobotSource.of(REAL_URDF))).equal


@pytest.mark.parametrize("fmt", ["text", "json", "markdown"])
def test_a_diff_says_no_with_exit_1_and_no_error_line(run, fmt):
    differ = run("inspect", SIM_URDF, "--diff", REAL_URDF, "--format", fmt)
    assert differ.exit_code == 1 and differ.stderr == "" and differ.stdout
    same = run("inspect", SIM_URDF, "--diff", SIM_URDF, "--format", fmt)
    assert same.exit_code == 0 and same.stderr == ""


def test_clamp_says_what_it_clamped(run):
    lower, upper = _limits(SHOULDER)
    base_lower, _ = _limits("arm_base_to_link1")
    result = run("inspect", "--section", "totals", "--format", "json", "--clamp",
                     "--joint", f"{SHOULDER}=99", "--joint", "arm_base_to_link1=-99",
                     "--joint", "arm_link2_to_link3=0.1")
    assert result.exit_code == 0, result.stderr
    assert result.stderr.splitlines() == [
        f"note: --clamp: joint '{SHOULDER}' 99 rad is above its upper limit; using {upper:g} rad",
        f"note: --clamp: joint 'arm_base_to_link1' -99 rad is below its lower limit; using "
        f"{base_lower:g} rad",
    ]
    configuration = json.loads(result.stdout)["totals"]["configuration_rad_or_m"]
    assert configuration[SHOULDER] == upper and configuration["arm_link2_to_link3"] == 0.1


def test_clamp_inside_the_limits_says_nothing(run):
    result = run("inspect", "--section", "totals", "--clamp", "--joint", f"{SHOULDER}=0.2")
    assert result.exit_code == 0 and result.stderr == ""


@pytest.mark.parametrize(("args", "needles"), [
    (["--view", "top"], ["--view has no effect without --render FILE.png"]),
    (["--clamp"], ["--clamp has no effect without --joint NAME=VALUE"]),
    (["--section", "tree", "--clamp"], ["--clamp", "--joint"]),
    (["--render", "r.png", "--format", "json"], ["--format json", "--render", "--section"]),
    (["--render", "r.png", "--format", "text"], ["--format text", "nothing is printed"]),
    (["--render", "r.png", "--format", "dot"], ["--format dot", "drop --format"]),
    (["--section", "tree", "--joint", f"{SHOULDER}=1"],
     ["--joint has no effect without --render FILE.png or --section totals"]),
    (["--format", "mermaid", "--joint", f"{SHOULDER}=1"], ["--joint has no effect"]),
    (["--section", "links", "--controllers", "c.yaml"],
     ["--controllers has no effect without --section topics"]),
    (["--render", "r.png", "--controllers", "c.yaml"], ["--controllers", "--section topics"]),
    (["--diff", REAL_URDF, "--controllers", "c.yaml"], ["--diff", "drop --controllers"]),
    (["--diff", REAL_URDF, "--joint", f"{SHOULDER}=1"], ["--diff", "drop --joint"]),
    (["--section", "totals", "--joint", f"{SHOULDER}=1", "--joint", f"{SHOULDER}=0.5"],
     ["--joint", f"'{SHOULDER}' is given twice"]),
])
def test_options_that_would_do_nothing_are_refused(run, tmp_path, args, needles):
    result = run("inspect", *[tmp_path / a if a == "r.png" else a for a in args])
    assert_one_line_error(result, 2, *needles)
    assert list(tmp_path.iterdir()) == []


def test_what_the_refused_options_need_makes_them_work(run, tmp_path):
    assert run("inspect", "--render", tmp_path / "r.svg", "--view", "top").exit_code == 0
    with_section = run("inspect", "--render", tmp_path / "r.png", "--format", "json",
                           "--section", "tree")
    assert with_section.exit_code == 0 and json.loads(with_section.stdout)["tree"]
    assert run("inspect", "--section", "topics", "--controllers",
                   "robots/controllers.yaml").exit_code == 0


def test_the_render_path_is_checked_before_the_description_is_read(run, tmp_path):
    result = run("inspect", tmp_path / "nope.urdf", "--render", tmp_path / "robot.bmp")
    assert_one_line_error(result, 2, "--render", "robot.bmp")
    result = run("inspect", tmp_path / "nope.urdf", "--render", tmp_path)
    assert_one_line_error(result, 2, "--render", "end in .png")
