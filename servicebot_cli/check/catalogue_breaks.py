"""What breaks when an error-level rule fires: a standard consumer refuses or changes the robot.

A rule is an error only when something here breaks; otherwise it is a warning.

Consumers named: urdfdom (robot_state_publisher, check_urdf, RViz, Gazebo's URDF import via
sdformat), KDL (robot_state_publisher), Gazebo, MoveIt, Pinocchio, MuJoCo, ros2_control.
"""

from __future__ import annotations

_URDFDOM = ("urdfdom refuses the file, so robot_state_publisher, RViz and Gazebo (sdformat) "
            "do not load the robot")
_OR_DROPS = ("; inside a link's <inertial>, <visual> or <collision> it loads the file instead "
             "but drops that element and the link's later ones (check_urdf still says it "
             "parsed): the robot silently changes")

BREAKS: dict[str, str] = {
    "SB001": "xacro and every loader stop at the missing file: nothing loads the robot",
    "SB002": _URDFDOM + "; Pinocchio and MuJoCo refuse it too",
    "SB003": "xacro and the Python loaders (yourdfpy, MoveIt's Python tools) refuse the bytes",
    "SB004": _URDFDOM + "; Pinocchio and MuJoCo refuse it too",
    "SB005": "hardened XML readers (xacro's) refuse it, and readers that expand entities read "
             "another document than robot_state_publisher's parser does",
    "SB006": "there is no URDF for robot_state_publisher, Gazebo or MoveIt to load",
    "SB008": _URDFDOM,
    "SB009": _URDFDOM,
    "SB012": _URDFDOM + _OR_DROPS + " (a <mesh filename=\"\"> passes urdfdom, but Gazebo, "
             "RViz and Pinocchio's collision model cannot open it)",
    "SB013": _URDFDOM + _OR_DROPS,
    "SB407": "without <robot version=\"1.1\"> urdfdom drops the whole <visual> or "
             "<collision> holding the capsule ('Could not parse'): Pinocchio and Gazebo lose it",
    "SB113": "urdfdom refuses the colour and drops the material ('not defined in file'): "
             "RViz and Gazebo draw every link that uses it in their default colour",
    "SB014": _URDFDOM + "; Pinocchio and MuJoCo would compute with NaN",
    "SB020": "MuJoCo's URDF import refuses the file ('repeated element'); urdfdom reads the "
             "first and ignores the second",
    "SB019": "RViz and Gazebo hold poses in single precision: the link's place becomes "
             "infinity, and every pose computed from it after a rotation is NaN",
    "SB015": "consumers take minutes or run out of memory on such a file; servicebot refuses it",
    "SB016": _URDFDOM,
    "SB101": _URDFDOM,
    "SB102": _URDFDOM,
    "SB103": _URDFDOM,
    "SB104": _URDFDOM,
    "SB105": _URDFDOM,
    "SB106": "check_urdf accepts it, but urdfdom keeps one parent: KDL (robot_state_publisher) "
             "and Pinocchio silently drop the other joint, which changes the robot",
    "SB107": "check_urdf prints the loop forever; KDL and Pinocchio cannot build a tree",
    "SB108": _URDFDOM + " (the link is a second root)",
    "SB109": _URDFDOM,
    "SB110": _URDFDOM,
    "SB111": _URDFDOM + " (a material that is not unique)",
    "SB201": _URDFDOM,
    "SB202": _URDFDOM,
    "SB205": "Pinocchio refuses it (min_effort above max_effort); MoveIt's time "
             "parameterisation and ros2_control's joint limiters get a negative maximum: every "
             "motion is refused or clamped to zero",
    "SB216": "Pinocchio refuses a negative friction (min_dry_friction above max_dry_friction)",
    "SB207": "KDL (robot_state_publisher) and Pinocchio normalise the axis: a zero vector gives "
             "NaN transforms or a joint that moves nothing",
    "SB209": "MoveIt refuses a mimic of an unknown joint, and Pinocchio's mimic joints cannot "
             "be built (nor of a fixed joint, whose mimic MuJoCo drops)",
    "SB210": "MoveIt and Pinocchio cannot resolve a joint that follows itself",
    "SB211": "MoveIt and Pinocchio cannot resolve a cycle of mimics: no joint drives the others",
    "SB302": "Gazebo's physics engines and MuJoCo refuse a negative mass",
    "SB303": "in simulation: Gazebo (sdformat) drops or merges a massless moving link and MuJoCo "
             "refuses a moving body without mass; kinematic-only consumers (MoveIt, RViz, "
             "robot_state_publisher) are fine, so it is a warning there",
    "SB306": "MuJoCo refuses an inertia that is not positive definite; Gazebo's simulation "
             "explodes and Pinocchio's dynamics are wrong",
    "SB308": "MuJoCo refuses it ('inertia must satisfy A + B >= C'); Gazebo simulates a body "
             "that cannot exist",
    "SB311": "Pinocchio's dynamics overflow (infinite total mass, NaN gravity torques) and "
             "MuJoCo refuses an inertia that breaks the triangle inequality",
    "SB310": "each consumer reads a different body: Gazebo (sdformat) takes mass 0 as no "
             "inertia at all, Pinocchio keeps a rotational inertia without mass",
    "SB401": "RViz and Gazebo show and collide with nothing there; Pinocchio's collision model "
             "and MuJoCo's compiler refuse the missing file",
    "SB402": "RViz and Gazebo show and collide with nothing there; Pinocchio's collision model "
             "and MuJoCo's compiler refuse the file",
    "SB403": "MuJoCo refuses a mesh without faces and Pinocchio's collision geometry (hpp-fcl) "
             "cannot be built; Gazebo collides with nothing there",
    "SB405": "MuJoCo refuses a zero or negative collision size; Pinocchio's collision "
             "geometry (coal) keeps a negative box as it is; urdfdom accepts them",
    "SB406": "urdfdom logs 'Unknown geometry type' and drops the <visual> or <collision>, and "
             "the link's later ones, loading the rest: the robot silently changes",
    "SB501": "Gazebo (sdformat's URDF conversion) drops the block silently: its friction, "
             "sensor or plugin is lost",
    "SB502": "Gazebo refuses the sensor or runs it with the out-of-range value",
    "SB504": "ros2_control's resource manager refuses the component (gz_ros2_control and the "
             "hardware do not start)",
    "SB506": "ros2_control exports a command for a joint that cannot move: gz_ros2_control "
             "refuses it, on hardware the controller moves nothing",
    "SB507": "ros2_control's resource manager refuses an interface exported twice",
    "SB509": "the controller manager cannot load a component without a plugin",
    "SB510": "the hardware component fails to open its port when it is activated",
    "SB511": "with gazebo_ros_control in the file, its DefaultRobotHWSim does not start (no "
             "controller runs); in <ros2_control>, ros2_control's component parser refuses the "
             "component (the controller manager, gazebo_ros2_control and gz_ros2_control do not "
             "start)",
    "SB514": "ros2_control's component parser throws 'invalid tag name': the controller "
             "manager and Gazebo's ros2_control plugins do not start",
    "SB513": "sdformat's conversion of the URDF throws (std::invalid_argument): Gazebo "
             "spawns nothing of the robot",
    "SB516": "Gazebo drives the robot at another speed and turn rate than commanded, and "
             "the plugin's encoder odometry drifts",
    "SB517": "ros2_control's parser or resource manager refuses the robot: the controller "
             "manager and Gazebo's ros2_control plugins do not start",
    "SB521": "gazebo_ros2_control and gz_ros2_control hand the file to rcl, which cannot open "
             "it ('Couldn't parse params file'): the controller manager does not start, and "
             "the robot spawns without controllers",
    "SB601": "the controller manager refuses parameters that are not valid YAML",
    "SB602": "the controller fails to configure: the joint's interfaces do not exist",
    "SB603": "diff_drive_controller accepts it and drives at the wrong speed and odometry",
    "SB604": "diff_drive_controller accepts it and turns at the wrong rate",
    "SB605": "diff_drive_controller turns the robot the wrong way",
    "SB606": "the controller fails to claim an interface of a joint that cannot move",
    "SB608": "rcl refuses the file (a list of mixed types), or the controller refuses the "
             "value at configure ('Wrong parameter type'): the controller does not start",
    "SB607": "the controller manager refuses to activate the controller (the interface is "
             "not available), and the joints it should move stay still",
    "SB701": "Pinocchio refuses the description",
}
"""For each rule that is (or can be) an error, what breaks."""
