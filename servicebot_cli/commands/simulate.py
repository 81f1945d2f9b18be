"""``servicebot simulate``: the headless kinematic simulator."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING

import click

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.kinematics_options import srdf_option
from servicebot_cli.commands.options import (
    Number,
    OutputPath,
    RobotArgs,
    format_option,
    refuse_with,
    robot_arguments,
)
from servicebot_cli.common.errors import AnswerIsNo

if TYPE_CHECKING:
    from servicebot_cli.simulate.expectations import Expectation

PLOT_SUFFIXES = (".png", ".svg", ".pdf")
"""What the plot writer produces, chosen by the file's extension."""


class ExpectationParam(click.ParamType["Expectation"]):
    """``FIELD OP NUMBER`` over the summary, checked at parsing (fields named as in the JSON)."""

    name = "EXPR"

    def convert(self, value: str | Expectation, param: click.Parameter | None,
                ctx: click.Context | None) -> Expectation:
        """Parse the expectation; a bad one is a usage error naming it."""
        from servicebot_cli.simulate.expectations import Expectation as Parsed
        from servicebot_cli.simulate.expectations import ExpectationError, parse_expectation

        if isinstance(value, Parsed):
            return value
        try:
            return parse_expectation(str(value))
        except ExpectationError as exc:
            self.fail(str(exc), param, ctx)


@click.command(cls=Command)
@robot_arguments()
@click.option("-s", "--scenario", "scenario_file", type=click.Path(dir_okay=False),
              help="Scenario file, YAML or JSON (default: the built-in loop in a room).")
@click.option("--headless", is_flag=True, help="No window: simulate, write outputs, print.")
@click.option("--out", "out_dir", type=OutputPath(directory=True),
              help="Write one CSV per stream and summary.json into this directory.")
@click.option("--bag", type=OutputPath(directory=True, fresh=True),
              help="Write a ROS 2 bag (MCAP storage) directory; it must not exist yet.")
@click.option("--plot", type=OutputPath(suffixes=PLOT_SUFFIXES, what="plot", named_format=True),
              metavar="FILE.png", help="Save a picture of the run (.png, .svg or .pdf).")
@click.option("--seed", type=click.IntRange(min=0, max=2**63 - 1), default=0, show_default=True,
              help="Seed of all sensor noise.")
@click.option("--duration-s", type=Number("S", positive=True, maximum=86400),
              help="Simulated time [s], instead of the scenario's.")
@click.option("--wheel-separation-multiplier", type=Number(positive=True),
              help="diff_drive_controller's wheel_separation_multiplier.")
@click.option("--saturation", type=click.Choice(["keep-curvature", "per-wheel"]),
              help="Wheel speed limits: scale both sides (keep the curvature) or clip each "
              "wheel alone as Gazebo does.  [scenario default: keep-curvature]")
@click.option("--cmd-vel-timeout-s", type=Number("S", positive=True),
              help="Commands older than this ramp to zero.  [scenario default: 0.5]")
@click.option("--max-linear-acceleration", "max_linear", type=Number("M_S2", positive=True),
              help="Acceleration limit [m/s^2].  [default: none]")
@click.option("--max-angular-acceleration", "max_angular", type=Number("RAD_S2", positive=True),
              help="Angular acceleration limit [rad/s^2].  [default: none]")
@click.option("--controllers", "controllers_file", type=click.Path(dir_okay=False),
              help="ros2_control controllers file for diff_drive_controller's parameters "
              "[default: the one the robot's gazebo_ros2_control plugin names, else "
              "controllers.yaml beside the robot].")
@click.option("--camera-scale", type=Number("S", positive=True, maximum=1.0),
              help="Render camera images at S times the URDF's image size (0 < S <= 1); "
              "turns images on.  [scenario default: 0.125]")
@click.option("--camera-rate-hz", type=Number("HZ", positive=True),
              help="Camera frames per simulated second, at most the URDF camera's update "
              "rate; turns images on.  [default: that rate]")
@click.option("--camera-depth", is_flag=True,
              help="Render a depth image (32FC1) with each camera image; turns images on.")
@click.option("--speed", type=Number(positive=True), default=1.0,
              show_default=True, help="Playback speed of the live window (not with --headless).")
@click.option("--print-scenario", is_flag=True, is_eager=True, expose_value=False,
              callback=lambda ctx, param, value: _print_scenario(ctx) if value else None,
              help="Print the built-in scenario (YAML, commented) as a starting point, and exit.")
@click.option("--expect", "expectations", type=ExpectationParam(), multiple=True,
              metavar="EXPR", help="Fail (exit 1) unless the summary meets EXPR, e.g. "
              "'collisions == 0' or 'odometry_drift.final_position_m < 0.05' (repeatable).")
@click.option("--allow-collisions", is_flag=True,
              help="Run arm trajectory points that put links into each other or the floor "
              "(refused by default, as ik refuses them); the run logs the self collisions.")
@srdf_option
@click.option("--progress/--no-progress", default=None,
              help="Progress bar on stderr  [default: on a terminal, outside CI].")
@format_option
def simulate(robot_args: RobotArgs, scenario_file: str | None, headless: bool,
             out_dir: str | None, bag: str | None, plot: str | None, seed: int,
             duration_s: float | None, wheel_separation_multiplier: float | None,
             saturation: str | None, cmd_vel_timeout_s: float | None, max_linear: float | None,
             max_angular: float | None, controllers_file: str | None,
             camera_scale: float | None, camera_rate_hz: float | None,
             camera_depth: bool, speed: float,
             expectations: tuple[Expectation, ...], allow_collisions: bool, srdf: str | None,
             progress: bool | None, fmt: str) -> None:
    """Simulate the robot's base, arm and sensors, headless and fast.

    Drives the diff-drive base with the scenario's timed cmd_vel, moves the arm along its
    joint_trajectory, and simulates the LIDAR, IMU, wheel odometry, joint states and
    camera_info as the URDF's <gazebo> sensors describe them; with --camera-scale or
    --camera-rate-hz (or the scenario's camera:) also the camera's images. Prints a
    summary; --out, --bag and --plot write files (atomically). Same --seed, same bytes.

    \b
    Examples:
      servicebot simulate --headless
      servicebot simulate --headless -s run.yaml --out results --bag run_bag --plot run.png
      servicebot simulate --headless --saturation per-wheel --format json
      servicebot simulate --headless --camera-scale 0.125 --camera-rate-hz 5 --bag run_bag
    """
    from servicebot_cli.output.simulate_text import show_simulation
    from servicebot_cli.simulate import session
    from servicebot_cli.simulate.session import Outputs, Overrides, SimulateRequest

    _refuse_without_effect(headless, out_dir, bag)
    overrides = Overrides(duration_s=duration_s, saturation=saturation,
                          wheel_separation_multiplier=wheel_separation_multiplier,
                          cmd_vel_timeout_s=cmd_vel_timeout_s,
                          max_linear_acceleration_m_s2=max_linear,
                          max_angular_acceleration_rad_s2=max_angular,
                          controllers_file=controllers_file, camera_scale=camera_scale,
                          camera_rate_hz=camera_rate_hz, camera_depth=camera_depth or None)
    request = SimulateRequest(robot_args.source(), scenario_file, overrides, seed,
                              Outputs(out_dir, bag, plot), live_window=not headless,
                              progress=progress, expectations=expectations,
                              allow_collisions=allow_collisions, srdf=srdf)
    from servicebot_cli.simulate.heap import keep_freed_memory

    keep_freed_memory()  # this process is the run's: its temporaries reuse the heap's pages
    report = session.run(request, stderr=sys.stderr)
    for note in report.notes:
        click.echo(note, err=True)
    show_simulation(report, fmt)
    if report.live_track is not None:  # gathered for the live window (not --headless)
        from servicebot_cli.simulate.files.live import show

        show(report.live_track, speed=speed)
    if report.unmet:
        from servicebot_cli.output.simulate_text import unmet_line

        raise AnswerIsNo(unmet_line(report))


def _refuse_without_effect(headless: bool, out_dir: str | None, bag: str | None) -> None:
    """Refuse ``--speed`` with ``--headless``, and one directory for ``--out`` and ``--bag``."""
    ctx = click.get_current_context()
    refuse_with(ctx, "--speed", "--headless", present=headless,
                why="it is the live window's playback speed")
    if out_dir is not None and bag is not None \
            and Path(out_dir).resolve() == Path(bag).resolve():
        raise click.BadParameter(f"'{bag}' is also the --out directory; give the bag its own "
                                 "path", ctx=ctx, param_hint="--bag")


def _print_scenario(ctx: click.Context) -> None:
    """Write the built-in scenario to stdout and end the command (``--print-scenario``)."""
    from servicebot_cli.simulate.scenario.definition import DEFAULT_SCENARIO

    click.echo(DEFAULT_SCENARIO.read_text(encoding="utf-8"), nl=False)
    ctx.exit(0)
