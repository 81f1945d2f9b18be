"""``ik`` as one call: a request in, the answer (or the best try and why) out. No click.

Nothing is printed. The command turns its options into an :class:`IkRequest`; :func:`run`
builds an :class:`~servicebot_cli.kinematics.ik_session.IkSession` (which loads the robot
through the shared loader and builds the solver) and solves; ``output.ik_report`` renders
the :class:`IkAnswer`. Batch mode (``--targets``) builds the same session from the same
:class:`~servicebot_cli.kinematics.ik_problem.IkProblem` (see ``batch.ik``). The clock is
passed in: solve times are measured around the pure solver.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from servicebot_cli.description.joint_space import JointSpace
from servicebot_cli.kinematics.ik_outcome import IkOutcome
from servicebot_cli.kinematics.ik_problem import IkProblem
from servicebot_cli.kinematics.ik_session import Clock, IkSession
from servicebot_cli.kinematics.inverse import IkTarget
from servicebot_cli.kinematics.targets import make_target, parse_axes


@dataclass(frozen=True)
class TargetSpec:
    """A target as typed: a position [m], optionally roll-pitch-yaw or a quaternion.

    Attributes:
        position_m: ``x, y, z`` [m] in the root link's frame.
        rpy: Roll, pitch, yaw [rad, or deg with the problem's ``deg``].
        quat: Quaternion ``x, y, z, w`` (normalised for you).
        axes: ``--orientation-axes`` as typed; None: all with an orientation, none without.
    """

    position_m: tuple[float, ...]
    rpy: tuple[float, ...] | None = None
    quat: tuple[float, ...] | None = None
    axes: str | None = None


@dataclass(frozen=True)
class IkRequest:
    """One target to reach."""

    problem: IkProblem
    target: TargetSpec


@dataclass(frozen=True)
class IkAnswer:
    """The answer to one target.

    Attributes:
        robot: The robot's name.
        frame: The frame moved.
        relative_to: The frame the target is in (the root link, or ``--relative-to``).
        target: The target.
        space: The joint space solved on (names, units and limits for the report).
        outcome: The solve.
        deg: Angles in degrees for the user.
        notes: Lines for stderr: the frame picked, start values clamped.
    """

    robot: str
    frame: str
    relative_to: str
    target: IkTarget
    space: JointSpace = field(repr=False)
    outcome: IkOutcome
    deg: bool = False
    notes: tuple[str, ...] = ()

    @property
    def success(self) -> bool:
        """The target was reached."""
        return self.outcome.success


def run(request: IkRequest, *, clock: Clock) -> IkAnswer:
    """Solve one target, from the request's start configuration.

    Raises:
        DescriptionError, FrameNotFound, JointNotFound, OutOfLimits: As :class:`IkSession`.
        BadTarget: A malformed target or orientation axes.
    """
    spec, problem = request.target, request.problem
    has_orientation = spec.rpy is not None or spec.quat is not None
    axes = parse_axes(spec.axes, has_orientation)
    session = IkSession(problem, clock)
    target = make_target(spec.position_m, rpy=spec.rpy, quat=spec.quat, deg=problem.deg,
                         axes=axes)
    return IkAnswer(session.robot.name, session.frame, session.relative_to, target,
                    session.space, session.solve(session.in_root(target), session.start),
                    problem.deg,
                    session.notes)
