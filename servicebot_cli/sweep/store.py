"""The sweep's directory: one record per finished run, so a re-run skips what is done.

``DIR/runs/KEY/run.json`` is written (atomically) as soon as a run finishes, with its values,
seed and summary; kept outputs go beside it (``csv/``, ``bag/``, ``plot.png``). A run whose
record exists, and whose kept outputs all exist, is not run again: KEY covers the robot, the
scenario with its values, the seed and the servicebot version.
"""

from __future__ import annotations

import json
import os
import shutil
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from servicebot_cli.common.files import OutputError, write_atomic
from servicebot_cli.simulate.session import Outputs

if TYPE_CHECKING:
    from servicebot_cli.simulate.summary import Summary
    from servicebot_cli.sweep.plan import Run

KEEPABLE = ("csv", "bag", "plot")
RECORD = "run.json"


@dataclass(frozen=True)
class Record:
    """A finished run as stored: its key, seed, values, summary and wall time [s]."""

    key: str
    seed: int
    values: dict[str, Any]
    summary: Summary
    wall_s: float


def run_dir(out_dir: Path, key: str) -> Path:
    """The directory of one run's record and kept outputs."""
    return out_dir / "runs" / key


def kept_outputs(out_dir: Path, key: str, keep: Sequence[str]) -> Outputs:
    """Where a run's kept outputs go (absolute paths, for workers anywhere)."""
    base = run_dir(out_dir, key).resolve()
    return Outputs(out_dir=str(base / "csv") if "csv" in keep else None,
                   bag=str(base / "bag") if "bag" in keep else None,
                   plot=str(base / "plot.png") if "plot" in keep else None)


def load_record(out_dir: Path, key: str, keep: Sequence[str]) -> Record | None:
    """The run's record when it finished before with every output in ``keep``; else None.

    A run found incomplete (a record without a kept output, or outputs without a record)
    has its directory removed, so it can run again cleanly.
    """
    directory = run_dir(out_dir, key)
    if not os.path.exists(directory):
        return None
    outputs = kept_outputs(out_dir, key, keep)
    wanted = [p for p in (outputs.out_dir, outputs.bag, outputs.plot) if p is not None]
    try:
        data = json.loads((directory / RECORD).read_text(encoding="utf-8"))
        if all(os.path.exists(Path(p)) for p in wanted) and data.get("key") == key:
            return Record(data["key"], data["seed"], data["values"], data["summary"],
                          data["wall_s"])
    except (OSError, ValueError, KeyError, TypeError):
        pass
    shutil.rmtree(directory, ignore_errors=True)
    return None


def save_record(out_dir: Path, run: Run, summary: Summary, wall_s: float) -> Record:
    """Write ``run``'s record.

    Raises:
        OutputError: The directory cannot be written.
    """
    record = Record(run.key, run.seed, dict(run.values), summary, wall_s)
    data = {"key": record.key, "seed": record.seed, "values": record.values,
            "summary": record.summary, "wall_s": record.wall_s}
    try:
        run_dir(out_dir, run.key).mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"{out_dir}: cannot write: {exc.strerror or exc}") from None
    write_atomic(run_dir(out_dir, run.key) / RECORD, json.dumps(data, indent=1) + "\n")
    return record
