"""The base and the arm stopped by obstacles, a stretch of ticks at a time.

Each tick the wheels ask for a step of the base (an arc from its pose) and the arm controller
for a step of the arm (toward its reference, within the velocity limits). A step that would
put any link into an obstacle is refused, as a wall refuses it. The steps are tried in order:

1. both: taken if every link is free;
2. the base's step with the arm where it was: taken if free, the arm's step refused;
3. the arm's step with the base where it was: taken if free, the base's step refused;
4. else both are refused.

The base is tried first (2 before 3) because it carries the arm. A refused motion waits
where it was: the wheels keep turning, the arm's reference goes on. It is tried again every
tick, and moves again with the first step that is free (turning or backing away, the
reference coming back; the arm then catches up within its velocity limits). A refusal of a
motion that was moving logs one contact: the link, the obstacle and the time the refused step
began; none while that motion stays refused.

Vectorised: the present state (each motion moving or waiting) is supposed to last to the end
of the stretch, every tick's tries are made at once, and the stretch is cut at the first tick
whose outcome is different; the next stretch starts there. A run in pieces has the same bits
as the run in one piece.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.controllers.arm_trajectory import ArmMotion
from servicebot_cli.simulate.world.motion import Contact, Integrator, Path2D, arc_step

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
BoolArray = npt.NDArray[np.bool_]
_State = tuple[FloatArray, FloatArray, FloatArray, FloatArray]  # x, y, yaw (n,), arm q (n, J)
_SHORTEST, _LONGEST = 16, 1 << 30  # ticks looked at after a change, and at most

Collides = Callable[[FloatArray, FloatArray, FloatArray, FloatArray], tuple[IntArray, IntArray]]
"""Given arm positions (P, J) and base poses ``x, y, yaw`` (P,): per pose the obstacle touched
and the link touching it (indices into the names), -1 where free."""


@dataclass(frozen=True)
class _Outcome:
    """Per tick of a stretch: what each motion asked and whether it was refused, and why."""

    base_moves: BoolArray  # the base's step changes its pose
    arm_moves: BoolArray  # the arm's step changes its positions
    base_refused: BoolArray
    arm_refused: BoolArray
    base_hit: tuple[IntArray, IntArray]  # (obstacle, link) that refused the base's step
    arm_hit: tuple[IntArray, IntArray]


class BlockedMotion:
    """The base's pose and the arm's positions with steps into obstacles refused.

    Args:
        start: The base's start pose (x [m], y [m], yaw [rad]).
        dt_s: Control period [s].
        names: The obstacles' names.
        links: The link of each collision part.
        arm: The arm controller.
    """

    def __init__(self, start: tuple[float, float, float], dt_s: float, names: list[str],
                 links: Sequence[str], arm: ArmMotion) -> None:
        self.dt_s, self.names, self.links, self.arm = dt_s, names, links, arm
        self.pose = start
        self.q = arm.start()
        self.integrator = Integrator(start)
        self.base_waiting = False
        self.arm_waiting = False
        self.window = _LONGEST  # ticks looked at in one stretch

    def advance(self, first_tick: int, linear_m_s: FloatArray, angular_rad_s: FloatArray,
                collides: Collides) -> tuple[Path2D, FloatArray, list[Contact]]:
        """The next ticks from ``first_tick``: the path, the arm and the contacts that began.

        Args:
            first_tick: The stretch's first tick.
            linear_m_s: The wheels' forward speed at each tick, shape (n,).
            angular_rad_s: Their yaw rate at each tick, shape (n,).
            collides: What each pose of the base and the arm would touch.

        Returns:
            The base's path, the arm's positions at the n + 1 tick boundaries (n+1, J), and
            the contacts, in time order.
        """
        n = len(linear_m_s)
        lin, ang = np.array(linear_m_s, float), np.array(angular_rad_s, float)
        ref = self.arm.references(
            np.arange(first_tick, first_tick + n + 1, dtype=np.float64) * self.dt_s)
        x, y, yaw = np.empty(n + 1), np.empty(n + 1), np.empty(n + 1)
        q = np.empty((n + 1, len(self.q)))
        x[0], y[0], yaw[0] = self.pose
        q[0] = self.q
        contacts: list[Contact] = []
        k = 0
        while k < n:
            k = self._stretch(first_tick, k, (x, y, yaw, q), lin, ang, ref, collides, contacts)
        self.pose = (float(x[n]), float(y[n]), float(yaw[n]))
        self.q = q[n].copy()
        held = (np.diff(x) == 0) & (np.diff(y) == 0) & (np.diff(yaw) == 0)
        path = Path2D(self.dt_s, x, y, yaw, np.where(held, 0.0, lin), np.where(held, 0.0, ang),
                      first_tick)
        return path, q, contacts

    def _stretch(self, first_tick: int, k: int, state: _State, lin: FloatArray,
                 ang: FloatArray, ref: FloatArray, collides: Collides,
                 contacts: list[Contact]) -> int:
        """Fill the ticks after ``k`` while each motion keeps moving or waiting; return the last.

        The tick where the outcome changes is filled too, and contacts logged for it. At most
        :attr:`window` ticks are looked at: short after a change, longer while none comes.
        """
        end = min(len(lin), k + self.window)
        asked, going, sums = self._suppose(k, state, lin[k:end], ang[k:end], ref[k:end + 1])
        x, y, yaw, q = state
        before = tuple(np.concatenate((v[k:k + 1], g[:-1])) for v, g in zip(state, going,
                                                                            strict=True))
        outcome = _outcome(collides, asked, before)  # type: ignore[arg-type]
        changed = (outcome.base_moves & ~outcome.base_refused if self.base_waiting
                   else outcome.base_refused)
        changed = changed | (outcome.arm_moves & ~outcome.arm_refused if self.arm_waiting
                             else outcome.arm_refused)
        events = np.flatnonzero(changed)
        e = int(events[0]) if len(events) else end - k  # ticks k+1 .. k+e go on as they are
        for whole, part in zip(state, going, strict=True):
            whole[k + 1:k + e + 1] = part[:e]
        if not len(events):
            if sums is not None:
                self.integrator.keep(sums, e)
            self.window = min(4 * self.window, _LONGEST)
            return end
        self.window = _SHORTEST
        t, time_s = k + e + 1, (first_tick + k + e) * self.dt_s  # the changed tick, its start
        pose = (float(x[t - 1]), float(y[t - 1]), float(yaw[t - 1]))
        if outcome.base_refused[e]:
            x[t], y[t], yaw[t] = pose
            if sums is not None:
                self.integrator.keep(sums, e)
            if not self.base_waiting:
                contacts.append(self._contact(time_s, outcome.base_hit, e, pose))
            self.base_waiting = True
        else:
            x[t], y[t], yaw[t] = (asked[0][e], asked[1][e], asked[2][e]) \
                if outcome.base_moves[e] else pose
            if sums is not None:
                self.integrator.keep(sums, e + 1)
            elif outcome.base_moves[e]:  # resumed: the step from the held pose, as tried
                self.integrator.restart(pose)
                self.integrator.keep(self.integrator.trial(lin[t - 1:t], ang[t - 1:t],
                                                           self.dt_s)[3], 1)
                self.base_waiting = False
        if outcome.arm_refused[e]:
            q[t] = q[t - 1]
            if not self.arm_waiting:
                contacts.append(self._contact(time_s, outcome.arm_hit, e, pose))
            self.arm_waiting = True
        else:
            q[t] = asked[3][e]
            self.arm_waiting = self.arm_waiting and not outcome.arm_moves[e]
        return t

    def _suppose(self, k: int, state: _State, lin: FloatArray, ang: FloatArray,
                 ref: FloatArray) -> tuple[_State, _State, FloatArray | None]:
        """The steps asked after tick ``k``, and the states if each motion goes on as it is.

        A moving base follows its integrator (whose running sums are returned to keep), a
        waiting one asks each step from where it waits; a moving arm follows the reference, a
        waiting one asks each step from where it waits.
        """
        x, y, yaw, q = state
        m = len(lin)
        sums = None
        if self.base_waiting:
            bx, by, byaw = _single_steps((x[k], y[k], yaw[k]), lin, ang, self.dt_s)
            sx, sy, syaw = (np.full(m, v) for v in (x[k], y[k], yaw[k]))
        else:
            bx, by, byaw, sums = self.integrator.trial(lin, ang, self.dt_s)
            sx, sy, syaw = bx, by, byaw
        if self.arm_waiting:
            aq = self.arm.step(np.broadcast_to(q[k], (m, q.shape[1])), ref[:-1], ref[1:])
            sq = np.broadcast_to(q[k], aq.shape)
        else:
            aq = self.arm.follow(ref, q[k])[1:]
            sq = aq
        return (bx, by, byaw, aq), (sx, sy, syaw, sq), sums

    def _contact(self, time_s: float, hit: tuple[IntArray, IntArray], e: int,
                 pose: tuple[float, float, float]) -> Contact:
        return Contact(time_s, self.names[int(hit[0][e])], self.links[int(hit[1][e])], *pose)


def _single_steps(pose: tuple[float, float, float], lin: FloatArray, ang: FloatArray,
                  dt_s: float) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Each tick's step from one held pose, as :class:`Integrator` restarted there makes it."""
    dx, dy, dyaw = arc_step(lin, ang, dt_s)
    c, s = np.cos(pose[2] + -0.0), np.sin(pose[2] + -0.0)
    return (pose[0] + (-0.0 + (c * dx - s * dy)), pose[1] + (-0.0 + (s * dx + c * dy)),
            pose[2] + (-0.0 + dyaw))


def _outcome(collides: Collides, asked: tuple[FloatArray, FloatArray, FloatArray, FloatArray],
             before: tuple[FloatArray, FloatArray, FloatArray, FloatArray]) -> _Outcome:
    """Each tick's tries (both steps, the base's alone, the arm's alone) and what they refuse.

    Only the tries a tick needs are made: none where nothing moves, the partial ones only
    where both move and together they touch.
    """
    bx, by, byaw, aq = asked
    px, py, pyaw, pq = before
    base_moves = (bx != px) | (by != py) | (byaw != pyaw)
    arm_moves = np.any(aq != pq, axis=1)
    both = _hits(collides, (bx, by, byaw, aq), base_moves | arm_moves)
    blocked = both[0] >= 0
    split = blocked & base_moves & arm_moves
    base_alone = _hits(collides, (bx, by, byaw, pq), split)
    base_stuck = base_alone[0] >= 0
    arm_alone = _hits(collides, (px, py, pyaw, aq), split & base_stuck)
    arm_stuck = arm_alone[0] >= 0
    only_base = blocked & ~arm_moves  # the base's step alone was tried, and refused
    only_arm = blocked & ~base_moves
    base_refused = only_base | (split & base_stuck)
    arm_refused = only_arm | (split & (~base_stuck | arm_stuck))
    return _Outcome(base_moves, arm_moves, base_refused, arm_refused,
                    _pick(only_base, both, base_alone),
                    _pick(only_arm | (split & ~base_stuck), both, arm_alone))


def _hits(collides: Collides, poses: tuple[FloatArray, FloatArray, FloatArray, FloatArray],
          rows: BoolArray) -> tuple[IntArray, IntArray]:
    """What the poses at ``rows`` touch (obstacle, link); -1 elsewhere.

    A pose with the same bits as the tick before is not tested again: a base held against an
    obstacle asks for the same step tick after tick.
    """
    obstacle = np.full(len(rows), -1, dtype=np.int64)
    link = np.full(len(rows), -1, dtype=np.int64)
    index = np.flatnonzero(rows)
    if len(index):
        x, y, yaw, q = poses
        bits = np.column_stack((x[index], y[index], yaw[index], q[index])).view(np.int64)
        new = np.ones(len(index), dtype=bool)
        new[1:] = np.any(bits[1:] != bits[:-1], axis=1)
        chosen = index[new]
        found = collides(q[chosen], x[chosen], y[chosen], yaw[chosen])
        at = np.cumsum(new) - 1  # each row's pose among those tested
        obstacle[index], link[index] = found[0][at], found[1][at]
    return obstacle, link


def _pick(first: BoolArray, a: tuple[IntArray, IntArray],
          b: tuple[IntArray, IntArray]) -> tuple[IntArray, IntArray]:
    """``a`` where ``first``, else ``b``."""
    return np.where(first, a[0], b[0]), np.where(first, a[1], b[1])
