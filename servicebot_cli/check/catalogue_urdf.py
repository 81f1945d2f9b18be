"""Catalogue texts for the URDF itself: parsing, the tree, joints, inertia, geometry."""

from __future__ import annotations

from servicebot_cli.check.catalogue import Rule
from servicebot_cli.check.findings import Severity

E, W, N = Severity.ERROR, Severity.WARNING, Severity.INFO

URDF_RULES: tuple[Rule, ...] = (
    # -- parse and safety ------------------------------------------------------------------------
    Rule("SB001", "unreadable-file", E, "A file cannot be read",
         "A file the description needs is missing, a directory, or not readable: a xacro "
         "include, or a file found while walking a directory. A FILE named on the command "
         "line that cannot be read stops the run with exit code 2 instead. In a walk, an "
         "include whose name has the gap an empty argument leaves (arms//dof/_macro.xacro), "
         "reached from an element that reads an argument declared with default=\"\", is a "
         "warning: its launch file fills the argument.",
         "Fix the path or the permissions (chmod +r)."),
    Rule("SB002", "empty-file", E, "The file is empty",
         "An empty file (or one holding only whitespace) describes no robot.",
         "Write a <robot name=\"...\"> element with at least one <link>."),
    Rule("SB003", "invalid-utf8", E, "The file is not valid UTF-8",
         "URDF and xacro files are read as UTF-8 (a UTF-8 byte-order mark is fine); a byte "
         "that is not UTF-8 usually means the file was saved as Latin-1 or Windows-1252, a "
         "UTF-16 byte-order mark or NUL bytes that it was saved as UTF-16 (Windows editors' "
         "\"Unicode\"). An image or archive is said to be one: the wrong file was named.",
         "Save the file as UTF-8 (an editor's 'Save with encoding'), or, for an image or "
         "archive, name the description file instead."),
    Rule("SB004", "malformed-xml", E, "The XML is not well-formed",
         "A strict parser stops at the first error and reports its line and column; nothing "
         "is guessed or recovered, since a recovering parser silently drops elements.",
         "Fix the XML at the reported position (a tag left open, a stray '<' or '&')."),
    Rule("SB005", "unsafe-xml", E, "A DTD declares entities or names an external DTD",
         "Entities can read local files (<!ENTITY x SYSTEM \"file:///etc/passwd\">) or expand "
         "exponentially (billion laughs): external and parameter entities, and entities that "
         "refer to others, are refused, never resolved, and the network is never used. A "
         "plain internal entity is read as xacro expands it; in a plain URDF a reference to "
         "one is an error, since urdfdom reads '&name;' as written. An external DTD that is "
         "only named is a warning: no robot description reader loads it; a reference to an "
         "entity it would declare is an error.",
         "Remove the DOCTYPE; use xacro properties for repeated values."),
    Rule("SB006", "xacro-failed", E, "xacro cannot expand the file",
         "An unknown macro or property, a bad expression, a missing argument or include. The "
         "position is the xacro element being expanded when it failed. A file found in a "
         "directory walk that only lacks an argument it gives no default (launch files pass "
         "it: universal_robot's ur.xacro reads $(arg robot_model)) is a warning; named, an "
         "error.",
         "Fix the xacro source at the reported line, or pass the missing NAME:=VALUE."),
    Rule("SB007", "package-not-found", W, "A $(find PKG) names a package that is nowhere",
         "Packages resolve as ROS finds them, with no ROS installed (the search is listed "
         "under SB408); the message lists where it looked. The file cannot be expanded, so "
         "nothing in it is checked; a missing package is the environment, not the file, so "
         "this is a warning (--strict fails on it).",
         "Pass --package NAME=DIR, or source the ROS workspace that holds the package."),
    Rule("SB008", "not-a-robot", E, "The root element is not <robot>",
         "A URDF's root element is <robot>; SDF files (<sdf>) and xacro fragments are not "
         "robot descriptions. A URDF <world> (DART reads it, placing the robots it "
         "includes) is a warning: a file of another kind, with nothing wrong in it.",
         "Check the right file."),
    Rule("SB009", "robot-unnamed", E, "<robot> has no name",
         "urdfdom refuses a robot without a name attribute. An empty name it loads (as "
         "Pinocchio and yourdfpy do): a warning, since what goes by the robot's name "
         "(MoveIt's SRDF, a spawned Gazebo model) gets none.",
         "Add name=\"my_robot\" to <robot>."),
    Rule("SB010", "unknown-element", W, "An element that URDF does not define",
         "Core URDF elements (link, joint, inertial, geometry...) are checked against the URDF "
         "specification; a misspelt one is silently ignored by every parser. Extension "
         "elements (gazebo, transmission, ros2_control, sensor, ...) and namespaced ones pass "
         "quietly.",
         "Use the suggested spelling, or remove the element."),
    Rule("SB011", "unknown-attribute", W, "An attribute that URDF does not define",
         "A misspelt attribute (<limit lowr=...>) is ignored by parsers and the default value "
         "is used instead.",
         "Use the suggested spelling, or remove the attribute."),
    Rule("SB012", "missing-attribute", E, "A required element or attribute is missing",
         "For example a joint without type, parent or child, an <inertial> without <mass> "
         "or with fewer than six inertia values, a <box> without size, a <mesh> without "
         "filename, a <limit> without effort or velocity, a <mimic> without joint.",
         "Add the element or attribute the message names."),
    Rule("SB013", "bad-number", E, "A value is not a number or has the wrong count",
         "Numbers are plain decimals (1, -0.5, 2e-3); vectors have exactly three "
         "components (rgba: four). urdfdom refuses anything else, including trailing spaces.",
         "Write plain decimal numbers, as many as the attribute takes, separated by spaces."),
    Rule("SB014", "non-finite", E, "NaN or infinity in a value",
         "nan, inf and numbers too large for a double make every computation that touches "
         "them meaningless; urdfdom refuses them.",
         "Write a finite number."),
    Rule("SB020", "ignored-duplicate", W, "A second element where URDF reads one",
         "urdfdom reads a joint's <origin>, <parent>, <child>, <axis>, <limit>, <dynamics>, "
         "<mimic>, <safety_controller> and <calibration>, a link's <inertial>, an "
         "inertial's <origin>, <mass> and <inertia>, a visual's or collision's <origin>, "
         "<geometry> and <material>, once: the first. A second one, meant as an override or "
         "left from an edit, changes nothing, and is not judged further: a warning. Where "
         "MuJoCo's URDF import refuses the file for it ('repeated element': a joint's "
         "<origin>, <parent>, <child>, <axis>, <limit>, <dynamics> or <mimic>, a link's "
         "<inertial> and what it holds, a collision's <origin> or <geometry>, a visual's "
         "<material>, a material's <color>), an error.",
         "Merge the two, or remove the one you do not mean."),
    Rule("SB019", "far-origin", E, "An origin farther than any robot reaches",
         "An <origin xyz> beyond 1e6 m (1,000 km) is a typo or a wrong unit; servicebot's "
         "fk, ik and simulate refuse it. Past 3.4e38 m, where single precision ends, it is "
         "an error; nearer, a warning.",
         "Write the origin in metres."),
    Rule("SB021", "origin-in-degrees", W, "An origin's rpy that looks like degrees",
         "URDF angles are radians: rpy=\"0 0 90\" turns the frame by 90 rad, 116.6 degrees, "
         "and check_urdf, Gazebo and robot_state_publisher all accept it. Every angle that "
         "is not 0 being a whole multiple of 5 from 15 to 360, one of them beyond 2 pi, is "
         "taken for degrees.",
         "Write the angles in radians."),
    Rule("SB015", "too-large", E, "The file is over the size or complexity limits",
         "Descriptions over 32 MB, with more than a million elements, nested over 256 deep "
         "or with more than 20000 links are refused at once, instead of a build that takes "
         "minutes.",
         "Check that this really is a robot description."),
    Rule("SB016", "urdf-version", E, "An unsupported <robot version>",
         "urdfdom accepts version=\"1.0\" to \"1.2\" in the form x.y, and refuses the rest.",
         "Remove the version attribute or set version=\"1.0\"."),
    Rule("SB017", "xacro-warning", W, "xacro warned while expanding",
         "xacro warns about deprecated syntax (for example a macro call without the xacro: "
         "prefix or an unused argument); newer xacro versions refuse it. A file whose name "
         "does not say xacro but that holds xacro gets the same warning, with how ROS tools "
         "read it. What a file prints itself is reported as it printed it: xacro.warning() "
         "as a warning, xacro.error() as a warning too (xacro goes on and writes the robot), "
         "xacro.message() as information.",
         "Each finding's fix says what to change for its warning."),
    Rule("SB018", "xacro-include", N, "A xacro include: checked through its includers",
         "A xacro file that only defines macros or properties, or holds parts of a robot that "
         "another file includes, or whose links all hang from one link it does not define "
         "(an end effector sent as a URDF fragment) with evidence that it is a part (a file "
         "of its package includes it, or it only calls macros it includes and the missing "
         "link is not world, map or odom), is no robot alone. A directory walk "
         "leaves the first two out; named on the command line (`servicebot check urdf "
         "$(git ls-files '*.xacro')`), or a part found in a directory, it gets this note "
         "instead of the errors a robot without a name, links or root would get. The files "
         "that include it are checked, with it, as the robot. A named robot that other files "
         "of a walk include is left out too, unless none of them expands (each needs a "
         "launch argument, say): then it is checked alone. So is a part only a comment "
         "includes (an alternative tool), without what the link it hangs from being "
         "absent causes.",
         "Nothing to fix: name a file that includes it (or its directory) to check it."),
    # -- tree and names --------------------------------------------------------------------------
    Rule("SB101", "duplicate-link", E, "Two links have the same name",
         "urdfdom refuses the file; the message names both lines.", "Rename one link."),
    Rule("SB102", "duplicate-joint", E, "Two joints have the same name",
         "urdfdom refuses the file; the message names both lines.", "Rename one joint."),
    Rule("SB103", "unknown-link", E, "A joint names a link that does not exist",
         "The joint's <parent link> or <child link> names no <link>.",
         "Use the suggested name, or add the link."),
    Rule("SB104", "no-root", E, "Every link has a parent: there is no root",
         "A URDF is a tree with one root link, the one that is no joint's child. When every "
         "link is some joint's child, the joints form a loop.",
         "Remove the joint that closes the loop (see SB107)."),
    Rule("SB105", "several-roots", E, "Several links have no parent",
         "A URDF has exactly one root; urdfdom refuses the file and Pinocchio would build a "
         "different robot. The message lists every root with the size of its subtree.",
         "Attach every part to the robot with a joint (a fixed one if it does not move)."),
    Rule("SB106", "two-parents", E, "A link is the child of two joints",
         "check_urdf accepts this and silently keeps one of the joints. The message names "
         "both joints.",
         "Remove one of the joints, or give the second one its own child link."),
    Rule("SB107", "kinematic-loop", E, "The joints form a loop",
         "URDF cannot describe closed chains; check_urdf prints such a file forever. The "
         "message prints the cycle.",
         "Break the loop: remove one joint and model the closure in the controller or "
         "simulator (a Gazebo joint in a <gazebo> block)."),
    Rule("SB108", "disconnected-link", E, "A link no joint connects",
         "A link that is neither parent nor child of any joint, in a robot with other links, "
         "is a second root.",
         "Attach it with a joint, or remove it."),
    Rule("SB109", "no-links", E, "The robot has no links",
         "A URDF needs at least one <link>.", "Add the robot's links."),
    Rule("SB110", "unnamed", E, "A link or joint without a name",
         "Every link and joint needs a non-empty, unique name: urdfdom refuses an empty one. "
         "A name of blanks only urdfdom, Pinocchio and MuJoCo take, but nothing can name "
         "it on a command line or in a TF lookup: a warning.", "Add a name attribute."),
    Rule("SB111", "duplicate-material", E, "Two top-level materials have the same name",
         "urdfdom refuses the file.", "Rename one material or remove the duplicate."),
    Rule("SB112", "undefined-material", W, "A material has no colour or texture and no definition",
         "A <material name> with neither <color> nor <texture>, defined nowhere at the top "
         "level, gives no colour (Gazebo/... names only mean something to Gazebo, in a "
         "<gazebo> block). A named material with a colour in a link's visual is defined for "
         "the links after it, as urdfdom reads them (motoman's arms colour every link so).",
         "Define the material at the top level with a <color rgba>."),
    Rule("SB113", "color-out-of-range", E, "An rgba component outside [0, 1]",
         "Colours are four numbers between 0 and 1, not 0-255. urdfdom refuses any other "
         "and drops the material: every link that uses it loses its colour.",
         "Divide 0-255 values by 255."),
    Rule("SB114", "material-redefined", W, "A link's material reuses a name with another colour",
         "urdfdom keeps the first definition of a material name (at the top level, or in an "
         "earlier link's visual) and gives it to every later visual of that name, whatever "
         "colour the visual writes: RViz, robot_state_publisher and Gazebo draw the first "
         "colour (urdf-rs's sample.urdf comes out white all over).",
         "Give each colour its own material name."),
    # -- joints ----------------------------------------------------------------------------------
    Rule("SB201", "unknown-joint-type", E, "A joint type URDF does not have",
         "URDF joints are revolute, continuous, prismatic, fixed, floating and planar. There "
         "is no ball (spherical) joint: chain three revolute joints through two massless "
         "links, or use floating.",
         "Use one of the URDF joint types."),
    Rule("SB202", "missing-limits", E, "A revolute or prismatic joint without <limit>",
         "urdfdom refuses revolute and prismatic joints without limits; continuous joints "
         "need none.",
         "Add <limit lower upper effort velocity> (a revolute joint that turns without end: "
         "make it continuous)."),
    Rule("SB203", "lower-above-upper", W, "A lower limit above the upper limit",
         "pybullet reads lower > upper as 'no limit' and some pybullet_data models rely on "
         "it; MuJoCo drops such a limit too, silently (limited false). urdfdom and Pinocchio "
         "take it as written, a range no position satisfies for a bounds check (MoveIt's). "
         "Swapped limits are usually a typo; for a joint without limits use type "
         "continuous.",
         "Swap the limits, or make the joint continuous."),
    Rule("SB204", "equal-limits", W, "Equal lower and upper limits",
         "The joint cannot move (check_urdf accepts it; some tools read 0/0 as no limits).",
         "Make it fixed, or give it its real range."),
    Rule("SB205", "negative-effort-velocity", E, "A negative effort or velocity limit",
         "Effort and velocity limits are magnitudes; a negative one forbids any motion. URDF "
         "1.2's acceleration, deceleration and jerk limits too: urdfdom refuses a negative "
         "one, and the joint with it.",
         "Write the magnitude."),
    Rule("SB206", "zero-effort-velocity", W, "A zero effort or velocity limit on a moving joint",
         "Planners and controllers that enforce a velocity limit of 0 never move the joint; a "
         "simulator's motors and effort-limited controllers cannot drive a joint whose effort "
         "limit is 0. MoveIt and position control do not read effort (ROS-Industrial's arms "
         "write effort=\"0\"), so an effort limit of 0 is information where no simulator "
         "runs the description.",
         "Write the actuator's real limits."),
    Rule("SB207", "zero-axis", E, "A moving joint with a zero axis",
         "The joint moves about or along nothing; Pinocchio and KDL produce NaNs.",
         "Write the axis, for example 0 0 1."),
    Rule("SB208", "non-unit-axis", W, "An axis that is not a unit vector",
         "Most tools normalise it, some scale the motion by its length.",
         "Write the normalised axis."),
    Rule("SB209", "mimic-unknown-joint", E, "<mimic> names a joint that does not exist or move",
         "The mimicking joint follows nothing: the joint is not there, or it is fixed (or "
         "floating or planar), which MuJoCo and Pinocchio take no mimic of.",
         "Name the joint it follows (a suggested name, or a joint that moves)."),
    Rule("SB210", "mimic-self", E, "A joint mimics itself", "The definition is circular.",
         "Name the joint it should follow."),
    Rule("SB211", "mimic-cycle", E, "Mimic joints that follow each other in a cycle",
         "No joint in the cycle has an independent position; the message prints the cycle.",
         "Make one joint of the cycle independent."),
    Rule("SB212", "limits-in-degrees", W, "Angular limits that look like degrees",
         "URDF angles are radians. Revolute limits beyond 2 pi that are whole numbers from "
         "30 to 720 (90, 180, 360) were almost certainly written in degrees.",
         "Convert to radians (180 -> 3.14159); where a symmetric range of half a turn or "
         "more each way stands for no limit, make the joint continuous."),
    Rule("SB213", "soft-limits-outside", W, "safety_controller soft limits outside the hard limits",
         "soft_lower_limit must be >= lower and soft_upper_limit <= upper (and soft lower <= "
         "soft upper), or the safety controller allows what the joint cannot do.",
         "Bring the soft limits inside the hard ones."),
    Rule("SB214", "limits-ignored", N, "Position limits on a continuous joint are ignored",
         "Continuous joints have no position limits; lower and upper are read by nothing.",
         "Remove them, or make the joint revolute."),
    Rule("SB217", "mimic-outside-limits", W,
         "A mimic joint the joint it follows takes outside its own limits",
         "multiplier x followed + offset, over the followed joint's range, leaves the mimic "
         "joint's own limits by more than a twentieth of its range: the description "
         "contradicts itself. A simulator that enforces the limit holds the joint there, "
         "and the linkage does not follow; servicebot's fk refuses those values. Often a "
         "multiplier of the wrong sign.",
         "Fix the multiplier's sign or the offset, or widen the mimic joint's limits."),
    # -- inertia ---------------------------------------------------------------------------------
    Rule("SB215", "wheel-without-velocity-limit", W, "A drive wheel without a velocity limit",
         "A continuous joint that turns a wheel of a differential drive (its link carries a "
         "cylinder turning about the joint axis, on the left or right) has no <limit "
         "velocity>. `servicebot drive` refuses such a robot, since nothing bounds the wheel "
         "speed it may command; urdfdom, Gazebo and diff_drive_controller accept it.",
         "Add <limit effort=\"...\" velocity=\"...\"/> with the motor's top speed in rad/s."),
    Rule("SB216", "negative-dynamics", E, "A negative <dynamics> damping or friction",
         "Damping and friction resist motion; a negative value drives it. Pinocchio refuses "
         "a negative friction (its dry friction's minimum above its maximum). A negative "
         "damping every consumer reads, and a simulator then feeds the joint energy: a "
         "warning.",
         "Write the magnitude, or 0 for none."),
    Rule("SB301", "inertia-mismatch", W, "Inertia does not match the mass and collision geometry",
         "The principal moments of the inertia are compared, in any frame, with those of a "
         "solid of the link's mass filling its collision geometry (boxes, cylinders and "
         "spheres by formula, closed meshes by their volume). Beyond a factor (2 by default, "
         "inertia-factor in the settings) the values are printed with the ones that match. "
         "Collision geometry under 1 cm^3 that the mass would make denser than any material "
         "is a placeholder (Baxter's 1 mm spheres): the visual geometry stands for the body "
         "where its volume is known (primitives, closed meshes), else nothing is compared. "
         "Where the collision geometry holds an open mesh (no volume), the inertia is only "
         "bounded: no mass within R of its centre has a moment over m R^2, R reaching the "
         "farthest corner of the link's shapes; ten times that is reported.",
         "Use the printed values, or compute the inertia from CAD."),
    Rule("SB302", "negative-mass", E, "A negative mass",
         "Mass is positive or zero; no body has a negative mass.",
         "Write the link's mass in kg."),
    Rule("SB303", "massless-moving-link", W, "A moving joint that moves nothing with mass",
         "A joint other than fixed whose child link, and everything attached below it, has "
         "no mass (zero, or no <inertial>): dynamics are singular and simulators drop or "
         "refuse the link. An error when the description is meant for a simulator (it has "
         "<gazebo> elements, or a ros2_control hardware plugin for Gazebo, Ignition or gz); "
         "a warning otherwise, since kinematic-only descriptions (MoveIt configurations, "
         "RViz models) are valid without masses. Massless frames on fixed joints (tool "
         "frames, sensor frames) are fine and not reported.",
         "Give the moving link its mass and inertia."),
    Rule("SB304", "missing-inertial", W, "A moving link without <inertial>",
         "The link is moved by a joint but has no mass of its own or of links fixed to it; "
         "links further down, past other moving joints, do. Gazebo (sdformat) drops a "
         "massless link with everything below it, KDL ignores it: an error when the "
         "description is meant for a simulator (as for SB303), a warning otherwise. Links "
         "fixed to it (a gripper on a flange link) lend it their mass: sdformat and Pinocchio "
         "merge them, so that is not reported. A fixed joint that a <gazebo reference> keeps "
         "apart (disableFixedJointLumping, preserveFixedJoint) is not merged: its child needs "
         "mass of its own, an error.",
         "Add an <inertial>, or merge the link into its child."),
    Rule("SB305", "zero-mass", W, "Zero mass on a moving link",
         "The link is moved by a joint and has mass 0 (links below it have mass).",
         "Give the link its mass, or merge it into its child."),
    Rule("SB306", "inertia-not-positive", E, "An inertia matrix that is not positive definite",
         "A principal moment is negative (or the matrix is not symmetric positive): no body "
         "has such an inertia, and simulators explode. The principal moments are printed.",
         "Compute the inertia again (solid formulas, or from CAD)."),
    Rule("SB307", "singular-inertia", W, "Mass with a zero principal moment of inertia",
         "A point or a rod: physically possible in the limit, but simulators need all three "
         "moments positive. A zero principal moment (a rod: 0, I, I) Gazebo and Pinocchio take, "
         "and MuJoCo refuses on any link ('inertia must have positive eigenvalues', or once "
         "its boundinertia raised it, 'A + B >= C'): the message says so where MuJoCo "
         "refuses it, an error in a file meant for MuJoCo (a <mujoco> block, or a MuJoCo "
         "ros2_control plugin). A point mass (no inertia at all) on a link a joint moves, with "
         "no fixed child whose inertia Gazebo and MuJoCo lump into it, is an error: MuJoCo "
         "refuses the robot.",
         "Give the link a small realistic inertia (or set <compiler boundinertia=\"1e-6\" "
         "balanceinertia=\"true\"/> in the file's <mujoco> block)."),
    Rule("SB308", "triangle-inequality", E, "Principal moments that break the triangle inequality",
         "For any body each principal moment is at most the sum of the other two "
         "(Ixx + Iyy >= Izz ...); the printed moments cannot belong to a real body. Two zero "
         "moments (0, 0, I) count on a link a joint moves; on a link fixed to another, which "
         "consumers lump into it, they are SB307. Missed by a rounding of the file's numbers "
         "(within a millionth), a warning: Gazebo and Pinocchio take it, MuJoCo, which tests "
         "A + B >= C exactly, refuses it.",
         "Compute the inertia again (solid formulas, or from CAD)."),
    Rule("SB309", "root-link-inertia", N, "The root link carries inertia",
         "KDL (robot_state_publisher, many ROS tools) ignores the root link's inertia and "
         "warns; Pinocchio and Gazebo use it.",
         "If KDL users matter, add a massless base_footprint root with a fixed joint."),
    Rule("SB310", "inertia-without-mass", E, "Mass 0 with a non-zero inertia",
         "Inertia is the integral of r^2 dm: a body without mass has none. A link with "
         "<mass value=\"0\"> and non-zero moments is no body at all; each consumer reads it "
         "differently (a massless frame, a body that turns but does not translate). The "
         "root link is the exception, a warning: pybullet reads its mass 0 as a base fixed "
         "to the world (cartpole.urdf, kuka_iiwa), whose inertia moves nothing.",
         "Give the link its real mass, or zero the inertia for a massless frame."),
    Rule("SB311", "implausible-mass", E, "A mass or inertia no robot's link has",
         "A mass over 1e12 kg or an inertia component over 1e12 kg m^2 is a unit or typing "
         "error (two links of 1e308 kg make the total mass infinite and Pinocchio's gravity "
         "torques NaN; an ixx of 1e13 beside 1 breaks the triangle inequality MuJoCo holds "
         "inertias to). The other inertia rules do not compute with such values.",
         "Write the mass in kg and the inertia in kg m^2."),
    # -- geometry and files ----------------------------------------------------------------------
    Rule("SB401", "mesh-not-found", E, "A mesh file cannot be found",
         "Relative paths resolve from the URDF's directory, file:// from the root, "
         "package://PKG/PATH in PKG's directory (found as in SB408). The package was found, "
         "but the file is not in it, or the path names no file, or a URI scheme no reader "
         "resolves (only package://, file://, Gazebo's model:// and http(s):// are). A "
         "package that is nowhere is SB408 instead.",
         "Fix the path."),
    Rule("SB402", "mesh-unloadable", E, "A mesh file cannot be loaded",
         "The file exists but is not a mesh that trimesh (or the built-in STL, OBJ and "
         "COLLADA readers) can read, or it is an OBJ that Assimp, the reader of RViz, Gazebo, "
         "MoveIt and Pinocchio, reads wrong: a vertex number without a digit before its "
         "point ('v .1 0 0') is not counted, and the vertex is dropped.",
         "Export the mesh again as STL, OBJ or DAE."),
    Rule("SB403", "mesh-empty", E, "A mesh with no triangles", "Nothing would be drawn or collide.",
         "Export the mesh again."),
    Rule("SB404", "mesh-scale", W, "A mesh of implausible size",
         "A mesh larger than 20 m or smaller than 1 mm across (after scale) is usually in the "
         "wrong unit: a mesh in millimetres is 1000 times too large. A description of one "
         "massless link (a ground plane, a scene) may be of any size.",
         "Set <mesh scale=\"0.001 0.001 0.001\"> or export in metres."),
    Rule("SB405", "non-positive-size", E, "A primitive with a zero or negative size",
         "Box sizes, cylinder radius and length, and sphere radius must be positive. A "
         "visual of zero size only draws nothing (upkie_description marks its frames with "
         "<box size=\"0 0 0\"/>): a warning.",
         "Write the real size in metres."),
    Rule("SB406", "unknown-geometry", E, "A <geometry> with no shape or an unknown one",
         "URDF geometry is one of box, cylinder, sphere or mesh.",
         "Use one of those shapes (a capsule: a cylinder and two spheres)."),
)
URDF_RULES += (
    Rule("SB408", "package-not-found-for-meshes", W, "Meshes in a package that is nowhere",
         "One finding per file and package, saying how many meshes it hides. A package is "
         "looked for as ROS does, with no ROS installed: --package NAME=DIR; the package "
         "holding the file (the nearest package.xml, by its <name>); every package of the "
         "enclosing colcon workspace or repository (skipping COLCON_IGNORE, AMENT_IGNORE, "
         "CATKIN_IGNORE); ROS_PACKAGE_PATH; AMENT_PREFIX_PATH (PREFIX/share/NAME); "
         "directories named NAME on those paths; a Gazebo model://NAME on GAZEBO_MODEL_PATH "
         "and GZ_SIM_RESOURCE_PATH too. A missing package is the environment, not "
         "the file (check_urdf accepts it), so a warning: the meshes are not checked.",
         "Pass --package NAME=DIR, or check from the workspace that holds the package."),
    Rule("SB409", "package-not-ros", W, "A package only some loaders would find",
         "The package resolved, but not the way ROS finds packages: a directory named NAME "
         "above the file (Pinocchio and yourdfpy read example-robot-data this way), NAME/ "
         "beside the file (pybullet_data's package://meshes/), or package:///abs/path. "
         "robot_state_publisher, RViz and Gazebo would not find the meshes. Gazebo's "
         "model://NAME/ (found on GAZEBO_MODEL_PATH or GZ_SIM_RESOURCE_PATH, else as package "
         "NAME, which gazebo_ros puts on the model path) is read by Gazebo alone. A xacro "
         "$(find NAME) found only as a directory named NAME: ROS's xacro fails on the file. "
         "One finding per file and package; --format json says how each package was found.",
         "Give the package a package.xml with its <name>, or use paths relative to the file."),
    Rule("SB410", "remote-mesh", N, "Meshes fetched over the network",
         "http:// and https:// meshes (Gazebo Fuel models) are fetched by Gazebo when the "
         "model loads; check never downloads them, so they are neither missing nor checked.",
         None),
    Rule("SB407", "capsule", W, "A <capsule>, which URDF defines from version 1.1 on",
         "urdfdom reads a capsule only in a <robot version=\"1.1\"> (or later): in any other "
         "file it drops the whole <visual> or <collision>, and Pinocchio and Gazebo lose it "
         "(an error). In a 1.1 file, urdfdom and Pinocchio read it, while older URDF readers "
         "(ROS 1's, pybullet aside) drop the shape: a warning.",
         "Set version=\"1.1\", or use a cylinder and two spheres."),
)
