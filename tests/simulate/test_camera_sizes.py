"""A camera no image can be made of is left out with a note; asked for images, an error."""

from __future__ import annotations

import pytest

from tests.conftest import assert_one_line_error, run_servicebot
from tests.simulate.plugin_robots import SAM_BOT, edited

_SIZES = [("<width>640</width>", "<width>0</width>", "its image, 0 x 480 px, is not 1 to "
           "65,535 px a side"),
          ("<width>640</width>", "<width>-5</width>", "its image, -5 x 480 px"),
          # 1e12 px ended in an internal error: camera_info's 32-bit width, or 373 GiB
          ("<width>640</width>", "<width>1e12</width>", "its image, 1000000000000 x 480 px"),
          # Gazebo takes a field of view up to 2 pi; a pinhole image shows less than pi
          ("<horizontal_fov>1.047198</horizontal_fov>", "<horizontal_fov>3.5</horizontal_fov>",
           "its horizontal_fov 3.5 rad is not more than 0 and less than pi")]


@pytest.mark.parametrize(("was", "now", "said"), _SIZES)
def test_a_camera_no_image_can_be_made_of_is_left_out_with_a_note(tmp_path, was, now, said):
    """It refused the whole run, in words that named neither the file nor the camera,
    where a ray sensor it cannot cast is left out with a note."""
    robot = edited(SAM_BOT, tmp_path / "robot", (was, now))
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "1")
    assert result.returncode == 0, result.stderr
    assert f"note: camera 'depth_camera' on camera_link of {robot} is not simulated: {said}" \
        in result.stderr
    assert "its topics are left out" in result.stderr


@pytest.mark.parametrize(("was", "now", "said"), _SIZES)
def test_camera_images_of_such_a_camera_are_refused_saying_why(tmp_path, was, now, said):
    robot = edited(SAM_BOT, tmp_path / "robot", (was, now))
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "1",
                            "--camera-scale", "0.05")
    assert_one_line_error(result, 2, "camera images asked, but camera 'depth_camera' on "
                          "camera_link", said)
