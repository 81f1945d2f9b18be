"""``ik --targets`` as one call: a request and a sink in, a summary out.

Solutions stream to the sink as they are computed, each solve warm-started from the last
solution; skipped lines, the frame picked and start values clamped are said through
``warn``. The summary lists the lines whose target was not reached.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from servicebot_cli.batch.ik_chunks import stream_csv
from servicebot_cli.batch.ik_rows import IkBatch
from servicebot_cli.batch.policy import OnError
from servicebot_cli.batch.stream import BatchSummary, RowSink, Warn, stream
from servicebot_cli.kinematics.ik_problem import IkProblem
from servicebot_cli.kinematics.ik_session import Clock, IkSession, compile_note
from servicebot_cli.kinematics.targets import parse_axes


@dataclass(frozen=True)
class IkBatchRequest:
    """A target per line of a file.

    Attributes:
        problem: What every solve shares.
        targets: The input file, ``-`` for stdin.
        axes: ``--orientation-axes`` as typed; None: per line (all with an orientation).
        on_error: What a bad line does.
    """

    problem: IkProblem
    targets: str
    axes: str | None = None
    on_error: OnError = "stop"


def run(request: IkBatchRequest, sink: RowSink, *, warn: Warn, clock: Clock) -> BatchSummary:
    """Stream a solution for every target of ``request.targets`` to ``sink``.

    Raises:
        DescriptionError, FrameNotFound, JointNotFound, OutOfLimits: As IkSession.
        BadTarget: Unknown orientation axes.
        BatchInputError: The input cannot be opened or its header is unusable.
        BadLine: An unusable line under ``--on-error stop``.
    """
    axes = parse_axes(request.axes, True)

    def compiled(ready_s: float) -> None:
        for line in compile_note(ready_s):
            warn(line)

    session = IkSession(request.problem, clock, compiled=True, on_compiled=compiled)
    for note in session.notes:
        warn(note)
    rows = IkBatch(session, axes=axes)
    summary = stream(rows, request.targets, sink, on_error=request.on_error, warn=warn,
                     chunked_csv=stream_csv)
    return replace(summary, failed=tuple(rows.failed))
