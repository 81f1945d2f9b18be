"""Camera images in a run: off by default, in the bag as ROS tools read them, and in --out.

The bag is read back with ``rosbags`` (no code shared with the writer) and the PNG with
matplotlib. The robot stands still 1.25 m in front of a wall, so the depth image's wall
pixels have one depth, known from the URDF alone; the first frame is rendered again from
the camera's pose as the URDF gives it and compared byte for byte.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from servicebot_cli.simulate.bag.ros_messages import publishers
from tests.simulate.helpers import body, run

WALL_SCENARIO = """\
duration_s: 1
initial_pose: {x_m: 0.2}
world:
  walls:
    - {from_m: [1.5, -2], to_m: [1.5, 2], thickness_m: 0.1, height_m: 1.0}
"""
CAMERA_X_M = 0.275  # camera_joint's xyz in service_robot.urdf.xacro
CAMERA_Z_M = 0.05
HFOV_RAD = 1.085595  # pi_camera's horizontal_fov in robots/xacro/gazebo.xacro
WALL_FACE_X_M = 1.45
ARM = ["arm_base_to_link1", "arm_link1_to_link2", "arm_link2_to_link3", "arm_link3_to_link4"]


@pytest.fixture(scope="module")
def recorded(tmp_path_factory):
    from click.testing import CliRunner

    from servicebot_cli.cli import main

    directory = tmp_path_factory.mktemp("camera")
    (directory / "s.yaml").write_text(WALL_SCENARIO)
    result = CliRunner().invoke(main, [
        "simulate", "--headless", "-s", str(directory / "s.yaml"), "--camera-scale", "0.05",
        "--camera-rate-hz", "10", "--camera-depth", "--seed", "3",
        "--bag", str(directory / "bag"), "--out", str(directory / "out")],
        catch_exceptions=False)
    assert result.exit_code == 0, result.stderr
    return directory


def _messages(bag):
    from rosbags.rosbag2 import Reader
    from rosbags.typesys import Stores, get_typestore

    store = get_typestore(Stores.ROS2_HUMBLE)
    seen: dict[str, list] = {}
    with Reader(bag) as reader:
        types = {c.topic: c.msgtype for c in reader.connections}
        for connection, stamp, raw in reader.messages():
            seen.setdefault(connection.topic, []).append(
                (stamp, store.deserialize_cdr(raw, connection.msgtype)))
    return types, seen


def test_images_are_off_unless_asked():
    result = run({"duration_s": 0.5})
    assert result.frames == ()
    assert (result.camera.width_px, result.camera.height_px) == (1920, 1080)
    topics = {p.topic for p in publishers(body())}
    assert "/pi_camera/camera_info" in topics and "/pi_camera/image_raw" not in topics


def test_the_bag_holds_rgb8_and_depth_images_that_camera_info_describes(recorded):
    types, seen = _messages(recorded / "bag")
    assert types["/pi_camera/image_raw"] == "sensor_msgs/msg/Image"
    assert types["/pi_camera/depth/image_raw"] == "sensor_msgs/msg/Image"
    infos, images = seen["/pi_camera/camera_info"], seen["/pi_camera/image_raw"]
    depths = seen["/pi_camera/depth/image_raw"]
    assert [s for s, _ in images] == [s for s, _ in infos] == [s for s, _ in depths] \
        == [k * 100_000_000 for k in range(1, 11)]  # 10 Hz, as asked
    f_px = 96 / (2 * math.tan(HFOV_RAD / 2))  # 1920 x 0.05 = 96 wide, 54 high
    for (_, info), (_, image), (_, depth) in zip(infos, images, depths, strict=True):
        assert (info.width, info.height) == (image.width, image.height) == (96, 54)
        assert info.k == pytest.approx([f_px, 0, 48.5, 0, f_px, 27.5, 0, 0, 1])
        assert image.encoding == "rgb8" and image.step == 3 * 96 and image.is_bigendian == 0
        assert len(image.data) == 54 * 96 * 3
        assert depth.encoding == "32FC1" and depth.step == 4 * 96
        assert image.header.frame_id == info.header.frame_id == "camera_link_optical"
        assert depth.header.frame_id == "camera_link_optical"


def test_the_depth_image_sees_the_wall_at_its_distance(recorded):
    _, seen = _messages(recorded / "bag")
    _, depth = seen["/pi_camera/depth/image_raw"][0]
    metres = np.frombuffer(bytes(depth.data), dtype="<f4").reshape(54, 96)
    middle = metres[24:30]  # rows around the optical axis: the wall, level with the camera
    assert np.median(middle) == pytest.approx(WALL_FACE_X_M - 0.2 - CAMERA_X_M, abs=1e-6)
    assert np.all(np.isfinite(metres))  # the floor below, the wall above: nothing is sky


def test_a_frame_is_the_render_from_the_cameras_pose(recorded):
    from servicebot_cli.simulate.scenario.definition import load_scenario
    from servicebot_cli.simulate.sensors.camera_image import (
        Scene,
        camera_view,
        render,
        scaled,
    )
    from servicebot_cli.simulate.sensors.camera_info import Intrinsics
    from servicebot_cli.simulate.sensors.noise import stream_rng
    from servicebot_cli.simulate.world.solids import world_solids

    _, seen = _messages(recorded / "bag")
    _, image = seen["/pi_camera/image_raw"][0]
    f = 1920 / (2 * math.tan(HFOV_RAD / 2))
    full = Intrinsics(1920, 1080, (f, 0, 960.5, 0, f, 540.5, 0, 0, 1),
                      (f, 0, 960.5, 0, 0, f, 540.5, 0, 0, 0, 1, 0))
    pose = np.eye(4)
    pose[:3, 3] = (0.2 + CAMERA_X_M, 0.0, body().base_height_m + CAMERA_Z_M)
    solids = world_solids(load_scenario(str(recorded / "s.yaml")).world)
    # near and far clip, noise stddev: pi_camera in robots/xacro/gazebo.xacro; seed 3
    expected = render(camera_view(scaled(full, 0.05), 0.05, 100.0), pose, Scene(solids),
                      0.007, stream_rng(3, "camera"))
    got = np.frombuffer(bytes(image.data), dtype=np.uint8).reshape(54, 96, 3)
    assert np.array_equal(got, expected.rgb)


def test_out_holds_the_last_frame_as_a_png(recorded):
    import matplotlib.image

    _, seen = _messages(recorded / "bag")
    _, last = seen["/pi_camera/image_raw"][-1]
    picture = matplotlib.image.imread(recorded / "out" / "camera.png")
    assert picture.shape == (54, 96, 3)
    pixels = np.rint(picture * 255).astype(np.uint8)
    assert np.array_equal(pixels, np.frombuffer(bytes(last.data), np.uint8).reshape(54, 96, 3))


def test_the_camera_sees_the_robots_own_arm_in_its_urdf_colour():
    """With the arm reaching down in front of the camera, its links' orange fills the view.

    The arm's links have ``<material name="orange"/>``, the top-level material of that name
    is rgba 1.0 0.5 0.1: red twice green whatever the shading; nothing else in this scene is.
    """
    def orange_pixels(positions):
        result = run({"duration_s": 1.0, "camera": {"scale": 0.05, "rate_hz": 1},
                      "arm": {"joint_names": ARM, "points": [
                          {"time_from_start_s": 0.7, "positions": positions}]}})
        assert result.arm_positions_rad[-1].tolist() == positions
        rgb = result.frames[-1].rgb.astype(int)
        return int(((rgb[..., 0] > 1.7 * rgb[..., 1]) & (rgb[..., 1] > 2.5 * rgb[..., 2])).sum())

    assert orange_pixels([0.0, 0.0, 0.0, 0.0]) == 0
    assert orange_pixels([0.0, 0.2, 0.6, 0.5]) > 1000


def test_a_run_kept_whole_refuses_frames_that_would_not_fit_in_memory():
    from servicebot_cli.simulate.scenario.located import ScenarioError

    # 20 s of full-size frames at 30 Hz: 600 x 6.2 MB, kept whole as the live window keeps it
    with pytest.raises(ScenarioError, match=r"would take 3\.7 GB.*use --headless"):
        run({"duration_s": 20, "camera": {"scale": 1, "rate_hz": 30}})
