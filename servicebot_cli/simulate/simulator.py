"""One simulation run: the scenario's commands through the robot's controllers and sensors.

A run is simulated a stretch of control ticks at a time (a piece, :data:`PIECE_S` simulated
seconds by default). For each piece the base's wheel speeds are planned (commands are known
ahead), the ground truth follows them along exact arcs and the arm follows its reference,
each held where a step would put a link into an obstacle (:mod:`.world.blocking`), and every
sensor is sampled from that motion in whole batches. Every stage carries its state to the
next piece (the limiter's last commands, the integrators' running sums, each noise
generator, the contact and clearance records), so the pieces hold the same bits as the run
computed in one piece, and memory stays flat however long the run is. Pure: the robot, the
scenario and the seed in, :class:`SimResult` pieces out.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Generator, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.forked import Worker, second_core
from servicebot_cli.description.sensors import CameraSpec, ImuSpec, LidarSpec
from servicebot_cli.kinematics import diff_drive
from servicebot_cli.simulate.body import Mounted, SimRobot
from servicebot_cli.simulate.controllers.arm_trajectory import ArmLimits, ArmMotion
from servicebot_cli.simulate.controllers.classic_drive import ENCODER, NEITHER, WORLD
from servicebot_cli.simulate.controllers.config import GAZEBO_STEP_HZ
from servicebot_cli.simulate.controllers.controller_wheels import ControllerWheels
from servicebot_cli.simulate.controllers.diff_drive import WheelPlan, WheelPlanner
from servicebot_cli.simulate.model_facts import FactsAhead
from servicebot_cli.simulate.pose_work import FromPoses, PoseJob, PoseWork
from servicebot_cli.simulate.scenario.definition import Scenario
from servicebot_cli.simulate.scenario.located import ScenarioError
from servicebot_cli.simulate.scenario.world_check import camera_rate_limit, check_scenario
from servicebot_cli.simulate.self_contact import SelfContact, SelfContactWatch
from servicebot_cli.simulate.sensors import camera_info, imu, joint_states, lidar, odometry
from servicebot_cli.simulate.sensors.noise import Noise, stream_rng
from servicebot_cli.simulate.sensors.sample import SampleClock, sample_count
from servicebot_cli.simulate.sensors.scan_jobs import ScanCaster, fixed_ranges_of
from servicebot_cli.simulate.shape_memo import TransformMemo
from servicebot_cli.simulate.world import blocking, motion
from servicebot_cli.simulate.world.clearance import Closest
from servicebot_cli.simulate.world.clearance_record import NO_CLEARANCE, ClearanceRecord
from servicebot_cli.simulate.world.contacts import Placed, Tester, obstacles
from servicebot_cli.simulate.world.raycast import Mesh
from servicebot_cli.simulate.world.solids import Solid

if TYPE_CHECKING:  # the camera's modules are imported only for runs that render images
    from servicebot_cli.simulate.sensors.camera_image import Frame
    from servicebot_cli.simulate.sensors.camera_stream import CameraStream

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
PIECE_S = 30.0
"""Simulated seconds per piece: long enough for numpy to work in bulk, short for memory."""
SCAN_PIECE_BYTES = 256_000_000
"""At most about this many bytes of scans in one piece (pieces are cut shorter)."""
SCAN_BYTES = 32
"""Bytes a piece holds per ray and scan: true ranges, noise, readings, their temporaries."""
AHEAD = 3
"""Pieces the simulator may run ahead of the worker doing their pose work: the worker's
first pieces are its slowest (the first clearance search, its first calls), and the
simulator no longer waits for them after its third piece. Two when pieces are cut for their
scans' size, so that those in memory stay within three times :data:`SCAN_PIECE_BYTES`."""
WHOLE_RUN_FRAME_BYTES = 2_000_000_000
"""At most this many bytes of camera frames in a run computed in one piece."""


@dataclass(frozen=True, eq=False)
class SimResult:
    """What a run produced over ticks ``first_tick`` .. ``first_tick + plan.ticks - 1``.

    A piece of the run, or all of it (``first_tick`` 0 and ``run_ticks`` ticks). Arrays at
    tick boundaries hold the piece's ticks and the boundary after its last; samples are
    those the piece's ticks hold. ``contacts`` and ``self_contacts`` began in the piece;
    ``closest`` is the record so far, over this piece and the ones before it. ``camera``
    describes the rendered images when the run renders them (``frames``, one per
    ``camera_times_s``), else the URDF's full-size camera.
    """

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
    closest: Closest  # its index is a tick, its part indexes body.shape.parts
    scans: tuple[lidar.Scans, ...]  # one per body.ray_sensors, in that order
    imu: imu.ImuSamples | None
    camera: camera_info.Intrinsics | None
    camera_times_s: FloatArray
    first_tick: int
    run_ticks: int
    frames: tuple[Frame, ...] = ()

    @property
    def first(self) -> bool:
        """This piece starts the run."""
        return self.first_tick == 0

    @property
    def last(self) -> bool:
        """This piece ends the run."""
        return self.first_tick + self.plan.ticks >= self.run_ticks


def pieces(body: SimRobot, scenario: Scenario, *, seed: int, solids: Sequence[Solid],
           meshes: Sequence[Mesh] = (), piece_s: float = PIECE_S,
           facts: FactsAhead | None = None) -> Generator[SimResult, None, None]:
    """Simulate ``scenario`` a piece of ``piece_s`` simulated seconds at a time.

    The scenario is checked against the robot and the world before the first piece. Pieces
    with camera frames are cut shorter so that their frames stay within
    :data:`~servicebot_cli.simulate.sensors.camera_stream.PIECE_BYTES`, and those of many
    rays so that their scans stay within :data:`SCAN_PIECE_BYTES`. With more than one
    piece and a second core, what each piece computes from its poses alone (its LIDAR
    scans and self contacts, :mod:`.pose_work`) is done by a forked worker process
    (:mod:`~servicebot_cli.common.forked`) while the next piece is simulated: the process
    that worked out ``facts``, when there is one, else one forked now. It is stopped and
    reaped when the pieces end or fail, or when the generator is closed (close it to stop
    it at once).

    Raises:
        ScenarioError: The arm's goal, the start pose or the camera does not fit the robot
            or the world, or a run in one piece would hold too many camera frames.
    """
    run = _Run(body, scenario, seed, list(solids), meshes)
    step = max(1, round(piece_s / run.dt_s)) if math.isfinite(piece_s) else run.ticks
    scan_bytes_s = sum(SCAN_BYTES * lidar.ray_count(m.spec) * clock.rate_hz
                       for m, clock in zip(body.ray_sensors, run.scan_clocks, strict=True))
    ahead = AHEAD
    if scan_bytes_s and math.isfinite(piece_s):  # a piece's ranges within SCAN_PIECE_BYTES
        cut = max(1, int(SCAN_PIECE_BYTES / scan_bytes_s / run.dt_s))
        ahead = AHEAD if cut > step else AHEAD - 1
        step = min(step, cut)
    if run.images is not None and math.isfinite(piece_s):  # frames kept within PIECE_BYTES
        from servicebot_cli.simulate.sensors.camera_stream import PIECE_BYTES

        frames = max(1, PIECE_BYTES // run.images.frame_bytes)
        step = min(step, max(1, int(frames / run.clocks["camera"].rate_hz / run.dt_s)))
    elif run.images is not None:
        _refuse_frames_beyond_memory(run.clocks["camera"].count * run.images.frame_bytes)
    firsts = range(0, run.ticks, step)
    name = "simulation's worker"
    poses = facts.take_over(run.from_poses, run.from_poses.prepare, name) \
        if facts is not None and len(firsts) > 1 else None
    if poses is None:
        poses = Worker(run.from_poses, forked=len(firsts) > 1 and second_core(), name=name,
                       prepare=run.from_poses.prepare)
    # forked: a piece's pose work is done while the next pieces run, up to AHEAD of them
    # (one with camera frames, which are most of a piece's memory)
    ahead = 0 if poses.pid is None else 1 if run.images is not None else ahead
    try:
        begun: list[SimResult] = []
        for first in firsts:
            begun.append(run.piece(range(first, min(first + step, run.ticks)), poses))
            if first == firsts[-1]:
                poses.no_more_jobs()
            if len(begun) > ahead:
                yield run.finish(begun.pop(0), poses)
        while begun:
            yield run.finish(begun.pop(0), poses)
        poses.close(finished=True)
    finally:
        poses.close()  # at once on an error, or when the pieces are left unread


def _refuse_frames_beyond_memory(total_bytes: int) -> None:
    """A run kept whole (for the live window) holds every frame: refuse more than that.

    Raises:
        ScenarioError: The frames would take more than :data:`WHOLE_RUN_FRAME_BYTES`.
    """
    if total_bytes > WHOLE_RUN_FRAME_BYTES:
        raise ScenarioError(
            f"the run's camera images would take {total_bytes / 1e9:.1f} GB, and a run kept "
            f"whole for the live window holds them all (at most "
            f"{WHOLE_RUN_FRAME_BYTES / 1e9:g} GB); use --headless, or a smaller camera "
            "scale or rate")


def run(body: SimRobot, scenario: Scenario, *, seed: int, solids: Sequence[Solid],
        meshes: Sequence[Mesh] = ()) -> SimResult:
    """Simulate ``scenario`` in one piece: every tick of the run in memory at once."""
    [whole] = pieces(body, scenario, seed=seed, solids=solids, meshes=meshes,
                     piece_s=math.inf)
    return whole


class _Run:
    """The state of a run between pieces."""

    def __init__(self, body: SimRobot, scenario: Scenario, seed: int, solids: list[Solid],
                 meshes: Sequence[Mesh]) -> None:
        self.body, self.scenario, self.seed, self.solids = body, scenario, seed, solids
        self.meshes = meshes
        self.tester = Tester(body.shape, obstacles(solids, meshes))
        self.transforms = TransformMemo(body.shape)  # the parts at a piece's configurations
        arm_q0 = check_scenario(body, scenario, solids, meshes, self.tester)
        geometry, ctrl, start = body.geometry, scenario.controller, scenario.initial_pose
        self.planner = WheelPlanner(scenario.cmd_vel, ctrl, geometry, scenario.duration_s,
                                    scenario.speed_limiter, scenario.classic_drive)
        self.dt_s, self.ticks = self.planner.dt_s, self.planner.ticks
        self.arm = _arm_motion(body, scenario, arm_q0, self.dt_s)
        self.motion = blocking.BlockedMotion((start.x_m, start.y_m, start.yaw_rad), self.dt_s,
                                             [o.name for o in self.tester.world],
                                             body.shape.links, self.arm)
        self.odometer = odometry.Odometer(self.dt_s, ControllerWheels.of(ctrl, geometry))
        self.wheel_angles = np.zeros(2)  # left, right at the piece's first boundary [rad]
        self.wheel_sums = np.array([-0.0, -0.0])  # -0.0 + v == v: an empty running sum
        self.twist_before = (0.0, 0.0)  # the followed twist of the tick before the piece
        duration = scenario.duration_s
        self.clocks = {
            "odometry": SampleClock(ctrl.publish_rate_hz, duration, self.dt_s),
            "joints": SampleClock(scenario.rates.joint_states_hz, duration, self.dt_s)}
        self.scan_clocks = [SampleClock(_rate(mounted.spec, scenario), duration, self.dt_s)
                            for mounted in body.ray_sensors]
        fixed = fixed_ranges_of(body.ray_sensors, body.shape)
        casters = tuple(
            ScanCaster(mounted, body.shape, body.base_height_m, solids, meshes,
                       Noise(mounted.spec.noise, stream_rng(seed, scan_stream(index, mounted))),
                       clock.period_s, fixed[index])
            for index, (mounted, clock) in enumerate(zip(body.ray_sensors, self.scan_clocks,
                                                         strict=True)))
        self.from_poses = PoseWork(
            body.shape, casters,
            SelfContactWatch(body.robot, body.shape, body.base_height_m, self.dt_s,
                             body.disabled_pairs, body.resolver) if body.arm_joints else None,
            ClearanceRecord(self.tester, body.base_height_m))
        self.imu_noise: list[Noise] = []
        if body.imu is not None:
            rate = _rate(body.imu.spec, scenario)
            self.clocks["imu"] = SampleClock(rate, duration, self.dt_s)
            self.imu_noise = imu.axis_noises(body.imu.spec, stream_rng(seed, "imu"),
                                             sample_count(rate, duration))
        self.camera = camera_info.intrinsics(body.camera.spec) if body.camera else None
        self.images: CameraStream | None = None
        if body.camera is not None:
            rate = _rate(body.camera.spec, scenario)
            if scenario.camera.enabled:
                from servicebot_cli.simulate.sensors.camera_stream import CameraStream

                self.images = CameraStream(body, scenario.camera, seed, solids, meshes)
                self.camera = self.images.intrinsics
                rate = scenario.camera.rate_hz or camera_rate_limit(body, scenario)[0]
            self.clocks["camera"] = SampleClock(rate, duration, self.dt_s)

    def piece(self, ticks: range, poses: Worker[PoseJob, FromPoses]) -> SimResult:
        """Simulate ``ticks``, the ticks after those of the pieces before, but its pose work.

        What comes from the piece's poses alone is handed to ``poses`` (the piece's scans,
        self contacts and clearance are left empty until :meth:`finish` puts them in), so
        that it is done while the next piece is simulated.
        """
        body, first = self.body, ticks.start
        stop = None if ticks.stop >= self.ticks else ticks.stop  # None: every sample left
        plan = self.planner.plan(ticks)
        self.transforms.clear()
        truth, arm_q, contacts = self._ground_truth(first, plan)
        poses.submit(PoseJob(first, truth, arm_q,
                             tuple(clock.take(stop) for clock in self.scan_clocks)))
        sides = self._wheel_angles(plan)
        odom_path, odom_before = self.odometer.advance(first, plan.left_rad_s, plan.right_rad_s)
        odom_times = self.clocks["odometry"].take(stop)
        source = self.scenario.classic_drive.odometry_source if self.scenario.classic_drive \
            else ENCODER  # diff_drive_controller and gz-sim integrate the wheels
        if source == WORLD:
            odom = odometry.in_world(truth, odom_times, self.twist_before, body.base_height_m)
        elif source == NEITHER:
            odom = odometry.at_rest(odom_times)
        else:
            odom = odometry.published(odom_path, odom_times, odom_before)
        names, positions = _joint_positions(body, sides, arm_q)
        camera_times = self.clocks["camera"].take(stop) if "camera" in self.clocks \
            else np.zeros(0)
        piece = SimResult(
            body, self.scenario, self.seed, self.solids, [o.name for o in self.tester.world],
            plan, truth, contacts, [],
            sides, odom,
            joint_states.at_times(names, positions, self.dt_s,
                                  self.clocks["joints"].take(stop), first),
            arm_q, NO_CLEARANCE, (),
            self._imu(truth, stop), self.camera, camera_times, first, self.ticks,
            self.images.frames(truth, arm_q, camera_times) if self.images else ())
        self.twist_before = (float(truth.linear_m_s[-1]), float(truth.angular_rad_s[-1]))
        return piece

    def finish(self, piece: SimResult, poses: Worker[PoseJob, FromPoses]) -> SimResult:
        """``piece`` from :meth:`piece` with what ``poses`` owes for it (the oldest it owes)."""
        done = poses.result()
        return dataclasses.replace(piece, scans=done.scans, self_contacts=done.self_contacts,
                                   closest=done.closest)

    def _ground_truth(self, first: int,
                      plan: WheelPlan) -> tuple[motion.Path2D, FloatArray, list[motion.Contact]]:
        """The base's and the arm's real motion, each held where it would touch an obstacle.

        The base follows the wheel speeds through the floor's slip. Returns the path, the
        arm's positions at the piece's boundaries (n+1, J) and the contacts that began.
        """
        body, slip = self.body, self.scenario.slip
        left_m, right_m = body.geometry.side_radii_m  # unequal sides: the base curves
        linear, angular = diff_drive.rolled_twist(
            plan.left_rad_s, plan.right_rad_s,  # type: ignore[arg-type]  # typed for floats
            left_radius_m=left_m, right_radius_m=right_m,
            track_m=body.geometry.track_m * slip.track_factor)
        keep = 1.0 - slip.longitudinal
        height = body.base_height_m

        def collides(q: FloatArray, x: FloatArray, y: FloatArray,
                     yaw: FloatArray) -> tuple[IntArray, IntArray]:
            return self.tester.first_hits(Placed(self.transforms(q), x, y, yaw, height))

        return self.motion.advance(first, np.asarray(linear) * keep, np.asarray(angular) * keep,
                                   collides)

    def _wheel_angles(self, plan: WheelPlan) -> FloatArray:
        """Left and right side angles at the piece's tick boundaries, shape (n+1, 2)."""
        turned = np.column_stack((plan.left_rad_s, plan.right_rad_s)) * plan.dt_s
        sums = np.cumsum(np.vstack((self.wheel_sums, turned)), axis=0)
        angles = np.vstack((self.wheel_angles, sums[1:]))
        self.wheel_sums = self.wheel_angles = sums[-1]
        return angles

    def _imu(self, truth: motion.Path2D, stop: int | None) -> imu.ImuSamples | None:
        mounted = self.body.imu
        if mounted is None:
            return None
        return imu.measure(mounted.spec, mounted.transform_sensor_to_base, truth,
                           self.clocks["imu"].take(stop), self.imu_noise, self.twist_before)


def _arm_motion(body: SimRobot, scenario: Scenario, q0: FloatArray, dt_s: float) -> ArmMotion:
    """The arm's joints (URDF order) following the scenario's trajectory within their limits."""
    space = body.joint_space
    index = [space.index(name) for name in body.arm_joints]
    limits = ArmLimits(space.lower[index], space.upper[index], space.velocity[index])
    order = [body.arm_joints.index(name) for name in scenario.arm.joint_names]
    return ArmMotion(scenario.arm, order, q0, limits, dt_s, body.arm_mimics)


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
    # a <mimic> of a wheel turns with it (those of the arm's joints are set already)
    return names, body.joint_mimics.applied(np.column_stack(columns))


def scan_stream(index: int, mounted: Mounted[LidarSpec]) -> str:
    """The name of ray sensor ``index``'s noise stream.

    The first (the one with the most rays, :attr:`SimRobot.ray_sensors`) draws from
    ``scan``, as the only ray sensor always did; each other from one named after its topic,
    its link and its name (a PMB2's three sonars share a topic; two sensors may share a
    link), so that a sensor with fewer rays more or less leaves the others' noise as it was.
    """
    if index == 0:
        return "scan"
    return f"scan {mounted.spec.topic} on {mounted.link}: {mounted.name}"


def _rate(spec: LidarSpec | ImuSpec | CameraSpec, scenario: Scenario) -> float:
    """A sensor's update rate [Hz], at most :data:`GAZEBO_STEP_HZ`.

    Without one (or with 0 or less, or not a number) Gazebo updates it every physics step;
    here every tick.
    """
    rate = spec.update_rate_hz
    if rate is None or not rate > 0:
        return float(scenario.controller.update_rate_hz)
    return float(min(rate, GAZEBO_STEP_HZ))
