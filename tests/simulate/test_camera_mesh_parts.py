"""The camera draws the robot's mesh collision links: where trimesh's ray caster meets them.

The robot is the bundled one with two links whose collision shapes are STL files written
here: a ``visor`` fixed on the base in front of the camera (scaled and turned by the URDF)
and a ``gripper`` at the end of the arm. Each has its own URDF colour. The reference is
trimesh's own ray-triangle code on the STL mesh placed by ``kinematics.link_poses`` (not
by the simulator's shape), cast along the frame's pixel rays.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import trimesh

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.kinematics.link_poses import link_transforms
from servicebot_cli.kinematics.transforms import planar_matrix, pose_matrix
from servicebot_cli.simulate.body import SimRobot, sim_robot
from servicebot_cli.simulate.scenario.camera import CameraImages
from servicebot_cli.simulate.sensors import camera_image as ci
from servicebot_cli.simulate.sensors.camera_info import Intrinsics
from servicebot_cli.simulate.sensors.camera_stream import CameraStream
from servicebot_cli.simulate.shape import Part
from servicebot_cli.simulate.world.solids import Solid
from tests.simulate.helpers import bundled_with

VISOR_SCALE = (0.5, 0.6, 0.5)
BLACK = (0, 0, 0)
VISOR_RGB = (26, 153, 178)  # rgba 0.1 0.6 0.7: teal
GRIPPER_RGB = (153, 26, 204)  # rgba 0.6 0.1 0.8: violet
LINKS = """
  <link name="visor">
    <visual><geometry><box size="0.1 0.1 0.1"/></geometry>
      <material name="teal"><color rgba="0.1 0.6 0.7 1"/></material></visual>
    <collision>
      <origin xyz="0.01 0.02 0.0" rpy="0.3 0 0.4"/>
      <geometry><mesh filename="visor.stl" scale="0.5 0.6 0.5"/></geometry>
    </collision>
  </link>
  <joint name="visor_joint" type="fixed">
    <parent link="base_link"/>
    <child link="visor"/>
    <origin xyz="0.62 0.05 0.07" rpy="0 0 0"/>
  </joint>
  <link name="gripper">
    <visual><geometry><box size="0.1 0.1 0.1"/></geometry>
      <material name="violet"><color rgba="0.6 0.1 0.8 1"/></material></visual>
    <collision>
      <origin xyz="0.05 0 0" rpy="0 1.5708 0"/>
      <geometry><mesh filename="gripper.stl"/></geometry>
    </collision>
  </link>
  <joint name="gripper_joint" type="fixed">
    <parent link="arm_link4"/>
    <child link="gripper"/>
    <origin xyz="0.3 0 0" rpy="0 0 0"/>
  </joint>
"""
REACHING = {"arm_base_to_link1": 0.0, "arm_link1_to_link2": 0.2, "arm_link2_to_link3": 0.6,
            "arm_link3_to_link4": 0.5}  # the arm reaching down in front of the camera
TURNED = {**REACHING, "arm_base_to_link1": 0.15}  # and turned a little to the left
FOCAL = 1920 / (2 * np.tan(1.047 / 2))
FULL_HD = Intrinsics(1920, 1080, (FOCAL, 0, 960.5, 0, FOCAL, 540.5, 0, 0, 1),
                     (FOCAL, 0, 960.5, 0, 0, FOCAL, 540.5, 0, 0, 0, 1, 0))
STL = {"visor": trimesh.creation.icosphere(subdivisions=1, radius=0.1),  # 80 triangles
       "gripper": trimesh.creation.cylinder(radius=0.04, height=0.1, sections=16)}


@pytest.fixture(scope="module")
def robot_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The bundled robot with the two mesh links, its URDF and STL files in one directory."""
    directory = tmp_path_factory.mktemp("mesh_links")
    for name, mesh in STL.items():
        mesh.export(directory / f"{name}.stl")
    return bundled_with(LINKS, directory)


@pytest.fixture(scope="module")
def camera(robot_file: Path) -> tuple[SimRobot, CameraStream]:
    body = sim_robot(load(RobotSource.of(robot_file)))
    assert [p.kind for p in body.shape.parts if p.link in STL] == ["mesh", "mesh"]
    return body, CameraStream(body, CameraImages(enabled=True, scale=1 / 16, depth=True), 0,
                              [], [])


def _frame(camera, joints, noise=0.0, solids=None, compiled=True, link=None):
    """The frame of the robot standing at the origin with its arm at ``joints``.

    ``solids`` replace the (empty) world; ``link`` alone of the robot's links is drawn, on
    black (floor and sky).
    """
    body, stream = camera
    shape = body.shape
    q = np.array([[joints.get(name, 0.0) for name in shape.joints]])
    base_to_world = planar_matrix(0.0, 0.0, 0.0, body.base_height_m)
    camera_to_world = (base_to_world @ shape.link_to_base(q, stream.link)
                       @ stream.camera_to_link)[0]
    parts_to_world = base_to_world @ shape.transforms_to_base(q)[:, stream.keep]
    scene = stream.scene
    if solids is not None:
        scene = ci.Scene(solids, (), scene.parts, None, scene.palette, scene.part_rgb)
    if link is not None:
        [index] = [i for i, p in enumerate(scene.parts) if p.link == link]
        scene = ci.Scene((), (), [scene.parts[index]], None,
                         ci.Palette(sky=BLACK, floor=(BLACK, BLACK)), [scene.part_rgb[index]])
        parts_to_world = parts_to_world[:, [index]]
    before, ci.COMPILED = ci.COMPILED, compiled
    try:
        [frame] = ci.render_frames(stream.view, camera_to_world[None], scene, parts_to_world,
                                   noise, np.random.default_rng(4))
    finally:
        ci.COMPILED = before
    return frame, camera_to_world


def _reference(camera, link, joints, camera_to_world):
    """Trimesh's distance to ``link``'s STL mesh along each pixel's ray, and its normals."""
    body, stream = camera
    [collision] = body.robot.link(link).collisions
    placed = STL[link].copy()
    if link == "visor":
        placed.apply_scale(VISOR_SCALE)
    placed.apply_transform(planar_matrix(0.0, 0.0, 0.0, body.base_height_m)
                           @ link_transforms(body.robot, joints)[link]
                           @ pose_matrix(collision.origin))
    directions = stream.view.directions @ camera_to_world[:3, :3].T
    origins = np.tile(camera_to_world[:3, 3], (len(directions), 1))
    caster = trimesh.ray.ray_triangle.RayMeshIntersector(placed)
    points, rays, triangles = caster.intersects_location(origins, directions,
                                                         multiple_hits=False)
    distance = np.full(len(directions), np.inf)
    along = points.reshape(-1, 3) - origins[rays]
    distance[rays] = np.einsum("ij,ij->i", along, directions[rays])
    normals = np.zeros((len(directions), 3))
    normals[rays] = placed.face_normals[triangles]
    return distance, normals


def _shaded(rgb, normals):
    """``rgb`` lit as the camera lights it: ambient, plus the rest by the light's cosine."""
    light = ci.AMBIENT + (1.0 - ci.AMBIENT) * np.abs(normals @ ci.LIGHT)
    return np.rint(np.array(rgb) * light[:, None]).astype(int)


def _check_against_trimesh(camera, link, rgb, joints):
    """``link`` alone shows on the pixels whose rays meet its mesh: shaded, at its depth.

    Returns:
        Row and column of each such pixel, (n, 2).
    """
    frame, camera_to_world = _frame(camera, joints, link=link)
    distance, normals = _reference(camera, link, joints, camera_to_world)
    hit = np.isfinite(distance)
    colours = frame.rgb.reshape(-1, 3).astype(int)
    assert np.array_equal(np.any(colours > 0, axis=1), hit)  # elsewhere black: floor, sky
    depth = frame.depth_m.reshape(-1).astype(np.float64)
    np.testing.assert_allclose(depth[hit], (distance * camera[1].view.forward)[hit], rtol=0,
                               atol=1e-6)
    assert np.all(np.abs(colours[hit] - _shaded(rgb, normals[hit])) <= 1)  # rounding of .5
    return np.argwhere(hit.reshape(frame.depth_m.shape))


def _showing(frame, pixels, rgb):
    """How many of ``pixels`` show ``rgb``, shaded (its channels' ratios, within 3 %)."""
    ratios = frame.rgb[tuple(pixels.T)].astype(float) / np.array(rgb)
    return int(np.sum(np.ptp(ratios, axis=1) < 0.03))


def test_pixels_whose_rays_meet_the_visor_show_it_at_trimeshs_depth(camera):
    pixels = _check_against_trimesh(camera, "visor", VISOR_RGB, {})
    rows, columns = camera[1].view.shape
    assert 0.05 * rows * columns < len(pixels) < 0.5 * rows * columns  # in view, not all of it
    with_robot, _ = _frame(camera, {})
    assert len(np.unique(with_robot.rgb[tuple(pixels.T)], axis=0)) > 10  # facet by facet
    assert _showing(with_robot, pixels, VISOR_RGB) == len(pixels)  # nothing in front of it


def test_the_arm_moving_its_mesh_link_moves_it_in_the_image(camera):
    assert len(_check_against_trimesh(camera, "gripper", GRIPPER_RGB, {})) == 0  # out of view
    reaching = _check_against_trimesh(camera, "gripper", GRIPPER_RGB, REACHING)
    turned = _check_against_trimesh(camera, "gripper", GRIPPER_RGB, TURNED)
    assert len(reaching) > 100 and len(turned) > 100
    # turned to the left (about +z), the gripper moves left in the image
    assert turned[:, 1].mean() < reaching[:, 1].mean() - 5
    # and the camera sees it there, with the rest of the robot (the arm's links hide some)
    for joints, pixels in ((REACHING, reaching), (TURNED, turned)):
        frame, _ = _frame(camera, joints)
        assert _showing(frame, pixels, GRIPPER_RGB) > 0.5 * len(pixels)


WALL = Solid("wall 1", "box", np.array([0.9, 0.0, 0.5]), np.eye(3), np.array([0.05, 2.0, 0.5]))
POST = Solid("cylinder 1", "cylinder", np.array([0.7, 0.12, 0.2]), np.eye(3),
             np.array([0.03, 0.03, 0.2]))  # through the visor's edge


@pytest.mark.parametrize("joints", [{}, REACHING, TURNED], ids=["at rest", "reaching",
                                                                 "turned"])
def test_the_numpy_path_gives_the_compiled_loops_bytes(camera, joints):
    compiled, _ = _frame(camera, joints, 0.007, [WALL, POST])
    plain, _ = _frame(camera, joints, 0.007, [WALL, POST], compiled=False)
    assert np.array_equal(compiled.depth_m, plain.depth_m)
    assert np.array_equal(compiled.rgb, plain.rgb)
    assert len(np.unique(compiled.rgb.reshape(-1, 3), axis=0)) > 100  # a scene, not one colour


def _visor_scene(near_m, camera_x_m):
    """The visor's mesh alone, 0.4 m ahead, seen level from ``camera_x_m``."""
    vertices = STL["visor"].vertices * 2.0  # 0.4 m across, centred on its frame
    part = Part("visor", "mesh", np.full(3, 0.2), np.eye(4), vertices,
                np.asarray(STL["visor"].faces))
    pose = np.eye(4)
    pose[:3, 3] = [0.4, 0.0, 0.5]
    camera_to_world = np.eye(4)
    camera_to_world[:3, 3] = [camera_x_m, 0.0, 0.5]
    view = ci.camera_view(ci.scaled(FULL_HD, 1 / 32), near_m, 30.0)
    scene = ci.Scene([WALL], (), [part], pose[None], part_rgb=[VISOR_RGB])
    return view, camera_to_world, scene


@pytest.mark.parametrize(("near_m", "camera_x_m", "low_m", "high_m"), [
    (0.05, 0.4, 0.45, 0.45),  # the camera inside the mesh: it is not seen, the wall is
    (0.35, 0.0, 0.85, 0.85),  # its near side cut by the near plane: what is behind shows
    (0.05, 0.0, 0.2, 0.4 - 0.2 * 0.9),  # in front: the mesh (faces within 10 % of its sphere)
], ids=["from inside", "cut by the near plane", "in front"])
def test_a_mesh_part_is_seen_from_outside_only_as_primitives_are(monkeypatch, near_m,
                                                                camera_x_m, low_m, high_m):
    view, camera_to_world, scene = _visor_scene(near_m, camera_x_m)
    frame = ci.render(view, camera_to_world, scene)
    centre = float(frame.depth_m[view.shape[0] // 2, view.shape[1] // 2])
    assert low_m - 1e-6 <= centre <= high_m + 1e-6  # the wall's face is at x = 0.85 m
    monkeypatch.setattr(ci, "COMPILED", False)
    plain = ci.render(view, camera_to_world, scene)
    assert np.array_equal(frame.rgb, plain.rgb) and np.array_equal(frame.depth_m, plain.depth_m)


def test_simulate_draws_a_robot_with_mesh_links(run, robot_file, tmp_path):
    import matplotlib.image

    # the default scenario's third arm point folds the gripper onto the visor: allowed here
    result = run("simulate", robot_file, "--headless", "--camera-scale", "0.05",
                 "--duration-s", "1", "--out", tmp_path / "out", "--allow-collisions")
    assert result.exit_code == 0, result.stderr
    picture = np.rint(matplotlib.image.imread(tmp_path / "out" / "camera.png") * 255)
    red, green, blue = (picture[..., i] for i in range(3))
    teal = (blue > 1.1 * green) & (green > 4 * red)  # the visor's 26:153:178, shaded, noisy
    assert picture.shape == (54, 96, 3) and teal.sum() > 200
