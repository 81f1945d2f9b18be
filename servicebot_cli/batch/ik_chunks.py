"""``ik --targets`` on CSV, a chunk of lines at a time: targets in and rows out with numpy.

Most of a batch's time outside the solver would go to Python work per line: a dict per row,
a conversion per cell, a target built number by number, a writer call per result. Here a
chunk of :data:`CHUNK_LINES` lines is split at once, the target columns converted by one
``np.array(cells, dtype=float)`` (which reads each cell as ``float()`` does), the targets
made for the whole chunk (:func:`~servicebot_cli.kinematics.target_table.table_targets`),
solved as the per-line path solves them, and the CSV rows of the targets reached made by one
%-format of a row template (``%r``: the ``repr`` of each float, as csv.writer writes it).
The output is the per-line path's, byte for byte.

A chunk with a line the fast path cannot take (a quoted or empty cell, a wrong field count,
not a number, a target :func:`~servicebot_cli.kinematics.targets.row_target` refuses) goes
through the per-line path instead, so every error still names its line and ``--on-error``
behaves the same. Memory stays bounded by the chunk size.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import IO

from servicebot_cli.batch.ik_rows import CHUNK, IkBatch
from servicebot_cli.batch.line_chunks import chunks, numbers, split_cells
from servicebot_cli.batch.policy import OnError, Tally
from servicebot_cli.batch.reading import Source, csv_rows
from servicebot_cli.batch.stream import (
    BatchSummary,
    RowKind,
    RowSink,
    Warn,
    WriteRow,
    refuse_no_lines,
    summarise,
    write_results,
)
from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.kinematics.ik_outcome import IkOutcome
from servicebot_cli.kinematics.inverse import IkTarget
from servicebot_cli.kinematics.target_table import TargetLayout, table_targets, target_layout

CHUNK_LINES = CHUNK
"""Raw lines read, solved and written at a time."""


def stream_csv(batch: IkBatch, source: Source, handle: IO[str], sink: RowSink, *,
               on_error: OnError, warn: Warn) -> BatchSummary:
    """Solutions for every target line of an open CSV ``source``, chunk by chunk, to ``sink``.

    Args:
        batch: The session, frame and orientation axes.
        source: The input, its header read (``handle`` stands just after it).
        handle: The open input.
        sink: Where result rows go.
        on_error: What a bad line does.
        warn: Where skipped lines are reported.

    Raises:
        BadTarget: A header column that is not a target column.
        BadLine: An unusable line under ``--on-error stop``.
    """
    batch.check_header(source.columns)
    layout = target_layout(source.columns, batch.frame, deg=batch.session.deg)
    tally = Tally()
    with sink.open(batch.columns()) as write:
        for lines in chunks(handle, source.header_line, CHUNK_LINES):
            targets = _targets(batch, layout, source, [text for _, text in lines]) \
                if lines and layout is not None else None
            if targets is None:  # line by line: the messages name the line
                write_results(batch, csv_rows(lines, source.columns, source.delimiter),
                              source.display, write, sink.kind, on_error=on_error, warn=warn,
                              tally=tally)
                continue
            tally.rows += len(lines)
            _write(batch, [n for n, _ in lines], batch.solve(targets), write, sink.kind)
        refuse_no_lines(source.display, tally)
    return summarise(source.display, tally, warn)


def _targets(batch: IkBatch, layout: TargetLayout, source: Source,
             texts: list[str]) -> list[IkTarget] | None:
    """The chunk's targets in the root frame; None: a line needs the per-line path."""
    width = len(source.columns)
    cells = split_cells(texts, source.delimiter, width)
    values = None if cells is None else numbers(cells, width, layout.columns)
    targets = None if values is None else table_targets(layout, values, batch.axes)
    if targets is None:
        return None
    try:
        return [batch.session.in_root(target) for target in targets]
    except ServicebotError:  # e.g. free angles in a turned --relative-to frame
        return None


def _write(batch: IkBatch, lines: Sequence[int], outcomes: Sequence[IkOutcome],
           write: WriteRow, kind: RowKind) -> None:
    """Rows for ``outcomes``: runs of targets reached as template text, the others one by one."""
    template = csv_template(batch, write.delimiter) if kind == "csv" else None
    run: list[int] = []
    for k, outcome in enumerate(outcomes):
        if template is not None and outcome.success and outcome.hint is None:
            run.append(k)
            continue
        if template is not None and run:
            write.text(_text(batch, template, lines, outcomes, run))
            run = []
        write(batch.row(lines[k], outcome, kind))
    if template is not None and run:
        write.text(_text(batch, template, lines, outcomes, run))


def csv_template(batch: IkBatch, delimiter: str) -> str | None:
    """A %-format of a reached target's CSV row; None with a mobile base (its own columns).

    ``line, true, joints..., position_error_m, orientation_error_rad, iterations, attempts,
    solutions, solve_time_s,`` (no hint): ``%r`` of a float is its ``repr``, as csv.writer
    writes it; the orientation error is ``%s``, to take an empty cell for a position alone.
    """
    space = batch.session.space
    if space.base_nq:
        return None
    d = delimiter
    return f"%d{d}true" + f"{d}%r" * len(space.names) + f"{d}%r{d}%s" + f"{d}%d" * 3 + \
        f"{d}%r{d}\n"


def _text(batch: IkBatch, template: str, lines: Sequence[int], outcomes: Sequence[IkOutcome],
          run: list[int]) -> str:
    """CSV rows of the reached targets ``run`` (indices into ``outcomes``): one %-format."""
    joints = batch.joint_table([outcomes[k].result.q for k in run])
    flat: list[object] = []
    for k, row in zip(run, joints.tolist(), strict=True):
        result = outcomes[k].result
        orientation = result.orientation_error_rad
        flat.append(lines[k])
        flat.extend(row)
        flat += [float(result.position_error_m), "" if orientation is None else
                 repr(float(orientation)), result.iterations, result.attempts,
                 result.solutions, float(outcomes[k].elapsed_s)]
    return (template * len(run)) % tuple(flat)
