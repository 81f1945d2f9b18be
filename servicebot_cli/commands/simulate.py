"""``servicebot simulate``: the headless kinematic simulator."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from servicebot_cli.commands.command import Command
from servicebot_cli.commands.options import Number, RobotArgs, format_option, robot_arguments
from servicebot_cli.common.errors import ServicebotError


@click.command(cls=Command)
@robot_arguments()
@click.option("-s", "--scenario", "scenario_file", type=click.Path(dir_okay=False),
              help="Scenario file, YAML or JSON (default: the built-in loop in a room).")
@click.option("--headless", is_flag=True, help="No window: simulate, write outputs, print.")
@click.option("--out", "out_dir", type=click.Path(file_okay=False),
              help="Write one CSV per stream and summary.json into this directory.")
@click.option("--bag", type=click.Path(), help="Write a ROS 2 bag (MCAP storage) directory.")
@click.option("--plot", type=click.Path(dir_okay=False), help="Save a picture of the run (PNG).")
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
@click.option("--speed", type=Number(positive=True), default=1.0,
              show_default=True, help="Playback speed of the live window.")
@click.option("--progress/--no-progress", default=None,
              help="Progress bar on stderr  [default: on a terminal, outside CI].")
@format_option
def simulate(robot_args: RobotArgs, scenario_file: str | None, headless: bool,
             out_dir: str | None, bag: str | None, plot: str | None, seed: int,
             duration_s: float | None, wheel_separation_multiplier: float | None,
             saturation: str | None, cmd_vel_timeout_s: float | None, max_linear: float | None,
             max_angular: float | None, speed: float, progress: bool | None, fmt: str) -> None:
    """Simulate the robot's base, arm and sensors, headless and fast.

    Drives the diff-drive base with the scenario's timed cmd_vel, moves the arm along its
    joint_trajectory, and simulates the LIDAR, IMU, wheel odometry, joint states and
    camera_info as the URDF's <gazebo> sensors describe them. Prints a summary; --out,
    --bag and --plot write files (atomically). Same --seed, same bytes.

    \b
    Examples:
      servicebot simulate --headless
      servicebot simulate --headless -s run.yaml --out results --bag run_bag --plot run.png
      servicebot simulate --headless --saturation per-wheel --format json
    """
    from servicebot_cli.description.loader import load
    from servicebot_cli.simulate.files.live import display_problem
    from servicebot_cli.simulate.scenario.definition import load_scenario
    from servicebot_cli.simulate.session import Outputs, simulate_and_write, with_overrides

    robot = load(robot_args.source())
    scenario = with_overrides(
        load_scenario(scenario_file), duration_s, saturation=saturation,
        wheel_separation_multiplier=wheel_separation_multiplier,
        cmd_vel_timeout_s=cmd_vel_timeout_s, max_linear_acceleration_m_s2=max_linear,
        max_angular_acceleration_rad_s2=max_angular)
    problem = "" if headless else display_problem()
    if problem:  # checked after the input, before any work
        raise ServicebotError(f"{problem}; use --headless (with --plot FILE.png for a picture)")
    base_dir = Path(scenario_file).parent if scenario_file else Path.cwd()
    report = simulate_and_write(robot, scenario, seed=seed, outputs=Outputs(out_dir, bag, plot),
                                scenario_dir=base_dir, stderr=sys.stderr,
                                progress=progress)
    _print(report, fmt)
    if not headless:
        from servicebot_cli.simulate.files.live import show

        show(report.result, speed=speed)


def _print(report: object, fmt: str) -> None:
    from servicebot_cli.common.jsonable import dumps
    from servicebot_cli.output.simulate_text import summary_lines

    summary = report.summary  # type: ignore[attr-defined]
    if fmt == "json":
        click.echo(dumps(summary), nl=False)
    else:
        for line in summary_lines(summary):
            click.echo(line)
    rtf = summary["duration_s"] / max(report.wall_s, 1e-9)  # type: ignore[attr-defined]
    click.echo(f"simulated {summary['duration_s']:g} s in {report.wall_s:.2f} s "  # type: ignore[attr-defined]
               f"(real-time factor {rtf:.0f})", err=True)
