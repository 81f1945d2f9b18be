"""Local workers get one BLAS thread each in their own environment; the caller's is untouched."""

from __future__ import annotations

import ctypes
import glob
import os
from pathlib import Path

from servicebot_cli.common.blas_threads import BLAS_THREADS
from servicebot_cli.description.loader import RobotSource
from servicebot_cli.sweep.engine import local_executor
from servicebot_cli.sweep.session import SweepRequest, run


def what_a_worker_sees() -> dict[str, object]:
    """In a worker: its BLAS variables, and the threads its OpenBLAS runs with (None when
    numpy's OpenBLAS cannot be asked)."""
    import numpy

    threads = None
    libs = Path(numpy.__file__).parent.parent / "numpy.libs"
    for path in glob.glob(str(libs / "*openblas*.so*")):
        library = ctypes.CDLL(path)
        for name in ("scipy_openblas_get_num_threads64_", "openblas_get_num_threads64_",
                     "openblas_get_num_threads"):
            if hasattr(library, name):
                threads = getattr(library, name)()
    return {"environ": {name: os.environ.get(name) for name in BLAS_THREADS},
            "openblas_threads": threads, "pid": os.getpid()}


def test_workers_get_one_blas_thread_and_the_caller_keeps_its_environment(
        monkeypatch, write_sweep, tmp_path):
    for name in BLAS_THREADS:
        monkeypatch.delenv(name, raising=False)
    monkeypatch.setenv("MKL_NUM_THREADS", "3")  # the user's choice is kept
    before = dict(os.environ)

    report = run(SweepRequest(str(write_sweep({"seeds": 2, "set": {"duration_s": 1}})),
                              RobotSource.bundled("sim"), jobs=2, out_dir=str(tmp_path / "o")))
    assert len(report.results) == 2
    assert dict(os.environ) == before

    with local_executor(2) as pool:
        seen = [pool.submit(what_a_worker_sees).result() for _ in range(4)]
    assert dict(os.environ) == before
    assert os.getpid() not in {s["pid"] for s in seen}
    for worker in seen:
        assert worker["environ"] == {"OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1",
                                     "MKL_NUM_THREADS": "3"}
        # numpy loaded after the variables were set: OpenBLAS runs one thread
        assert worker["openblas_threads"] in (1, None)
