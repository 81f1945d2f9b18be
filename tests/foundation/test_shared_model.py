"""One loaded model, shared; joint values in user units; the diff-drive law; packages; files."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from servicebot_cli.common.errors import JointNotFound, OutOfLimits, PackageNotFound
from servicebot_cli.common.files import OutputError, atomic_output, write_atomic
from servicebot_cli.description.loader import RobotSource, load, read_description
from servicebot_cli.description.packages import PackageResolver
from servicebot_cli.kinematics import diff_drive
from tests.conftest import FIXTURES, SIM_URDF


def test_load_is_memoised_per_source():
    first = load(RobotSource.of(SIM_URDF))
    assert load(RobotSource.of(SIM_URDF)) is first
    assert first.model is first.model and first.data is first.data
    assert load(RobotSource.bundled("real")) is not first


def test_joint_space_hides_cos_sin_of_continuous_joints():
    robot = load(RobotSource.of(FIXTURES / "planar_2r.urdf"))
    space = robot.joint_space
    assert space.names == ("shoulder", "elbow")
    assert (space.nq, space.nv) == (3, 2)
    values = space.vector({"elbow": 3.0, "shoulder": -1.0})
    q = space.to_q(values)
    assert q[space.idx_q[1]: space.idx_q[1] + 2] == pytest.approx([math.cos(3.0), math.sin(3.0)])
    assert space.from_q(q) == pytest.approx([-1.0, 3.0])
    # continuous joints wrap into (-pi, pi]
    assert space.from_q(space.to_q(np.array([0.0, 4.0])))[1] == pytest.approx(4.0 - 2 * math.pi)
    assert math.isnan(space.lower[1]) and space.upper[0] == pytest.approx(3.14159)


def test_planar_2r_forward_kinematics_is_closed_form():
    import pinocchio as pin

    robot = load(RobotSource.of(FIXTURES / "planar_2r.urdf"))
    model, data = robot.model, robot.data
    for a, b in [(0.3, -1.2), (2.0, 2.5), (-3.0, 0.1)]:
        pin.framesForwardKinematics(model, data, robot.joint_space.to_q(np.array([a, b])))
        tip = data.oMf[model.getFrameId("tip")].translation
        expected = [math.cos(a) + 0.5 * math.cos(a + b), math.sin(a) + 0.5 * math.sin(a + b), 0.0]
        assert tip == pytest.approx(expected, abs=1e-12)


def test_joint_names_and_limits_are_checked():
    space = load(RobotSource.bundled("sim")).joint_space
    with pytest.raises(JointNotFound, match="did you mean 'arm_link1_to_link2'"):
        space.vector({"arm_link1_to_lnk2": 0.1})
    with pytest.raises(OutOfLimits, match=r"outside its limits \[-1.57, 1.57\] rad.*--clamp"):
        space.vector({"arm_link1_to_link2": 2.0})
    clamped = space.vector({"arm_link1_to_link2": 2.0, "front_left_wheel_joint": 9.0}, clamp=True)
    assert clamped[space.index("arm_link1_to_link2")] == 1.57
    assert clamped[space.index("front_left_wheel_joint")] == 9.0  # continuous: no position limit


def test_planar_base_model_adds_x_y_yaw():
    robot = load(RobotSource.bundled("sim"))
    model = robot.model_with_base("planar")
    assert (model.nq, model.nv) == (robot.model.nq + 4, robot.model.nv + 3)
    assert robot.model_with_base("planar") is model


speeds = st.floats(min_value=-5, max_value=5, allow_nan=False)


@given(speeds, speeds)
def test_wheel_speeds_and_body_twist_are_inverse(linear, angular):
    left, right = diff_drive.wheel_speeds(linear, angular, wheel_radius_m=0.07, track_m=0.54)
    back = diff_drive.body_twist(left, right, wheel_radius_m=0.07, track_m=0.54)
    assert back == pytest.approx((linear, angular), abs=1e-9)


@given(speeds, speeds, st.floats(min_value=0.01, max_value=2))
def test_saturation_keeps_curvature_and_limit(left, right, limit):
    a, b = diff_drive.saturate_keep_curvature(left, right, limit)
    assert max(abs(a), abs(b)) <= limit + 1e-12
    assert a * right == pytest.approx(b * left, abs=1e-9)  # same ratio, same curvature
    c, d = diff_drive.saturate_per_wheel(left, right, limit)
    assert max(abs(c), abs(d)) <= limit


def test_turn_in_place_at_the_limit():
    left, right = diff_drive.wheel_speeds(0.0, 1.0, wheel_radius_m=0.07, track_m=0.54)
    left, right = diff_drive.saturate_keep_curvature(left, right, 0.44)
    assert (left, right) == pytest.approx((-0.44, 0.44))
    assert diff_drive.body_twist(left, right, wheel_radius_m=0.07, track_m=0.54)[1] == (
        pytest.approx(2 * 0.44 * 0.07 / 0.54))


def test_rate_limit():
    assert diff_drive.rate_limit(0.0, 1.0, 2.0, 0.1) == pytest.approx(0.2)
    assert diff_drive.rate_limit(0.0, -1.0, 2.0, 0.1) == pytest.approx(-0.2)
    assert diff_drive.rate_limit(0.0, 0.1, 2.0, 0.1) == 0.1
    assert diff_drive.rate_limit(0.0, 5.0, math.inf, 0.1) == 5.0


def test_package_resolver_crawls_and_reports(tmp_path):
    nested = tmp_path / "src" / "a" / "b" / "real_dir_name"
    nested.mkdir(parents=True)
    (nested / "package.xml").write_text("<package>\n  <name>named_pkg</name>\n</package>")
    resolver = PackageResolver.from_environment(environ={"ROS_PACKAGE_PATH": str(tmp_path)})
    assert resolver.find("named_pkg") == nested
    assert resolver.resolve_uri("package://named_pkg/m/x.stl", tmp_path) == nested / "m" / "x.stl"
    assert resolver.resolve_uri("file:///abs/y.dae", tmp_path).as_posix() == "/abs/y.dae"
    assert resolver.resolve_uri("rel/z.stl", tmp_path) == tmp_path / "rel" / "z.stl"
    with pytest.raises(PackageNotFound, match=f"'real_dir_name' not found.*{tmp_path}"):
        resolver.find("real_dir_name")  # the manifest's name wins over the directory's


def test_atomic_output_leaves_nothing_on_error(tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("old")
    with pytest.raises(RuntimeError), atomic_output(target) as handle:
        handle.write("half")
        raise RuntimeError("interrupted")
    assert target.read_text() == "old"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.csv"]
    write_atomic(target, "new")
    assert target.read_text() == "new"
    with pytest.raises(OutputError, match="is a directory"):
        write_atomic(tmp_path, "x")


def test_read_description_tolerates_what_load_refuses(tmp_path):
    odd = tmp_path / "odd.urdf"
    odd.write_text('<robot><link name="a"/><joint name="j" type="ball"/></robot>')
    robot = read_description(RobotSource.of(odd))
    assert robot.name == "" and robot.joints[0].type == "ball" and robot.joints[0].parent is None


def test_bundled_robot_is_named_by_a_real_path(monkeypatch, tmp_path):
    source = RobotSource.bundled("sim")
    assert source.display == "robots/service_robot.urdf.xml"  # tests run from the repository
    monkeypatch.chdir(tmp_path)
    outside = RobotSource.bundled("real")
    assert outside.display == str(SIM_URDF.parent.resolve() / "service_robot_real.urdf.xml")


def test_atomic_directory_appears_whole_or_not_at_all(tmp_path):
    from servicebot_cli.common.files import atomic_directory

    target = tmp_path / "bag"
    with pytest.raises(RuntimeError), atomic_directory(target) as building:
        (building / "part.mcap").write_bytes(b"half")
        raise RuntimeError("interrupted")
    assert list(tmp_path.iterdir()) == []
    with atomic_directory(target) as building:
        (building / "a.mcap").write_bytes(b"whole")
    assert (target / "a.mcap").read_bytes() == b"whole"
    with pytest.raises(OutputError, match="already exists"), atomic_directory(target):
        pass
    with pytest.raises(OutputError, match="does not exist"), atomic_directory(tmp_path / "x" / "y"):
        pass
