"""Batch text made in a worker process is the text made in-process, in order, byte for byte.

A real child process formats; one test kills it half way and the rest is formatted here.
"""

from __future__ import annotations

import subprocess
import sys
import threading

import numpy as np

from servicebot_cli.batch.fk_chunks import csv_template, jsonl_template
from servicebot_cli.batch.formatting import Formatter, format_rows

TRICKY = [0.1, 1e-05, 1e16, 123456789.12345679, -0.0 + 0.0, 5e-324, 1.7976931348623157e308,
          0.30000000000000004, 2.0 / 3.0]


def chunks(count: int, rows: int, width: int) -> list[tuple[list[int], np.ndarray]]:
    rng = np.random.default_rng(0)
    out = []
    for k in range(count):
        values = rng.uniform(-2.0, 2.0, size=(rows, width))
        values.flat[: len(TRICKY)] = TRICKY
        out.append((list(range(2 + k * rows, 2 + (k + 1) * rows)), values))
    return out


def formatted(template: str, parts, kill_after: int | None = None) -> tuple[str, bool]:
    written: list[str] = []
    used_worker = False
    with Formatter(template, written.append) as formatter:
        for k, (lines, values) in enumerate(parts):
            formatter.submit(lines, values)
            used_worker = used_worker or formatter._process is not None
            if kill_after is not None and k == kill_after and formatter._process is not None:
                formatter._process.kill()
    return "".join(written), used_worker


def test_the_worker_writes_what_repr_writes_in_order():
    parts = chunks(6, 300, 10)
    template = csv_template(10, ",")
    text, used_worker = formatted(template, parts)
    assert used_worker
    expected = "".join(format_rows(template, lines, values) for lines, values in parts)
    assert text == expected
    first = text.splitlines()[0].split(",")
    assert first[0] == "2" and [float(v) for v in first[1:]] == TRICKY + [parts[0][1][0, 9]]
    assert first[1:3] == ["0.1", "1e-05"]  # repr, not a fixed precision


def test_json_lines_through_the_worker_are_the_template_filled():
    parts = chunks(3, 50, 10)
    template = jsonl_template(["arm_tool_link"], "rad")
    text, _ = formatted(template, parts)
    assert text == "".join(format_rows(template, lines, values) for lines, values in parts)


def test_a_worker_that_dies_leaves_its_chunks_to_be_formatted_here():
    parts = chunks(8, 2000, 10)
    template = csv_template(10, "\t")
    text, used_worker = formatted(template, parts, kill_after=2)
    assert used_worker
    assert text == "".join(format_rows(template, lines, values) for lines, values in parts)


def test_one_chunk_needs_no_worker():
    parts = chunks(1, 10, 10)
    template = csv_template(10, ",")
    text, used_worker = formatted(template, parts)
    assert not used_worker
    assert text == format_rows(template, *parts[0])


def test_a_write_that_fails_in_the_thread_is_raised_here_and_nothing_hangs():
    parts = chunks(6, 300, 10)
    template = csv_template(10, ",")
    written: list[str] = []

    def write(text: str) -> None:
        if len(written) == 2:  # the output went away while the worker's text came back
            raise BrokenPipeError(32, "Broken pipe")
        written.append(text)

    formatter = Formatter(template, write)
    raised: list[BaseException] = []

    def feed() -> None:
        try:
            with formatter:
                for lines, values in parts:
                    formatter.submit(lines, values)
        except BaseException as exc:  # noqa: BLE001 -- what reached the caller's thread
            raised.append(exc)

    caller = threading.Thread(target=feed, daemon=True)
    caller.start()
    caller.join(timeout=30)
    assert not caller.is_alive()  # a write error in the thread once made drain() wait forever
    assert [type(e) for e in raised] == [BrokenPipeError]
    assert len(written) == 2
    assert formatter._process is None  # the worker was ended


def test_fk_into_a_pipe_closed_early_ends_at_once_without_a_traceback(tmp_path):
    names = ["arm_base_to_link1", "arm_link1_to_link2", "arm_link2_to_link3",
             "arm_link3_to_link4"]
    configs = tmp_path / "configs.csv"
    rows = np.random.default_rng(0).uniform(-1, 1, (40_000, 4)).tolist()
    configs.write_text(",".join(names) + "\n" + "".join(",".join(map(repr, r)) + "\n"
                                                        for r in rows))
    process = subprocess.Popen([sys.executable, "-m", "servicebot_cli", "fk", "--configs",
                                str(configs), "--format", "csv"], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE)
    assert process.stdout is not None and process.stderr is not None
    head = [process.stdout.readline() for _ in range(6000)]
    process.stdout.close()  # as `| head -n 6000` does
    try:
        code = process.wait(timeout=60)  # a failed write in the thread once hung here
    finally:
        process.kill()
    stderr = process.stderr.read().decode()
    assert code == 0
    assert len(head[5999].split(b",")) > 4  # the 6,000th line was written whole
    assert "Traceback" not in stderr and stderr == ""
