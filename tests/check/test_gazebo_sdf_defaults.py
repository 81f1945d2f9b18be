"""Gazebo blocks as sdformat reads them: its defaults are no defects (sdformat's own tests)."""

from __future__ import annotations

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
