"""Single ``fk`` and ``ik`` answers as CSV: a header, then rows. Rendering only.

The columns are those of the batch results (``fk --configs``, ``ik --targets``) without the
``line`` column, so one answer and a batch read the same way::

    fk:  frame,x_m,y_m,z_m,roll_rad,pitch_rad,yaw_rad,qx,qy,qz,qw      (a row per frame)
    ik:  success,<joint>...,[base_x_m,base_y_m,base_yaw_rad,]position_error_m,
         orientation_error_rad,iterations,attempts,solutions,solve_time_s,hint

Numbers are written in full (``repr``), angles in the answer's unit, which the columns name
with ``--deg``: ``roll_deg``, ``base_yaw_deg``, ``<joint>_deg`` (``<joint>_m`` for a
prismatic joint; bare joint names are radians); ``true``/``false`` for booleans, an empty
cell for none.
"""

from __future__ import annotations

import csv
import io
from collections.abc import Sequence
from typing import TYPE_CHECKING

from servicebot_cli.output.poses import rpy_of

if TYPE_CHECKING:
    from servicebot_cli.kinematics.fk import FkResult
    from servicebot_cli.kinematics.ik import IkAnswer
    from servicebot_cli.kinematics.json_types import JsonValue


def csv_text(header: Sequence[str], rows: Sequence[Sequence[JsonValue]]) -> str:
    """``header`` and ``rows`` as CSV text (``\\n`` line ends)."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(header)
    writer.writerows([[_cell(v) for v in row] for row in rows])
    return out.getvalue()


def fk_csv(result: FkResult) -> str:
    """An ``fk`` answer: a row per frame, in the reference frame."""
    unit = "deg" if result.deg else "rad"
    header = ["frame", "x_m", "y_m", "z_m", f"roll_{unit}", f"pitch_{unit}", f"yaw_{unit}",
              "qx", "qy", "qz", "qw"]
    rows: list[list[JsonValue]] = [[pose.frame, *(float(v) + 0.0 for v in pose.position_m),
             *(v + 0.0 for v in rpy_of(pose, result.deg)),
             *(float(v) + 0.0 for v in pose.quaternion_xyzw)] for pose in result.poses]
    return csv_text(header, rows)


def ik_csv(answer: IkAnswer) -> str:
    """An ``ik`` answer: one row, the joints (and base) in the user's units."""
    from servicebot_cli.kinematics.ik_outcome import flat_values, outcome_values
    from servicebot_cli.kinematics.joint_columns import joint_column_names

    values = outcome_values(answer.space, answer.outcome, answer.deg)
    row = flat_values(values, joint_column_names(answer.space, answer.deg))
    return csv_text(list(row), [list(row.values())])


def _cell(value: JsonValue) -> JsonValue:
    if isinstance(value, bool):
        return "true" if value else "false"
    return "" if value is None else value
