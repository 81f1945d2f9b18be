"""Catalogue texts for what URDF parsers ignore: Gazebo, ros2_control, controllers, the model."""

from __future__ import annotations

from servicebot_cli.check.catalogue import Rule
from servicebot_cli.check.findings import Severity

E, W, N = Severity.ERROR, Severity.WARNING, Severity.INFO

ROS_RULES = (
    # -- Gazebo, ros2_control, transmissions -----------------------------------------------------
    Rule("SB501", "gazebo-unknown-reference", E, "<gazebo reference> names no link or joint",
         "Gazebo silently ignores the block: its friction, colour, sensors or plugins never "
         "apply. A warning when the xacro sources define that link or joint in a part this "
         "expansion leaves out (a condition not taken, an include its options leave out): the "
         "block is then for an optional part, as its author meant. A warning too when the "
         "block is empty: nothing is lost.",
         "Use the suggested name."),
    Rule("SB502", "sensor-parameter", E, "A sensor parameter out of range",
         "samples > 0, min_angle < max_angle (equal for a single ray: its direction, as "
         "Gazebo reads it), 0 < range min < range max (a Gazebo Classic "
         "\"ray\" sensor may start at range min 0; a GPU lidar's range min is a camera's "
         "near clip, which must be positive), image width and height > 0, clip near < far, "
         "noise stddev >= 0, an update_rate sdformat can read (0, SDF's default, updates at "
         "every simulation step; a negative one does too, a warning). A force_torque sensor "
         "on a fixed joint that Gazebo lumps away measures nothing (a warning).",
         "Write the sensor's real values."),
    Rule("SB503", "mixed-gazebo", W, "Gazebo Classic and gz-sim plugins in one file",
         "libgazebo_ros_* plugins load only in Gazebo Classic, gz-sim-* (ignition-gazebo-*) "
         "only in gz-sim: one of the two sets never loads.",
         "Keep one simulator's plugins, or select them with a xacro argument."),
    Rule("SB504", "control-unknown-joint", E, "<ros2_control> names a joint that does not exist",
         "The controller manager refuses to start.", "Use the suggested name."),
    Rule("SB505", "control-interface", W, "A ros2_control interface name that is not standard",
         "Standard interfaces are position, velocity, acceleration and effort; controllers "
         "look for those names. A close misspelling is almost certainly a typo.",
         "Use the suggested name."),
    Rule("SB506", "control-fixed-joint", E, "A command interface on a fixed joint",
         "A fixed joint cannot be commanded. A fixed joint with state interfaces only is a "
         "warning: from Jazzy on, ros2_control refuses any fixed joint in <ros2_control>; "
         "Humble exports its states.", "Remove the command interface."),
    Rule("SB507", "control-joint-twice", E, "A joint interface in two ros2_control components",
         "Two hardware components export the same command or state interface of a joint "
         "(joint/position twice); the resource manager refuses the duplicate. One joint in an "
         "actuator that only commands and a sensor that only reports (different interfaces) "
         "is a supported layout and not reported.",
         "Keep each interface of the joint in one component."),
    Rule("SB508", "control-limits", W, "Command limits outside the URDF limits",
         "A command interface's min/max allows more than the joint's URDF position or "
         "velocity limits.",
         "Bring min/max inside the URDF limits."),
    Rule("SB509", "control-no-plugin", E, "<ros2_control> without a hardware plugin",
         "<hardware><plugin> names the hardware interface to load; without it nothing runs. "
         "A warning for a component with no <hardware> at all in a robot Gazebo's "
         "ros2_control plugin runs: it skips that component and runs the others.",
         "Add <hardware><plugin>package/Class</plugin></hardware>."),
    Rule("SB510", "control-hardware-param", E, "A malformed hardware parameter",
         "A serial port must be a device path (/dev/ttyUSB0, /dev/serial/by-id/...) or a "
         "network port number, and a baud rate a standard one (9600, 115200, ...) or, from "
         "1 Mbaud, any rate a USB adapter takes (Dynamixel buses run at 4.5 or 6.25 Mbaud). "
         "A simulated or mock component (Gazebo's systems, mock_components) opens no port and "
         "is not judged.",
         "Write a device path and a standard baud rate."),
    Rule("SB511", "transmission-unknown-joint", W,
         "<transmission> names a joint that does not exist",
         "An error where a reader of transmissions in the file refuses it: ROS 1's "
         "gazebo_ros_control plugin (libgazebo_ros_control.so, default robotSimType) parses "
         "top-level <transmission>s, and its DefaultRobotHWSim fails to start on a "
         "single-joint transmission with a <hardwareInterface> whose joint is not in the "
         "model; ros2_control (and gazebo_ros2_control, gz_ros2_control) refuses a "
         "<ros2_control> component whose nested <transmission> names a joint that is not one "
         "of the component's <joint>s. A warning otherwise: ros2_control, urdfdom, KDL and "
         "sdformat ignore top-level <transmission>s, so motor or actuator transmissions meant "
         "for a robot's own hardware interface (NASA Valkyrie's) break nothing they read.",
         "Use the suggested name, or remove the transmission."),
    Rule("SB512", "control-limit-text", W, "A command interface min or max that is not a number",
         "ros2_control reads a command interface's <param name=\"min\"> and \"max\" as "
         "numbers; text it cannot read (a value in quotes, a unit, a decimal comma) makes it "
         "log \"Error parsing the limits\" and go on without the interface's limits.",
         "Write a plain decimal number."),
    Rule("SB513", "gazebo-number", E, "A <gazebo> setting sdformat cannot read as a number",
         "sdformat's URDF converter reads mu1, mu2, kp, kd, maxVel, minDepth, dampingFactor, "
         "maxContacts, laserRetro, springReference, springStiffness, stopCfm, stopErp and "
         "fudgeFactor as numbers (std::stod, std::stoi), which fail on text that does not "
         "start as one: an unexpanded ${mu}, a word, nothing.",
         "Write a plain number (expand the xacro property)."),
    # -- controller configuration ----------------------------------------------------------------
    Rule("SB514", "control-unknown-element", E, "An element <ros2_control> does not read",
         "ros2_control's component parser reads <hardware>, <joint>, <sensor>, <gpio>, "
         "<transmission> (and <properties>) in <ros2_control>, and throws 'invalid tag name' "
         "for anything else: the controller manager and Gazebo's ros2_control plugins do not "
         "start.", "Remove it, fix its name, or move a parameter into <hardware>."),
    Rule("SB515", "control-mimic-joint", W, "A mimic joint ros2_control refuses (Jazzy on)",
         "From Jazzy on, ros2_control takes a joint with a URDF <mimic> as following its "
         "leader unless mimic=\"false\": it may have no command interface and its leader must "
         "be a joint of the same <ros2_control>; mimic=\"true\" on a joint without a URDF "
         "<mimic> is refused too. Humble ignores both, so a warning.",
         "Drop the mimic joint's command interfaces, or put its leader in the same "
         "component."),
    Rule("SB516", "plugin-wheel-geometry", E,
         "A Gazebo diff-drive plugin's wheel numbers disagree with the URDF's wheels",
         "Gazebo's diff-drive plugins (Classic's gazebo_ros_diff_drive, gz-sim's DiffDrive) "
         "make wheel speeds from their own <wheel_separation> and <wheel_diameter> (gz: "
         "<wheel_radius>), or their defaults (0.34 m and 0.15 m; gz: 1 m and 0.2 m) where "
         "not written; the URDF's wheels roll the robot. Beyond 10 % an error; from 1 to "
         "10 % a warning, since teams calibrate odometry to the floor that way; on a base "
         "with two or more wheels a side, a wider track (up to twice the wheels') is its "
         "effective one: a warning.",
         "Write the value the URDF's wheels imply, or fix the URDF."),
    Rule("SB517", "control-markup", E, "<ros2_control> markup ros2_control's parser refuses",
         "ros2_control's component parser throws on a <ros2_control> without name or type, "
         "and on a joint, sensor, gpio, interface or <param> without a name; the resource "
         "manager refuses two components of one name and loads only system, actuator and "
         "sensor components (Gazebo's ros2_control plugins load any as a system: there a "
         "warning). No controller runs.",
         "Add the attribute, rename one of the components, or fix the type."),
    Rule("SB518", "plugin-ros-element", W,
         "An element in a Gazebo ROS plugin's <ros> that gazebo_ros does not read",
         "gazebo_ros' node reads <namespace>, <remapping>, <argument>, <parameter> and <qos> in "
         "a ROS 2 plugin's <ros>; anything else (roslaunch's <remap from to>) does nothing, "
         "and the plugin keeps the names it would have without it.",
         "Write a remapping as <remapping>FROM:=TO</remapping>."),
    Rule("SB519", "ros1-plugin-parameter", W,
         "A ROS 1 parameter in a Gazebo plugin of a file whose plugins are ROS 2's",
         "One Gazebo runs every plugin of a file; a <ros> block in one of them, or a plugin "
         "only ROS 2 has (gazebo_ros2_control, gazebo_ros_ray_sensor), makes the file "
         "ROS 2's gazebo_ros, whose plugins read none of gazebo_ros_pkgs' ROS 1 names "
         "(<frameName>, <topicName>, <updateRate>): the value does nothing, and the plugin "
         "keeps its default frame, topic or rate.",
         "Write the ROS 2 name: <frame_name>, <camera_name>, a <ros><remapping> for a topic, "
         "<ros><namespace> for the namespace."),
    Rule("SB520", "plugin-odometry-frames", W,
         "A drive plugin's odometry frames that leave the robot without odometry in TF",
         "A Gazebo drive plugin (diff drive, skid steer, planar move; gz-sim's DiffDrive) "
         "broadcasts odom -> base on /tf. tf2 ignores a transform from a frame to itself "
         "(TF_SELF_TRANSFORM), so an odometry frame equal to the base frame is never on /tf; "
         "a base frame that is no link of the robot joins no frame robot_state_publisher "
         "publishes, so odom and the robot's links are two trees. Only frames written in the "
         "file are judged: a launch file may publish a default base_footprint.",
         "Name the odometry frame odom and the base frame a link of the robot."),
    Rule("SB521", "control-parameters-file", E,
         "A ros2_control Gazebo plugin's <parameters> names no file",
         "gazebo_ros2_control and gz_ros2_control pass every <parameters> of their plugin to "
         "the controller manager as --params-file; rcl refuses a file it cannot open "
         "('Couldn't parse params file'), the controller manager does not start, and no "
         "controller runs: the robot spawns and never moves. A relative path is taken from "
         "the description's directory, as servicebot's simulator takes it, and is a warning "
         "where it is not there: Gazebo takes it from its own working directory (write "
         "$(find PKG)/... instead). A value holding a launch substitution $(...) is left to "
         "the launch file.",
         "Name the controllers YAML: $(find PKG)/config/FILE.yaml in a xacro file."),
    Rule("SB601", "controllers-yaml", E, "The controllers YAML cannot be read",
         "Not YAML, or not the shape of a ros2_control parameters file "
         "(controller: ros__parameters: ...).",
         "Fix the YAML at the reported line."),
    Rule("SB602", "controller-unknown-joint", E,
         "A controller names a joint the URDF does not have",
         "left_wheel_names, right_wheel_names and joints must name URDF joints.",
         "Use the suggested name."),
    Rule("SB603", "wheel-radius", E, "wheel_radius disagrees with the URDF's wheels",
         "diff_drive_controller's odometry and speed scale by the radius; the URDF's wheel "
         "cylinders imply another value. Beyond 10 % an error; from 1 to 10 % a warning, "
         "since teams calibrate odometry to the floor that way.",
         "Use the value the URDF implies, or fix the URDF."),
    Rule("SB604", "wheel-separation", E, "wheel_separation disagrees with the URDF's wheels",
         "Turn rates and odometry scale by the separation of the left and right wheels; the "
         "URDF's wheel positions imply another value. Beyond 10 % an error; from 1 to 10 % "
         "a warning, since teams calibrate odometry to the floor that way. On a base with "
         "two or more wheels a side, which skid when it turns, a wider track (up to twice "
         "the wheels') is its effective one: a warning.",
         "Use the value the URDF implies, or fix the URDF."),
    Rule("SB605", "wheel-side", E, "A left wheel on the right, or a right wheel on the left",
         "The URDF puts the wheel on the other side of the robot (y > 0 is left, REP 103).",
         "Swap the names between left_wheel_names and right_wheel_names."),
    Rule("SB606", "controller-fixed-joint", E, "A controller commands a joint that cannot move",
         "The joint is fixed in the URDF.", "Remove it from the controller."),
    Rule("SB607", "controller-interface", E,
         "A controller claims an interface the URDF's <ros2_control> does not export",
         "The controller manager activates a controller once the hardware exports every "
         "interface it claims: diff_drive_controller each wheel's velocity command and its "
         "position state (velocity with position_feedback false; with open_loop true only "
         "Humble's claims a state, a warning), "
         "joint_trajectory_controller its command_interfaces and state_interfaces, "
         "forward_command_controller its interface_name, the JointGroup controllers the "
         "interface of their type, the gripper action controllers their joint's command "
         "(and max_effort_interface) and its position and velocity, the IMU, force-torque "
         "and range broadcasters their sensor's states (a sensor_name no <ros2_control> "
         "sensor has is SB602). A URDF without <ros2_control> joints is not judged: its "
         "hardware is described elsewhere. Gazebo's systems, the mock and "
         "topic_based_ros2_control export what the URDF lists; another driver may export "
         "interfaces of its own (canopen's Cia402System): a warning there.",
         "Export the interface in the joint's <ros2_control> entry, or claim one it exports."),
    Rule("SB608", "controller-parameter", E,
         "A controller parameter the controller refuses: its type, or its value",
         "rcl types each value by its text: a boolean word (true, on, y...), an integer, a "
         "floating-point number, else a string; a quoted value is a string, and a list takes "
         "its items' one type. A list that mixes types (0.001 beside 0; joints [x, y, z], "
         "where y is a boolean) makes rcl refuse the whole file. ros2_controllers declare "
         "each parameter's type and refuse another at configure (\"Wrong parameter type\"): "
         "wheel_separation \"0.10\" or 1, a wheel list written as one name. A type a "
         "letter or two off a ros2_controllers plugin is no class pluginlib can load. "
         "JointTrajectoryController validates its lists (unique, not empty, known "
         "interfaces; no velocity state without position), ForwardCommandController needs "
         "an interface_name, a gripper's max_effort is not negative. A section whose name "
         "is a letter or two off a controller controller_manager declares configures "
         "nothing, and that controller starts with no parameters (an error where it needs "
         "some); a declared controller with no section in a file that configures others "
         "is a warning (another file may give its parameters). controller_manager's own "
         "update_rate is an integer (above 0 from Jazzy on): another type stops the node; a "
         "controller it declares with no type, given nowhere, it cannot load.",
         "Write the value in the declared type: 1.0 for a double, no quotes for a number, a "
         "list for an array."),
    # -- model -----------------------------------------------------------------------------------
    Rule("SB701", "model-build", E, "Pinocchio cannot build the model",
         "Every servicebot command builds the same Pinocchio model; this is what Pinocchio "
         "said. Built only when the cheaper rules found no error. The other commands also "
         "refuse what Pinocchio builds but would move wrongly, which rules report: a zero "
         "axis (SB207), a mimic of itself or of no joint (SB209, SB210), a negative "
         "friction (SB216).",
         "Fix what the message says."),
    Rule("SB702", "model-skipped", N, "The model was not built because of errors above",
         "Building the model of a broken description says nothing new; fix the errors "
         "reported before this one and check again."),
)
