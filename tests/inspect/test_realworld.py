"""inspect on urdf_tutorial (ros/urdf_tutorial, vendored under tests/realworld/ws/src).

Every step of the tutorial is inspected as its users would, with no ROS variable set: the
package is found from the workspace. Numbers are held against yourdfpy's forward kinematics
and the file's own masses read with ElementTree; a picture of a robot whose texture images are
missing is drawn with one warning line per mesh, never a library's traceback.
"""

from __future__ import annotations

import json
import shutil
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from tests.conftest import REPO, run_servicebot

TUTORIAL = REPO / "tests" / "realworld" / "ws" / "src" / "urdf_tutorial"
STEPS = sorted((TUTORIAL / "urdf").glob("0*"))
NO_ROS = {"ROS_PACKAGE_PATH": "", "AMENT_PREFIX_PATH": ""}


@pytest.mark.parametrize("path", STEPS, ids=lambda p: p.name)
def test_every_tutorial_step_is_inspected_without_a_library_message(path):
    result = run_servicebot("inspect", path, "--format", "json", env=NO_ROS)
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    assert json.loads(result.stdout)["robot"]


def test_mass_and_centre_of_mass_match_yourdfpy():
    import yourdfpy

    path = TUTORIAL / "urdf" / "07-physics.urdf"
    result = run_servicebot("inspect", path, "--section", "totals", "--format", "json",
                            env=NO_ROS)
    assert result.returncode == 0, result.stderr
    totals = json.loads(result.stdout)["totals"]
    urdf = yourdfpy.URDF.load(str(path), load_meshes=False, build_collision_scene_graph=False)
    masses, moments = [], []
    for link in ET.parse(path).getroot().iter("link"):
        mass = link.find("inertial/mass")
        if mass is None:
            continue
        origin = link.find("inertial/origin")
        xyz = [float(v) for v in (origin.get("xyz", "0 0 0") if origin is not None
                                  else "0 0 0").split()]
        placed = urdf.get_transform(link.get("name"), urdf.base_link) @ np.array([*xyz, 1.0])
        masses.append(float(mass.get("value")))
        moments.append(masses[-1] * placed[:3])
    assert totals["mass_kg"] == pytest.approx(sum(masses), rel=1e-12)
    np.testing.assert_allclose(totals["centre_of_mass_m"], np.sum(moments, axis=0) / sum(masses),
                               atol=1e-9)


def test_a_picture_with_missing_texture_images_is_drawn_without_a_word(tmp_path):
    """urdf_tutorial's DAE files name bump maps it does not ship: trimesh printed two
    tracebacks loading them. The meshes are now read by the readers check uses, which read
    geometry only: a picture shaded without textures needs no image."""
    ws = tmp_path / "ws" / "src"
    shutil.copytree(TUTORIAL, ws / "urdf_tutorial")
    for image in (ws / "urdf_tutorial" / "meshes").glob("*.png"):
        image.unlink()
    picture = tmp_path / "robot.png"
    result = run_servicebot("inspect", ws / "urdf_tutorial" / "urdf" / "07-physics.urdf",
                            "--render", picture, env=NO_ROS)
    assert result.returncode == 0, result.stderr
    assert result.stderr.splitlines() == [f"wrote {picture}"]
    import matplotlib.image

    assert matplotlib.image.imread(picture).shape[2] in (3, 4)
