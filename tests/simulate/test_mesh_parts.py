"""Links whose collision shape is a mesh: seen by the LIDAR, touching obstacles, or left out.

The robot is the bundled one with a ``bumper`` link in front of its LIDAR, whose collision
shape is an STL file written here (scaled and turned by the URDF). The references are trimesh's
own ray caster and Coal, with the mesh placed by ``kinematics.link_poses``.
"""

from __future__ import annotations

import math
from pathlib import Path

import coal
import numpy as np
import pytest
import trimesh

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.kinematics.link_poses import link_transforms
from servicebot_cli.kinematics.transforms import pose_matrix
from servicebot_cli.simulate import simulator
from servicebot_cli.simulate.body import SimRobot, sim_robot
from servicebot_cli.simulate.sensors import lidar
from servicebot_cli.simulate.shape import outlines
from servicebot_cli.simulate.world.robot_rays import cast_parts
from servicebot_cli.simulate.world.solids import world_solids
from tests.simulate.helpers import bundled_with, scenario

SCALE = (0.5, 1.0, 1.0)
BUMPER = """
  <link name="bumper">
    <collision>
      <origin xyz="0.01 0.02 0.0" rpy="0 0 0.4"/>
      <geometry><mesh filename="{mesh}" scale="0.5 1.0 1.0"/></geometry>
    </collision>
  </link>
  <joint name="bumper_joint" type="fixed">
    <parent link="base_link"/>
    <child link="bumper"/>
    <origin xyz="0.55 0.0 0.125" rpy="0 0 0"/>
  </joint>
"""


def _robot(tmp_path: Path, mesh: str) -> SimRobot:
    """The bundled robot with the bumper, its URDF and ``mesh`` written in ``tmp_path``."""
    return sim_robot(load(RobotSource.of(bundled_with(BUMPER.format(mesh=mesh), tmp_path))))


def _stl(tmp_path: Path) -> trimesh.Trimesh:
    """An icosphere of 80 triangles, 0.1 m across before scaling, written as binary STL."""
    mesh = trimesh.creation.icosphere(subdivisions=1, radius=0.1)
    mesh.export(tmp_path / "bumper.stl")
    return mesh


def _placed_bumper(body: SimRobot, mesh: trimesh.Trimesh) -> trimesh.Trimesh:
    """The bumper's mesh in the base frame, placed from the URDF tree (not the simulator)."""
    [collision] = body.robot.link("bumper").collisions
    placed = mesh.copy()
    placed.apply_scale(SCALE)
    placed.apply_transform(link_transforms(body.robot)["bumper"] @ pose_matrix(collision.origin))
    return placed


@pytest.fixture(scope="module")
def with_bumper(tmp_path_factory: pytest.TempPathFactory) -> tuple[SimRobot, trimesh.Trimesh]:
    directory = tmp_path_factory.mktemp("bumper")
    mesh = _stl(directory)
    return _robot(directory, "bumper.stl"), mesh


def test_the_lidar_sees_the_mesh_where_trimesh_does(with_bumper):
    body, mesh = with_bumper
    [part] = [p for p in body.shape.parts if p.link == "bumper"]
    assert part.kind == "mesh" and len(part.faces) == 80
    mount = body.ray_sensors[0]
    directions = lidar.ray_directions(mount.spec, mount.transform_sensor_to_base)
    origins = np.broadcast_to(mount.transform_sensor_to_base[:3, 3], directions.shape)
    points, index, _ = _placed_bumper(body, mesh).ray.intersects_location(origins, directions)
    expected = np.full(len(directions), np.inf)
    np.minimum.at(expected, index, np.linalg.norm(points - origins[index], axis=1))
    assert 10 < np.isfinite(expected).sum() < 90  # the rays ahead, not the others
    q = np.zeros((1, len(body.shape.joints)))
    alone = cast_parts([part], body.shape.transforms_to_base(q)[:, [body.shape.parts.index(part)]],
                       origins, directions)[0]
    np.testing.assert_allclose(alone, expected, rtol=0, atol=1e-6)  # trimesh: 1e-9 m
    # in the LIDAR's own ranges (every link), the bumper is what the rays ahead see first
    own = lidar.own_ranges(body.shape, mount.link, mount.transform_sensor_to_base, directions, q)[0]
    ahead = np.isfinite(expected)
    np.testing.assert_allclose(own[ahead], expected[ahead], rtol=0, atol=1e-6)  # trimesh: 1e-9 m


def test_a_ray_from_inside_the_mesh_sees_nothing_of_it(with_bumper):
    body, _ = with_bumper
    [part] = [p for p in body.shape.parts if p.link == "bumper"]
    transform = np.eye(4)[None, None]
    inside = np.zeros((1, 3))
    toward = np.array([[1.0, 0.0, 0.0]])
    assert cast_parts([part], transform, inside, toward)[0, 0] == np.inf
    outside = np.array([[-1.0, 0.0, 0.0]])
    expected = 1.0 + part.vertices_m[:, 0].min()  # the icosphere has a vertex on the x axis
    assert cast_parts([part], transform, outside, toward)[0, 0] == pytest.approx(expected)


def test_an_obstacle_touching_only_the_mesh_is_a_contact(with_bumper):
    body, mesh = with_bumper
    low = 0.15  # a low box: under the arm, ahead of the base's own front
    document = {"duration_s": 4,
                "controller": {"max_linear_acceleration_m_s2": 2.0},
                "cmd_vel": [{"duration_s": 4, "linear_m_s": 0.3}],
                "world": {"boxes": [{"center_m": [0.8, 0.0], "size_m": [0.2, 0.4, low + 0.2]}]}}
    s = scenario(document)
    result = simulator.run(body, s, seed=0, solids=world_solids(s.world))
    assert [(c.link, c.obstacle) for c in result.contacts] == [("bumper", "box 1")]
    # Coal, on the bumper placed from the URDF tree: it stopped within a tick of the box
    stop = round(result.contacts[0].time_s / result.plan.dt_s)
    x = result.truth.x_m[stop]
    assert np.all(result.truth.x_m[stop:] == x)
    placed = _placed_bumper(body, mesh)
    placed.apply_translation([x, 0.0, body.base_height_m])
    bvh = coal.BVHModelOBBRSS()
    bvh.beginModel(len(placed.faces), len(placed.vertices))
    bvh.addVertices(np.asarray(placed.vertices))
    bvh.addTriangles(np.asarray(placed.faces))
    bvh.endModel()
    box = coal.Box(0.2, 0.4, low + 0.2)
    answer = coal.DistanceResult()
    coal.distance(bvh, coal.Transform3s(), box,
                  coal.Transform3s(np.eye(3), np.array([0.8, 0.0, (low + 0.2) / 2])),
                  coal.DistanceRequest(), answer)
    assert 0 <= answer.min_distance <= 0.3 * result.plan.dt_s + 1e-9
    # the footprint holds the mesh's outline too
    parts = body.shape.parts
    index = [i for i, p in enumerate(parts) if p.link == "bumper"]
    transforms = body.shape.transforms_to_base(np.zeros((1, len(body.shape.joints))))[0]
    [outline] = outlines([parts[i] for i in index], transforms[index])
    assert outline[:, 0].max() == pytest.approx(placed.vertices[:, 0].max() - x, abs=1e-9)


@pytest.mark.parametrize("content", [b"solid nothing\nendsolid nothing\n", None],
                         ids=["no triangles", "missing"])
def test_a_mesh_that_cannot_be_read_is_left_out_with_a_note(tmp_path, content):
    if content is not None:
        (tmp_path / "bumper.stl").write_bytes(content)
    body = _robot(tmp_path, "bumper.stl")
    assert "bumper" not in body.shape.links
    [note] = body.shape.skipped
    assert note.startswith("bumper: mesh 'bumper.stl' left out: ")
    assert ("no triangles" if content else "is not a file") in note
    assert math.isfinite(body.base_height_m)


def test_the_command_says_which_collision_shapes_it_left_out(tmp_path):
    """A link mesh with a NaN vertex is no part of the simulated robot, and stderr says so."""
    from tests.conftest import SIM_URDF, run_servicebot

    (tmp_path / "bad.obj").write_bytes(b"v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n")
    start = SIM_URDF.read_text().index('<link name="arm_link2">')
    text = SIM_URDF.read_text()
    box = text.index('<box size="0.3 0.1 0.1"/>', text.index("<collision>", start))
    robot = tmp_path / "robot.urdf"
    robot.write_text(text[:box] + '<mesh filename="bad.obj"/>'
                     + text[box + len('<box size="0.3 0.1 0.1"/>'):])
    (tmp_path / "controllers.yaml").write_text(
        (SIM_URDF.parent / "controllers.yaml").read_text())
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "2")
    assert result.returncode == 0, result.stderr
    assert ("note: the simulator's collision shape of link arm_link2: mesh 'bad.obj' left out"
            in result.stderr)
    assert "not finite" in result.stderr
