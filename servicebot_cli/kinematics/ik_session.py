"""The model, solver, start and random generator of one ``ik`` command, and its solves.

:class:`IkSession` loads the robot (through the shared loader) for an
:class:`~servicebot_cli.kinematics.ik_problem.IkProblem`, builds the solver with the
collision check the problem asks for (:func:`collision_check`), and solves targets one by
one or in series. The clock is passed in: solve times are measured around the pure solver.
No click.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.description.joint_space import JointSpace
from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.description.robot import RobotDescription
from servicebot_cli.kinematics.chain import Chain
from servicebot_cli.kinematics.collisions import CollisionCheck, build_check
from servicebot_cli.kinematics.diagnosis import collision_hint, hint, timeout_hint
from servicebot_cli.kinematics.drive_geometry import drive_geometry
from servicebot_cli.kinematics.frames import link_names, pick_frame
from servicebot_cli.kinematics.ik_outcome import IkOutcome, outcome_values
from servicebot_cli.kinematics.ik_problem import CollisionOptions, IkProblem
from servicebot_cli.kinematics.inverse import IkSolver, IkTarget
from servicebot_cli.kinematics.json_types import JsonObject
from servicebot_cli.kinematics.mesh_wheels import no_points
from servicebot_cli.kinematics.mimics import Mimics
from servicebot_cli.kinematics.series import series_search, solve_leading
from servicebot_cli.kinematics.srdf import robot_disabled_pairs
from servicebot_cli.kinematics.target_frame import TargetFrame
from servicebot_cli.kinematics.user_joints import clamped_user_vector

if TYPE_CHECKING:
    import pinocchio as pin

FloatArray = npt.NDArray[np.float64]
Clock = Callable[[], float]
"""Seconds from an arbitrary origin (``time.perf_counter``)."""


class IkSession:
    """The model, solver, start configuration and random generator of one command.

    Attributes:
        robot: The description.
        space: Joint space solved on (with the planar base for ``with_base``).
        solver: The IK solver for the chain of the frame.
        start: Full configuration to start from.
        deg: Angles in degrees for the user.
        notes: Lines for stderr: the frame picked, start values clamped.
    """

    def __init__(self, problem: IkProblem, clock: Clock, *, compiled: bool = False,
                 on_compiled: Callable[[float], None] | None = None) -> None:
        """Load the robot and build everything a solve needs.

        With ``compiled``, attempts run in the compiled loop where it can (see
        :class:`~servicebot_cli.kinematics.inverse.IkSolver`): worth it for many targets,
        since the first process on a machine compiles it (seconds) at its first solve, and
        ``on_compiled`` then hears how many seconds that took.

        Raises:
            DescriptionError: The robot cannot be loaded.
            FrameNotFound: The frame is not a link.
            JointNotFound, OutOfLimits: A bad start value (without ``clamp``).
        """
        robot = load(problem.robot)
        frame, note = pick_frame(robot, problem.frame)
        model = robot.model_with_base("planar") if problem.with_base else robot.model
        space = JointSpace.of(model, robot.movable_joints) if problem.with_base \
            else robot.joint_space
        chain = Chain(model, space, frame, link_names(robot), Mimics.of(robot.joints, space))
        values, clamped = clamped_user_vector(
            space, problem.start, deg=problem.deg, clamp=problem.clamp,
            fixed=robot.unvalued_joints)
        # a start is a starting point: joints it does not name start inside their limits
        self.robot: RobotDescription = robot
        self.space = space
        check = collision_check(robot, model, problem.robot, problem.collisions, chain.names)
        self.solver = IkSolver(chain, problem.settings, check, compiled=compiled,
                             on_compiled=on_compiled)
        self.start: FloatArray = space.to_q(space.clamped(values))
        self.deg = problem.deg
        self.notes = (*((note,) if note else ()), *(c.note() for c in clamped))
        self.target_frame = None if problem.relative_to is None else TargetFrame.at(
            model, self.start, problem.relative_to, link_names(robot))
        self._rng = np.random.default_rng(problem.seed)
        self._clock = clock
        self._timeout_s = problem.timeout_s

    @property
    def frame(self) -> str:
        """The frame solved for."""
        return self.solver.chain.frame_name

    @property
    def relative_to(self) -> str:
        """The frame targets are given in."""
        return self.robot.root_link or "" if self.target_frame is None else \
            self.target_frame.name

    def in_root(self, target: IkTarget) -> IkTarget:
        """``target``, given in :attr:`relative_to`, in the frame :meth:`solve` takes.

        Raises:
            BadTarget: Orientation angles left free in a turned ``relative_to`` frame.
        """
        return target if self.target_frame is None else self.target_frame.to_root(target)

    def solve(self, target: IkTarget, start: FloatArray) -> IkOutcome:
        """Solve for ``target`` from ``start``; with a hint when it was not reached.

        ``target`` is in the root link's frame (see :meth:`in_root`).
        """
        clock, timeout_s = self._clock, self._timeout_s
        begin = clock()
        stop = None if timeout_s is None else lambda: clock() - begin > timeout_s
        result = self.solver.solve(target, start, self._rng, stop)
        elapsed_s = clock() - begin
        why = None if result.success else collision_hint(result.contact) if result.contact \
            else timeout_hint(timeout_s, result.attempts) if result.stopped and timeout_s \
            else hint(self.solver, target, start, self._rng)
        return IkOutcome(result, elapsed_s, why)

    def solve_series(self, targets: Sequence[IkTarget], start: FloatArray) -> list[IkOutcome]:
        """:meth:`solve` each target in turn, each from the last success.

        The first starts from ``start``. The outcomes are the same, with runs of targets
        solved in one compiled call where the settings allow it (see
        :mod:`~servicebot_cli.kinematics.series`).

        A target solved in such a run is given its share of the run's time as ``elapsed_s``.
        """
        compiled = None if self._timeout_s is not None else series_search(self.solver,
                                                                            self._rng)
        if compiled is None:
            return self._one_by_one(targets, start)
        outcomes: list[IkOutcome] = []
        while len(outcomes) < len(targets):
            begin = self._clock()
            results = solve_leading(self.solver, compiled, targets[len(outcomes):], start,
                                    self._rng)
            share_s = (self._clock() - begin) / max(1, len(results))
            outcomes.extend(IkOutcome(result, share_s, None) for result in results)
            if results:
                start = results[-1].q
            if len(outcomes) < len(targets):
                outcome = self.solve(targets[len(outcomes)], start)
                outcomes.append(outcome)
                if outcome.success:
                    start = outcome.result.q
        return outcomes

    def _one_by_one(self, targets: Sequence[IkTarget], start: FloatArray) -> list[IkOutcome]:
        outcomes = []
        for target in targets:
            outcome = self.solve(target, start)
            if outcome.success:
                start = outcome.result.q
            outcomes.append(outcome)
        return outcomes

    def values(self, outcome: IkOutcome) -> JsonObject:
        """``outcome`` as JSON values in the user's units (see :func:`outcome_values`)."""
        return outcome_values(self.space, outcome, self.deg)


_COMPILED_S = 1.0  # the compiled loop takes longer than this to be ready only when compiled


def compile_note(ready_s: float) -> tuple[str, ...]:
    """A line for stderr when the compiled loop had to be compiled, which happens once."""
    if ready_s < _COMPILED_S:
        return ()
    return (f"compiled the IK loop in {ready_s:.1f} s; later runs load it from numba's cache",)


def collision_check(robot: RobotDescription, model: pin.Model, source: RobotSource,
                    options: CollisionOptions, moving: tuple[str, ...]) -> CollisionCheck | None:
    """The collision check ``options`` ask for on ``model``, of the pairs ``moving`` moves.

    None when turned off.

    Raises:
        BadSrdf: An unreadable SRDF, or one that names a link the robot does not have.
        CollisionSetupError: A collision mesh that cannot be read.
    """
    if not options.check:
        return None
    disabled = robot_disabled_pairs(options.srdf, robot)
    return build_check(robot, model, source.resolver(), disabled=disabled, moving=moving,
                       floor=is_mobile(robot))


def is_mobile(robot: RobotDescription) -> bool:
    """Whether ``robot`` stands on wheels, and so on a floor its links must stay above.

    A fixed arm has no floor: it may be mounted on a table, a pedestal or a wall, and reach
    below its base plane.
    """
    try:
        drive_geometry(robot, no_points)  # whether it has wheels, not where: no mesh read
    except DescriptionError:
        return False
    return True
