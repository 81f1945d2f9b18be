"""Whatever a real URDF is mutated into, inspect reports it or refuses it in one line.

No internal error and no library's warning text (numpy, trimesh, matplotlib) reaches the user:
every warning is turned into an error here.
"""

from __future__ import annotations

import contextlib
import io
import json
import random
import warnings
import xml.etree.ElementTree as ET

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.description.loader import RobotSource
from servicebot_cli.inspect import SECTIONS
from servicebot_cli.inspect.run import InspectRequest, run
from servicebot_cli.output.inspect_text import show
from tests.check.corpus import erd_root, erd_urdfs
from tests.conftest import REAL_URDF, run_servicebot
from tests.mutants import mutate

_SOURCES = [REAL_URDF, *[p for p in erd_urdfs() if p.name in ("ur5_robot.urdf", "solo12.urdf")]]


@settings(max_examples=int(__import__("os").environ.get("MUTANTS", 40)), deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(source=st.sampled_from(_SOURCES), seed=st.integers(0, 2**32 - 1),
       steps=st.integers(1, 12), fmt=st.sampled_from(["text", "json"]))
def test_mutated_real_urdfs_are_inspected_or_refused_in_one_line(tmp_path_factory, source, seed,
                                                                 steps, fmt):
    root = ET.parse(source).getroot()
    mutate(root, random.Random(seed), steps)
    path = tmp_path_factory.mktemp("mutant") / "robot.urdf"
    path.write_bytes(ET.tostring(root))
    robot = RobotSource.of(path, packages=(("example-robot-data", str(erd_root())),))
    out = io.StringIO()
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a numpy or library warning fails the test
        try:
            result = run(InspectRequest(robot, SECTIONS, picture=True))
        except ServicebotError as exc:
            assert str(exc) and "\n" not in str(exc).strip()
            return
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
            show(result, fmt, None, "iso")
    assert out.getvalue()
    if fmt == "json":
        json.loads(out.getvalue())


ROBOT = """<robot name="r">
  <link name="base">
    <inertial><mass value="1"/>
      <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial>
    <visual><geometry><box size="0.2 0.2 0.2"/></geometry></visual>
    <visual>{origin}<geometry>{geometry}</geometry></visual>
    <collision>{origin}<geometry>{geometry}</geometry></collision>
  </link>
</robot>
"""


@pytest.mark.parametrize("origin, geometry", [
    ('<origin rpy="0 0"/>', '<box size="1 1 1"/>'),
    ('<origin xyz=" "/>', '<box size="1 1 1"/>'),
    ('<origin xyz="nan 0 0"/>', '<sphere radius="0.1"/>'),
    ("", '<cylinder radius="0.1" length="inf"/>'),
    ("", '<cylinder radius="nan" length="1"/>'),
    ("", '<box size="1e200 1 1"/>'),
    ("", '<box size="0 0 0"/>'),
    ("", '<mesh filename="" scale="0 0 0"/>'),
    ("", '<sphere radius="\uff10.\uff11"/>'),
])
@pytest.mark.parametrize("args", [("--format", "json"), ("--section", "totals"),
                                  ("--render", "robot.png")], ids=["json", "totals", "render"])
def test_bad_values_give_a_report_and_no_library_warning(tmp_path, origin, geometry, args):
    path = tmp_path / "robot.urdf"
    path.write_text(ROBOT.format(origin=origin, geometry=geometry), encoding="utf-8")
    result = run_servicebot("inspect", path, *args, cwd=tmp_path,
                            env={"PYTHONWARNINGS": "error"})
    assert result.returncode == 0, result.stderr
    assert "Warning" not in result.stderr and "Traceback" not in result.stderr


@pytest.mark.parametrize("distance", ["1e7", "1e200", "1e300"])
def test_a_bare_frame_beyond_any_robot_is_left_out_of_the_picture(tmp_path, distance):
    """A tool frame 1e200 m away made matplotlib's 3-D projection singular: exit 3."""
    path = tmp_path / "far.urdf"
    path.write_text('<robot name="far"><link name="base_link"><visual><geometry>'
                    '<box size="0.1 0.1 0.1"/></geometry></visual></link>'
                    '<joint name="j" type="fixed"><parent link="base_link"/><child link="tool"/>'
                    f'<origin xyz="{distance} 0 0"/></joint><link name="tool"/></robot>')
    result = run_servicebot("inspect", path, "--render", "far.png", cwd=tmp_path,
                            env={"PYTHONWARNINGS": "error"})
    assert result.returncode == 0, result.stderr
    assert f"frame 'tool' not drawn: {float(distance):.3g} m from the root" in result.stderr
    assert (tmp_path / "far.png").read_bytes().startswith(b"\x89PNG")
