"""``ik --targets``: one target per line in, one solution per line out, warm-started.

Each solve starts from the previous line's solution (the first from ``--seed``), so a path
of nearby targets gives a smooth path of joint values. A target that is not reached still
gives a line (``success`` false, the best try and a hint); the run then ends with exit 1.

Output rows::

    JSON Lines: {"line": 2, "success": true, "joints": {...}, "base": null,
                 "position_error_m": ..., "orientation_error_rad": ..., "iterations": n,
                 "attempts": n, "solutions": n, "solve_time_s": ..., "hint": null}
    CSV:        line,success,<joint>...,[base_x_m,base_y_m,base_yaw_rad,]position_error_m,...
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Sequence
from typing import Any, Protocol

import numpy as np
import numpy.typing as npt

from servicebot_cli.batch.reading import Row
from servicebot_cli.description.joint_space import JointSpace
from servicebot_cli.kinematics.inverse import IkResult, IkTarget
from servicebot_cli.kinematics.targets import TARGET_KEYS, BadTarget, row_target

FloatArray = npt.NDArray[np.float64]

_TAIL = ("position_error_m", "orientation_error_rad", "iterations", "attempts", "solutions",
         "solve_time_s", "hint")
TARGET_COLUMNS = TARGET_KEYS | {"line"}


class Solves(Protocol):
    """What the batch needs from the command: a seed, a solve, and a report."""

    space: JointSpace
    seed: FloatArray
    deg: bool

    def solve(self, target: IkTarget, seed: FloatArray) -> tuple[IkResult, float, str | None]:
        """Solve from ``seed``: the result, the time [s], a hint on failure."""

    def report(self, result: IkResult, elapsed_s: float, why: str | None) -> dict[str, Any]:
        """JSON-ready values of a result."""


class IkBatch:
    """Targets from lines, solutions to lines.

    Attributes:
        failed: Line numbers of targets that were not reached.
    """

    def __init__(self, run: Solves, frame: str, *, axes: tuple[str, ...] | None) -> None:
        """Read targets for ``frame``; ``axes`` from ``--orientation-axes`` (None: per line)."""
        self.run, self.frame, self.axes = run, frame, axes
        self.failed: list[int] = []

    def columns(self) -> list[str]:
        """CSV header of the results."""
        base = ["base_x_m", "base_y_m", f"base_yaw_{'deg' if self.run.deg else 'rad'}"] \
            if self.run.space.base_nq else []
        return ["line", "success", *self.run.space.names, *base, *_TAIL]

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
        return row_target(row.values, self.frame, deg=self.run.deg, axes=self.axes)

    def results(self, items: Iterable[tuple[Row, IkTarget]],
                kind: str) -> Iterator[dict[str, Any]]:
        """Solve each target from the last solution; one output row each."""
        seed = self.run.seed
        for row, target in items:
            result, elapsed_s, why = self.run.solve(target, seed)
            if result.success:
                seed = result.q
            else:
                self.failed.append(row.line)
            report = self.run.report(result, elapsed_s, why)
            yield {"line": row.line, **report} if kind == "jsonl" else self._flat(row.line, report)

    def _flat(self, line: int, report: dict[str, Any]) -> dict[str, Any]:
        flat = {"line": line, "success": report["success"], **report["joints"]}
        if report["base"]:
            flat.update({f"base_{k}": v for k, v in report["base"].items()})
        flat.update({k: report[k] for k in _TAIL})
        return flat
