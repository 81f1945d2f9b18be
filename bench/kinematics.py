"""IK and FK speed: servicebot against TRAC-IK (pytracik), ikpy and yourdfpy, in one process.

    pip install -e '.[bench]'
    python bench/kinematics.py                 # 1000 targets per robot, 100 for ikpy
    python bench/kinematics.py --targets 300 --ikpy-targets 30 --fk-configs 5000

For UR5 and Panda (from the example-robot-data package) and the service arm, the same
random reachable targets (FK of random in-limit configurations) and the same random seeds
go to every solver. Every answer is checked by the same FK (Pinocchio): a success is an
answer within 2e-5 m and 2e-5 rad of the target (TRAC-IK's epsilon is 1e-5 per twist
component; servicebot's tolerance is its default, 1e-6) and within the joint limits.
servicebot returns its first solution (--solutions 1), as TRAC-IK's Speed mode does.

FK throughput: servicebot's batch mode (`fk --configs`: CSV in, JSON Lines out, in-process)
and its core (poses only), against yourdfpy's update_cfg + get_transform.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import sys
import tempfile
import time
import warnings
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from importlib.metadata import PackageNotFoundError, files
from pathlib import Path

import numpy as np
import pinocchio as pin

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from servicebot_cli.description.loader import RobotSource, load  # noqa: E402
from servicebot_cli.kinematics.chain import Chain  # noqa: E402
from servicebot_cli.kinematics.frames import frame_id, link_names  # noqa: E402
from servicebot_cli.kinematics.inverse import IkSettings, IkSolver, IkTarget  # noqa: E402

CHECK_M = CHECK_RAD = 2e-5


@dataclass(frozen=True)
class Case:
    name: str
    urdf: Path
    base: str
    tip: str


def example_robot(relative: str) -> Path:
    """A URDF shipped in the example-robot-data wheel."""
    try:
        for entry in files("example-robot-data") or ():
            if str(entry).endswith(f"robots/{relative}"):
                return Path(entry.locate())
    except PackageNotFoundError:
        pass
    sys.exit(f"example-robot-data has no {relative}: pip install -e '.[bench]'")


def cases() -> list[Case]:
    return [
        Case("UR5", example_robot("ur_description/urdf/ur5_robot.urdf"), "base_link", "tool0"),
        Case("Panda", example_robot("panda_description/urdf/panda.urdf"), "panda_link0",
             "panda_hand_tcp"),
        Case("service arm", REPO / "robots" / "service_robot.urdf.xml", "base_link",
             "arm_tool_link"),
    ]


class Problem:
    """A robot's chain, its random targets and seeds, and the shared checker."""

    def __init__(self, case: Case, count: int, rng: np.random.Generator) -> None:
        self.case = case
        self.robot = load(RobotSource.of(case.urdf))
        self.model, self.data = self.robot.model, self.robot.model.createData()
        self.chain = Chain(self.model, self.robot.joint_space, case.tip, link_names(self.robot))
        self.tip = frame_id(self.model, case.tip, link_names(self.robot))
        self.base = frame_id(self.model, case.base, link_names(self.robot))
        neutral = pin.neutral(self.model)
        self.seeds = [self.chain.to_full(self.chain.random_q(rng), neutral) for _ in range(count)]
        self.targets = [self.pose(self.chain.to_full(self.chain.random_q(rng), neutral))
                        for _ in range(count)]

    def pose(self, q: np.ndarray) -> pin.SE3:
        """``transform_tip_to_base`` at ``q``."""
        pin.framesForwardKinematics(self.model, self.data, q)
        return self.data.oMf[self.base].actInv(self.data.oMf[self.tip])

    def ok(self, q: np.ndarray | None, target: pin.SE3, orientation: bool = True) -> bool:
        if q is None:
            return False
        q_chain = self.chain.to_chain(q)
        if np.any(q_chain < self.chain.lower - 1e-9) or np.any(q_chain > self.chain.upper + 1e-9):
            return False
        pose = self.pose(q)
        if np.linalg.norm(pose.translation - target.translation) > CHECK_M:
            return False
        return not orientation or np.linalg.norm(pin.log3(pose.rotation.T @ target.rotation)) \
            <= CHECK_RAD


def chain_values(problem: Problem, q: np.ndarray) -> np.ndarray:
    return problem.chain.to_chain(q)


def servicebot_solver(problem: Problem, axes: tuple[str, ...] = ("roll", "pitch", "yaw")
                      ) -> Callable[[int], np.ndarray | None]:
    solver = IkSolver(problem.chain, IkSettings(solutions=1))
    rng = np.random.default_rng(7)
    pin.framesForwardKinematics(problem.model, problem.data, pin.neutral(problem.model))
    root_to_base = problem.data.oMf[problem.base].copy()
    targets = [root_to_base * t for t in problem.targets]
    ik_targets = [IkTarget(t.translation.copy(), t.rotation.copy(), axes) for t in targets]

    def solve(i: int) -> np.ndarray | None:
        result = solver.solve(ik_targets[i], problem.seeds[i], rng)
        return result.q if result.success else None

    return solve


def tracik_solver(problem: Problem) -> Callable[[int], np.ndarray | None]:
    import pytracik

    urdf = problem.case.urdf.read_text()
    solver = pytracik.TRAC_IK(problem.case.base, problem.case.tip, urdf, 0.005, 1e-5,
                              pytracik.SolveType.Speed)
    # pytracik reads Panda's limits as zero (its safety_controller tags); give it the URDF's.
    pytracik.set_joint_limits(solver, problem.chain.lower, problem.chain.upper)
    goals = []
    for t in problem.targets:
        quat = pin.Quaternion(t.rotation)
        goals.append((*t.translation, quat.x, quat.y, quat.z, quat.w))
    seeds = [chain_values(problem, s) for s in problem.seeds]
    neutral = pin.neutral(problem.model)

    def solve(i: int) -> np.ndarray | None:
        answer = pytracik.ik(solver, seeds[i], *goals[i])
        return problem.chain.to_full(answer[1:], neutral) if answer[0] >= 0 else None

    return solve


def ikpy_solver(problem: Problem, mode: str | None = "all") -> Callable[[int], np.ndarray | None]:
    import ikpy.chain

    robot, elements = problem.robot, [problem.case.tip]
    while elements[0] != problem.case.base:
        joint = next(j for j in robot.joints if j.child == elements[0])
        elements[:0] = [joint.parent, joint.name]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        chain = ikpy.chain.Chain.from_urdf_file(str(problem.case.urdf), base_elements=elements)
        active = np.array([link.joint_type != "fixed" for link in chain.links])
        chain = ikpy.chain.Chain.from_urdf_file(str(problem.case.urdf), base_elements=elements,
                                                active_links_mask=active)
    neutral = pin.neutral(problem.model)

    def ikpy_q(q: np.ndarray) -> np.ndarray:
        values = np.zeros(len(chain.links))
        values[active] = chain_values(problem, q)
        return values

    # ikpy drops the rpy of some fixed joints (Panda's hand is off by 45 degrees about z):
    # measure that constant tip offset once and aim ikpy's own tip at the same target.
    offsets = [np.linalg.inv(problem.pose(q).homogeneous) @ chain.forward_kinematics(ikpy_q(q))
               for q in problem.seeds[:2]]
    assert np.allclose(offsets[0], offsets[1], atol=1e-9), "ikpy's tip offset is not constant"

    def solve(i: int) -> np.ndarray | None:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            answer = chain.inverse_kinematics_frame(
                problem.targets[i].homogeneous @ offsets[0],
                initial_position=ikpy_q(problem.seeds[i]), orientation_mode=mode)
        return problem.chain.to_full(np.asarray(answer)[active], neutral)

    return solve


@contextlib.contextmanager
def quiet() -> Iterator[None]:
    """Silence file descriptors 1 and 2 (C++ libraries print there directly)."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    with open(os.devnull, "w") as sink:
        os.dup2(sink.fileno(), 1)
        os.dup2(sink.fileno(), 2)
        try:
            yield
        finally:
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            for fd in saved:
                os.close(fd)


@dataclass
class Row:
    robot: str
    solver: str
    targets: int
    success: float
    median_ms: float
    p95_ms: float


def run(problem: Problem, label: str, solve: Callable[[int], np.ndarray | None],
        count: int, orientation: bool = True, robot: str = "") -> Row:
    times, good = [], 0
    for i in range(count):
        start = time.perf_counter()
        q = solve(i)
        times.append(time.perf_counter() - start)
        good += problem.ok(q, problem.targets[i], orientation)
    return Row(robot or problem.case.name, label, count, good / count,
               float(np.median(times) * 1e3), float(np.percentile(times, 95) * 1e3))


def fk_throughput(count: int) -> list[tuple[str, float]]:
    """Configurations per second: servicebot batch (CLI, in-process), servicebot core, yourdfpy."""
    from click.testing import CliRunner

    from servicebot_cli.cli import main
    from servicebot_cli.kinematics.forward import transforms

    robot = load(RobotSource.bundled("sim"))
    space = robot.joint_space
    rng = np.random.default_rng(3)
    values = rng.uniform(-1.5, 1.5, size=(count, len(space.names)))
    with tempfile.TemporaryDirectory() as tmp:
        configs = Path(tmp) / "configs.csv"
        configs.write_text(",".join(space.names) + "\n" + "\n".join(
            ",".join(repr(float(v)) for v in row) for row in values) + "\n")
        start = time.perf_counter()
        result = CliRunner().invoke(main, ["fk", "--configs", str(configs), "-o",
                                           str(Path(tmp) / "poses.jsonl")])
        batch_s = time.perf_counter() - start
        assert result.exit_code == 0, result.output
    model, data = robot.model, robot.model.createData()
    tip = frame_id(model, "arm_tool_link", link_names(robot))
    root = frame_id(model, "base_link", link_names(robot))
    start = time.perf_counter()
    for row in values:
        transforms(model, data, space.to_q(row), [tip], root)
    core_s = time.perf_counter() - start
    import yourdfpy

    urdf = yourdfpy.URDF.load(str(REPO / "robots" / "service_robot.urdf.xml"),
                              load_meshes=False, build_collision_scene_graph=False)
    subset = values[: max(1, count // 10)]
    start = time.perf_counter()
    for row in subset:
        urdf.update_cfg(dict(zip(space.names, row, strict=True)))
        urdf.get_transform("arm_tool_link", "base_link")
    yourdfpy_s = (time.perf_counter() - start) * len(values) / len(subset)
    return [("servicebot fk --configs (CSV in, JSON Lines out)", count / batch_s),
            ("servicebot core (poses only)", count / core_s),
            ("yourdfpy update_cfg + get_transform", count / yourdfpy_s)]


def print_ik_table(rows: list[Row]) -> None:
    ours = {r.robot: r for r in rows if r.solver == "servicebot"}
    print("| robot | solver | targets | success | median [ms] | p95 [ms] | median / servicebot's |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for r in rows:
        ratio = r.median_ms / ours[r.robot].median_ms if r.robot in ours else float("nan")
        print(f"| {r.robot} | {r.solver} | {r.targets} | {r.success * 100:.1f}% | "
              f"{r.median_ms:.3f} | {r.p95_ms:.3f} | {ratio:.2f}x |")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--targets", type=int, default=1000)
    parser.add_argument("--ikpy-targets", type=int, default=100)
    parser.add_argument("--fk-configs", type=int, default=20000)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    rows = []
    for case in cases():
        problem = Problem(case, args.targets, np.random.default_rng(args.seed))
        rows.append(run(problem, "servicebot", servicebot_solver(problem), args.targets))
        with quiet():  # KDL warns about root links with inertia, on stdout
            tracik = tracik_solver(problem)
        rows.append(run(problem, "TRAC-IK (pytracik)", tracik, args.targets))
        rows.append(run(problem, "ikpy", ikpy_solver(problem), min(args.ikpy_targets,
                                                                    args.targets)))
        if case.name == "service arm":  # its own problem too: four joints, position only
            label = "service arm, position only"  # pytracik cannot leave orientation free
            rows.append(run(problem, "servicebot", servicebot_solver(problem, ()), args.targets,
                            orientation=False, robot=label))
            rows.append(run(problem, "ikpy", ikpy_solver(problem, None),
                            min(args.ikpy_targets, args.targets), orientation=False,
                            robot=label))
        print(f"{case.name}: done", file=sys.stderr)
    print(f"IK, full pose unless said, {args.targets} random reachable targets per robot (ikpy: "
          f"the first {args.ikpy_targets}); success = FK within {CHECK_M:g} m and "
          f"{CHECK_RAD:g} rad, limits kept\n")
    print_ik_table(rows)
    print(f"\nFK throughput, service robot, {args.fk_configs} configurations\n")
    print("| implementation | configurations/s |")
    print("|---|---:|")
    for label, rate in fk_throughput(args.fk_configs):
        print(f"| {label} | {rate:,.0f} |")


if __name__ == "__main__":
    main()
