"""README.md's simulate section says where odometry comes from as the simulator does it.

Gazebo Classic's diff-drive plugin defaults to the WORLD odometry source (gazebo_ros_pkgs'
``gazebo_ros_diff_drive.cpp``: ``odometry_source`` 1, ROS 1 ``world``), the true pose: the
README must not call all odometry dead reckoning.
"""

from __future__ import annotations

import re

from servicebot_cli.simulate.controllers.classic_drive import WORLD, ClassicDrive, odometry_source
from tests.conftest import REPO

README = re.sub(r"\s+", " ", (REPO / "README.md").read_text())


def test_the_readme_says_a_classic_plugins_default_odometry_is_the_true_pose():
    assert ClassicDrive().odometry_source == WORLD  # the plugin's default
    assert odometry_source(None, ros1=False) == odometry_source(None, ros1=True) == WORLD
    assert "Odometry is dead reckoning" not in README
    assert ("Classic `gazebo_ros_diff_drive` with its default odometry source, WORLD "
            "(`<odometry_source>` 1, ROS 1 `<odometrySource>world`), publishes the true pose"
            in README)


def test_the_readme_says_the_bag_holds_only_what_the_robot_publishes():
    assert "as `inspect --section topics` lists them, and no others" in README
