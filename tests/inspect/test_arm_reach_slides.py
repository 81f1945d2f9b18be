"""inspect's arm reach is a bound: a prismatic joint's travel belongs in it.

A 2 m rail under a 1.2 m arm was 'at most 1.2 m' while fk put the tool 2.7 m from the rail
and ik's out-of-reach test used 3.2 m; Piper's 0.038 m finger stroke was left out too.
"""

from __future__ import annotations

import json
import math

INERTIAL = ('<inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" '
            'ixz="0" iyz="0"/></inertial>')


def _joint(name: str, kind: str, parent: str, child: str, axis: str, origin: str = "0 0 0",
           limits: str = 'lower="-3" upper="3"') -> str:
    return (f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
            f'<origin xyz="{origin}"/><axis xyz="{axis}"/><limit {limits} effort="10" '
            'velocity="1"/></joint>')


RAILBOT = ('<robot name="railbot"><link name="world"/>'
           + "".join(f'<link name="{n}">{INERTIAL}</link>' for n in ("carriage", "l1", "l2", "l3"))
           + _joint("rail", "prismatic", "world", "carriage", "1 0 0", limits='lower="0" upper="2"')
           + _joint("j1", "revolute", "carriage", "l1", "0 0 1", "0 0 0.5")
           + _joint("j2", "revolute", "l1", "l2", "0 1 0")
           + _joint("j3", "revolute", "l2", "l3", "0 1 0", "0 0 0.4")
           + '<joint name="tool_joint" type="fixed"><parent link="l3"/><child link="tool0"/>'
           '<origin xyz="0 0 0.3"/></joint><link name="tool0"/></robot>')


def test_a_rails_travel_is_part_of_the_arms_reach(run, tmp_path):
    path = tmp_path / "railbot.urdf"
    path.write_text(RAILBOT)
    result = run("inspect", path, "--section", "totals", "--format", "json")
    assert json.loads(result.stdout)["totals"]["arm"] == {
        "shoulder": "rail", "tip": "tool0", "reach_m": 3.2, "travel_m": 2.0}
    text = run("inspect", path, "--section", "totals").stdout
    assert "3.2 m, rail to tool0, at most (its links end to end, its slides out by 2 m)" in text
    # the bound holds where fk puts the tool, rail out and arm level
    fk = run("fk", path, "-j", "rail=2", "-j", f"j2={math.pi / 2}", "--format", "json")
    x_m, _, z_m = json.loads(fk.stdout)["poses"][0]["position_m"]
    assert math.hypot(x_m, z_m) <= 3.2 and x_m > 2.69
    ik = run("ik", path, "--position", "9", "0", "0.6", "--allow-collisions")
    assert "beyond the arm's reach (3.2 m from joint 'rail')" in ik.output


def test_a_lift_under_the_arm_is_part_of_its_reach(run, tmp_path):
    """A vertical lift, its shoulder straight above it: the reach started at the shoulder
    (the lift's segment runs along its own axis), leaving out the lift's metre of travel
    that ik's bound holds."""
    lift = RAILBOT.replace('"rail" type="prismatic"', '"lift" type="prismatic"').replace(
        '<axis xyz="1 0 0"/><limit lower="0" upper="2"', '<axis xyz="0 0 1"/><limit lower="0" '
        'upper="1"')
    path = tmp_path / "liftbot.urdf"
    path.write_text(lift)
    result = run("inspect", path, "--section", "totals", "--format", "json")
    assert json.loads(result.stdout)["totals"]["arm"] == {
        "shoulder": "lift", "tip": "tool0", "reach_m": 2.2, "travel_m": 1.0}
    ik = run("ik", path, "--position", "9", "0", "0.6", "--allow-collisions")
    assert "beyond the arm's reach (2.2 m from joint 'lift')" in ik.output


def test_of_two_equal_fingers_the_reach_ends_where_fk_and_ik_go(run, tmp_path):
    """The WAM's BarrettHand: inspect's reach ended at the first finger's tip, fk and ik
    (without --frame) took the second's: the reach was not that of the frame ik moves."""
    fingers = "".join(
        _joint(f"{side}1", "revolute", "palm", f"{side}_prox", "1 0 0", f"0 {y} 0.05",
               'lower="0" upper="1"')
        + f'<joint name="{side}2" type="fixed"><parent link="{side}_prox"/>'
        f'<child link="{side}_tip"/><origin xyz="0 0 0.05"/></joint>'
        for side, y in (("fa", 0.02), ("fb", -0.02)))
    links = ("l1", "l2", "palm", "fa_prox", "fa_tip", "fb_prox", "fb_tip")
    robot = tmp_path / "hand.urdf"
    robot.write_text('<robot name="h"><link name="base_link"/>'
                     + "".join(f'<link name="{n}"/>' for n in links)
                     + _joint("j1", "revolute", "base_link", "l1", "0 0 1", "0 0 0.1")
                     + _joint("j2", "revolute", "l1", "l2", "0 1 0", "0 0 0.1")
                     + _joint("j3", "revolute", "l2", "palm", "0 1 0", "0 0 0.3")
                     + fingers + "</robot>")
    fk = run("fk", robot)
    assert "using 'fb_tip'" in fk.stderr
    arm = json.loads(run("inspect", robot, "--format", "json").stdout)["totals"]["arm"]
    assert arm["tip"] == "fb_tip"


def test_the_reach_ends_at_the_frame_fk_moves_not_at_a_deeper_camera(run, tmp_path):
    """Trossen's wxai: a camera's optical frame, three fixed frames down the last link, was
    the tip (0.064 m here) while fk and ik move the gripper frame 0.3 m out: the bound
    stated was short of where fk puts the tool."""
    camera = ('<joint name="mount_j" type="fixed"><parent link="l3"/><child link="cam_mount"/>'
              '<origin xyz="0.05 0 0.02"/></joint><link name="cam_mount"/>'
              '<joint name="cam_j" type="fixed"><parent link="cam_mount"/><child '
              'link="cam_link"/><origin xyz="0.01 0 0"/></joint><link name="cam_link"/>'
              '<joint name="optical_j" type="fixed"><parent link="cam_link"/><child '
              'link="cam_optical"/></joint><link name="cam_optical"/>')
    path = tmp_path / "camarm.urdf"
    path.write_text(RAILBOT.replace("tool0", "ee_gripper_link").replace("</robot>",
                                                                         camera + "</robot>"))
    fk = run("fk", path, "--format", "json")
    assert json.loads(fk.stdout)["poses"][0]["frame"] == "ee_gripper_link"
    result = run("inspect", path, "--section", "totals", "--format", "json")
    assert json.loads(result.stdout)["totals"]["arm"] == {
        "shoulder": "rail", "tip": "ee_gripper_link", "reach_m": 3.2, "travel_m": 2.0}


def test_a_slide_whose_tool_sits_on_its_carriage_reaches_its_travel(run, tmp_path):
    """OnRobot's 2FG7: each finger's tip frame is fixed to its slide's carriage with no
    offset. The slide's segment has no length, so the reach started below it: 'arm reach
    0 m', where ik bounds it by the slide's 0.3 m."""
    path = tmp_path / "slide.urdf"
    path.write_text('<robot name="slide"><link name="base_link"/><link name="carriage">'
                    f'{INERTIAL}</link><link name="finger"/>'
                    + _joint("slide_joint", "prismatic", "base_link", "carriage", "1 0 0",
                             "0 0 0.12", limits='lower="0" upper="0.3"')
                    + '<joint name="finger_joint" type="fixed"><parent link="carriage"/>'
                    '<child link="finger"/></joint></robot>')
    result = run("inspect", path, "--section", "totals", "--format", "json")
    assert json.loads(result.stdout)["totals"]["arm"] == {
        "shoulder": "slide_joint", "tip": "finger", "reach_m": 0.3, "travel_m": 0.3}
    ik = run("ik", path, "-f", "finger", "--position", "0.5", "0", "0.12")
    assert "beyond the arm's reach (0.3 m from joint 'slide_joint')" in ik.output
