"""The closest the robot came to an obstacle, measured with Coal only where it can matter.

Bounds first (:mod:`.part_groups`): a group of parts at a pose, against one obstacle, is
opened (its parts bounded one by one) only if its bound could beat the best distance measured
(without a clearance known yet, the nearest groups are measured first to find one); a
part-obstacle pair is bounded again with boxes, and measured only while its bound could beat
it. Of equal distances the first pose wins (then the first part, then the first obstacle), so
the answer is the least (distance, pose, part, obstacle) of all the pairs below the clearance
already known, whatever the order of measuring.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from servicebot_cli.simulate.world.contacts import Placed, Tester, as_placed
from servicebot_cli.simulate.world.part_groups import MARGIN_M

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
_CHUNK = 32  # exact distances measured per round of the search
_GROUPS = 64  # groups opened to find a first clearance


@dataclass(frozen=True)
class Closest:
    """The closest the robot came to an obstacle.

    Attributes:
        distance_m: The clearance [m]; inf in an empty world.
        index: The pose (tick) where it happened, -1 for none.
        obstacle: Index into the obstacles, -1 for none.
        part: Index into the robot's parts, -1 for none.
    """

    distance_m: float
    index: int
    obstacle: int
    part: int


def closest(tester: Tester, posed: FloatArray | Placed, below: float = np.inf) -> Closest:
    """The smallest part-obstacle distance over all poses, measured only where it can be.

    Only a distance below ``below`` (a clearance already known) counts: none is found
    otherwise.
    """
    none = Closest(float("inf"), -1, -1, -1)
    posed = as_placed(posed)
    if not tester.world or not len(posed):
        return none
    search = _Search(tester, posed, float(below))
    centres, near = tester.near(posed, search.best)
    groups = near.ravel()
    open_ = np.flatnonzero(np.isfinite(groups))
    if not np.isfinite(search.best) and len(open_) > _GROUPS:  # a first best, from the nearest
        first = open_[np.argpartition(groups[open_], _GROUPS)[:_GROUPS]]
        search.add(centres, np.sort(first), near.shape)
        while search.measure():
            pass
        groups[first] = np.nan  # opened: neither below nor above any bound
    open_ = open_[groups[open_] <= search.best + MARGIN_M]
    search.add(centres, open_, near.shape)
    while search.measure():
        pass
    return search.answer()


class _Search:
    """The pairs opened so far, their bounds, and the best distance measured."""

    def __init__(self, tester: Tester, posed: Placed, below: float) -> None:
        self.tester, self.posed = tester, posed
        self.shape = posed.shape + (len(tester.world),)  # (poses, parts, obstacles)
        self.best, self.best_flat = below, -1
        self.bounds = np.zeros(0)
        self.flats = np.zeros(0, dtype=np.int64)

    def add(self, centres: FloatArray, groups: IntArray, grid: tuple[int, ...]) -> None:
        """Open ``groups`` (flat indices into (poses, groups, obstacles)): bound their pairs.

        The pairs whose sphere bound could beat (or equal) the best are bounded again with
        boxes; only those that still could are kept.
        """
        pose, group, obstacle = np.unravel_index(groups, grid)
        bounds, flats = [self.bounds], [self.flats]
        key = group * grid[2] + obstacle
        for k in sorted(set(key.tolist())):  # np.unique would import numpy.ma
            rows = pose[key == k]
            g, o = divmod(k, grid[2])
            pair_bounds, members = self.tester.pairs(centres, rows, g, o)
            i, j = np.nonzero(pair_bounds <= self.best)
            closer = self.tester.closer(self.posed, centres, rows[i], members[j], o,
                                        pair_bounds[i, j])
            near = closer <= self.best
            bounds.append(closer[near])
            flats.append(np.ravel_multi_index(
                (rows[i[near]], members[j[near]], np.full(np.count_nonzero(near), o)),
                self.shape))
        self.bounds, self.flats = np.concatenate(bounds), np.concatenate(flats)

    def measure(self) -> bool:
        """Measure the (up to :data:`_CHUNK`) least-bounded pairs that could beat the best.

        A pair bounded by the best distance may still equal it, at an earlier pose. Returns
        False when no pair could.
        """
        bounds = self.bounds
        open_ = np.flatnonzero(bounds <= self.best) if self.best_flat >= 0 \
            else np.flatnonzero(bounds < self.best)
        if not len(open_):
            return False
        take = open_ if len(open_) <= _CHUNK else \
            open_[np.argpartition(bounds[open_], _CHUNK)[:_CHUNK]]
        for flat in np.sort(self.flats[take]).tolist():
            p, s, o = np.unravel_index(flat, self.shape)
            d = self.tester.distance(self.posed, int(p), int(s), int(o))
            if d < self.best or (d == self.best and self.best_flat >= 0
                                 and flat < self.best_flat):
                self.best, self.best_flat = d, flat
        keep = bounds <= self.best  # the others can neither beat nor equal it
        keep[take] = False
        self.bounds, self.flats = bounds[keep], self.flats[keep]
        return True

    def answer(self) -> Closest:
        if self.best_flat < 0:
            return Closest(float("inf"), -1, -1, -1)
        p, s, o = np.unravel_index(self.best_flat, self.shape)
        return Closest(self.best, int(p), int(o), int(s))
