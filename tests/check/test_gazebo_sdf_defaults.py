"""Gazebo blocks as sdformat reads them (sdformat's own tests): its defaults are no defects,
what it cannot read or model is."""

from __future__ import annotations

import pytest

from tests.check.helpers import findings

ROBOT = """<robot name="r">
  <link name="base_link">
    <inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/>
    </inertial>
  </link>
  {gazebo}
</robot>
"""
IMU = ('<gazebo reference="base_link"><sensor name="imu" type="imu"><always_on>1</always_on>'
       '<update_rate>{rate}</update_rate></sensor></gazebo>')


def _found(run, tmp_path, gazebo: str) -> tuple[int, list[tuple[str, str, str]]]:
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(gazebo=gazebo))
    result = run("check", path, "--format", "json", "--isolated", "--ignore", "SB309,SB702")
    return result.exit_code, [(f["code"], f["severity"], f["message"])
                              for f in findings(result.stdout)]


def test_an_update_rate_of_0_is_every_simulation_step(run, tmp_path):
    """SDF's default: gz-sensors and Gazebo Classic update such a sensor at every step
    (SubT's contact sensors write it); it was SB502 'must be positive'."""
    assert _found(run, tmp_path, IMU.format(rate="0")) == (0, [])
    assert _found(run, tmp_path, IMU.format(rate="50")) == (0, [])


def test_a_negative_rate_is_read_as_0_and_text_is_not_read(run, tmp_path):
    code, found = _found(run, tmp_path, IMU.format(rate="-5"))
    assert code == 0 and [(c, s) for c, s, _ in found] == [("SB502", "warning")]
    assert "every simulation step, as for 0" in found[0][2]
    code, found = _found(run, tmp_path, IMU.format(rate="${rate}"))
    assert code == 1 and [(c, s) for c, s, _ in found] == [("SB502", "error")]
    assert "update_rate '${rate}' is not a number" in found[0][2]


def test_an_empty_reference_is_the_model(run, tmp_path):
    """sdformat's ParseSDFExtension reads reference="" as no reference: the block applies to
    the model. It was SB501 with 'use base_link', which moves <static> into a link."""
    block = '<gazebo reference=""><static>true</static></gazebo>'
    assert _found(run, tmp_path, block) == (0, [])
    code, found = _found(run, tmp_path, block.replace('""', '"base_lnk"'))
    assert code == 1 and [c for c, _, _ in found] == ["SB501"]


def test_a_camera_field_of_view_of_0_says_what_is_allowed(run, tmp_path):
    camera = ('<gazebo reference="base_link"><sensor name="cam" type="camera"><camera>'
              '<horizontal_fov>{fov}</horizontal_fov><image><width>640</width><height>480'
              '</height></image><clip><near>0.1</near><far>10</far></clip></camera></sensor>'
              '</gazebo>')
    messages = [m for _, _, m in _found(run, tmp_path, camera.format(fov="0"))[1]]
    assert messages == ["sensor 'cam': horizontal_fov 0 rad must be more than 0 and less "
                        "than 2 pi"]
    messages = [m for _, _, m in _found(run, tmp_path, camera.format(fov="${fov}"))[1]]
    assert messages == ["sensor 'cam': horizontal_fov is not a number"]


CHAIN = """<robot name="r">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01"
    iyz="0" izz="0.01"/></inertial></link>
  <link name="a"/>
  <link name="b"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01"
    iyz="0" izz="0.01"/></inertial></link>
  <joint name="j1" type="continuous"><parent link="base"/><child link="a"/></joint>
  <joint name="j2" type="continuous"><parent link="a"/><child link="b"/></joint>
  {gazebo}
</robot>"""


def test_a_massless_link_between_moving_joints_fails_where_gazebo_runs_it(run, tmp_path):
    """sdformat's ZeroMassIntermediateLinkWithNoFixedJoints: link 'a' and all below it are
    not modelled. It was a warning even in a file with <gazebo>, where a massless leaf link
    (SB303) is an error."""
    path = tmp_path / "r.urdf"
    path.write_text(CHAIN.format(gazebo=""))
    result = run("check", path, "--format", "json", "--isolated", "--ignore", "SB309")
    assert result.exit_code == 0
    assert [(f["code"], f["severity"]) for f in findings(result.stdout)] == [
        ("SB304", "warning")]
    path.write_text(CHAIN.format(gazebo='<gazebo reference="b"><material>Gazebo/Red</material>'
                                        '</gazebo>'))
    result = run("check", path, "--format", "json", "--isolated", "--ignore", "SB309,SB702")
    found = findings(result.stdout)
    assert result.exit_code == 1 and [(f["code"], f["severity"]) for f in found] == [
        ("SB304", "error")]
    assert found[0]["message"].endswith("; Gazebo drops it, and every link below it")


def test_a_setting_sdformat_reads_as_a_number_must_start_as_one(run, tmp_path):
    """sdformat's ParseGazeboInvalidDampingFactor: <dampingFactor>foo</dampingFactor> makes
    the conversion throw; std::stod reads ' 0.5', '1e3' and '.5', and stops at trailing text."""
    def codes(settings: str) -> list[str]:
        block = f'<gazebo reference="base_link">{settings}</gazebo>'
        return [c for c, _, _ in _found(run, tmp_path, block)[1]]

    assert codes("<mu1> 0.5</mu1><kp>1e3</kp><kd>.5</kd><maxContacts>10</maxContacts>"
                 "<dampingFactor value='0.1'/><minDepth>0.001m</minDepth>") == []
    assert codes("<dampingFactor>foo</dampingFactor>") == ["SB513"]
    # beyond the type's range, stod and stoi throw too; stoi stops at a point or an exponent
    assert codes("<kp>1e999</kp>") == ["SB513"] and codes("<mu1>-inf</mu1>") == []
    assert codes("<maxContacts>99999999999</maxContacts>") == ["SB513"]
    assert codes("<maxContacts>1e999</maxContacts>") == []
    assert codes("<mu2></mu2>") == ["SB513"]
    assert codes("<material>Gazebo/Grey</material><selfCollide>true</selfCollide>") == []


KEPT = """<robot name="r">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01"
    iyz="0" izz="0.01"/></inertial></link>
  <link name="imu"/>
  <link name="chip">{chip}</link>
  <joint name="imu_joint" type="fixed"><parent link="base"/><child link="imu"/></joint>
  <joint name="chip_joint" type="fixed"><parent link="imu"/><child link="chip"/></joint>
  <gazebo reference="imu_joint"><{setting}>true</{setting}></gazebo>
</robot>"""
MASS = ('<inertial><mass value="0.01"/><inertia ixx="1e-6" ixy="0" ixz="0" iyy="1e-6" iyz="0" '
        'izz="1e-6"/></inertial>')


@pytest.mark.parametrize("setting", ["disableFixedJointLumping", "preserveFixedJoint"])
def test_a_fixed_joint_kept_apart_needs_a_child_with_mass(run, tmp_path, setting):
    """sdformat's ZeroMassLeafLink and ZeroMassIntermediateLinkWithFixedParentJoint: with
    lumping off, a massless child of a fixed joint is not modelled, nor anything below it.
    Mass rules took every fixed child as merged into its parent: nothing was reported."""
    path = tmp_path / "r.urdf"
    path.write_text(KEPT.format(setting=setting, chip=""))
    result = run("check", path, "--format", "json", "--isolated", "--ignore", "SB309,SB702")
    found = findings(result.stdout)
    assert result.exit_code == 1 and [(f["code"], f["severity"]) for f in found] == [
        ("SB304", "error")]
    assert f"fixed joint 'imu_joint', which <{setting}> keeps a body" in found[0]["message"]
    path.write_text(KEPT.format(setting=setting, chip=MASS))  # lumped into imu: it has mass
    result = run("check", path, "--format", "json", "--isolated", "--ignore", "SB309")
    assert result.exit_code == 0 and findings(result.stdout) == []


FT = """<robot name="r">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01"
    iyz="0" izz="0.01"/></inertial></link>
  <link name="tool">{mass}</link>
  <joint name="wrist" type="{kind}"><parent link="base"/><child link="tool"/>{limit}</joint>
  <gazebo reference="wrist"><sensor name="ft" type="force_torque"><update_rate>100
    </update_rate></sensor>{setting}</gazebo>
</robot>"""


def test_a_force_torque_sensor_on_a_lumped_joint_measures_nothing(run, tmp_path):
    """sdformat's invalid_force_torque_sensor_lumped_and_reduced.urdf: 'users need to be
    wary' (its test); the joint becomes a frame, the sensor attaches to nothing."""
    def found(kind: str, setting: str = "") -> list[tuple[str, str, str]]:
        limit = '<limit lower="-1" upper="1" effort="1" velocity="1"/>' if kind != "fixed" else ""
        text = FT.format(kind=kind, limit=limit, setting=setting, mass=MASS)
        path = tmp_path / "r.urdf"
        path.write_text(text)
        result = run("check", path, "--format", "json", "--isolated", "--ignore", "SB309")
        return [(f["code"], f["severity"], f["message"]) for f in findings(result.stdout)]

    (lumped,) = found("fixed")
    assert lumped[:2] == ("SB502", "warning") and "the sensor measures nothing" in lumped[2]
    assert found("fixed", "<preserveFixedJoint>true</preserveFixedJoint>") == []
    assert found("revolute") == []


def test_a_gazebo_block_inside_a_link_and_a_sensor_on_a_joint_are_found(run, tmp_path):
    """sam_bot's diff-drive <gazebo> moved into base_link, and its lidar referenced by
    lidar_joint, passed with nothing said; sdformat reads <gazebo> under <robot> only, and
    Gazebo Classic's Joint.cc loads force_torque sensors alone ('A joint cannot load')."""
    path = tmp_path / "r.urdf"
    path.write_text(
        '<robot name="r"><link name="base_link"><gazebo><plugin name="d" '
        'filename="libgazebo_ros_diff_drive.so"/></gazebo></link><link name="lidar_link"/>'
        '<joint name="lidar_joint" type="fixed"><parent link="base_link"/>'
        '<child link="lidar_link"/></joint><gazebo reference="lidar_joint">'
        '<sensor name="lidar" type="ray"><update_rate>5</update_rate></sensor>'
        '<sensor name="ft" type="force_torque"/><preserveFixedJoint>true</preserveFixedJoint>'
        '</gazebo></robot>')
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB010,SB502")
    found = {f["code"]: f for f in findings(result.stdout)}
    assert len(findings(result.stdout)) == 2
    assert found["SB010"]["message"].startswith("<gazebo> inside <link> 'base_link': ")
    assert found["SB010"]["fix"] == 'move it under <robot> as <gazebo reference="base_link">'
    assert found["SB502"]["message"].startswith(
        "sensor 'lidar' (ray) is in <gazebo reference=\"lidar_joint\">, a joint: ")
    assert found["SB502"]["fix"].startswith('<gazebo reference="lidar_link">')


def test_camera_settings_outside_camera_leave_gazebo_its_default_camera(run, tmp_path):
    """bcr_bot's stereo camera: <horizontal_fov>, <image> and <clip> directly under <sensor>.
    sdformat reads them only inside <camera>: Gazebo ran a 320 x 240 camera, check passed."""
    camera = ('<gazebo reference="base_link"><sensor name="cam" type="camera">{inside}'
              '</sensor></gazebo>')
    settings = ("<horizontal_fov>1.5</horizontal_fov><image><width>1024</width><height>1024"
                "</height></image><clip><near>0.1</near><far>10</far></clip>")
    assert _found(run, tmp_path, camera.format(inside=f"<camera>{settings}</camera>"))[1] == []
    messages = [m for _, _, m in _found(run, tmp_path, camera.format(inside=settings))[1]]
    assert messages == ["sensor 'cam': <horizontal_fov>, <image>, <clip> directly under "
                        "<sensor>: sdformat reads them only inside <camera>, so Gazebo runs "
                        "the default camera (320 x 240, horizontal_fov 1.047, clip 0.1 to 100 m)"]
    lidar = ('<gazebo reference="base_link"><sensor name="scan" type="ray"><scan><horizontal>'
             "<samples>360</samples></horizontal></scan></sensor></gazebo>")
    (message,) = [m for _, _, m in _found(run, tmp_path, lidar)[1]]
    assert message.startswith("sensor 'scan': <scan> directly under <sensor>: sdformat reads "
                              "it only inside <ray> or <lidar>")


def test_a_roslaunch_remap_in_a_plugins_ros_does_nothing(run, tmp_path):
    """sam_bot: <remap from="cmd_vel" to="/cmd_vel"/> in the diff drive's <ros>; gazebo_ros
    reads <remapping>, so the plugin listens on /demo/cmd_vel."""
    plugin = ('<gazebo><plugin name="d" filename="libgazebo_ros_joint_state_publisher.so"><ros>'
              '<namespace>/demo</namespace>{inside}</ros></plugin></gazebo>')
    assert _found(run, tmp_path, plugin.format(
        inside="<remapping>joint_states:=/joint_states</remapping><qos/>"))[1] == []
    path = tmp_path / "r.urdf"
    path.write_text(ROBOT.format(gazebo=plugin.format(
        inside='<remap from="joint_states" to="/joint_states"/>')))
    result = run("check", path, "--format", "json", "--isolated", "--select", "SB518")
    ((severity, message, fix),) = [(f["severity"], f["message"], f["fix"])
                                   for f in findings(result.stdout)]
    assert severity == "warning" and "<remap> in <ros>: gazebo_ros reads only" in message
    assert fix == "write <remapping>joint_states:=/joint_states</remapping>"
