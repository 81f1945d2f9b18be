"""The built-in scenario drives each robot with the robot's own controller.

It sets no controller field, so a controllers file (found or given) is not overridden by the
bundled robot's numbers, and the bundled robot gets its own from robots/controllers.yaml.
"""

from __future__ import annotations

import json


def test_the_bundled_robot_takes_its_controller_from_its_controllers_file(run):
    result = run("simulate", "--headless", "--duration-s", "1", "--format", "json")
    assert result.exit_code == 0, result.output
    controller = json.loads(result.stdout)["controller"]
    for name, value in (("max_linear_acceleration_m_s2", 0.05), ("update_rate_hz", 100.0),
                        ("publish_rate_hz", 50.0)):
        assert controller[name]["value"] == value
        assert controller[name]["source"].endswith("robots/controllers.yaml"), name


def test_a_controllers_file_given_is_not_overridden_by_the_built_in_scenario(run, tmp_path):
    controllers = tmp_path / "controllers.yaml"
    controllers.write_text("controller_manager:\n  ros__parameters:\n    update_rate: 40\n"
                           "    base:\n      type: diff_drive_controller/DiffDriveController\n"
                           "base:\n  ros__parameters:\n    publish_rate: 10.0\n"
                           "    linear.x.max_acceleration: 0.5\n")
    result = run("simulate", "--headless", "--duration-s", "2", "--format", "json",
                 "--controllers", controllers)
    assert result.exit_code == 0, result.output
    summary = json.loads(result.stdout)
    controller = summary["controller"]
    assert controller["update_rate_hz"] == {"value": 40.0, "source": str(controllers)}
    assert controller["publish_rate_hz"] == {"value": 10.0, "source": str(controllers)}
    assert controller["max_linear_acceleration_m_s2"] == {"value": 0.5,
                                                          "source": str(controllers)}
    assert summary["messages"]["/base/odom"] == 20


def test_enable_odom_tf_false_broadcasts_no_odom_to_base(run, tmp_path):
    controllers = tmp_path / "controllers.yaml"
    base = ("controller_manager:\n  ros__parameters:\n    base:\n"
            "      type: diff_drive_controller/DiffDriveController\n"
            "base:\n  ros__parameters:\n    publish_rate: 10.0\n")
    counts = []
    for extra in ("", "    enable_odom_tf: false\n"):
        controllers.write_text(base + extra)
        result = run("simulate", "--headless", "--duration-s", "2", "--format", "json",
                     "--controllers", controllers)
        assert result.exit_code == 0, result.output
        counts.append(json.loads(result.stdout)["messages"].get("/tf", 0))
    # the odometry's 10 Hz over 2 s, and only those (no joint_state_broadcaster: no joints')
    assert counts == [20, 0]
