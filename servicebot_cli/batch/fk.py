"""``fk --configs`` as one call: a request and a sink in, a summary out.

Poses stream to the sink as they are computed; skipped lines, the frame picked and values
clamped are said through ``warn``. See :mod:`servicebot_cli.batch.fk_rows` for the rows.
"""

from __future__ import annotations

from dataclasses import dataclass

from servicebot_cli.batch.fk_chunks import stream_csv
from servicebot_cli.batch.fk_rows import FkBatch
from servicebot_cli.batch.policy import OnError
from servicebot_cli.batch.stream import BatchSummary, RowSink, Warn, stream
from servicebot_cli.description.loader import load
from servicebot_cli.kinematics.fk import FrameQuery, resolve_frames


@dataclass(frozen=True)
class FkBatchRequest:
    """Poses for every configuration line of a file.

    Attributes:
        query: The frames and units.
        configs: The input file, ``-`` for stdin.
        on_error: What a bad line does.
    """

    query: FrameQuery
    configs: str
    on_error: OnError = "stop"


def run(request: FkBatchRequest, sink: RowSink, *, warn: Warn) -> BatchSummary:
    """Stream the poses of every configuration of ``request.configs`` to ``sink``.

    Raises:
        DescriptionError, FrameNotFound: The robot or a frame.
        BatchInputError: The input cannot be opened or its header is unusable.
        BadLine: An unusable line under ``--on-error stop``.
    """
    query = request.query
    robot = load(query.robot)
    frames, reference, notes = resolve_frames(robot, query)
    for note in notes:
        warn(note)
    rows = FkBatch(robot, frames, reference, deg=query.deg, clamp=query.clamp,
                   in_world=query.transform_root_to_world())
    summary = stream(rows, request.configs, sink, on_error=request.on_error, warn=warn,
                     chunked_csv=stream_csv)
    if rows.clamped_values:
        warn(f"note: --clamp moved {rows.clamped_values} joint value"
             f"{'s' if rows.clamped_values != 1 else ''} onto a limit, on {rows.clamped_lines} "
             f"of {summary.rows} lines of {summary.source}")
    return summary
