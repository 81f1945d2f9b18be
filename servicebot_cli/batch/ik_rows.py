"""``ik --targets``: one target per line in, one solution per line out, warm-started.

Each solve starts from the previous line's solution (the first from ``--start``), so a path
of nearby targets gives a smooth path of joint values. A target that is not reached still
gives a line (``success`` false, the best try and a hint); the run then ends with exit 1.

Output rows::

    JSON Lines: {"line": 2, "angle_unit": "rad", "success": true, "joints": {...},
                 "base": null, "position_error_m": ..., "orientation_error_rad": ...,
                 "iterations": n, "attempts": n, "solutions": n, "solve_time_s": ...,
                 "hint": null}
    CSV:        line,success,<joint>...,[base_x_m,base_y_m,base_yaw_rad,]position_error_m,...

The unit travels with the values, so ``fk`` reads them back right: with ``--deg`` the JSON
says ``"angle_unit": "deg"`` and each CSV joint column is ``<joint>_deg`` (``<joint>_m``
for a prismatic joint); in radians the columns are the bare joint names.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterable, Iterator, Sequence

import numpy as np
import numpy.typing as npt

from servicebot_cli.batch.reading import Row
from servicebot_cli.batch.stream import RowKind
from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.kinematics.ik_outcome import FLAT_TAIL, IkOutcome, flat_values
from servicebot_cli.kinematics.ik_session import IkSession
from servicebot_cli.kinematics.inverse import IkTarget
from servicebot_cli.kinematics.joint_columns import joint_column_names
from servicebot_cli.kinematics.json_types import JsonObject
from servicebot_cli.kinematics.targets import TARGET_KEYS, BadTarget, row_target
from servicebot_cli.kinematics.user_joints import angular

TARGET_COLUMNS = TARGET_KEYS | {"line"}
CHUNK = 1024
"""Targets read, then solved, at a time."""
FloatArray = npt.NDArray[np.float64]


class IkBatch:
    """Targets from lines, solutions to lines.

    Attributes:
        failed: Line numbers of targets that were not reached.
    """

    def __init__(self, session: IkSession, *, axes: tuple[str, ...] | None) -> None:
        """Read targets for the session's frame; ``axes`` from ``--orientation-axes``.

        ``axes`` None: each line uses all three angles if it has an orientation, none if not.
        """
        self.session, self.frame, self.axes = session, session.frame, axes
        self.failed: list[int] = []
        self._start = session.start
        self._unit = "deg" if session.deg else "rad"
        self._joint_columns = joint_column_names(session.space, session.deg)

    def columns(self) -> list[str]:
        """CSV header of the results."""
        space = self.session.space
        base = ["base_x_m", "base_y_m", f"base_yaw_{self._unit}"] if space.base_nq else []
        return ["line", "success", *self._joint_columns.values(), *base, *FLAT_TAIL]

    def check_header(self, columns: Sequence[str]) -> None:
        """Every CSV column must be a target column (other frames' columns are skipped).

        Raises:
            BadTarget: An unknown column.
        """
        prefix = f"{self.frame}."
        for name in columns:
            key = name[len(prefix):] if name.startswith(prefix) else name
            if key not in TARGET_COLUMNS and "." not in key:
                raise BadTarget(f"column '{name}' is not a target column; use x_m y_m z_m, then "
                                "roll_rad pitch_rad yaw_rad (or _deg) or qx qy qz qw")

    def parse(self, row: Row) -> IkTarget:
        """The target of one line (raises BadTarget or BadNumber when unusable)."""
        return self.session.in_root(row_target(row.values, self.frame, deg=self.session.deg,
                                               axes=self.axes))

    def results(self, items: Iterable[tuple[Row, IkTarget]],
                kind: RowKind) -> Iterator[JsonObject]:
        """Solve each target from the last solution; one output row each.

        Targets are solved :data:`CHUNK` at a time (see :meth:`IkSession.solve_series`), so
        memory stays bounded; a bad line ends the run only after the lines before it.
        """
        iterator = iter(items)
        while True:
            chunk: list[tuple[Row, IkTarget]] = []
            try:
                chunk.extend(itertools.islice(iterator, CHUNK))
            except ServicebotError:  # a bad line under --on-error stop: the lines before it
                yield from self._rows(chunk, kind)
                raise
            if not chunk:
                return
            yield from self._rows(chunk, kind)

    def solve(self, targets: Sequence[IkTarget]) -> list[IkOutcome]:
        """Solve ``targets`` in turn, from the last line's solution; note the failures' index.

        The next call goes on from this one's last solution.
        """
        outcomes = self.session.solve_series(targets, self._start)
        for outcome in outcomes:
            if outcome.success:
                self._start = outcome.result.q
        return outcomes

    def row(self, line: int, outcome: IkOutcome, kind: RowKind) -> JsonObject:
        """The result row of one line (and the line noted when its target was not reached)."""
        if not outcome.success:
            self.failed.append(line)
        values = self.session.values(outcome)
        if kind == "jsonl":
            return {"line": line, "angle_unit": self._unit, **values}
        return self._flat(line, values)

    def joint_table(self, qs: Sequence[FloatArray]) -> FloatArray:
        """Joint values in the user's units, one row per configuration, as :meth:`row` shows.

        Args:
            qs: Full configurations.

        Returns:
            Shape (len(qs), joints), the values
            :func:`~servicebot_cli.kinematics.ik_outcome.outcome_values` gives, bit for bit.
        """
        space = self.session.space
        if "continuous" in space.types:  # atan2 of (cos, sin), one configuration at a time
            values = np.array([space.from_q(q) for q in qs]).reshape(len(qs), -1)
        else:
            values = np.array(qs).reshape(len(qs), -1)[:, list(space.idx_q)]
        return np.where(angular(space), np.degrees(values), values) if self.session.deg \
            else values

    def _rows(self, chunk: list[tuple[Row, IkTarget]], kind: RowKind) -> Iterator[JsonObject]:
        outcomes = self.solve([target for _, target in chunk])
        for (row, _), outcome in zip(chunk, outcomes, strict=True):
            yield self.row(row.line, outcome, kind)

    def _flat(self, line: int, values: JsonObject) -> JsonObject:
        return {"line": line, **flat_values(values, self._joint_columns)}
