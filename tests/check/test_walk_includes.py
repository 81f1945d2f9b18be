"""A directory walk leaves out includes laid out as real description packages lay them out."""

from __future__ import annotations

import json
from pathlib import Path

from servicebot_cli.check.files import walk

XACRO_NS = 'xmlns:xacro="http://www.ros.org/wiki/xacro"'
ROBOT = f'<robot name="r" {XACRO_NS}><link name="base"/></robot>'


def _walked(directory: Path, files: dict[str, str]) -> list[str]:
    for name, text in files.items():
        (directory / name).parent.mkdir(parents=True, exist_ok=True)
        (directory / name).write_text(text)
    return [p.relative_to(directory).as_posix() for p in walk(directory)]


def test_an_unnamed_urdf_placeholder_or_xacro_snippet_is_an_include(tmp_path):
    # husky's empty.urdf, the default of $(optenv HUSKY_URDF_EXTRAS empty.urdf), and
    # jackal's custom_example.urdf: macro calls and joints for JACKAL_URDF_EXTRAS
    walked = _walked(tmp_path, {
        "robot.urdf": ROBOT,
        "empty.urdf": "<robot>\n  <!-- placeholder -->\n</robot>\n",
        "custom_example.urdf": '<robot><xacro:camera_mount prefix="front"/><joint name="j" '
                               'type="fixed"><parent link="a"/><child link="b"/></joint></robot>',
        "no_name.urdf": '<robot><link name="base"/></robot>',
    })
    # a plain URDF that only lacks its name is still checked: SB009 tells it
    assert walked == ["no_name.urdf", "robot.urdf"]


def test_a_xacro_of_properties_only_is_an_include(tmp_path):
    # kobuki's common_properties.urdf.xacro: a named <robot> with properties and no link
    walked = _walked(tmp_path, {
        "common_properties.urdf.xacro": f'<robot name="xacro_properties" {XACRO_NS}>'
        '<xacro:property name="M_PI" value="3.14159"/><xacro:property name="white">'
        '<material name="white"><color rgba="1 1 1 1"/></material></xacro:property></robot>',
        "kobuki.urdf.xacro": ROBOT,
    })
    assert walked == ["kobuki.urdf.xacro"]


def test_a_robot_file_that_only_includes_its_parts_is_still_a_robot(tmp_path):
    # articubot_one's robot.urdf.xacro includes robot_core.xacro, which holds the links
    walked = _walked(tmp_path, {
        "robot.urdf.xacro": f'<robot name="robot" {XACRO_NS}><xacro:arg name="sim" '
        'default="false"/><xacro:include filename="$(arg parts)"/></robot>',
    })
    assert walked == ["robot.urdf.xacro"]


def test_a_xacro_with_another_root_is_an_include(tmp_path):
    # PR2's sensors/prosilica_gc2450_camera.urdf.xacro: <root xmlns:xacro=...> holding a macro
    walked = _walked(tmp_path, {
        "camera.urdf.xacro": f'<?xml version="1.0"?>\n<root {XACRO_NS}><xacro:macro '
        'name="cam" params="parent"><link name="cam"/></xacro:macro></root>',
        "world.xacro": '<sdf version="1.6"><world name="w"/></sdf>',
        "robot.urdf.xacro": ROBOT,
    })
    # a xacro file that is not a robot and not a xacro include is still checked (SB008)
    assert walked == ["robot.urdf.xacro", "world.xacro"]


def test_moveit_srdf_xacro_is_not_a_urdf(tmp_path):
    walked = _walked(tmp_path, {
        "panda_arm.srdf.xacro": f'<robot name="panda" {XACRO_NS}><group name="arm">'
        '<chain base_link="l0" tip_link="l8"/></group></robot>',
        "panda.urdf.xacro": ROBOT,
    })
    assert walked == ["panda.urdf.xacro"]


def test_what_a_srdf_xacro_includes_is_semantic_too(tmp_path):
    # husky_manipulation: panda.srdf.xacro includes config/arm.xacro, the arm's <group> and
    # <disable_collisions> in a <robot> of their own, which reads $(arg arm_id)
    walked = _walked(tmp_path, {
        "urdf/robot.urdf.xacro": ROBOT,
        "config/panda.srdf.xacro": f'<robot name="panda" {XACRO_NS}>'
                                   '<xacro:include filename="arm.xacro"/></robot>',
        "config/arm.xacro": f'<robot name="$(arg arm_id)" {XACRO_NS}><group name="arm">'
                            '<chain base_link="$(arg arm_id)_link0" tip_link="x"/></group>'
                            '<group_state name="ready" group="arm"><joint name="j1" value="0"/>'
                            '</group_state></robot>',
    })
    assert walked == ["urdf/robot.urdf.xacro"]


def test_a_robot_file_a_srdf_xacro_includes_is_still_checked(tmp_path):
    """A .srdf.xacro may include the robot's own xacro (for its arguments or macros): that
    file defines joints, so it is a robot, and the walk still checks it."""
    walked = _walked(tmp_path, {
        "config/bot.srdf.xacro": f'<robot name="bot" {XACRO_NS}>'
                                 '<xacro:include filename="../urdf/robot.urdf.xacro"/>'
                                 '<group name="arm"><chain base_link="a" tip_link="b"/></group>'
                                 '</robot>',
        "urdf/robot.urdf.xacro": f'<robot name="r" {XACRO_NS}><link name="a"/><link name="b"/>'
                                 '<joint name="j" type="revolute"><parent link="a"/>'
                                 '<child link="b"/></joint></robot>',
    })
    assert walked == ["urdf/robot.urdf.xacro"]


def test_a_directory_of_includes_only_passes_with_nothing_to_check(run, tmp_path):
    # pal_urdf_utils: deg_to_rad.xacro, pi.xacro, materials.urdf.xacro, all libraries;
    # pre-commit runs "servicebot check urdf ." at its root
    _walked(tmp_path, {
        "urdf/pi.xacro": f'<robot {XACRO_NS}><xacro:property name="M_PI" value="3.14"/></robot>',
        "urdf/materials.urdf.xacro": f'<robot name="materials" {XACRO_NS}>'
                                     '<xacro:property name="grey" value="0.5"/></robot>',
    })
    result = run("check", "urdf", tmp_path, "--isolated")
    assert result.exit_code == 0, result.output
    assert (f"0 files checked ({tmp_path} holds only xacro includes, 2 files, checked through "
            "the robot files that include them): 0 errors") in result.stdout
    summary = json.loads(run("check", "urdf", tmp_path, "--isolated", "--format", "json").stdout)
    assert summary["summary"]["includes_only"] == [{"directory": str(tmp_path), "files": 2}]
    empty = tmp_path / "empty"
    empty.mkdir()
    assert run("check", "urdf", empty, "--isolated").exit_code == 2


def test_an_include_of_an_include_is_not_a_robot(run, tmp_path):
    """VRX's wamv_gazebo: the robot includes a macro file, which includes macros.xacro, a
    named <robot> that only includes the sensor macros. The walk checked it alone: SB109,
    'the robot has no <link>', exit 1."""
    urdf = tmp_path / "boat_description" / "urdf"
    urdf.mkdir(parents=True)
    (urdf.parent / "package.xml").write_text(
        "<package format=\"3\"><name>boat_description</name></package>")
    head = '<?xml version="1.0"?>\n<robot xmlns:xacro="http://ros.org/wiki/xacro"'
    find = "$(find boat_description)/urdf"
    (urdf / "boat.urdf.xacro").write_text(
        f'{head} name="boat">\n  <xacro:include filename="{find}/boat_macro.xacro"/>\n'
        "  <xacro:boat/>\n</robot>\n")
    (urdf / "boat_macro.xacro").write_text(
        f'{head}>\n  <xacro:include filename="{find}/macros.xacro"/>\n'
        '  <xacro:macro name="boat">\n    <link name="base_link"/>\n'
        '    <xacro:sensor_link name="imu"/>\n  </xacro:macro>\n</robot>\n')
    (urdf / "macros.xacro").write_text(
        f'{head} name="BOAT">\n  <xacro:include filename="{find}/sensor.xacro"/>\n</robot>\n')
    (urdf / "sensor.xacro").write_text(
        f'{head}>\n  <xacro:macro name="sensor_link" params="name">\n'
        '    <link name="${name}_link"/>\n    <joint name="${name}_joint" type="fixed">\n'
        '      <parent link="base_link"/><child link="${name}_link"/>\n    </joint>\n'
        "  </xacro:macro>\n</robot>\n")
    result = run("check", "urdf", tmp_path / "boat_description", "--isolated", "--format",
                 "json")
    assert result.exit_code == 0, result.stdout
    assert [report["file"].rsplit("/", 1)[-1] for report in
            json.loads(result.stdout)["files"]] == ["boat.urdf.xacro"]


def _package(root: Path, name: str, files: dict[str, str]) -> None:
    (root / name).mkdir(parents=True)
    (root / name / "package.xml").write_text(
        f'<?xml version="1.0"?><package format="3"><name>{name}</name></package>')
    for file, text in files.items():
        (root / name / file).parent.mkdir(parents=True, exist_ok=True)
        (root / name / file).write_text(text)


def test_a_robot_whose_every_includer_needs_a_launch_argument_is_checked_alone(run, tmp_path):
    """Ekumen's andino: andino_gz_classic's xacro includes the complete andino.urdf.xacro
    and reads $(arg ...) with no default, so a walk cannot expand it: the robot was left out
    as an include and never checked, and the walk passed."""
    src = tmp_path / "ws" / "src"
    _package(src, "bot_description", {"urdf/bot.urdf.xacro": (
        f'<robot name="bot" {XACRO_NS}><link name="base"/><link name="arm"/>'
        '<joint name="j" type="fixed"><parent link="base"/><child link="arm_missing"/>'
        '</joint></robot>')})
    sim = (f'<robot name="sim" {XACRO_NS}><xacro:include filename='
           '"$(find bot_description)/urdf/bot.urdf.xacro"/>'
           '<xacro:if value="$(arg use_sim)"><gazebo/></xacro:if></robot>')
    _package(src, "bot_gazebo", {"urdf/sim.xacro": sim})
    result = run("check", src, "--isolated", "--format", "json")
    reports = {Path(f["file"]).name: [x["code"] for x in f["findings"]]
               for f in json.loads(result.stdout)["files"]}
    assert result.exit_code == 1
    assert reports["sim.xacro"] == ["SB006"]
    assert "SB103" in reports["bot.urdf.xacro"]
    # an includer that expands checks the robot with it: not alone as well
    (src / "bot_gazebo" / "urdf" / "sim.xacro").write_text(sim.replace("$(arg use_sim)", "1"))
    result = run("check", src, "--isolated", "--format", "json")
    assert [Path(f["file"]).name for f in json.loads(result.stdout)["files"]] == ["sim.xacro"]


def test_a_file_of_constants_whose_includer_needs_an_argument_is_not_checked_alone(run,
                                                                                   tmp_path):
    """unitree_ros's aliengoZ1 robot.xacro needs DEBUG:=, which its launch files pass; the
    const.xacro it includes (a named robot of properties and one include) was then checked
    alone, and failed with SB109 "the robot has no <link>"."""
    src = tmp_path / "ws" / "src"
    _package(src, "dog_description", {
        "xacro/robot.xacro": (f'<robot name="dog" {XACRO_NS}><xacro:include '
                              'filename="$(find dog_description)/xacro/const.xacro"/>'
                              '<xacro:if value="$(arg DEBUG)"><link name="debug"/></xacro:if>'
                              '<link name="trunk"/></robot>'),
        "xacro/const.xacro": (f'<robot name="dog" {XACRO_NS}>'
                              '<xacro:include filename="base_const.xacro"/>'
                              '<xacro:property name="offset" value="${length / 2}"/></robot>'),
        "xacro/base_const.xacro": (f'<robot name="base" {XACRO_NS}>'
                                   '<xacro:property name="length" value="0.5"/></robot>')})
    result = run("check", src, "--isolated", "--format", "json")
    reports = {Path(f["file"]).name: [x["code"] for x in f["findings"]]
               for f in json.loads(result.stdout)["files"]}
    assert reports == {"robot.xacro": ["SB006"]}  # DEBUG: check it by name with DEBUG:=...
    assert result.exit_code == 0, result.stdout


def test_a_part_hung_from_its_includers_links_is_not_checked_alone(run, tmp_path):
    """stretch's stretch_aruco.xacro hangs from base_link and link_lift of the robot file
    that includes it; that file could not be expanded (an include the repository lacks),
    and checked alone the part gave SB103 for every link it hangs from."""
    src = tmp_path / "ws" / "src"
    _package(src, "bot_description", {
        "urdf/robot.xacro": (f'<robot name="bot" {XACRO_NS}><link name="base_link"/>'
                             '<xacro:include filename="missing_wrist.xacro"/>'
                             '<xacro:include filename="markers.xacro"/></robot>'),
        "urdf/markers.xacro": (f'<robot name="markers" {XACRO_NS}><link name="marker"/>'
                               '<joint name="m" type="fixed"><parent link="base_link"/>'
                               '<child link="marker"/></joint><link name="marker2"/>'
                               '<joint name="m2" type="fixed"><parent link="link_lift"/>'
                               '<child link="marker2"/></joint></robot>')})
    result = run("check", src, "--isolated", "--format", "json")
    reports = {Path(f["file"]).name: [x["code"] for x in f["findings"]]
               for f in json.loads(result.stdout)["files"]}
    assert reports == {"robot.xacro": ["SB001"]}


def test_a_defect_in_a_shared_include_names_the_robot_checked(run, tmp_path):
    """ros2_kortex: two robot files include kortex_robot.xacro, which fails on a parameter
    both pass; the text report printed the same include's line twice, naming neither robot."""
    src = tmp_path / "ws" / "src"
    macro = (f'<robot {XACRO_NS}><xacro:macro name="arm" params="prefix">'
             '<link name="${prefix}base"/></xacro:macro>'
             '<xacro:macro name="load_robot" params="prefix">'
             '<xacro:arm prefix="${prefix}" gripper="none"/></xacro:macro></robot>')
    robot = (f'<robot name="{{}}" {XACRO_NS}><xacro:include filename="arm.xacro"/>'
             '<xacro:load_robot prefix="{{}}_"/></robot>')
    _package(src, "arm_description", {"urdf/arm.xacro": macro,
                                       "urdf/left.urdf.xacro": robot.format("left", "left"),
                                       "urdf/right.urdf.xacro": robot.format("right", "right")})
    result = run("check", src, "--isolated")
    lines = result.stdout.splitlines()
    failing = [i for i, line in enumerate(lines) if " error SB006 " in line]
    assert len(failing) == 2 and all("arm.xacro:" in lines[i] for i in failing)
    assert sorted(lines[i + 1].strip() for i in failing) == [
        f"while checking {src / 'arm_description/urdf/left.urdf.xacro'}",
        f"while checking {src / 'arm_description/urdf/right.urdf.xacro'}"]
    one = run("check", src / "arm_description/urdf/left.urdf.xacro", "--isolated")
    assert "while checking" not in one.stdout  # one file named: the report is its own
    annotations = [line for line in run("check", src, "--isolated", "--format",
                                         "github").stdout.splitlines() if "SB006" in line]
    assert len(annotations) == 2 and all(
        line.startswith(f"::error file={src / 'arm_description/urdf/arm.xacro'},")
        for line in annotations)  # one line each, the robot checked after an escaped break
    assert sorted(line.rsplit("%0A", 1)[1] for line in annotations) == [
        f"while checking {src / 'arm_description/urdf/left.urdf.xacro'}",
        f"while checking {src / 'arm_description/urdf/right.urdf.xacro'}"]


def test_a_part_whose_includer_stopped_at_a_missing_package_is_not_checked_alone(run,
                                                                                 tmp_path):
    """TIAGo includes pmb2_description (not installed), then gazebo.urdf.xacro, which reads
    its includer's 'is_multiple': checked alone, it failed (SB006), an error where a missing
    package is a warning (SB007)."""
    package = tmp_path / "ws" / "src" / "mybot"
    (package / "robots").mkdir(parents=True)
    (package / "gazebo").mkdir()
    (package / "package.xml").write_text("<package format='3'><name>mybot</name></package>")
    (package / "robots" / "mybot.urdf.xacro").write_text(
        '<robot name="mybot" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'
        '  <xacro:property name="is_multiple" value="false"/>\n'
        '  <xacro:include filename="$(find other_pkg)/urdf/base.urdf.xacro"/>\n'
        '  <link name="base_link"/>\n'
        '  <xacro:include filename="$(find mybot)/gazebo/gazebo.urdf.xacro"/>\n</robot>\n')
    (package / "gazebo" / "gazebo.urdf.xacro").write_text(
        '<robot name="mybot" xmlns:xacro="http://www.ros.org/wiki/xacro">\n  <gazebo>\n'
        '    <xacro:if value="${is_multiple}"><static>false</static></xacro:if>\n'
        '  </gazebo>\n</robot>\n')
    result = run("check", "urdf", package, "--isolated", "--jobs", "1", "--format", "json")
    assert result.exit_code == 0, result.stdout
    document = json.loads(result.stdout)
    assert [f["code"] for file in document["files"] for f in file["findings"]] == ["SB007"]
