"""Checks of a scenario against the robot and the world, with the scenario line of each fault.

The scenario's own checks need no robot; these do: the arm's joint names and limits come
from the URDF, and the start pose must leave every link clear of every obstacle.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.errors import NameNotFound
from servicebot_cli.description.sensors import CAMERA_TYPES
from servicebot_cli.simulate.body import SimRobot
from servicebot_cli.simulate.scenario.definition import Scenario
from servicebot_cli.simulate.scenario.located import Located, ScenarioError
from servicebot_cli.simulate.world.contacts import Tester, obstacles, posed_parts
from servicebot_cli.simulate.world.raycast import Mesh
from servicebot_cli.simulate.world.solids import Solid

FloatArray = npt.NDArray[np.float64]


def _error(scenario: Scenario, path: tuple[str | int, ...], message: str) -> ScenarioError:
    located = scenario.source or Located({}, {}, scenario.name)
    return located.error(path, message)


def check_scenario(body: SimRobot, scenario: Scenario, solids: Sequence[Solid],
                   meshes: Sequence[Mesh], tester: Tester | None = None) -> FloatArray:
    """Check the arm goal and the start pose; return the arm's start positions [rad].

    ``tester`` holds the solids and meshes already (built from them when None).

    Raises:
        ScenarioError: An unknown or wheel joint, a position outside its limits, a start
            pose where a link touches an obstacle, or camera images asked of a robot
            without a camera or faster than its camera's update rate.
    """
    q0 = _check_arm(body, scenario)
    _check_camera(body, scenario)
    if tester is None:
        tester = Tester(body.shape, obstacles(solids, meshes))
    start = scenario.initial_pose
    posed = posed_parts(body.shape, np.array([start.x_m]), np.array([start.y_m]),
                        np.array([start.yaw_rad]), body.base_height_m, q0[None, :])
    obstacle, part = tester.first_hits(posed)
    if obstacle[0] >= 0:
        raise _error(scenario, ("initial_pose",), f"the robot's {body.shape.links[part[0]]} "
                     f"touches {tester.world[obstacle[0]].name}; start it somewhere clear")
    return q0


def check_arm_points(body: SimRobot, scenario: Scenario) -> None:
    """Refuse a trajectory point that puts links of the robot into each other or the floor.

    The check and the words are ``ik``'s and ``drive --arm``'s (the pairs ``ik`` leaves out,
    and ``body.disabled_pairs``); the arm's way between points is what the run logs as self
    collisions. Joints the trajectory does not name stay where the run starts them.

    Raises:
        ScenarioError: A point in collision, with its line in the scenario.
    """
    trajectory = scenario.arm
    if not trajectory.points:
        return
    from servicebot_cli.simulate.self_contact import SelfContactWatch

    q0 = _check_arm(body, scenario)
    columns = [body.arm_joints.index(name) for name in trajectory.joint_names]
    points = np.repeat(q0[None], len(trajectory.points), axis=0)
    points[:, columns] = [point.positions for point in trajectory.points]
    body.arm_mimics.applied(points)
    watch = SelfContactWatch(body.robot, body.shape, body.base_height_m, 1.0,
                             body.disabled_pairs, body.resolver)
    events = watch.advance(0, points)  # one point per "tick": an event's time is its index
    if not events:
        return
    from servicebot_cli.kinematics.collisions import Contact
    from servicebot_cli.kinematics.diagnosis import ways_out

    k = round(events[0].time_s)
    contact = Contact(events[0].first, events[0].second)
    typed = " ".join(f"{name}={value:g}" for name, value
                     in zip(trajectory.joint_names, trajectory.points[k].positions, strict=True))
    raise _error(scenario, ("arm", "points", k), (
        f"arm point {typed} is reachable only through a collision: {contact} would "
        f"intersect; {ways_out(contact)}"))


def _check_arm(body: SimRobot, scenario: Scenario) -> FloatArray:
    space = body.joint_space
    index = [space.index(n) for n in body.arm_joints]
    lower, upper = space.lower[index], space.upper[index]
    q0 = np.clip(np.zeros(len(index)), np.nan_to_num(lower, nan=-np.inf),
                 np.nan_to_num(upper, nan=np.inf))
    trajectory = scenario.arm
    for i, name in enumerate(trajectory.joint_names):
        if name not in body.arm_joints:
            wheel = name in {w.joint for w in body.geometry.wheels}
            reason = ("is a wheel; wheels follow cmd_vel" if wheel else
                      str(NameNotFound.for_name(name, body.arm_joints)).replace("no name ", "")
                      if body.arm_joints else f"'{name}'; {body.robot.name or 'the robot'} has no "
                      "movable joints but its wheels (leave out arm:)")
            raise _error(scenario, ("arm", "joint_names", i), f"'{name}' {reason}"
                         if wheel else f"unknown arm joint: {reason}")
    for i, name in enumerate(trajectory.joint_names):
        refusal = _follower_refusal(body, name)
        if refusal:
            raise _error(scenario, ("arm", "joint_names", i), refusal)
    mimics = body.arm_mimics
    for p, point in enumerate(trajectory.points):
        for i, name in enumerate(trajectory.joint_names):
            j = body.arm_joints.index(name)
            value, lo, hi = point.positions[i], lower[j], upper[j]
            if not math.isnan(lo) and not lo - 1e-9 <= value <= hi + 1e-9:
                raise _error(scenario, ("arm", "points", p, "positions", i),
                             f"{name} = {value:g} rad is outside its URDF limits "
                             f"[{lo:g}, {hi:g}] rad")
    return mimics.applied(q0)


def _follower_refusal(body: SimRobot, name: str) -> str:
    """Why the arm joint ``name`` cannot be commanded: it follows another (``<mimic>``).

    Empty when it can: no mimic, or one of a joint that does not move (fixed, unknown).
    """
    leaders = {j.name: j.mimic.joint for j in body.robot.joints if j.mimic is not None}
    if name not in leaders:
        return ""
    chain, root = [name], leaders[name]
    while root in leaders and root not in chain:
        chain.append(root)
        root = leaders[root]
    if root in chain:
        return (f"'{name}' is in a loop of <mimic> joints ({' -> '.join([*chain, root])}); "
                "give one of them no <mimic> ('servicebot check' shows the loop)")
    if root not in body.joint_space.names:
        return ""
    joint = next(j for j in body.robot.joints if j.name == name)
    assert joint.mimic is not None
    rule = f"'{name}' mimics '{joint.mimic.joint}' (x {joint.mimic.multiplier:g} + " \
        f"{joint.mimic.offset:g})"
    if root in {w.joint for w in body.geometry.wheels}:
        return f"{rule} and turns with the wheel '{root}'; leave it out of arm:"
    return f"{rule} and moves with it; move '{root}' instead"


def _check_camera(body: SimRobot, scenario: Scenario) -> None:
    """Images need a camera; their rate is at most its update rate and the control rate."""
    images = scenario.camera
    if not images.enabled:
        return
    cli = images.from_cli
    if body.camera is None:
        message = f"camera images asked, but {_no_camera(body)}"
        if cli:
            raise ScenarioError(f"--camera-scale/--camera-rate-hz/--camera-depth: {message}")
        raise _error(scenario, ("camera",), message)
    limit, what = camera_rate_limit(body, scenario)
    if images.rate_hz is not None and images.rate_hz > limit + 1e-9:
        message = f"{images.rate_hz:g} Hz is above {what} ({limit:g} Hz)"
        if "rate_hz" in cli:
            raise ScenarioError(f"--camera-rate-hz: {message}")
        raise _error(scenario, ("camera", "rate_hz"), message)


def _no_camera(body: SimRobot) -> str:
    """Why a run has no camera: none, one it cannot image, or one that nothing publishes."""
    robot = body.robot
    if body.camera_left_out is not None:
        return body.camera_left_out
    unpublished = next((s for s in robot.sensors if s.type in CAMERA_TYPES), None)
    if unpublished is None:
        return f"{robot.display} has no camera sensor"
    return (f"nothing publishes camera sensor '{unpublished.name}' (link "
            f"{unpublished.reference}) of {robot.display}; "
            f"add a gazebo_ros_camera plugin (libgazebo_ros_camera.so) to its <sensor>, "
            f"or a <topic> for gz-sim")


def camera_rate_limit(body: SimRobot, scenario: Scenario) -> tuple[float, str]:
    """The highest camera rate a run can have [Hz], and what sets it.

    The URDF camera's ``<update_rate>`` when it has one below the control rate, else the
    control rate (Gazebo updates a sensor without a rate every step).
    """
    control = scenario.controller.update_rate_hz
    urdf = body.camera.spec.update_rate_hz if body.camera is not None else None
    if urdf and urdf < control:
        return float(urdf), "the URDF camera's update rate"
    return control, "the control rate (controller.update_rate_hz)"
