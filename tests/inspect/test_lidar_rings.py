"""inspect shows a 3D lidar's rings (its <vertical> scan), not its horizontal scan alone."""

from __future__ import annotations

import pytest

RAY = """<robot name="r"><link name="base"/><link name="lidar"/>
<joint name="j" type="fixed"><parent link="base"/><child link="lidar"/></joint>
<gazebo reference="lidar"><sensor type="ray" name="scanner"><update_rate>10</update_rate>
<ray><scan><horizontal><samples>440</samples><resolution>1</resolution>
<min_angle>-3.14159</min_angle><max_angle>3.14159</max_angle></horizontal>{vertical}</scan>
<range><min>0.3</min><max>131</max><resolution>0.001</resolution></range></ray>
<plugin name="p" filename="libgazebo_ros_ray_sensor.so"><ros><remapping>~/out:=points</remapping>
</ros><output_type>sensor_msgs/PointCloud2</output_type><frame_name>lidar</frame_name>
</plugin></sensor></gazebo></robot>"""
RINGS = ("<vertical><samples>16</samples><resolution>1</resolution>"
         "<min_angle>-0.261799</min_angle><max_angle>0.261799</max_angle></vertical>")


@pytest.mark.parametrize(("vertical", "row"), [
    (RINGS, "vertical scan  16 rings over [-0.261799, 0.261799] rad"),
    ("", None),  # a planar lidar
    (RINGS.replace("<samples>16", "<samples>1"), None),  # one ring is planar too
])
def test_a_lidar_with_rings_shows_them(run, tmp_path, vertical, row):
    path = tmp_path / "r.urdf"
    path.write_text(RAY.format(vertical=vertical))
    result = run("inspect", path, "--section", "sensors")
    assert result.exit_code == 0, result.stderr
    assert "440 samples over [-3.14159, 3.14159] rad" in result.stdout
    if row:
        assert row in result.stdout, result.stdout
    else:
        assert "vertical scan" not in result.stdout
