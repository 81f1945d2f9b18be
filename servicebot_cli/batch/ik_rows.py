"""``ik --targets``: one target per line in, one solution per line out, warm-started.

Each solve starts from the previous line's solution (the first from ``--start``), so a path
of nearby targets gives a smooth path of joint values. A target that is not reached still
gives a line (``success`` false, the best try and a hint); the run then ends with exit 1.

Output rows::

    JSON Lines: {"line": 2, "success": true, "joints": {...}, "base": null,
                 "position_error_m": ..., "orientation_error_rad": ..., "iterations": n,
                 "attempts": n, "solutions": n, "solve_time_s": ..., "hint": null}
    CSV:        line,success,<joint>...,[base_x_m,base_y_m,base_yaw_rad,]position_error_m,...
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping, Sequence

from servicebot_cli.batch.reading import Row
from servicebot_cli.batch.stream import RowKind
from servicebot_cli.kinematics.ik import IkSession
from servicebot_cli.kinematics.inverse import IkTarget
from servicebot_cli.kinematics.json_types import JsonObject
from servicebot_cli.kinematics.targets import TARGET_KEYS, BadTarget, row_target

_TAIL = ("position_error_m", "orientation_error_rad", "iterations", "attempts", "solutions",
         "solve_time_s", "hint")
TARGET_COLUMNS = TARGET_KEYS | {"line"}


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

    def columns(self) -> list[str]:
        """CSV header of the results."""
        space = self.session.space
        base = ["base_x_m", "base_y_m", f"base_yaw_{'deg' if self.session.deg else 'rad'}"] \
            if space.base_nq else []
        return ["line", "success", *space.names, *base, *_TAIL]

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
        """Solve each target from the last solution; one output row each."""
        start = self.session.start
        for row, target in items:
            outcome = self.session.solve(target, start)
            if outcome.success:
                start = outcome.result.q
            else:
                self.failed.append(row.line)
            values = self.session.values(outcome)
            yield {"line": row.line, **values} if kind == "jsonl" else \
                self._flat(row.line, values)

    def _flat(self, line: int, values: JsonObject) -> JsonObject:
        flat: JsonObject = {"line": line, "success": values["success"]}
        joints, base = values["joints"], values["base"]
        if isinstance(joints, Mapping):
            flat.update(joints)
        if isinstance(base, Mapping):
            flat.update({f"base_{k}": v for k, v in base.items()})
        flat.update({k: values[k] for k in _TAIL})
        return flat
