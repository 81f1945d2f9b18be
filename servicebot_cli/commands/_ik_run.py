"""The two ways ``ik`` runs: one target, or a stream of them (``--targets``).

Imported by the command's callback only: it pulls in numpy and Pinocchio. The clock lives
here, at the edge: solve times are measured around the pure solver.
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import click
import numpy as np
import numpy.typing as npt

from servicebot_cli.batch.ik_rows import IkBatch
from servicebot_cli.batch.stream import stream
from servicebot_cli.common.errors import ExitCode, ServicebotError
from servicebot_cli.common.jsonable import dumps
from servicebot_cli.description.joint_space import JointSpace
from servicebot_cli.description.robot import RobotDescription
from servicebot_cli.kinematics.chain import Chain
from servicebot_cli.kinematics.diagnosis import hint
from servicebot_cli.kinematics.frames import link_names
from servicebot_cli.kinematics.inverse import IkResult, IkSettings, IkSolver, IkTarget
from servicebot_cli.kinematics.rotations import rpy_from_matrix
from servicebot_cli.kinematics.user_joints import angular, user_values, user_vector
from servicebot_cli.output.ik_report import ik_text

FloatArray = npt.NDArray[np.float64]


class IkFailed(ServicebotError):
    """IK did not reach the target (or some batch targets): the answer is no."""

    exit_code = ExitCode.FAILED


@dataclass
class Setup:
    """Everything a solve needs, built once per command.

    Attributes:
        robot: The description.
        space: Joint space of the model solved on (with the planar base for --with-base).
        solver: The IK solver for the chain of ``frame``.
        seed: Full configuration to start from.
        rng: Random restarts.
        deg: Angles in degrees for the user.
    """

    robot: RobotDescription
    space: JointSpace
    solver: IkSolver
    seed: FloatArray
    rng: np.random.Generator
    deg: bool

    def solve(self, target: IkTarget, seed: FloatArray) -> tuple[IkResult, float, str | None]:
        """Solve from ``seed``; the result, the solve time [s], and a hint when it failed."""
        start = time.perf_counter()
        result = self.solver.solve(target, seed, self.rng)
        elapsed_s = time.perf_counter() - start
        why = None if result.success else hint(self.solver, target, seed, self.rng)
        return result, elapsed_s, why

    def report(self, result: IkResult, elapsed_s: float, why: str | None) -> dict[str, Any]:
        """The result as JSON-ready values (joints and base in the user's units)."""
        space, q = self.space, result.q
        base = None
        if space.base_nq:
            yaw = math.atan2(q[3], q[2])
            base = {"x_m": float(q[0]), "y_m": float(q[1]),
                    f"yaw_{'deg' if self.deg else 'rad'}": math.degrees(yaw) if self.deg else yaw}
        return {"success": result.success, "joints": user_values(space, space.from_q(q),
                                                                   deg=self.deg),
                "base": base, "position_error_m": result.position_error_m,
                "orientation_error_rad": result.orientation_error_rad,
                "iterations": result.iterations, "attempts": result.attempts,
                "solutions": result.solutions, "solve_time_s": elapsed_s, "hint": why}


def setup(robot: RobotDescription, frame: str, seeds: Sequence[tuple[str, float]], *,
          with_base: bool, settings: IkSettings, random_seed: int | None, deg: bool,
          clamp: bool) -> Setup:
    """Build the model, chain, solver, seed and generator for ``frame``."""
    model = robot.model_with_base("planar") if with_base else robot.model
    space = JointSpace.of(model, robot.movable_joints) if with_base else robot.joint_space
    chain = Chain(model, space, frame, link_names(robot))
    # a seed is a starting point: joints it does not name start inside their limits
    seed = space.to_q(space.clamped(user_vector(space, seeds, deg=deg, clamp=clamp)))
    return Setup(robot, space, IkSolver(chain, settings), seed,
                 np.random.default_rng(random_seed), deg)


def single(run: Setup, target: IkTarget, fmt: str) -> None:
    """Solve one target, print the answer; IkFailed (exit 1) when it was not reached."""
    result, elapsed_s, why = run.solve(target, run.seed)
    report = {"robot": run.robot.name, "frame": run.solver.chain.frame_name,
              "relative_to": run.robot.root_link, "target": _target_json(target, run.deg),
              "angle_unit": "deg" if run.deg else "rad",
              **run.report(result, elapsed_s, why)}
    if fmt == "json":
        click.echo(dumps(report), nl=False)
    else:
        for line in ik_text(report, *_limits(run.space, run.deg)):
            click.echo(line)
    if not result.success:
        raise IkFailed(f"no IK solution for {report['frame']}: best position error "
                       f"{result.position_error_m:.3g} m; {why}")


def batch(run: Setup, targets: str, *, axes: tuple[str, ...] | None, output: str | None,
          fmt: str, on_error: str) -> None:
    """Solve every target line of ``targets``, warm-starting each from the last solution."""
    rows = IkBatch(run, run.solver.chain.frame_name, axes=axes)
    tally, display = stream(rows, targets, output=output, fmt=fmt, on_error=on_error,
                            warn=lambda message: click.echo(message, err=True))
    if rows.failed:
        shown = ", ".join(str(n) for n in rows.failed[:5]) + (", ..." if len(rows.failed) > 5
                                                              else "")
        raise IkFailed(f"{len(rows.failed)} of {tally.rows - tally.skipped} targets not reached "
                       f"(line {shown} of {display})")


def _target_json(target: IkTarget, deg: bool) -> dict[str, Any]:
    rpy = None if target.rotation is None else rpy_from_matrix(target.rotation)
    if rpy is not None and deg:
        rpy = np.degrees(rpy)
    return {"position_m": target.position_m.tolist(),
            f"rpy_{'deg' if deg else 'rad'}": None if rpy is None else rpy.tolist(),
            "orientation_axes": list(target.axes)}


def _limits(space: JointSpace, deg: bool) -> tuple[list[str], list[float | None],
                                                   list[float | None]]:
    scale = np.where(angular(space) & deg, math.degrees(1.0), 1.0)
    units = ["m" if t == "prismatic" else "deg" if deg else "rad" for t in space.types]
    lower = [None if math.isnan(v) else float(v * s) for v, s in zip(space.lower, scale,
                                                                       strict=True)]
    upper = [None if math.isnan(v) else float(v * s) for v, s in zip(space.upper, scale,
                                                                       strict=True)]
    return units, lower, upper
