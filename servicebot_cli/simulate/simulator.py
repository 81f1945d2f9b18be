"""One simulation run: the scenario's commands through the robot's controllers and sensors.

The base's wheel speeds are planned for every control tick first (commands are known ahead),
the ground truth follows them along exact arcs until an obstacle stops it, and every sensor is
then sampled from that motion in whole batches. Pure: the robot, the scenario and the seed
in, a :class:`SimResult` out; progress is reported through an optional callback.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.description.sensors import CameraSpec, ImuSpec, LidarSpec
from servicebot_cli.kinematics import diff_drive
from servicebot_cli.simulate.body import SimRobot
from servicebot_cli.simulate.controllers import arm_trajectory as arm
from servicebot_cli.simulate.controllers.diff_drive import WheelPlan, plan_wheels
from servicebot_cli.simulate.scenario.definition import Scenario
from servicebot_cli.simulate.scenario.world_check import check_scenario
from servicebot_cli.simulate.self_contact import SelfContact, self_contacts
from servicebot_cli.simulate.sensors import camera_info, imu, joint_states, lidar, odometry
from servicebot_cli.simulate.sensors.noise import stream_rng
from servicebot_cli.simulate.sensors.sample import sample_times
from servicebot_cli.simulate.world import motion
from servicebot_cli.simulate.world.contacts import Closest, Tester, closest, obstacles, posed_parts
from servicebot_cli.simulate.world.raycast import Mesh
from servicebot_cli.simulate.world.solids import Solid

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True, eq=False)
class SimResult:
    """Everything a run produced; writers and the summary read from here."""

    body: SimRobot
    scenario: Scenario
    seed: int
    solids: list[Solid]
    obstacle_names: list[str]
    plan: WheelPlan
    truth: motion.Path2D
    contacts: list[motion.Contact]
    self_contacts: list[SelfContact]
    wheel_angles_rad: FloatArray  # (n+1, 2): left, right side angle at tick boundaries
    odometry: odometry.Odometry
    joints: joint_states.JointStates
    arm_positions_rad: FloatArray  # (n+1, arm joints) at tick boundaries
    closest: Closest  # over tick boundaries; its part indexes body.shape.parts
    scans: lidar.Scans | None
    imu: imu.ImuSamples | None
    camera: camera_info.Intrinsics | None
    camera_times_s: FloatArray


def run(body: SimRobot, scenario: Scenario, *, seed: int, solids: Sequence[Solid],
        meshes: Sequence[Mesh] = (), progress: Callable[[int], None] | None = None) -> SimResult:
    """Simulate ``scenario``; ``progress`` is told how many LIDAR scans were cast."""
    solids = list(solids)
    tester = Tester(body.shape, obstacles(solids, meshes))
    arm_q0 = check_scenario(body, scenario, solids, meshes, tester)
    geometry, ctrl = body.geometry, scenario.controller
    plan = plan_wheels(scenario.cmd_vel, ctrl, geometry, scenario.duration_s)
    dt, n = plan.dt_s, plan.ticks
    ticks = np.arange(n + 1, dtype=np.float64) * dt
    arm_q = _arm_positions(body, scenario, arm_q0, ticks, dt)
    truth, contacts = _ground_truth(body, scenario, plan, tester, arm_q)
    sides = np.vstack((np.zeros((1, 2)), np.cumsum(np.column_stack((plan.left_rad_s,
                                                                     plan.right_rad_s)) * dt, 0)))
    odom_path = odometry.dead_reckoning(
        plan.left_rad_s, plan.right_rad_s, dt, wheel_radius_m=geometry.wheel_radius_m,
        track_m=geometry.track_m * ctrl.wheel_separation_multiplier)
    names, positions = _joint_positions(body, sides, arm_q)
    publish = sample_times(ctrl.publish_rate_hz, scenario.duration_s)
    nearest = closest(tester, posed_parts(body.shape, truth.x_m, truth.y_m, truth.yaw_rad,
                                          body.base_height_m, arm_q))
    return SimResult(
        body, scenario, seed, solids, [o.name for o in tester.world], plan, truth, contacts,
        self_contacts(body.robot, body.shape, body.base_height_m, arm_q, dt)
        if body.arm_joints else [],
        sides,
        odometry.published(odom_path, publish),
        joint_states.at_times(names, positions, dt,
                              sample_times(scenario.rates.joint_states_hz, scenario.duration_s)),
        arm_q, nearest,
        _scans(body, scenario, truth, arm_q, solids, meshes, seed, progress),
        _imu(body, scenario, truth, seed),
        camera_info.intrinsics(body.camera.spec) if body.camera else None,
        sample_times(_rate(body.camera.spec, scenario), scenario.duration_s)
        if body.camera else np.zeros(0),
    )


def _ground_truth(body: SimRobot, scenario: Scenario, plan: WheelPlan, tester: Tester,
                  arm_q: FloatArray) -> tuple[motion.Path2D, list[motion.Contact]]:
    """The base's real motion: wheel speeds through the floor's slip, stopped by obstacles.

    Any link touching an obstacle (with the arm where it is at that tick) stops the base.
    """
    geometry, slip = body.geometry, scenario.slip
    linear, angular = diff_drive.body_twist(
        plan.left_rad_s, plan.right_rad_s,  # type: ignore[arg-type]  # body_twist is typed for floats
        wheel_radius_m=geometry.wheel_radius_m, track_m=geometry.track_m * slip.track_factor)
    keep = 1.0 - slip.longitudinal
    start = scenario.initial_pose

    def collides(ticks: npt.NDArray[np.int64], x: FloatArray, y: FloatArray,
                 yaw: FloatArray) -> tuple[npt.NDArray[np.int64], npt.NDArray[np.int64]]:
        return tester.first_hits(posed_parts(body.shape, x, y, yaw, body.base_height_m,
                                             arm_q[ticks]))

    return motion.integrate_blocked((start.x_m, start.y_m, start.yaw_rad),
                                    np.asarray(linear) * keep, np.asarray(angular) * keep,
                                    plan.dt_s, collides, [o.name for o in tester.world],
                                    body.shape.links)


def _arm_positions(body: SimRobot, scenario: Scenario, q0: FloatArray, ticks: FloatArray,
                   dt: float) -> FloatArray:
    space = body.joint_space
    index = [space.index(name) for name in body.arm_joints]
    limits = arm.ArmLimits(space.lower[index], space.upper[index], space.velocity[index])
    trajectory = scenario.arm
    if not trajectory.points:
        return np.broadcast_to(q0, (len(ticks), len(q0))).copy()
    order = [body.arm_joints.index(name) for name in trajectory.joint_names]
    ref = np.broadcast_to(q0, (len(ticks), len(q0))).copy()
    ref[:, order] = arm.reference(trajectory, q0[order], ticks)
    return arm.follow(ref, q0, limits, dt)


def _joint_positions(body: SimRobot, sides: FloatArray,
                     arm_q: FloatArray) -> tuple[tuple[str, ...], FloatArray]:
    """Every movable joint's position at tick boundaries, in URDF order."""
    names = body.joint_space.names
    columns = []
    wheels = {w.joint: w for w in body.geometry.wheels}
    for name in names:
        if name in wheels:
            wheel = wheels[name]
            columns.append(wheel.axis_sign * sides[:, 0 if wheel.side == "left" else 1])
        elif name in body.arm_joints:
            columns.append(arm_q[:, body.arm_joints.index(name)])
        else:
            columns.append(np.zeros(len(sides)))
    return names, np.column_stack(columns)


def _scans(body: SimRobot, scenario: Scenario, truth: motion.Path2D, arm_q: FloatArray,
           solids: list[Solid], meshes: Sequence[Mesh], seed: int,
           progress: Callable[[int], None] | None) -> lidar.Scans | None:
    """The LIDAR's scans: the world and the robot's own links (the arm where it is)."""
    if body.lidar is None:
        return None
    spec, mount = body.lidar.spec, body.lidar.transform_sensor_to_base
    times = sample_times(_rate(spec, scenario), scenario.duration_s)
    ticks = np.clip(np.floor(times / truth.dt_s + 1e-9).astype(np.int64), 0, len(arm_q) - 1)
    own = lidar.own_ranges(body.shape, body.lidar.link, mount,
                           lidar.ray_directions(spec, mount), arm_q[ticks])
    return lidar.scan(spec, mount, body.base_height_m, truth, times, solids, meshes,
                      stream_rng(seed, "scan"), progress, own)


def _imu(body: SimRobot, scenario: Scenario, truth: motion.Path2D,
         seed: int) -> imu.ImuSamples | None:
    if body.imu is None:
        return None
    spec = body.imu.spec
    times = sample_times(_rate(spec, scenario), scenario.duration_s)
    return imu.measure(spec, body.imu.transform_sensor_to_base, truth, times,
                       stream_rng(seed, "imu"))


def scan_count(body: SimRobot, scenario: Scenario) -> int:
    """How many scans a run will cast (the progress bar's length)."""
    if body.lidar is None:
        return 0
    return len(sample_times(_rate(body.lidar.spec, scenario), scenario.duration_s))


def _rate(spec: LidarSpec | ImuSpec | CameraSpec, scenario: Scenario) -> float:
    """A sensor's update rate [Hz]; without one Gazebo updates every step, here every tick."""
    return float(spec.update_rate_hz or scenario.controller.update_rate_hz)
