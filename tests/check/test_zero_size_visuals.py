"""A visual of zero size marks a frame: a warning; a collision of zero size is an error.

upkie_description (vendored under ``tests/realworld/frames``, without its 8 MB of meshes)
gives each of its virtual links (frames: ``base``, ``imu``, the wheel contacts...) a
``<box size="0 0 0"/>`` visual. MuJoCo drops URDF visuals and Pinocchio keeps an empty box:
nothing refuses it. A collision of that size MuJoCo refuses ("size 0 must be positive in
geom").
"""

from __future__ import annotations

import json
from pathlib import Path

from tests.check.helpers import findings
from tests.conftest import REPO

UPKIE = REPO / "tests/realworld/frames/upkie_description/urdf/upkie.urdf"
NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}


def _sb405(run, path: Path) -> list[dict]:
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB405",
                 env=NO_ROS)
    json.loads(result.stdout)
    return findings(result.stdout)


def test_upkies_frame_markers_are_warnings(run):
    found = _sb405(run, UPKIE)
    assert len(found) == 8
    assert {f["severity"] for f in found} == {"warning"}
    assert all("visual of link" in f["message"] for f in found)


def test_the_same_box_as_a_collision_is_an_error(run, tmp_path):
    text = UPKIE.read_text()
    marker = '<box size="0 0 0"/>'
    start = text.index("<visual>", text.index('<link name="imu">'))
    end = text.index("</visual>", start) + len("</visual>")
    assert marker in text[start:end]
    collision = text[start:end].replace("visual", "collision")
    path = tmp_path / "upkie.urdf"
    path.write_text(text[:end] + collision + text[end:])
    found = _sb405(run, path)
    errors = [f for f in found if f["severity"] == "error"]
    assert len(found) == 9 and len(errors) == 1
    assert "collision of link 'imu'" in errors[0]["message"]
