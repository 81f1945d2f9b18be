"""Every bad scenario field is one error line naming the file, the line and the field."""

from __future__ import annotations

import pytest

from tests.conftest import assert_one_line_error, run_servicebot
from tests.simulate.helpers import NO_ROS
from tests.simulate.plugin_robots import SAM_BOT, edited

YAML_CASES = [
    ("duration_s: fast\n", ":1:", "duration_s: expected a number, got 'fast'"),
    ("duration_s: 10\ncmd_vel:\n  - {duration_s: 1, linear: 0.1}\n", ":3:",
     "cmd_vel[0].linear: unknown field; did you mean 'linear_m_s'?"),
    ("duration_s: 10\nworld:\n  boxes:\n    - center_m: [1, 2]\n      size_m: [1, 2]\n",
     ":5:", "world.boxes[0].size_m: expected a list of 3 numbers"),
    ("duration_s: 10\ncontroller:\n  saturation: sometimes\n", ":3:",
     "controller.saturation: 'sometimes' is not one of: keep-curvature, per-wheel"),
    ("duration_s: -1\n", ":1:", "duration_s: must be positive"),
    ("cmd_vel: []\n", ":1:", "'duration_s' is required"),
    ("duration_s: 10\narm:\n  joint_names: [arm_base_to_link]\n  points:\n"
     "    - {time_from_start_s: 1, positions: [0.1]}\n", ":3:",
     "arm.joint_names[0]: unknown arm joint"),
    ("duration_s: 10\narm:\n  joint_names: [arm_base_to_link1]\n  points:\n"
     "    - {time_from_start_s: 1, positions: [0.1]}\n    - {time_from_start_s: 2, "
     "positions: [2.5]}\n", ":6:", "arm.points[1].positions[0]: arm_base_to_link1 = 2.5 rad "
     "is outside its URDF limits"),
    ("duration_s: 10\narm:\n  joint_names: [front_left_wheel_joint]\n  points: []\n", ":3:",
     "is a wheel"),
    ("duration_s: 10\ninitial_pose: {x_m: 1.0}\nworld:\n  cylinders:\n"
     "    - {center_m: [1.2, 0], radius_m: 0.2}\n", ":2:", "base_link touches cylinder 1"),
    ("duration_s: 10\ncmd_vel:\n  - {start_s: 5, duration_s: 2}\n  - {start_s: 6, "
     "duration_s: 1}\n", ":4:", "cmd_vel[1].start_s: 6 s is before the previous segment"),
    ("duration_s: [1\n", ":2:", "not valid YAML"),
    ("duration_s: 10\nduration_s: 11\n", ":2:", "given twice"),
    # Values the command line refuses are refused in the file too.
    ("duration_s: .nan\n", ":1:", "duration_s: expected a finite number, got nan"),
    ("duration_s: .inf\n", ":1:", "duration_s: expected a finite number, got inf"),
    ("duration_s: 10\ncontroller:\n  wheel_separation_multiplier: .nan\n", ":3:",
     "controller.wheel_separation_multiplier: expected a finite number, got nan"),
    ("duration_s: 10\ncontroller:\n  max_linear_acceleration_m_s2: .inf\n", ":3:",
     "controller.max_linear_acceleration_m_s2: expected a finite number, got inf"),
    ("duration_s: 10\ncontroller:\n  cmd_vel_timeout_s: -.inf\n", ":3:",
     "controller.cmd_vel_timeout_s: expected a finite number, got -inf"),
    ("duration_s: 10\ncmd_vel:\n  - {duration_s: 1, linear_m_s: .NaN}\n", ":3:",
     "cmd_vel[0].linear_m_s: expected a finite number, got nan"),
    ("duration_s: 10\ninitial_pose: {x_m: 1" + "0" * 400 + "}\n", ":2:",
     "initial_pose.x_m: expected a finite number, got an integer too large for a float"),
    ("duration_s: 10\ninitial_pose: {x_m: 1" + "0" * 5000 + "}\n", ":2:",
     "initial_pose.x_m: expected a finite number, got an integer too long to read"),
    # Camera images: a scale of the URDF's size, a rate the URDF camera can give.
    ("duration_s: 10\ncamera:\n  scale: 1.5\n", ":3:", "camera.scale: must be at most 1"),
    ("duration_s: 10\ncamera:\n  scale: 0\n", ":3:", "camera.scale: must be positive"),
    ("duration_s: 10\ncamera:\n  depth: yes please\n", ":3:",
     "camera.depth: expected true or false"),
    ("duration_s: 10\ncamera:\n  rate_hz: 40\n", ":3:",
     "camera.rate_hz: 40 Hz is above the URDF camera's update rate (30 Hz)"),
    ("duration_s: 10\ncamera:\n  size: 2\n", ":3:", "camera.size: unknown field"),
    ("duration_s: 10\ncamera: on\n", ":2:", "camera: expected a mapping"),
    # Colours: "#rrggbb" or [r, g, b] in 0-1, each refused naming its field.
    ("duration_s: 10\nworld:\n  boxes:\n    - {center_m: [1, 1], size_m: [1, 1, 1], "
     "color: red}\n", ":4:", 'world.boxes[0].color: expected [r, g, b] with each in 0-1, or '
     '"#rrggbb", got \'red\''),
    ("duration_s: 10\nworld:\n  cylinders:\n    - center_m: [1, 1]\n      radius_m: 0.2\n"
     "      color: [0.5, 2, 0]\n", ":6:",
     "world.cylinders[0].color[1]: must be at most 1, got 2"),
    ("duration_s: 10\nworld:\n  walls:\n    - from_m: [0, 0]\n      to_m: [1, 0]\n"
     "      color: [1, 0]\n", ":6:", "world.walls[0].color: expected [r, g, b]"),
    ("duration_s: 10\nworld:\n  floor:\n    color: #00ff00\n", ":4:",
     "world.floor.color: expected [r, g, b] with each in 0-1, or \"#rrggbb\", got nothing "
     "(quote a \"#rrggbb\""),
    ("duration_s: 10\nworld:\n  floor:\n    colour: '#00ff00'\n", ":4:",
     "world.floor.colour: unknown field; did you mean 'color'?"),
    # The seed is the command line's alone (--seed): a scenario cannot carry one.
    ("duration_s: 10\nseed: -1\n", ":2:", "seed: unknown field"),
]


JSON_CASES = [
    ('{\n  "duration_s": 10,\n  "slip": {\n    "track_factor": "wide"\n  }\n}\n', ":4:",
     "slip.track_factor: expected a number"),
    ('{\n  "duration_s": 10,\n  "rates": {"joint_states_hz": 0}\n}\n', ":3:",
     "rates.joint_states_hz: must be positive"),
    ('{\n  "duration_s": 10,\n}\n', ":3:", "not valid JSON"),
    ('{"duration_s": 10, "world": {"walls": [{"from_m": [0, 0], "to_m": [0, 0]}]}}', ":1:",
     "world.walls[0].to_m: a wall needs two different ends"),
    ('{\n  "duration_s": 1e999\n}\n', ":2:", "duration_s: expected a finite number, got inf"),
    ('{\n  "duration_s": NaN\n}\n', ":2:", "not valid JSON: unexpected 'N'"),
    ('{\n  "duration_s": 1' + "0" * 5000 + '\n}\n', ":2:",
     "not valid JSON: a number too long to read"),
]


@pytest.mark.parametrize(("name", "text", "line", "message"),
                         [("run.yaml", *case) for case in YAML_CASES]
                         + [("run.json", *case) for case in JSON_CASES])
def test_bad_field(run, tmp_path, name, text, line, message):
    path = tmp_path / name
    path.write_text(text)
    error = assert_one_line_error(run("simulate", "--headless", "-s", path), 2, message)
    assert f"{path}{line}" in error


@pytest.mark.parametrize(("name", "text"), [("run.yaml", ""), ("run.yaml", "# to do\n"),
                                          ("run.json", "{}"), ("run.yaml", "{}\n")])
def test_a_scenario_file_with_nothing_in_it_says_so(run, tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    assert_one_line_error(run("simulate", "--headless", "-s", path), 2,
                          f"{path}: holds no scenario (it is empty, or only comments)",
                          "servicebot simulate --print-scenario")


def test_missing_scenario_file(run, tmp_path):
    assert_one_line_error(run("simulate", "--headless", "-s", tmp_path / "nope.yaml"), 2,
                          "no such file")


def test_missing_mesh_file(run, tmp_path):
    path = tmp_path / "run.yaml"
    path.write_text("duration_s: 1\nworld:\n  meshes:\n    - {file: room.stl}\n")
    error = assert_one_line_error(run("simulate", "--headless", "-s", path), 2, "room.stl")
    assert f"{path}:4:" in error


@pytest.mark.parametrize(("text", "needle"), [
    ("duration_s: 10\ncmd_vel:\n  - {start_s: 0, duration_s: 5}\n"
     "  - {start_s: 12, duration_s: 5, linear_m_s: 0.1}\n",
     ":4: cmd_vel[1].start_s: starts at 12 s, when the run has ended (duration_s: 10)"),
    ("duration_s: 10\narm:\n  joint_names: [arm_base_to_link1]\n  start_s: 10\n"
     "  points:\n    - {time_from_start_s: 1, positions: [0.1]}\n",
     ":4: arm.start_s: the goal is sent at 10 s, when the run has ended"),
    ("duration_s: 10\narm:\n  joint_names: [arm_base_to_link1]\n"
     "  points:\n    - {time_from_start_s: 11, positions: [0.1]}\n",
     ":5: arm.points[0].time_from_start_s: reached at 11 s, after the run ends"),
    ("duration_s: 10\nrates: {joint_states_hz: 200}\n",
     ":2: rates.joint_states_hz: 200 Hz is above the control rate"),
    ("duration_s: 10\ncontroller: {update_rate_hz: 20, publish_rate_hz: 50}\n",
     ":2: controller.publish_rate_hz: 50 Hz is above the control rate"),
])
def test_a_scenario_that_cannot_be_what_was_meant_is_refused(run, tmp_path, text, needle):
    scenario = tmp_path / "s.yaml"
    scenario.write_text(text)
    assert_one_line_error(run("simulate", "--headless", "-s", scenario), 2, needle)


@pytest.mark.parametrize(("args", "code", "needle"), [
    (("--camera-scale", "0"), 2, "--camera-scale"),
    (("--camera-scale", "1.5"), 2, "above the maximum 1"),
    (("--camera-rate-hz", "-5"), 2, "--camera-rate-hz"),
    (("--camera-rate-hz", "31"), 2,
     "--camera-rate-hz: 31 Hz is above the URDF camera's update rate (30 Hz)"),
])
def test_bad_camera_options_are_refused_before_the_run(run, args, code, needle):
    assert_one_line_error(run("simulate", "--headless", "--duration-s", "1", *args), code,
                          needle)


def test_camera_images_of_a_camera_nothing_publishes_say_what_to_add(tmp_path):
    """sam_bot without its gazebo_ros_camera plugin: the sensor is there, nothing publishes it."""
    text = SAM_BOT.read_text()
    start = text.index('<plugin name="depth_camera_controller"')
    plugin = text[start:text.index("</plugin>", start) + len("</plugin>")]
    robot = edited(SAM_BOT, tmp_path, (plugin, ""))
    result = run_servicebot("simulate", robot, "--headless", "--duration-s", "1",
                            "--camera-scale", "0.125", env=NO_ROS)
    line = assert_one_line_error(result, 2, "nothing publishes camera sensor 'depth_camera'",
                                 "add a gazebo_ros_camera plugin")
    assert "has no camera sensor" not in line
