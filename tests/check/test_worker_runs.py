"""How ``check urdf --jobs N`` cuts the files into runs: in order, a small directory whole."""

from __future__ import annotations

import itertools
from pathlib import Path

from servicebot_cli.check.workers import runs
from servicebot_cli.description.loader import RobotSource
from tests.check.corpus import erd_urdfs, pybullet_urdfs


def _sources(paths: list[Path]) -> list[tuple[RobotSource, bool]]:
    return [(RobotSource.of(path), True) for path in paths]


def test_every_file_once_in_order_and_no_small_directory_split():
    paths = sorted(erd_urdfs()) + sorted(pybullet_urdfs())
    cut = list(runs(_sources(paths), jobs=2))
    assert [source.path for run in cut for source, _ in run] == paths
    run_of = {source.path: number for number, run in enumerate(cut) for source, _ in run}
    for _, group in itertools.groupby(paths, key=lambda p: p.parent):
        files = list(group)  # neighbours in one directory
        if len(files) <= 16:
            assert len({run_of[p] for p in files}) == 1, files
    where: dict[Path, set[int]] = {}
    for path, number in run_of.items():
        where.setdefault(path.parent, set()).add(number)
    # romeo's and talos's variants share their meshes: each directory is in one run
    assert len(where[next(p.parent for p in paths if p.name == "romeo_small.urdf")]) == 1
    # still many short runs, so that no worker is left idle long at the end
    assert len(cut) > 100 and max(len(run) for run in cut) <= 16

def test_a_big_directory_is_cut_into_runs_of_at_most_eight():
    paths = [Path(f"/d/{i:03}.urdf") for i in range(40)]
    cut = list(runs(_sources(paths), jobs=2))
    assert [len(run) for run in cut] == [5] * 8


def test_a_run_of_many_files_collects_garbage_rarely():
    """The cycle collector's default spent 6 to 8 % of a corpus run finding no cycle."""
    import subprocess
    import sys

    probe = ("import gc; from servicebot_cli.check.workers import collect_garbage_rarely; "
             "collect_garbage_rarely(); print(gc.get_threshold(), gc.get_freeze_count() > 0)")
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                         check=True).stdout
    assert out.split() == ["(50000,", "20,", "20)", "True"]
