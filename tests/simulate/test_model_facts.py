"""The model's facts ``simulate`` reads, worked out by a forked process meanwhile.

The forked process must give the bits the in-process one gives, its error must be the one
reported when the scenario is wrong too (as when the model is built first), and the
command's own process must then never import Pinocchio. The end effector, placed by the
robot's shape, must be where Pinocchio's forward kinematics puts it.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.common.forked import WorkerEnded, second_core
from servicebot_cli.description.loader import RobotSource, load, read_description
from servicebot_cli.simulate.model_facts import HANDOVER_BYTES, FactsAhead, model_facts
from servicebot_cli.simulate.scenario.definition import load_scenario
from servicebot_cli.simulate.session import Outputs, run_and_write
from servicebot_cli.simulate.summary import _arm_tip
from tests.check.helpers import fixture
from tests.conftest import assert_one_line_error, run_servicebot
from tests.processes import children, reaped

REFUSED = fixture("SB701")  # a URDF Pinocchio refuses


def test_forked_facts_are_the_in_process_bits():
    robot = read_description(RobotSource.bundled())
    ahead = FactsAhead(robot, fork=True)
    pid = ahead._worker.pid
    assert pid is not None
    forked = ahead.result()
    assert not reaped(pid)  # kept for the work to be handed over
    ahead.close()
    assert reaped(pid)
    here = model_facts(read_description(RobotSource.bundled()))
    assert forked.joint_space.names == here.joint_space.names
    assert forked.joint_space.idx_q == here.joint_space.idx_q
    assert np.array_equal(forked.joint_space.lower, here.joint_space.lower, equal_nan=True)
    assert forked.placements.keys() == here.placements.keys()
    assert "lidar_link" in forked.placements
    for link, placement in here.placements.items():
        assert np.array_equal(forked.placements[link], placement), link


def test_a_refused_model_is_pinocchios_error_from_the_forked_process():
    robot = read_description(RobotSource(REFUSED, REFUSED.name))
    with pytest.raises(DescriptionError) as here:
        model_facts(robot)
    with FactsAhead(robot, fork=True) as ahead, pytest.raises(DescriptionError) as forked:
        ahead.result()
    assert str(forked.value) == str(here.value)
    assert "not a valid URDF" in str(here.value)


def test_a_stopped_worker_is_reaped():
    ahead = FactsAhead(read_description(RobotSource.bundled()), fork=True)
    pid = ahead._worker.pid
    ahead.close()
    assert pid is not None and reaped(pid)


def test_the_model_error_comes_before_the_scenario_error(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("duration_s: -1\n")
    for scenario in ([], ["-s", bad]):
        result = run_servicebot("simulate", REFUSED, "--headless", *scenario)
        assert_one_line_error(result, 2, "not a valid URDF")


@pytest.mark.skipif(not second_core(), reason="one core: the facts are worked out in-process")
def test_the_command_process_imports_neither_pinocchio_nor_coal(tmp_path):
    # the built-in scenario's pieces go to a forked worker, and no contact needs Coal here
    script = (
        "import sys\n"
        "from servicebot_cli.description.loader import RobotSource\n"
        "from servicebot_cli.simulate.session import SimulateRequest, run\n"
        "report = run(SimulateRequest(RobotSource.bundled()))\n"
        "print(report.summary['end_effector']['frame'], "
        "[m for m in ('pinocchio', 'coal') if m in sys.modules])\n"
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          timeout=120, cwd=tmp_path, check=True)
    assert done.stdout.split() == ["arm_tool_link", "[]"]


def test_the_end_effector_is_where_pinocchio_puts_it():
    robot = load(RobotSource.bundled())
    scenario = load_scenario(None)
    report = run_and_write(robot, scenario, seed=0, outputs=Outputs(), scenario_dir=".",
                           keep_run=True)
    result = report.result
    assert result is not None
    body = result.body
    tip = _arm_tip(body)
    effector = report.summary["end_effector"]
    assert effector is not None and effector["frame"] == tip
    positions = dict(zip(body.arm_joints, result.arm_positions_rad[-1], strict=True))
    space = body.joint_space
    q = space.to_q(np.array([positions.get(n, 0.0) for n in space.names]))
    yaw = result.truth.yaw_rad[-1]
    q[:4] = (result.truth.x_m[-1], result.truth.y_m[-1], np.cos(yaw), np.sin(yaw))
    model = robot.model_with_base("planar")
    data = model.createData()
    pin.framesForwardKinematics(model, data, q)
    expected = np.array(data.oMf[model.getFrameId(tip, pin.BODY)].translation)
    expected[2] += body.base_height_m
    assert np.allclose(effector["position_m"], expected, rtol=0, atol=1e-12)
    assert np.linalg.norm(expected) > 0.3  # the arm's tip, not the base's origin


def test_a_killed_worker_is_one_error_each_time_it_is_asked():
    ahead = FactsAhead(read_description(RobotSource.bundled()), fork=True)
    pid = ahead._worker.pid
    assert pid is not None
    os.kill(pid, signal.SIGKILL)  # long before Pinocchio is imported
    errors = []
    for _ in range(2):
        with pytest.raises(WorkerEnded) as caught:
            ahead.result()
        errors.append(caught.value)
    assert errors[0] is errors[1] and "model-building process" in str(errors[0])
    ahead.close()
    assert reaped(pid)


def _chain(path, joints: int, kind: str = "revolute"):
    """A URDF of ``joints`` joints, in a row (revolute) or all on the base (fixed)."""
    limit = '<limit lower="-1" upper="1" effort="1" velocity="1"/>' if kind == "revolute" else ""
    links = "".join(
        f'<link name="x{i}"/><joint name="j{i}" type="{kind}"><parent link="'
        f'{"base_link" if i == 0 or kind == "fixed" else f"x{i - 1}"}"/><child link="x{i}"/>'
        f'<origin xyz="0 0 0.001"/><axis xyz="0 0 1"/>{limit}</joint>' for i in range(joints))
    path.write_text(f'<robot name="chain"><link name="base_link"/>{links}</robot>')
    return path


@pytest.mark.skipif(not second_core(), reason="one core: the model is built in-process")
def test_ctrl_c_while_the_model_is_built_stops_its_process_at_once(tmp_path):
    # 40,000 fixed joints: Pinocchio takes about 10 s to build them (in 350 MB), while the
    # main process finds at once that the scenario is wrong and waits for the model's verdict
    robot = _chain(tmp_path / "chain.urdf", 40_000, "fixed")
    bad = tmp_path / "bad.yaml"
    bad.write_text("duration_s: -1\n")
    process = subprocess.Popen([sys.executable, "-m", "servicebot_cli", "simulate", robot,
                                "--headless", "-s", bad], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, start_new_session=True)
    deadline = time.monotonic() + 60
    while not children(process.pid):
        assert process.poll() is None and time.monotonic() < deadline
        time.sleep(0.01)
    [child] = children(process.pid)
    time.sleep(1.0)
    os.killpg(process.pid, signal.SIGINT)  # Ctrl-C: the model's process ignores it
    sent = time.monotonic()
    _, stderr = process.communicate(timeout=60)
    assert time.monotonic() - sent < 4, "waited for the model instead of stopping it"
    assert process.returncode == 130, stderr
    assert not Path(f"/proc/{child}").exists()


def test_a_model_too_large_for_memory_is_one_error_line(tmp_path):
    # Pinocchio's data for a chain grows steeply (10.8 GB for 550 joints); 3,500 joints are
    # also deeper than its recursive parser takes
    result = run_servicebot("simulate", _chain(tmp_path / "chain.urdf", 300), "--headless")
    assert_one_line_error(result, 2, "has 303 degrees of freedom, over the 250")  # +3: base
    result = run_servicebot("simulate", _chain(tmp_path / "deep.urdf", 3500), "--headless")
    assert_one_line_error(result, 2, "3500 joints deep, over the 3,000")


_ARM = """
  <link name="a1"><collision><geometry><box size="0.05 0.05 0.1"/></geometry></collision></link>
  <link name="a2"><collision><geometry><box size="0.05 0.05 0.1"/></geometry></collision></link>
  <link name="tool"/>
  <joint name="j1" type="revolute"><parent link="base_link"/><child link="a1"/>
    <origin xyz="0 0 0.2"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="j2" type="revolute"><parent link="a1"/><child link="a2"/>
    <origin xyz="0.1 0 0.05"/><axis xyz="0 1 0"/>
    <limit lower="-3" upper="3" effort="1" velocity="1"/></joint>
  <joint name="jt" type="fixed"><parent link="a2"/><child link="tool"/>
    <origin xyz="0.3 0 0"/></joint>
  <gazebo><plugin name="jsp" filename="libgazebo_ros_joint_state_publisher.so">
    <update_rate>50</update_rate>{joints}</plugin></gazebo>
"""


@pytest.mark.parametrize("listed", [["j2", "j1"], ["j2"]])
def test_the_end_effector_follows_the_arm_whatever_joint_states_are_sent(tmp_path, listed):
    """A joint-state publisher may send the arm's joints in another order, or some of them:
    the end effector is where the arm's final positions put it, as ``fk`` places it."""
    import shutil

    package = tmp_path / "sam_bot_description"
    shutil.copytree(Path(__file__).parents[1] / "fixtures" / "sam_bot_description", package)
    urdf = package / "src" / "description" / "sam_bot_description.urdf"
    joints = "".join(f"<joint_name>{name}</joint_name>" for name in listed)
    urdf.write_text(urdf.read_text().replace("</robot>", _ARM.format(joints=joints)
                                             + "</robot>"))
    scenario = tmp_path / "arm.yaml"
    scenario.write_text("duration_s: 2\ncmd_vel:\n  - {duration_s: 2, linear_m_s: 0}\n"
                        "arm:\n  joint_names: [j1, j2]\n  points:\n"
                        "    - {time_from_start_s: 1.5, positions: [1.0, -0.5]}\n")
    result = run_servicebot("simulate", urdf, "--headless", "-s", scenario, "--format", "json")
    assert result.returncode == 0, result.stderr
    summary = json.loads(result.stdout)
    assert summary["arm_final_positions_rad"] == {"j1": 1.0, "j2": -0.5}
    fk = run_servicebot("fk", urdf, "--frame", "tool", "-j", "j1=1.0", "-j", "j2=-0.5",
                        "--format", "json")
    assert fk.returncode == 0, fk.stderr
    [expected] = json.loads(fk.stdout)["poses"]
    effector = summary["end_effector"]
    assert effector["frame"] == "tool"
    # fk places the tool on the root link; the run's base stands still at the origin
    assert effector["position_m"][:2] == pytest.approx(expected["position_m"][:2], abs=1e-12)
    assert abs(expected["position_m"][0]) > 0.1  # the arm turned: not its zero pose


class _Tally:
    """Work with state carried from job to job, as the pose work's noise is."""

    def __init__(self) -> None:
        self.jobs = 0
        self.prepared_in: int | None = None

    def prepare(self) -> None:
        self.prepared_in = os.getpid()

    def __call__(self, job: int) -> tuple[int, int | None, int]:
        self.jobs += 1
        return os.getpid(), self.prepared_in, self.jobs


def test_the_facts_process_takes_over_the_work_handed_to_it():
    ahead = FactsAhead(read_description(RobotSource.bundled()), fork=True,
                       then_import=("servicebot_cli.simulate.pose_work",))
    pid = ahead._worker.pid
    tally = _Tally()
    worker = ahead.take_over(tally, tally.prepare, "tally")
    assert worker is not None and worker.pid == pid and worker.name == "tally"
    assert ahead.take_over(_Tally(), None, "again") is None  # one taker
    for job in range(3):
        worker.submit(job)
    worker.no_more_jobs()
    assert [worker.result() for _ in range(3)] == [(pid, pid, n) for n in (1, 2, 3)]
    assert tally.jobs == 0  # the work's state lives in that process
    worker.close(finished=True)
    ahead.close()
    assert pid is not None and reaped(pid)


def test_no_process_no_takeover_and_work_that_cannot_cross_is_left_here():
    robot = read_description(RobotSource.bundled())
    with FactsAhead(robot, fork=False) as here:
        assert here.take_over(_Tally(), None, "tally") is None
        assert here.result().joint_space.names
    ahead = FactsAhead(robot, fork=True)
    pid = ahead._worker.pid
    assert ahead.take_over(lambda job: job, None, "lambda") is None  # a lambda does not pickle
    assert pid is not None and reaped(pid)
    assert ahead.result().joint_space.names  # the facts stay
    ahead.close()


def test_a_model_error_is_raised_by_the_takeover():
    with FactsAhead(read_description(RobotSource(REFUSED, REFUSED.name)), fork=True) as ahead:
        with pytest.raises(DescriptionError, match="not a valid URDF"):
            ahead.take_over(_Tally(), None, "tally")


@pytest.mark.skipif(not second_core(), reason="one core: the pose work is done in-process")
def test_the_pose_work_handed_over_gives_the_bytes_of_a_worker_forked_for_it(tmp_path,
                                                                          monkeypatch):
    robot = load(RobotSource.bundled(), build_model=False)
    scenario = load_scenario(None)
    forks: list[int] = []
    real_fork = os.fork

    def counted_fork() -> int:
        pid = real_fork()
        if pid:
            forks.append(pid)
        return pid

    monkeypatch.setattr(os, "fork", counted_fork)
    bags = []
    for name, fork in (("handed", True), ("own", False)):
        with FactsAhead(robot, fork=fork,
                        then_import=("servicebot_cli.simulate.pose_work",)) as facts:
            run_and_write(robot, scenario, seed=3, outputs=Outputs(bag=str(tmp_path / name)),
                          scenario_dir=".", facts=facts)
        bags.append(next((tmp_path / name).glob("*.mcap")).read_bytes())
        # handed: the facts' process did the pose work; own: a worker forked for it
        assert len(forks) == 1, name
        forks.clear()
    assert bags[0] == bags[1]


class _Heavy(_Tally):
    """Work that pickles to more than a handover carries."""

    def __init__(self) -> None:
        super().__init__()
        self.payload = np.zeros(HANDOVER_BYTES // 8 + 1)


def test_work_too_large_or_needing_a_new_package_is_not_handed_over(tmp_path, monkeypatch):
    robot = read_description(RobotSource.bundled())
    ahead = FactsAhead(robot, fork=True)
    pid = ahead._worker.pid
    assert ahead.take_over(_Heavy(), None, "heavy") is None
    assert pid is not None and reaped(pid)  # stopped: the caller forks its own
    ahead.close()
    # a class of a package imported after the fork: most of a second to import there (trimesh)
    package = tmp_path / "late_package"
    package.mkdir()
    (package / "__init__.py").write_text("class Work:\n    def __call__(self, job):\n"
                                         "        return job\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    ahead = FactsAhead(robot, fork=True)
    pid = ahead._worker.pid
    import late_package  # noqa: PLC0415 -- after the fork, on purpose

    try:
        assert ahead.take_over(late_package.Work(), None, "late") is None
    finally:
        del sys.modules["late_package"]
    assert pid is not None and reaped(pid)
    ahead.close()
