"""``fk --configs`` on CSV, a chunk of lines at a time: parse, place and format with numpy.

Most of a batch's time would go to Python work per line: a dict per row, a conversion per
cell, a writer call per result. Here a chunk of :data:`CHUNK_LINES` lines is split at once,
the joint columns converted by one ``np.array(cells, dtype=float)`` (which reads each
cell as ``float()`` does), the limits checked on the whole
chunk, the poses computed by Pinocchio into one array, and the CSV text of the chunk made by
one %-format of a per-row template (``%r``: the ``repr`` of each float), so output is byte
for byte the per-line path's. From the second chunk on, that formatting runs in a worker
process (:mod:`~servicebot_cli.batch.formatting`) while the next chunks are read and
computed.

A chunk with a line the fast path cannot take (a quoted or empty cell, a wrong field count,
not a number, a value outside its limits) goes through the per-line path instead, so every
error still names its line and ``--on-error`` behaves the same. Memory stays bounded by
the chunk size.
"""

from __future__ import annotations

import contextlib
import json
from collections.abc import Sequence
from typing import IO

import numpy as np
import numpy.typing as npt

from servicebot_cli.batch.fk_rows import BASE_COLUMNS, RESULT_COLUMNS, FkBatch
from servicebot_cli.batch.formatting import Formatter, format_rows
from servicebot_cli.batch.line_chunks import chunks, numbers, split_cells
from servicebot_cli.batch.policy import OnError, Tally
from servicebot_cli.batch.reading import Source, csv_rows
from servicebot_cli.batch.stream import (
    BatchSummary,
    RowSink,
    Warn,
    refuse_no_lines,
    summarise,
    write_results,
)
from servicebot_cli.kinematics.joint_columns import UnitConflict

FloatArray = npt.NDArray[np.float64]

CHUNK_LINES = 4096
"""Raw lines read, parsed and written at a time."""


def stream_csv(batch: FkBatch, source: Source, handle: IO[str], sink: RowSink, *,
               on_error: OnError, warn: Warn) -> BatchSummary:
    """Poses for every line of an open CSV ``source``, chunk by chunk, to ``sink``.

    Args:
        batch: The frames, units and clamping.
        source: The input, its header read (``handle`` stands just after it).
        handle: The open input.
        sink: Where result rows go.
        on_error: What a bad line does.
        warn: Where skipped lines are reported.

    Raises:
        JointNotFound: A header column that is neither a joint nor an ik result column.
        UnitConflict: Joint columns whose units disagree, or disagree with ``--deg``.
        BadLine: An unusable line under ``--on-error stop``.
    """
    try:
        batch.check_header(source.columns)
    except UnitConflict as exc:  # the header's units: named by file and line
        raise UnitConflict(f"{source.display}:{source.header_line}: {exc}") from None
    parser = ChunkParser(batch, source.columns, source.delimiter)
    template = jsonl_template(batch.frames, batch.unit)
    tally = Tally()
    with sink.open(batch.columns()) as write, contextlib.ExitStack() as stack:
        formatter: Formatter | None = None  # made at the first chunk of numbers
        for lines in chunks(handle, source.header_line, CHUNK_LINES):
            values = parser.values([text for _, text in lines]) if lines else None
            if values is None:  # line by line: the messages name the line
                if formatter is not None:
                    formatter.drain()
                write_results(batch, csv_rows(lines, source.columns, source.delimiter),
                              source.display, write, sink.kind, on_error=on_error, warn=warn,
                              tally=tally)
                continue
            tally.rows += len(lines)
            if formatter is None:
                row = template if sink.kind == "jsonl" else \
                    csv_template(len(batch.columns()) - 1, write.delimiter)
                formatter = stack.enter_context(Formatter(row, write.text))
            formatter.submit([n for n, _ in lines], batch.pose_table(values))
        refuse_no_lines(source.display, tally)
    return summarise(source.display, tally, warn)


class ChunkParser:
    """Joint values of a chunk of CSV lines, or None when a line needs the per-line path."""

    def __init__(self, batch: FkBatch, columns: Sequence[str], delimiter: str) -> None:
        """Read ``columns`` (the header, checked by ``batch``) for ``batch``'s joints."""
        self.batch, self.delimiter = batch, delimiter
        self.width = len(columns)
        self.joint_columns = [k for k, name in enumerate(columns) if name not in RESULT_COLUMNS]
        units = batch.header_units
        self.joints = [] if units is None else \
            [batch.space.index(units.joint(columns[k])) for k in self.joint_columns]
        # ik --with-base results, and lines that each say their angle unit
        self.by_line = units is None or bool(set(columns) & set(BASE_COLUMNS))

    def values(self, texts: list[str]) -> FloatArray | None:
        """One value per joint and line [rad or m], limits checked; None: go line by line.

        Lines with a base column go line by line, each with its base; so do lines with an
        ``angle_unit`` column, each in its unit.
        """
        if self.by_line:
            return None
        cells = split_cells(texts, self.delimiter, self.width)
        given = None if cells is None else numbers(cells, self.width, self.joint_columns)
        return None if given is None else self.batch.chunk_vectors(given, self.joints)


def jsonl_template(frames: Sequence[str], unit: str) -> str:
    """A %-format of one JSON Lines result: the line (``%d``), then each number (``%r``).

    The keys, their order and the separators are those of ``json.dumps`` of
    :meth:`~servicebot_cli.batch.fk_rows.FkBatch.json_row`, which writes a float as its
    ``repr``: so the text is the same, byte for byte.
    """
    names = [json.dumps(frame).replace("%", "%%") for frame in frames]
    poses = ", ".join(
        f'{{"frame": {name}, "position_m": [%r, %r, %r], "rpy_{unit}": [%r, %r, %r], '
        '"quaternion_xyzw": [%r, %r, %r, %r]}' for name in names)
    return '{"line": %d, "poses": [' + poses + "]}\n"


def jsonl_text(lines: Sequence[int], poses: FloatArray, template: str) -> str:
    """JSON Lines results for a chunk, by one %-format of ``template`` repeated per line."""
    return format_rows(template, lines, poses)


def csv_template(width: int, delimiter: str) -> str:
    """A %-format of one CSV result row: the line (``%d``), then ``width`` numbers (``%r``).

    ``%r`` of a float is its ``repr``, as csv.writer writes it.
    """
    return "%d" + f"{delimiter}%r" * width + "\n"


def csv_text(lines: Sequence[int], poses: FloatArray, delimiter: str) -> str:
    """CSV rows ``line, pose...`` for a chunk: ``repr`` of every number, as csv.writer writes.

    One %-format of a row template repeated per line (``%r`` of a float is its ``repr``).
    """
    width = poses.reshape(len(lines), -1).shape[1] if len(lines) else 0
    return format_rows(csv_template(width, delimiter), lines, poses)
