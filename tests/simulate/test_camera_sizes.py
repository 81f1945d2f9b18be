"""A camera image size no camera has is one error line before the run, not a crash."""

from __future__ import annotations

import pytest

from tests.conftest import assert_one_line_error, run_servicebot
from tests.simulate.plugin_robots import SAM_BOT, edited


@pytest.mark.parametrize(("width", "shown"), [("0", "0"), ("-5", "-5"),
                                              ("1e12", "1000000000000")])
@pytest.mark.parametrize("images", [[], ["--camera-scale", "0.05"]])
def test_a_camera_size_beyond_any_image_is_refused(tmp_path, width, shown, images):
    # 1e12 px ended in an internal error: camera_info's 32-bit width, or 373 GiB of pixels
    robot = edited(SAM_BOT, tmp_path / "robot", ("<width>640</width>", f"<width>{width}</width>"))
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "1", *images)
    assert_one_line_error(result, 2, f"camera image {shown} x 480 px is not a size of 1 to "
                          "65535 px a side")
