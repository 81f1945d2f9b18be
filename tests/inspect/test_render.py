"""--render: a real picture, from real geometry (meshes too), written atomically."""

from __future__ import annotations

import numpy as np
import pytest
import trimesh
from matplotlib.image import imread

from tests.conftest import assert_one_line_error, run_servicebot

ORANGE = np.array([1.0, 0.5, 0.1])  # the arm's material
BLUE = np.array([0.1, 0.3, 0.8])  # the sensors'


def _mask(image: np.ndarray, rgb: np.ndarray) -> np.ndarray:
    """Pixels whose hue is that of ``rgb`` whatever the shading (same ratios of channels)."""
    pixels = image[..., :3]
    scale = pixels.max(axis=-1, keepdims=True)
    ratio = np.divide(pixels, scale, out=np.zeros_like(pixels), where=scale > 0.15)
    return np.all(np.abs(ratio - rgb / rgb.max()) < 0.12, axis=-1)


def _render(run, path, *args):
    result = run("inspect", "--render", path, *args)
    assert result.exit_code == 0, result.stderr
    assert result.stdout == "" and result.stderr.strip() == f"wrote {path}"
    return imread(path)


def test_the_picture_shows_arm_and_sensors_and_moves_with_the_joints(run, tmp_path):
    zero = _render(run, tmp_path / "zero.png")
    assert zero.shape[:2] == (900, 1200)
    arm, sensors = _mask(zero, ORANGE), _mask(zero, BLUE)
    assert arm.sum() > 20_000 and sensors.sum() > 1_000
    bent = _render(run, tmp_path / "bent.png", "--joint", "arm_link1_to_link2=-1.2",
                   "--joint", "arm_base_to_link1=1.0")
    moved = _mask(bent, ORANGE)
    rows_zero, rows_bent = np.nonzero(arm)[0], np.nonzero(moved)[0]
    assert rows_bent.min() < rows_zero.min() - 50  # the arm now reaches higher in the image
    assert _mask(bent, BLUE).sum() > 500  # the arm now hides part of the sensor head


@pytest.mark.parametrize("name,magic", [("robot.svg", b"<?xml"), ("robot.pdf", b"%PDF")])
def test_other_picture_formats(run, tmp_path, name, magic):
    result = run("inspect", "--render", tmp_path / name, "--view", "top")
    assert result.exit_code == 0
    assert (tmp_path / name).read_bytes().startswith(magic)


def test_bad_render_targets_leave_nothing_behind(run, tmp_path):
    assert_one_line_error(run("inspect", "--render", tmp_path / "robot.gif"), 2,
                          "--render", "end in .png or .svg or .pdf", "robot.png")
    assert_one_line_error(run("inspect", "--render", tmp_path / "no" / "robot.png"), 2,
                          "does not exist")
    assert_one_line_error(run("inspect", "--render", tmp_path / "r.png", "--joint", "nope=1"),
                          2, "--joint", "no joint 'nope'")
    assert list(tmp_path.iterdir()) == []


def test_an_existing_picture_is_replaced_whole(run, tmp_path):
    target = tmp_path / "robot.png"
    target.write_bytes(b"old")
    _render(run, target, "--view", "side")
    assert target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert [p.name for p in tmp_path.iterdir()] == ["robot.png"]


def test_render_and_sections_together(run, tmp_path):
    result = run("inspect", "--render", tmp_path / "r.png", "--section", "totals",
                 "--joint", "arm_link1_to_link2=0.5")
    assert result.exit_code == 0, result.stderr
    assert "at arm_link1_to_link2=0.5" in result.stdout


def _mesh_robot(tmp_path, mesh_uri: str) -> object:
    urdf = tmp_path / "desc" / "urdf" / "mesh_bot.urdf"
    urdf.parent.mkdir(parents=True)
    urdf.write_text(
        '<robot name="mesh_bot"><material name="red"><color rgba="0.9 0.1 0.1 1"/></material>'
        '<link name="base"><visual><origin xyz="0 0 0.5"/><geometry>'
        f'<mesh filename="{mesh_uri}" scale="0.001 0.001 0.001"/></geometry>'
        '<material name="red"/></visual>'
        '<visual><origin xyz="1 0 0"/><geometry><sphere radius="0.25"/></geometry></visual>'
        "</link></robot>")
    return urdf


def test_meshes_are_measured_and_drawn(run, inspect_json, tmp_path):
    """A 200 mm cube mesh in millimetres, found through package:// and --package."""
    package = tmp_path / "desc"
    urdf = _mesh_robot(tmp_path, "package://mesh_desc/meshes/cube.stl")
    (package / "meshes").mkdir()
    trimesh.creation.box(extents=(200, 200, 200)).export(package / "meshes" / "cube.stl")
    (package / "package.xml").write_text("<package><name>mesh_desc</name></package>")
    document = inspect_json(urdf, "--package", f"mesh_desc={package}", "--section", "totals")
    box = document["totals"]["bounding_box_m"]
    assert box["min_m"] == pytest.approx([-0.1, -0.25, -0.25])
    assert box["max_m"] == pytest.approx([1.25, 0.25, 0.6])
    image = _render(run, tmp_path / "mesh.png", urdf, "--package", f"mesh_desc={package}")
    assert _mask(image, np.array([0.9, 0.1, 0.1])).sum() > 2_000


def test_a_missing_mesh_is_a_warning_not_a_failure(run, inspect_json, tmp_path):
    urdf = _mesh_robot(tmp_path, "meshes/missing.stl")
    document = inspect_json(urdf, "--section", "totals")
    assert any("mesh meshes/missing.stl: no such file" in n for n in document["totals"]["notes"])
    assert document["totals"]["bounding_box_m"]["max_m"] == pytest.approx([1.25, 0.25, 0.25])
    result = run("inspect", urdf, "--render", tmp_path / "m.png")
    assert result.exit_code == 0
    assert result.stderr.splitlines()[0].startswith("warning: mesh meshes/missing.stl")


def test_renders_without_a_display(tmp_path):
    """A real process with no DISPLAY and no matplotlib backend chosen."""
    target = tmp_path / "headless.png"
    result = run_servicebot("inspect", "--render", target, env={"DISPLAY": "", "MPLBACKEND": ""})
    assert result.returncode == 0, result.stderr
    assert target.read_bytes()[:4] == b"\x89PNG"
