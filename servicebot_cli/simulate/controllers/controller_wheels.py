"""The wheel geometry diff_drive_controller computes with: its parameters, not the URDF's.

The controller turns a twist into wheel speeds, and wheel turns into odometry, with its own
``wheel_separation * wheel_separation_multiplier`` and ``wheel_radius`` times each side's
``*_wheel_radius_multiplier`` (diff_drive_controller.cpp: ``velocity_left = (linear -
angular * wheel_separation / 2) / left_wheel_radius``). The robot moves as its URDF wheels
carry it, so a file whose geometry is not the robot's moves it other than commanded and its
odometry drifts. Where the file gives no ``wheel_separation`` or ``wheel_radius``, the URDF's
stands in. Pure.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics import diff_drive
from servicebot_cli.kinematics.drive_geometry import DriveGeometry
from servicebot_cli.simulate.scenario.definition import Controller

FloatArray = npt.NDArray[np.float64]


@dataclass(frozen=True)
class ControllerWheels:
    """Separation [m] and each side's radius [m], as the controller computes with them."""

    separation_m: float
    left_radius_m: float
    right_radius_m: float

    @classmethod
    def of(cls, controller: Controller, geometry: DriveGeometry) -> ControllerWheels:
        """The controller's wheels, the URDF's ``geometry`` where it sets none."""
        c = controller
        separation = c.wheel_separation_m if c.wheel_separation_m is not None \
            else geometry.track_m
        radius = c.wheel_radius_m if c.wheel_radius_m is not None else geometry.wheel_radius_m
        return cls(separation * c.wheel_separation_multiplier,
                   radius * c.left_wheel_radius_multiplier,
                   radius * c.right_wheel_radius_multiplier)

    def wheel_speeds(self, linear_m_s: float, angular_rad_s: float) -> tuple[float, float]:
        """Left and right wheel speeds [rad/s] the controller commands for a twist."""
        half = angular_rad_s * self.separation_m / 2.0
        return (linear_m_s - half) / self.left_radius_m, (linear_m_s + half) / self.right_radius_m

    def twist(self, left_rad_s: FloatArray, right_rad_s: FloatArray
              ) -> tuple[FloatArray, FloatArray]:
        """The body twist [m/s], [rad/s] the controller's odometry reads from wheel speeds.

        With equal radii, the arithmetic is the ground truth's (:func:`.diff_drive.body_twist`):
        a file whose geometry is the robot's gives odometry equal to it to the last bit.
        """
        left, right = np.asarray(left_rad_s, float), np.asarray(right_rad_s, float)
        if self.left_radius_m == self.right_radius_m:
            linear, angular = diff_drive.body_twist(
                left, right,  # type: ignore[arg-type]  # plain arithmetic on arrays
                wheel_radius_m=self.left_radius_m, track_m=self.separation_m)
            return np.asarray(linear, float), np.asarray(angular, float)
        left, right = left * self.left_radius_m, right * self.right_radius_m
        return (left + right) / 2.0, (right - left) / self.separation_m
