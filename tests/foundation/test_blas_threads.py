"""check runs numpy's BLAS on one thread unless the user set the count (fresh processes)."""

from __future__ import annotations

import os
import subprocess
import sys

from tests.conftest import REPO

_REPORT = """
import os, sys
from servicebot_cli.cli import main
try:
    main(sys.argv[1:], standalone_mode=False)
except SystemExit:
    pass
import numpy
print("BLAS", os.environ.get("OPENBLAS_NUM_THREADS"), os.environ.get("OMP_NUM_THREADS"))
"""


def _blas_threads(*args: str, **environ: str) -> str:
    env = {k: v for k, v in os.environ.items()
           if k not in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS")}
    done = subprocess.run([sys.executable, "-c", _REPORT, *args], capture_output=True,
                          text=True, cwd=REPO, env={**env, **environ}, timeout=120)
    return done.stdout.splitlines()[-1]


def test_check_asks_for_one_blas_thread():
    assert _blas_threads("check", "urdf", "robots/service_robot.urdf.xml") == "BLAS 1 1"


def test_a_count_the_user_set_is_kept():
    assert _blas_threads("check", "urdf", "robots/service_robot.urdf.xml",
                         OPENBLAS_NUM_THREADS="2") == "BLAS 2 1"


def test_other_commands_keep_the_default():
    assert _blas_threads("fk", "-j", "arm_link1_to_link2=0.5") == "BLAS None None"
