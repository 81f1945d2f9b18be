"""Gazebo Classic's ``gazebo_ros_diff_drive``: where its odometry comes from, how it ramps wheels.

Read in gazebo_ros_pkgs' ``gazebo_plugins/src/gazebo_ros_diff_drive.cpp`` (branches ``ros2``
and ``noetic-devel``):

- *Odometry source*: ``<odometry_source>`` (ROS 2, an integer: 0 ENCODER, 1 WORLD, default 1)
  or ``<odometrySource>`` (ROS 1: ``encoder`` or ``world``, default and fallback ``world``).
  WORLD publishes the model's true pose in the world (its start pose and the height of its
  origin included) and its world velocities turned into the base frame; ENCODER integrates
  the wheel speeds from zero.
- *Wheel acceleration*: ``<max_wheel_acceleration>`` (ROS 1 ``<wheelAcceleration>``, default
  0: none) bounds the change of each wheel's surface speed [m/s^2]. At each of the plugin's
  updates (``<update_rate>``, ROS 1 ``<updateRate>``, default 100 Hz) it compares the
  wanted speeds with the wheels' current ones: with no limit, or once both wheels (ROS 1:
  either wheel) are within 0.01 m/s of theirs, the wanted speeds are set as they are;
  otherwise a running command, starting at zero, moves by the difference clamped to
  ``+-acceleration * seconds since the last update``, and the wheels get that command.
- ``<max_wheel_torque>`` (ROS 1 ``<wheelTorque>``, default 5 N m) caps the joint motors'
  force; a kinematic simulation has no dynamics to cap, so it is only reported.

Pure.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

FloatArray = npt.NDArray[np.float64]
REACHED_M_S = 0.01
"""A wheel this close to its wanted surface speed [m/s] gets it exactly (the plugin's 0.01)."""
ENCODER, WORLD, NEITHER = "encoder", "world", "neither"
"""The odometry sources of :func:`odometry_source`."""


@dataclass(frozen=True)
class ClassicDrive:
    """What the Classic diff-drive plugin does beyond diff_drive_controller's parameters.

    Attributes:
        odometry_source: :data:`ENCODER`, :data:`WORLD`, or :data:`NEITHER` (a ROS 2
            ``odometry_source`` that is neither: the plugin never updates its odometry).
        wheel_acceleration_m_s2: Bound on each wheel's surface acceleration; 0: none.
        wheel_torque_nm: The motors' force cap (reported only: no dynamics here).
        update_rate_hz: How often the plugin commands the wheels; 0: every step.
        ros1: The ROS 1 plugin (either wheel reaching its speed ends the ramp; its update
            clock advances by whole periods, after more than one has passed).
    """

    odometry_source: str = WORLD
    wheel_acceleration_m_s2: float = 0.0
    wheel_torque_nm: float = 5.0
    update_rate_hz: float = 100.0
    ros1: bool = False


def odometry_source(text: str | None, *, ros1: bool) -> str:
    """What ``<odometry_source>`` (ROS 1: ``<odometrySource>``) text selects.

    ROS 2 reads an integer, 0 ENCODER and 1 WORLD (also when sdformat cannot read it as an
    integer: the default, 1); it casts any other integer to its source enum and then updates
    neither, so its odometry stays the message it started as, at the origin and at rest.
    ROS 1 reads ``encoder``; any other text keeps the default, WORLD.
    """
    value = (text or "").strip()
    if ros1:
        return ENCODER if value == "encoder" else WORLD
    try:
        number = int(value) if value else 1
    except ValueError:
        return WORLD
    return ENCODER if number == 0 else WORLD if number == 1 else NEITHER


class WheelRamp:
    """The plugin's wheel-speed ramp, a stretch of control ticks at a time.

    The wheels follow the command they are given within a tick (the simulation is
    kinematic), so their current speed is the last command set.
    """

    def __init__(self, drive: ClassicDrive, dt_s: float, wheel_radius_m: float) -> None:
        self.drive, self.radius = drive, wheel_radius_m
        self.step_ns = round(dt_s * 1e9)
        rate = drive.update_rate_hz
        self.period_ns = round(1e9 / rate) if rate > 0 else 0
        self.last_ns = 0  # the plugin's last update (it loads at time 0)
        self.command = np.zeros(2)  # the running command [m/s], left and right
        self.current = np.zeros(2)  # the wheels' surface speeds [m/s]

    def run(self, first_tick: int, left_rad_s: FloatArray,
            right_rad_s: FloatArray) -> tuple[FloatArray, FloatArray]:
        """The wheel speeds [rad/s] of the ticks from ``first_tick`` for the wanted ones."""
        wanted = np.column_stack((left_rad_s, right_rad_s)) * self.radius
        out = np.empty_like(wanted)
        for i, want in enumerate(wanted):
            now = (first_tick + i) * self.step_ns
            if self._due(now):
                self._update(want, (now - self.last_ns) / 1e9)
                self.last_ns = self.last_ns + self.period_ns if self.drive.ros1 else now
            out[i] = self.current
        out /= self.radius
        return out[:, 0], out[:, 1]

    def _due(self, now_ns: int) -> bool:
        """Whether the plugin updates at ``now_ns`` (ROS 2: a period passed; ROS 1: more)."""
        elapsed = now_ns - self.last_ns
        return elapsed > self.period_ns if self.drive.ros1 else elapsed >= self.period_ns

    def _update(self, wanted: FloatArray, elapsed_s: float) -> None:
        near = np.abs(wanted - self.current) < REACHED_M_S
        reached = near.any() if self.drive.ros1 else near.all()
        limit = self.drive.wheel_acceleration_m_s2
        if limit == 0 or reached:
            self.current = wanted.copy()  # the running command is left as it was
            return
        step = limit * elapsed_s
        self.command = self.command + np.clip(wanted - self.current, -step, step)
        self.current = self.command.copy()
