"""Scenario, sweep and controllers files built to hurt the reader are one error line, fast.

YAML aliases share composed nodes: an alias inside the value it names recursed until Python's
stack ran out (exit 3), and aliases of aliases (YAML's billion laughs) expanded without end.
Deep nesting overflowed the JSON reader and PyYAML's pure-Python composer (exit 3).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.conftest import assert_one_line_error, run_servicebot

LAUGHS = "a0: &a0 [x, x, x, x, x, x, x, x, x]\n" + "".join(
    f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 9) + "]\n" for i in range(1, 12))

SCENARIOS = [
    ("loop.yaml", "duration_s: 1\nworld: &w {walls: [*w]}\n",
     ["loop.yaml:2:", "world.walls[0]: an alias (*name) inside the value it names"]),
    ("laughs.yaml", "duration_s: 1\n" + LAUGHS,
     ["laughs.yaml:", "aliases (*name) expand the document past 1000000 values"]),
    ("key.yaml", "duration_s: 1\n? &k [*k]\n: 1\n",
     ["key.yaml:2:", "a key that is a list or mapping"]),
    ("deep.json", '{"duration_s": 1, "x": ' + "[" * 100_000 + "]" * 100_000 + "}\n",
     ["deep.json:1: not valid JSON: lists and objects nested over 100 deep"]),
]


@pytest.mark.parametrize(("name", "text", "needles"), SCENARIOS,
                         ids=[case[0] for case in SCENARIOS])
def test_a_hostile_scenario_is_one_line(tmp_path: Path, name: str, text: str,
                                        needles: list[str]) -> None:
    (tmp_path / name).write_text(text)
    result = run_servicebot("simulate", "--headless", "-s", name, cwd=tmp_path, timeout=30)
    assert_one_line_error(result, 2, *needles)


@pytest.mark.parametrize(("text", "needle"), [
    ("scenario: default\nseeds: &s [*s]\n", "seeds[0]: an alias (*name) inside the value"),
    ("scenario: default\nseeds: 1\n" + LAUGHS, "past 1000000 values"),
])
def test_a_hostile_sweep_is_one_line(tmp_path: Path, text: str, needle: str) -> None:
    (tmp_path / "sweep.yaml").write_text(text)
    result = run_servicebot("sweep", "sweep.yaml", "--jobs", "1", cwd=tmp_path, timeout=30)
    assert_one_line_error(result, 2, "sweep.yaml:", needle)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sweep.yaml"]


DEEP_YAML = "x: " + "[" * 20_000 + "]" * 20_000 + "\n"


def test_a_deeply_nested_controllers_file_is_a_finding(tmp_path: Path) -> None:
    (tmp_path / "controllers.yaml").write_text(DEEP_YAML)
    result = run_servicebot("check", "controllers", "controllers.yaml", "--robot", "sim",
                            cwd=tmp_path, timeout=30)
    assert result.returncode == 1, result.stderr
    assert "SB601" in result.stdout and "nested too deep" in result.stdout
    assert "internal error" not in result.stderr


def test_a_deeply_nested_controllers_option_is_one_line(tmp_path: Path) -> None:
    (tmp_path / "controllers.yaml").write_text(DEEP_YAML)
    result = run_servicebot("inspect", "--section", "topics", "--controllers",
                            "controllers.yaml", cwd=tmp_path, timeout=30)
    assert_one_line_error(result, 2, "controllers.yaml: lists and mappings nested too deep")


@pytest.mark.parametrize("radius", ["nan", "1e-320", "-0.07", "1e300"])
def test_a_wheel_radius_no_wheel_has_is_one_line(tmp_path, radius):
    """simulate ran a wheel of radius nan, 1e-320 or -0.07 and wrote NaN (or a backward
    wheel's) results, exit 0."""
    from tests.conftest import SIM_URDF, assert_one_line_error, run_servicebot

    text = SIM_URDF.read_text()
    start = text.index('<link name="front_left_wheel"')
    end = text.index("</link>", start)
    wheel = text[start:end]
    assert 'radius="' in wheel
    import re

    wheel = re.sub(r'radius="[^"]*"', f'radius="{radius}"', wheel)
    path = tmp_path / "robot.urdf"
    path.write_text(text[:start] + wheel + text[end:])
    result = run_servicebot("simulate", path, "--headless", "--duration-s", "0.5", "--out",
                            tmp_path / "run")
    assert_one_line_error(result, 2, "wheel joint 'front_left_wheel_joint' rolls on a radius")
    assert not (tmp_path / "run").exists()


def test_a_joint_loop_is_refused_as_fk_and_inspect_refuse_it(tmp_path):
    """simulate ran a robot with a joint from a link to itself, and wrote its results."""
    from tests.conftest import SIM_URDF, assert_one_line_error, run_servicebot

    text = SIM_URDF.read_text()
    end = text.rindex("</robot>")
    path = tmp_path / "robot.urdf"
    path.write_text(text[:end] + '<link name="s"/><joint name="selfj" type="fixed">'
                    '<parent link="s"/><child link="s"/></joint>\n' + text[end:])
    result = run_servicebot("simulate", path, "--headless", "--duration-s", "0.5", "--out",
                            tmp_path / "run")
    assert_one_line_error(result, 2, "joint 'selfj' connects link 's' to itself")
    assert not (tmp_path / "run").exists()
