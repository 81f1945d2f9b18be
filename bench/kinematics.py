"""IK and FK speed: servicebot against roboticstoolbox's ik_LM (C++), TRAC-IK, ikpy, yourdfpy.

    pip install -e '.[bench]'
    python bench/kinematics.py                 # 1000 targets per robot, 100 for ikpy
    python bench/kinematics.py --targets 300 --ikpy-targets 30 --fk-configs 5000
    python bench/kinematics.py --batch-only    # ik --targets and fk --configs end to end

For UR5, Panda and Kinova's 6-DoF Jaco 2 (j2s6s200), all from the example-robot-data
package, and the service arm: the same random reachable targets (FK of random in-limit
configurations) go to every solver, one after the other, each solve seeded with that solver's
previous answer (the first with the neutral configuration), as a program that follows a path
of targets does. Every answer is checked by the same FK (Pinocchio): a success is an answer
within 2e-5 m and 2e-5 rad of the target and within the joint limits. servicebot's tolerance
is its default (1e-6 m, 1e-6 rad) and it returns its first solution (--solutions 1);
roboticstoolbox's ik_LM stops at 0.5 |e|^2 < 1e-10 (|e| < 1.4e-5), TRAC-IK's epsilon is 1e-5.
servicebot runs twice: with its compiled loop (numba) and with its Pinocchio loop alone.
Peers that are not installed are left out, with a note on stderr.

Ratios are against the fastest solver on the same robot in the same run.

FK throughput: servicebot's batch mode (`fk --configs`: CSV in, JSON Lines out, in-process)
and its core (poses only), against yourdfpy's update_cfg + get_transform.
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import os
import subprocess
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
from servicebot_cli.kinematics.chain_arrays import chain_arrays  # noqa: E402
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
        Case("Jaco 2 (6-DoF)", example_robot("kinova_description/robots/kinova.urdf"),
             "j2s6s200_link_base", "j2s6s200_end_effector"),
        Case("service arm", REPO / "robots" / "service_robot.urdf.xml", "base_link",
             "arm_tool_link"),
    ]


class Problem:
    """A robot's chain, its random targets, and the shared checker."""

    def __init__(self, case: Case, count: int, rng: np.random.Generator) -> None:
        self.case = case
        self.robot = load(RobotSource.of(case.urdf))
        self.model, self.data = self.robot.model, self.robot.model.createData()
        self.chain = Chain(self.model, self.robot.joint_space, case.tip, link_names(self.robot))
        self.tip = frame_id(self.model, case.tip, link_names(self.robot))
        self.base = frame_id(self.model, case.base, link_names(self.robot))
        neutral = pin.neutral(self.model)
        self.neutral = neutral
        arrays = chain_arrays(self.chain)
        assert arrays is not None, f"{case.name}: not a chain of single-axis joints"
        self.arrays = arrays
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
    """The chain's joint values in a full ``q``, as plain angles (continuous joints too)."""
    return problem.arrays.to_angles(problem.chain.to_chain(q))


def full_q(problem: Problem, theta: np.ndarray) -> np.ndarray:
    """The full ``q`` from the chain's plain joint values (others neutral)."""
    return problem.chain.to_full(problem.arrays.to_q(np.asarray(theta, dtype=float),
                                                     problem.chain.model.nq), problem.neutral)


Solve = Callable[[int, np.ndarray], "np.ndarray | None"]
"""Target index and seed (a full q, the solver's previous answer) -> full q, or None."""


def servicebot_solver(problem: Problem, axes: tuple[str, ...] = ("roll", "pitch", "yaw"),
                      compiled: bool = True) -> Solve:
    solver = IkSolver(problem.chain, IkSettings(solutions=1), compiled=compiled)
    solver.prepare()  # compiled, or loaded from numba's cache, before the clock runs
    rng = np.random.default_rng(7)
    pin.framesForwardKinematics(problem.model, problem.data, pin.neutral(problem.model))
    root_to_base = problem.data.oMf[problem.base].copy()
    targets = [root_to_base * t for t in problem.targets]
    ik_targets = [IkTarget(t.translation.copy(), t.rotation.copy(), axes) for t in targets]

    def solve(i: int, seed: np.ndarray) -> np.ndarray | None:
        result = solver.solve(ik_targets[i], seed, rng)
        return result.q if result.success else None

    return solve


def rtb_solver(problem: Problem) -> Solve:
    """roboticstoolbox's ik_LM (C++) on the chain from base to tip, called as its ETS."""
    import roboticstoolbox as rtb
    import xacrodoc.packages
    from roboticstoolbox.models.URDF.URDFRobot import URDF_file

    share = next((p for p in problem.case.urdf.parents if p.name == "example-robot-data"), None)
    if share is not None:  # its URDFs name their meshes by package://example-robot-data
        xacrodoc.packages.update_package_cache({"example-robot-data": str(share)})
    urdf = problem.case.urdf
    if urdf.suffix != ".urdf":  # rtb takes any other name for one of robot_descriptions'
        urdf = Path(tempfile.mkdtemp()) / f"{urdf.name.split('.')[0]}.urdf"
        urdf.write_text(problem.case.urdf.read_text())
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        links, name, _ = URDF_file(str(urdf))
    ets = rtb.Robot(links, name=name).ets(problem.case.base, problem.case.tip)
    assert problem.arrays.size == ets.n, "rtb's chain is not servicebot's"

    def pin_q(theta: np.ndarray) -> np.ndarray:
        return full_q(problem, theta)

    # rtb's ETS from a link starts at that link's parent: measure the constant offset once
    # (at two configurations, to be sure it is one) and aim rtb's tip at the same target.
    rng = np.random.default_rng(2)
    offsets = [np.asarray(ets.fkine(theta)) @ np.linalg.inv(problem.pose(pin_q(theta)).homogeneous)
               for theta in (rng.uniform(-1, 1, ets.n), rng.uniform(-1, 1, ets.n))]
    assert np.allclose(offsets[0], offsets[1], atol=1e-9), "rtb's base offset is not constant"
    targets = [offsets[0] @ t.homogeneous for t in problem.targets]

    def solve(i: int, seed: np.ndarray) -> np.ndarray | None:
        answer = ets.ik_LM(targets[i], q0=chain_values(problem, seed), tol=1e-10)
        return pin_q(np.asarray(answer.q, dtype=float)) if answer.success else None

    return solve


def tracik_solver(problem: Problem) -> Solve:
    import pytracik

    urdf = problem.case.urdf.read_text()
    solver = pytracik.TRAC_IK(problem.case.base, problem.case.tip, urdf, 0.005, 1e-5,
                              pytracik.SolveType.Speed)
    # pytracik reads Panda's limits as zero (its safety_controller tags); give it the URDF's.
    # Continuous joints: +-inf, which KDL's joint limits take as none.
    pytracik.set_joint_limits(solver, problem.arrays.limits[0], problem.arrays.limits[1])
    goals = []
    for t in problem.targets:
        quat = pin.Quaternion(t.rotation)
        goals.append((*t.translation, quat.x, quat.y, quat.z, quat.w))

    def solve(i: int, seed: np.ndarray) -> np.ndarray | None:
        answer = pytracik.ik(solver, chain_values(problem, seed), *goals[i])
        return full_q(problem, answer[1:]) if answer[0] >= 0 else None

    return solve


def ikpy_solver(problem: Problem, mode: str | None = "all") -> Solve:
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

    def ikpy_q(q: np.ndarray) -> np.ndarray:
        values = np.zeros(len(chain.links))
        values[active] = chain_values(problem, q)
        return values

    # ikpy drops the rpy of some fixed joints (Panda's hand is off by 45 degrees about z):
    # measure that constant tip offset once and aim ikpy's own tip at the same target.
    offsets = [np.linalg.inv(problem.pose(q).homogeneous) @ chain.forward_kinematics(ikpy_q(q))
               for q in (problem.neutral, problem.chain.to_full(
                   problem.chain.random_q(np.random.default_rng(1)), problem.neutral))]
    assert np.allclose(offsets[0], offsets[1], atol=1e-9), "ikpy's tip offset is not constant"

    def solve(i: int, seed: np.ndarray) -> np.ndarray | None:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            answer = chain.inverse_kinematics_frame(
                problem.targets[i].homogeneous @ offsets[0],
                initial_position=ikpy_q(seed), orientation_mode=mode)
        return full_q(problem, np.asarray(answer)[active])

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


def run(problem: Problem, label: str, solve: Solve, count: int, orientation: bool = True,
        robot: str = "") -> Row:
    """Solve the first ``count`` targets in order, each from the previous answer."""
    times, good, seed = [], 0, problem.neutral
    for i in range(count):
        start = time.perf_counter()
        q = solve(i, seed)
        times.append(time.perf_counter() - start)
        if problem.ok(q, problem.targets[i], orientation):
            good += 1
            assert q is not None
            seed = q
    return Row(robot or problem.case.name, label, count, good / count,
               float(np.median(times) * 1e3), float(np.percentile(times, 95) * 1e3))


def installed(module: str) -> bool:
    """Whether a peer can be imported; a note on stderr when not."""
    try:
        __import__(module)
    except ImportError:
        print(f"{module} is not installed: its rows are left out", file=sys.stderr)
        return False
    return True


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


def servicebot_command(*args: str) -> float:
    """Seconds ``servicebot ARGS`` takes as a new process (exit 0 or 1: not every target)."""
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "servicebot_cli", *args], cwd=REPO,
                          capture_output=True, text=True)
    elapsed = time.perf_counter() - start
    assert done.returncode in (0, 1), done.stderr
    return elapsed


BatchRow = tuple[str, int, float, float]
"""Label, items, seconds, success rate."""


def batch_ik(count: int) -> list[BatchRow]:
    """UR5, ``count`` full-pose targets: ``ik --targets`` as a process against rtb's loop.

    servicebot runs end to end: process start, model
    and collision set-up, CSV in, CSV out (its compiled loop already in numba's cache).
    """
    case = next(c for c in cases() if c.name == "UR5")
    problem = Problem(case, count, np.random.default_rng(5))
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        targets, answers = Path(tmp) / "targets.csv", Path(tmp) / "joints.csv"
        lines = ["x_m,y_m,z_m,qx,qy,qz,qw"]
        pin.framesForwardKinematics(problem.model, problem.data, problem.neutral)
        root_to_base = problem.data.oMf[problem.base].copy()  # the command takes root frame
        for target in (root_to_base * t for t in problem.targets):
            quat = pin.Quaternion(target.rotation)
            lines.append(",".join(repr(float(v)) for v in (*target.translation, quat.x,
                                                            quat.y, quat.z, quat.w)))
        targets.write_text("\n".join(lines) + "\n")
        args = (str(case.urdf), "--frame", case.tip, "--seed", "1", "-o", str(answers))
        servicebot_command("ik", *args[:-2], "--position", "0.4", "0.2", "0.3")  # warm caches
        for label, options in (("--solutions 1 --allow-collisions", ("--solutions", "1",
                                                                       "--allow-collisions")),
                               ("defaults", ())):
            elapsed = servicebot_command("ik", *args, *options, "--targets", str(targets))
            with answers.open() as handle:
                reached = sum(row["success"] == "true" for row in csv.DictReader(handle))
            rows.append((f"servicebot ik --targets, {label} (a process)", count, elapsed,
                         reached / count))
    if installed("roboticstoolbox"):
        solve = rtb_solver(problem)
        start = time.perf_counter()
        row = run(problem, "rtb", solve, count)
        rows.append(("roboticstoolbox ik_LM loop (in-process)", count,
                     time.perf_counter() - start, row.success))
    return rows


def batch_fk(count: int) -> list[BatchRow]:
    """The service arm, ``count`` configurations: ``fk --configs`` as a process against a
    plain in-process loop over Pinocchio."""
    robot = load(RobotSource.bundled("sim"))
    names = [n for n in robot.joint_space.names if n.startswith("arm_")]
    values = np.random.default_rng(4).uniform(-1.5, 1.5, size=(count, len(names)))
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        configs = Path(tmp) / "configs.csv"
        with configs.open("w") as handle:
            handle.write(",".join(names) + "\n")
            np.savetxt(handle, values, delimiter=",", fmt="%.17g")
        elapsed = servicebot_command("fk", "--configs", str(configs), "-o",
                                     str(Path(tmp) / "poses.csv"))
        rows.append(("servicebot fk --configs (a process: start, CSV in, CSV out)", count,
                     elapsed, 1.0))
    model, data = robot.model, robot.model.createData()
    tip = model.getFrameId("arm_tool_link")
    q = pin.neutral(model)
    index = [model.joints[model.getJointId(n)].idx_q for n in names]
    start = time.perf_counter()
    for row in values:
        q[index] = row
        pin.framesForwardKinematics(model, data, q)
        data.oMf[tip].homogeneous  # noqa: B018 (the pose, as a user would read it)
    rows.append(("Pinocchio framesForwardKinematics loop (in-process)", count,
                 time.perf_counter() - start, 1.0))
    return rows


def print_batch_table(title: str, rows: list[BatchRow]) -> None:
    fastest = min(seconds for _, _, seconds, _ in rows)
    print(f"\n{title}\n")
    print("| run | seconds | per second | success | time / fastest |")
    print("|---|---:|---:|---:|---:|")
    for label, count, seconds, success in rows:
        print(f"| {label} | {seconds:.2f} | {count / seconds:,.0f} | {success * 100:.1f}% | "
              f"{seconds / fastest:.2f}x |")


def print_ik_table(rows: list[Row]) -> None:
    fastest: dict[str, float] = {}
    for r in rows:
        fastest[r.robot] = min(fastest.get(r.robot, np.inf), r.median_ms)
    print("| robot | solver | targets | success | median [ms] | p95 [ms] | median / fastest |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for r in rows:
        print(f"| {r.robot} | {r.solver} | {r.targets} | {r.success * 100:.1f}% | "
              f"{r.median_ms:.3f} | {r.p95_ms:.3f} | {r.median_ms / fastest[r.robot]:.2f}x |")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--targets", type=int, default=1000)
    parser.add_argument("--ikpy-targets", type=int, default=100)
    parser.add_argument("--fk-configs", type=int, default=20000)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--batch-targets", type=int, default=10000,
                        help="ik --targets end to end, against rtb's loop (0: skip)")
    parser.add_argument("--batch-configs", type=int, default=200000,
                        help="fk --configs end to end, against Pinocchio's loop (0: skip)")
    parser.add_argument("--batch-only", action="store_true",
                        help="only the end-to-end batch tables (ik --targets, fk --configs)")
    args = parser.parse_args()
    if args.batch_only:
        batch_tables(args)
        return
    rows = []
    peers = {name: installed(name) for name in ("roboticstoolbox", "pytracik", "ikpy")}
    for case in cases():
        problem = Problem(case, args.targets, np.random.default_rng(args.seed))
        rows.append(run(problem, "servicebot", servicebot_solver(problem), args.targets))
        rows.append(run(problem, "servicebot, Pinocchio loop only",
                        servicebot_solver(problem, compiled=False), args.targets))
        if peers["roboticstoolbox"]:
            rows.append(run(problem, "roboticstoolbox ik_LM (C++)", rtb_solver(problem),
                            args.targets))
        if peers["pytracik"]:
            with quiet():  # KDL warns about root links with inertia, on stdout
                tracik = tracik_solver(problem)
            rows.append(run(problem, "TRAC-IK (pytracik)", tracik, args.targets))
        if peers["ikpy"]:
            rows.append(run(problem, "ikpy", ikpy_solver(problem),
                            min(args.ikpy_targets, args.targets)))
        if case.name == "service arm":  # its own problem too: four joints, position only
            label = "service arm, position only"  # pytracik cannot leave orientation free
            rows.append(run(problem, "servicebot", servicebot_solver(problem, ()), args.targets,
                            orientation=False, robot=label))
            if peers["ikpy"]:
                rows.append(run(problem, "ikpy", ikpy_solver(problem, None),
                                min(args.ikpy_targets, args.targets), orientation=False,
                                robot=label))
        print(f"{case.name}: done", file=sys.stderr)
    print(f"IK, full pose unless said, {args.targets} random reachable targets per robot (ikpy: "
          f"the first {args.ikpy_targets}), each solve seeded with the previous answer; "
          f"success = FK within {CHECK_M:g} m and {CHECK_RAD:g} rad, limits kept\n")
    print_ik_table(rows)
    print(f"\nFK throughput, service robot, {args.fk_configs} configurations\n")
    print("| implementation | configurations/s |")
    print("|---|---:|")
    for label, rate in fk_throughput(args.fk_configs):
        print(f"| {label} | {rate:,.0f} |")
    batch_tables(args)


def batch_tables(args: argparse.Namespace) -> None:
    if args.batch_targets:
        print_batch_table(f"Batch IK, UR5, {args.batch_targets} full-pose targets",
                          batch_ik(args.batch_targets))
    if args.batch_configs:
        print_batch_table(f"Batch FK, service arm, {args.batch_configs} configurations",
                          batch_fk(args.batch_configs))


if __name__ == "__main__":
    main()
