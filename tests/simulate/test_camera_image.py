"""Camera frames against an independent ray caster: trimesh on tessellated copies of the scene.

The renderer intersects primitives in closed form; the reference turns every primitive into
triangles with trimesh and casts the same pixel rays with trimesh's own ray-triangle code.
Depth images must agree to a millimetre (the 128-sided cylinders are 0.05 mm off the round
one, more at grazing angles) wherever both see the same surface (all but the few pixels on a
silhouette where the tessellation differs), and ``camera_info`` must place known points on
the pixels that show them.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import trimesh

from servicebot_cli.simulate.sensors import camera_image as ci
from servicebot_cli.simulate.sensors.camera_info import Intrinsics
from servicebot_cli.simulate.shape import Part
from servicebot_cli.simulate.world.solids import Solid, yaw_rotation

HFOV_RAD = 1.047  # the bundled robot's camera
FOCAL = 1920 / (2 * math.tan(HFOV_RAD / 2))
FULL_HD = Intrinsics(1920, 1080, (FOCAL, 0, 960.5, 0, FOCAL, 540.5, 0, 0, 1),
                     (FOCAL, 0, 960.5, 0, 0, FOCAL, 540.5, 0, 0, 0, 1, 0))
SOLIDS = [
    Solid("wall 1", "box", np.array([3.0, 0.0, 0.5]), np.eye(3), np.array([0.05, 3.0, 0.5])),
    Solid("box 1", "box", np.array([2.0, 0.6, 0.2]), yaw_rotation(0.5), np.array([0.2] * 3)),
    Solid("cylinder 1", "cylinder", np.array([1.5, -0.7, 0.4]), np.eye(3),
          np.array([0.15, 0.15, 0.4])),
]
# a link of the robot in view (low, in front of the camera), as a part placed in the world
PART = Part("arm_link1", "box", np.array([0.05, 0.05, 0.05]), np.eye(4))
PART_POSE = np.eye(4)
PART_POSE[:3, 3] = [0.5, 0.2, 0.3]


def camera_pose(x=0.0, y=0.0, z=0.5, yaw=0.0, pitch=0.0):
    pose = np.eye(4)
    cy, sy, cp, sp = math.cos(yaw), math.sin(yaw), math.cos(pitch), math.sin(pitch)
    pose[:3, :3] = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]]) @ np.array(
        [[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    pose[:3, 3] = [x, y, z]
    return pose


def obstacle_mesh():
    """A mesh obstacle: a pyramid of four triangles, placed in the world."""
    mesh = trimesh.creation.cone(radius=0.25, height=0.6, sections=4)
    mesh.apply_translation([2.2, -0.2, 0.0])
    return mesh


def reference_mesh(solids, meshes, parts, part_poses):
    """Every surface as triangles (a 40 m floor square, 128-sided cylinders)."""
    pieces = [trimesh.Trimesh([[-20, -20, 0], [20, -20, 0], [20, 20, 0], [-20, 20, 0]],
                              [[0, 1, 2], [0, 2, 3]])]
    for solid in solids:
        pose = np.eye(4)
        pose[:3, :3], pose[:3, 3] = solid.rotation, solid.center_m
        if solid.kind == "box":
            pieces.append(trimesh.creation.box(extents=2 * solid.half_m, transform=pose))
        else:
            pieces.append(trimesh.creation.cylinder(radius=solid.half_m[0],
                                                    height=2 * solid.half_m[2], sections=128,
                                                    transform=pose))
    pieces.extend(meshes)
    for part, pose in zip(parts, part_poses, strict=True):
        pieces.append(trimesh.creation.box(extents=2 * part.half_m, transform=pose))
    return trimesh.util.concatenate(pieces)


def reference_depth(view, pose, solids, meshes=(), parts=(), part_poses=()):
    scene = reference_mesh(solids, meshes, parts, part_poses)
    directions = view.directions @ pose[:3, :3].T
    origins = np.tile(pose[:3, 3], (len(directions), 1))
    caster = trimesh.ray.ray_triangle.RayMeshIntersector(scene)
    locations, rays, _ = caster.intersects_location(origins, directions, multiple_hits=False)
    distance = np.full(len(directions), np.inf)
    distance[rays] = np.einsum("ij,ij->i", locations - origins[rays], directions[rays])
    depth = distance * view.forward
    depth[(depth < view.near_m) | (depth > view.far_m)] = np.inf
    return depth.reshape(view.shape)


def agreement(ours, reference):
    with np.errstate(invalid="ignore"):  # inf - inf where both see nothing
        same = (np.isinf(ours) & np.isinf(reference)) | (np.abs(ours - reference) < 1e-3)
    return float(same.mean())


@pytest.mark.parametrize("pose", [camera_pose(), camera_pose(0.3, 0.2, 0.9, 0.4, 0.35),
                                  camera_pose(4.0, 1.0, 0.3, math.pi - 0.3)],
                         ids=["level", "tilted down", "from behind the wall"])
def test_depth_matches_an_independent_ray_caster(pose):
    view = ci.camera_view(ci.scaled(FULL_HD, 1 / 16), 0.05, 30.0)
    meshes = [obstacle_mesh()]
    scene = ci.Scene(SOLIDS, meshes, [PART], np.array([PART_POSE]))
    frame = ci.render(view, pose, scene)
    expected = reference_depth(view, pose, SOLIDS, meshes, [PART], [PART_POSE])
    assert frame.rgb.shape == (*view.shape, 3) and frame.rgb.dtype == np.uint8
    assert agreement(frame.depth_m.astype(np.float64), expected) > 0.995
    assert np.isfinite(expected).mean() > 0.5  # the view is mostly of things, not sky


def test_camera_info_puts_a_known_point_on_the_pixel_that_shows_it():
    info = ci.scaled(FULL_HD, 1 / 8)
    assert (info.width_px, info.height_px) == (240, 135)
    view = ci.camera_view(info, 0.05, 30.0)
    pose = camera_pose()
    frame = ci.render(view, pose, ci.Scene(SOLIDS))
    fx, cx, fy, cy = info.k[0], info.k[2], info.k[4], info.k[5]

    def pixel(world):
        """Row and column of a world point, projected with camera_info's K (one-based)."""
        x, y, z = np.asarray(world) - pose[:3, 3]
        optical = np.array([-y, -z, x])  # x right, y down, z forward
        u, v = fx * optical[0] / optical[2] + cx, fy * optical[1] / optical[2] + cy
        return round(v) - 1, round(u) - 1

    # a point of the wall's face, upper left; and the cylinder's side nearest the camera,
    # which stands right of the view's centre and below the lens
    assert frame.depth_m[pixel([2.95, 0.9, 0.8])] == pytest.approx(2.95, abs=1e-5)
    row, column = pixel([1.35, -0.7, 0.3])
    assert column > view.shape[1] / 2 and row > view.shape[0] / 2
    assert frame.depth_m[row, column] == pytest.approx(1.35, abs=0.02)
    assert ci.field_of_view_rad(info) == pytest.approx(HFOV_RAD, rel=1e-3)


def test_what_is_nearer_than_the_near_plane_is_not_drawn():
    view = ci.camera_view(ci.scaled(FULL_HD, 1 / 16), 0.6, 30.0)
    close = Solid("box 2", "box", np.array([0.4, 0.0, 0.5]), np.eye(3), np.array([0.05] * 3))
    frame = ci.render(view, camera_pose(), ci.Scene([close, SOLIDS[0]]))
    assert np.nanmin(frame.depth_m) >= 0.6
    assert frame.depth_m[view.shape[0] // 2, view.shape[1] // 2] == pytest.approx(2.95)


def test_a_part_around_the_camera_does_not_hide_the_view():
    """As Gazebo's camera inside its own link: the link's box around the lens is not seen."""
    view = ci.camera_view(ci.scaled(FULL_HD, 1 / 16), 0.05, 30.0)
    around = np.eye(4)
    around[:3, 3] = [0.0, 0.0, 0.5]
    housing = Part("camera_link", "box", np.array([0.02, 0.05, 0.02]), np.eye(4))
    frame = ci.render(view, camera_pose(), ci.Scene(SOLIDS, (), [housing], np.array([around])))
    assert frame.depth_m[view.shape[0] // 2, view.shape[1] // 2] == pytest.approx(2.95)


def test_noise_is_gaussian_on_pixel_values_scaled_to_one():
    view = ci.camera_view(ci.scaled(FULL_HD, 1 / 8), 0.05, 30.0)
    scene = ci.Scene(SOLIDS)
    clean = ci.render(view, camera_pose(), scene).rgb.astype(np.float64)
    noisy = ci.render(view, camera_pose(), scene, 0.007, np.random.default_rng(3))
    unclipped = (clean > 10) & (clean < 245)
    spread = (noisy.rgb.astype(np.float64) - clean)[unclipped].std() / 255.0
    assert spread == pytest.approx(0.007, rel=0.1)  # rounding to integers adds 1/sqrt(12)/255


def test_the_scene_is_shaded_and_coloured_by_what_the_rays_meet():
    view = ci.camera_view(ci.scaled(FULL_HD, 1 / 8), 0.05, 30.0)
    frame = ci.render(view, camera_pose(), ci.Scene(SOLIDS))
    sky = frame.rgb[0, 0]
    assert tuple(sky) == ci.Palette().sky and np.isinf(frame.depth_m[0, 0])
    wall = frame.rgb[view.shape[0] // 2, view.shape[1] // 2].astype(int)
    assert wall[0] > wall[2]  # the beige wall, lit from above at a slant: darker than white


def _placed(x, y, z):
    pose = np.eye(4)
    pose[:3, 3] = [x, y, z]
    return pose


@pytest.mark.parametrize("pose", [camera_pose(), camera_pose(0.3, 0.2, 0.9, 0.4, 0.35),
                                  camera_pose(4.0, 1.0, 0.3, math.pi - 0.3)],
                         ids=["level", "tilted down", "from behind the wall"])
def test_the_compiled_loop_draws_what_the_numpy_path_draws(pose, monkeypatch):
    """Without meshes frames come from numba's loop; the numpy path gives the same bytes."""
    import sys

    view = ci.camera_view(ci.scaled(FULL_HD, 1 / 16), 0.05, 30.0)
    parts = [PART, Part("ball", "sphere", np.full(3, 0.1), np.eye(4)),
             Part("post", "cylinder", np.array([0.08, 0.08, 0.2]), np.eye(4))]
    poses = np.array([PART_POSE, _placed(1.0, -0.3, 0.4), _placed(0.8, 0.5, 0.2)])
    scene = ci.Scene(SOLIDS, (), parts, poses)
    compiled = ci.render(view, pose, scene, 0.007, np.random.default_rng(1))
    assert "servicebot_cli.simulate.sensors.camera_kernel" in sys.modules
    monkeypatch.setattr(ci, "COMPILED", False)
    plain = ci.render(view, pose, scene, 0.007, np.random.default_rng(1))
    assert np.array_equal(compiled.depth_m, plain.depth_m)
    assert np.array_equal(compiled.rgb, plain.rgb)
    assert len(np.unique(compiled.rgb.reshape(-1, 3), axis=0)) > 100  # a scene, not one colour


def test_the_compiled_loop_matches_the_independent_ray_caster():
    view = ci.camera_view(ci.scaled(FULL_HD, 1 / 16), 0.05, 30.0)
    pose = camera_pose(0.3, 0.2, 0.9, 0.4, 0.35)
    frame = ci.render(view, pose, ci.Scene(SOLIDS, (), [PART], np.array([PART_POSE])))
    expected = reference_depth(view, pose, SOLIDS, (), [PART], [PART_POSE])
    assert agreement(frame.depth_m.astype(np.float64), expected) > 0.995


def test_frames_are_the_same_bytes_on_one_thread_or_two_and_alone_or_together():
    """Frames are shared out between threads; a frame's bytes depend on its inputs alone."""
    import numba

    view = ci.camera_view(ci.scaled(FULL_HD, 1 / 16), 0.05, 30.0)
    poses = np.array([camera_pose(), camera_pose(0.3, 0.2, 0.9, 0.4, 0.35),
                      camera_pose(4.0, 1.0, 0.3, math.pi - 0.3)])
    scene = ci.Scene(SOLIDS, [obstacle_mesh()], [PART])
    part_poses = np.array([[PART_POSE], [_placed(0.6, 0.1, 0.3)], [PART_POSE]])

    def frames(threads):
        before = numba.get_num_threads()
        numba.set_num_threads(threads)
        try:
            return ci.render_frames(view, poses, scene, part_poses, 0.007,
                                    np.random.default_rng(5))
        finally:
            numba.set_num_threads(before)

    one, two = frames(1), frames(min(2, numba.config.NUMBA_NUM_THREADS))
    rng = np.random.default_rng(5)
    alone = [ci.render(view, p, scene.posed(q), 0.007, rng) for p, q in zip(poses, part_poses,
                                                                          strict=True)]
    for a, b, c in zip(one, two, alone, strict=True):
        assert np.array_equal(a.rgb, b.rgb) and np.array_equal(a.rgb, c.rgb)
        assert np.array_equal(a.depth_m, b.depth_m) and np.array_equal(a.depth_m, c.depth_m)
    assert not np.array_equal(one[0].rgb, one[2].rgb)


def test_a_mesh_of_many_triangles_matches_the_independent_ray_caster():
    """A 320-triangle sphere and a 4-triangle pyramid, through the compiled loop's hierarchy."""
    view = ci.camera_view(ci.scaled(FULL_HD, 1 / 24), 0.05, 30.0)
    ball = trimesh.creation.icosphere(subdivisions=2, radius=0.35)
    ball.apply_translation([1.8, 0.3, 0.35])
    assert len(ball.faces) == 320
    meshes = [ball, obstacle_mesh()]
    pose = camera_pose(0.0, 0.0, 0.6, 0.0, 0.15)
    frame = ci.render(view, pose, ci.Scene(SOLIDS[:1], meshes, mesh_rgb=[(255, 0, 0),
                                                                         (0, 0, 255)]))
    expected = reference_depth(view, pose, SOLIDS[:1], meshes)
    assert agreement(frame.depth_m.astype(np.float64), expected) > 0.995
    rgb = frame.rgb.reshape(-1, 3).astype(int)
    assert ((rgb[:, 0] > 100) & (rgb[:, 1] == 0) & (rgb[:, 2] == 0)).sum() > 20  # the ball
    assert ((rgb[:, 2] > 100) & (rgb[:, 0] == 0) & (rgb[:, 1] == 0)).sum() > 2  # the pyramid


def test_noise_keyed_by_pixel_is_the_same_in_numpy_and_draws_a_normal_table():
    from servicebot_cli.simulate.sensors import camera_noise

    table = camera_noise.normal_table()
    assert len(table) == 65536 and np.all(np.diff(table) > 0)
    assert table.mean() == pytest.approx(0.0, abs=1e-12)
    assert table.std() == pytest.approx(1.0, abs=1e-3)
    drawn = camera_noise.standard_normal(np.uint64(12345), 200_000)
    assert drawn.mean() == pytest.approx(0.0, abs=0.01)
    assert drawn.std() == pytest.approx(1.0, abs=0.01)
    assert abs(np.corrcoef(drawn[:, 0], drawn[:, 1])[0, 1]) < 0.01  # channels independent
