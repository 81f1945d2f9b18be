"""The QoS each topic's publisher offers, as rosbag2 (Humble) records it in a bag.

``ros2 bag play`` offers the recorded reliability and durability again, and Foxglove and
RViz read a transient-local topic (``/robot_description``, ``/tf_static``) from a late
subscription. rosbag2 keeps, per topic, one profile per publisher as a YAML string: the
list rosbag2_transport's ``YAML::convert<Rosbag2QoS>::encode`` makes, dumped by yaml-cpp
(``YAML::Dump``: no trailing newline). Metadata version 5 (Humble) writes the rmw enums as
integers and durations as ``{sec, nsec}``; an infinite one is ``RMW_DURATION_INFINITE``.

Each profile below is the one the publishing ROS node asks for (sources in its docstring).
``rclcpp::SystemDefaultsQoS`` leaves the policies to the DDS vendor; it is written as ROS 2's
default profile (keep last 10, reliable, volatile), what it comes to with the vendors' own
defaults for a volatile publisher.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

# rmw enums (rmw/types.h)
KEEP_LAST = 1
RELIABLE, BEST_EFFORT = 1, 2
TRANSIENT_LOCAL, VOLATILE = 1, 2
AUTOMATIC = 1
INFINITE_SEC, INFINITE_NSEC = 9223372036, 854775807  # RMW_DURATION_INFINITE


@dataclass(frozen=True)
class Qos:
    """One publisher's offered profile: history depth, reliability and durability."""

    depth: int
    reliability: int = RELIABLE
    durability: int = VOLATILE

    @property
    def transient_local(self) -> bool:
        """Late subscribers get the last ``depth`` messages (a latched topic)."""
        return self.durability == TRANSIENT_LOCAL

    def yaml_lines(self) -> list[str]:
        """The profile as one item of rosbag2's list, keys in rosbag2's order."""
        infinite = ["    sec: " + str(INFINITE_SEC), "    nsec: " + str(INFINITE_NSEC)]
        return [f"- history: {KEEP_LAST}", f"  depth: {self.depth}",
                f"  reliability: {self.reliability}", f"  durability: {self.durability}",
                "  deadline:", *infinite, "  lifespan:", *infinite,
                f"  liveliness: {AUTOMATIC}", "  liveliness_lease_duration:", *infinite,
                "  avoid_ros_namespace_conventions: false"]


SENSOR_DATA = Qos(5)
"""gazebo_ros ray, IMU and camera plugins: ``rclcpp::SensorDataQoS().reliable()``."""
SYSTEM_DEFAULTS = Qos(10)
"""diff_drive_controller and joint_state_broadcaster: ``rclcpp::SystemDefaultsQoS()``."""
DYNAMIC_TF = Qos(100)
"""robot_state_publisher's ``/tf``: tf2_ros ``DynamicBroadcasterQoS``."""
STATIC_TF = Qos(1, durability=TRANSIENT_LOCAL)
"""robot_state_publisher's ``/tf_static``: tf2_ros ``StaticBroadcasterQoS``."""
ROBOT_DESCRIPTION = Qos(1, durability=TRANSIENT_LOCAL)
"""robot_state_publisher's ``robot_description``: ``rclcpp::QoS(1).transient_local()``."""
CLOCK = Qos(1, reliability=BEST_EFFORT)
"""gazebo_ros_init's ``/clock``: ``rclcpp::ClockQoS()``."""


def offered_qos_profiles(profiles: Sequence[Qos]) -> str:
    """The ``offered_qos_profiles`` string of a topic with these publishers ("" for none)."""
    return "\n".join(line for profile in profiles for line in profile.yaml_lines())
