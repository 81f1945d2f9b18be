"""Benchmark: `servicebot check urdf` over the real URDF corpus against check_urdf.

Corpus: every URDF of example-robot-data and pybullet_data (pip install '.[test]').
servicebot checks the whole corpus in one call (worker processes: one per core; and with
--jobs 1; and with --mesh-cache, once the cache holds every mesh); check_urdf (urdfdom) runs
once per file,
both as the pip-installed command (a Python wrapper from cmeel-urdfdom) and as the native
binary it wraps, run from Python (the fastest way to loop) and from a bash loop (as a CI
script runs it). servicebot is timed with every rule, and with the URDF rules only (no mesh
files read: --ignore SB4,SB301), which is closer to what check_urdf looks at. Last, a single
UR5 check from a cold process. Medians of REPEATS runs of the wall time, and of the CPU
time (user + system, every process) that a shared machine disturbs less; a ratio is a
command's wall time over servicebot's (above 1: servicebot is faster).

Python commands run with their bytecode cached (in a temporary PYTHONPYCACHEPREFIX, even
where PYTHONDONTWRITEBYTECODE is set), as pip leaves an installed package: a cold process
is a new process, not the first run after an install. Compiling servicebot's modules from
source would add about 0.05 s to every run.

    python bench/check.py [REPEATS]
"""

from __future__ import annotations

import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from servicebot_cli.output.table import table  # noqa: E402
from tests.check.corpus import (  # noqa: E402
    check_urdf_commands,
    erd_root,
    erd_urdfs,
    pybullet_urdfs,
)

SERVICEBOT = [sys.executable, "-m", "servicebot_cli", "check", "urdf", "--isolated",
              "--format", "json", "--package", f"example-robot-data={erd_root()}"]


# what a CI step writes: ``for f in urdf/*.urdf; do check_urdf "$f"; done`` (bash forks a
# copy of itself for each file, where Python's subprocess uses vfork)
_SHELL_LOOP = 'command=$1; shift; for f; do "$command" "$f" >/dev/null 2>&1; done'


def _cpu_s() -> float:
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    return used.ru_utime + used.ru_stime


def _timed(commands: list[list[str]], env: dict[str, str] | None = None) -> tuple[float, float]:
    """Wall and CPU seconds of running ``commands`` one after the other."""
    cpu, start = _cpu_s(), time.perf_counter()
    for command in commands:  # no timeout: waiting with one polls the child with sleeps,
        # which added about 1.7 ms to each of the 1,164 native check_urdf runs
        subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    return time.perf_counter() - start, _cpu_s() - cpu


def _median(repeats: int, commands: list[list[str]],
            env: dict[str, str] | None = None) -> tuple[float, float]:
    runs = [_timed(commands, env) for _ in range(repeats)]
    return statistics.median(r[0] for r in runs), statistics.median(r[1] for r in runs)


def _python_env(pycache: str) -> dict[str, str]:
    """This environment, with Python's bytecode written to and read from ``pycache``."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    return {**env, "PYTHONPYCACHEPREFIX": pycache}


def main(repeats: int = 3) -> None:
    files = [str(p) for p in erd_urdfs() + pybullet_urdfs()]
    ur5 = str(next(p for p in erd_urdfs() if p.name == "ur5_robot.urdf"))
    wrapper, native, native_env = check_urdf_commands()
    print(f"corpus: {len(files)} URDF files (example-robot-data + pybullet_data); "
          f"median of {repeats} runs", file=sys.stderr)
    with tempfile.TemporaryDirectory() as cache, tempfile.TemporaryDirectory() as pycache:
        env = _python_env(pycache)
        _timed([SERVICEBOT + [ur5], wrapper + [ur5]], env)  # compiles the bytecode
        cached = {**env, "XDG_CACHE_HOME": cache}
        _timed([SERVICEBOT + ["--mesh-cache"] + files], cached)  # fills the mesh cache
        warm = _median(repeats, [SERVICEBOT + ["--mesh-cache"] + files], cached)
        corpus = {
            "servicebot check urdf, every rule, one call": _median(repeats, [SERVICEBOT + files],
                                                                   env),
            "servicebot check urdf, URDF rules only, one call":
                _median(repeats, [SERVICEBOT + ["--ignore", "SB4,SB301"] + files], env),
            "servicebot check urdf, every rule, --jobs 1": _median(repeats, [SERVICEBOT + [
                "--jobs", "1"] + files], env),
            "servicebot check urdf, every rule, --mesh-cache (warm)": warm,
            "check_urdf (pip-installed wrapper), once per file":
                _median(repeats, [wrapper + [f] for f in files], env),
            "check_urdf (native binary), once per file":
                _median(repeats, [native + [f] for f in files], native_env),
            "check_urdf (native binary), from a shell loop": _median(
                repeats, [["bash", "-c", _SHELL_LOOP, "check_urdf", *native, *files]],
                native_env),
        }
        single = {
            "servicebot check urdf ur5_robot.urdf (cold process)":
                _median(max(repeats, 5), [SERVICEBOT + [ur5]], env),
            "servicebot check urdf ur5_robot.urdf, URDF rules only":
                _median(max(repeats, 5), [SERVICEBOT + ["--ignore", "SB4,SB301", ur5]], env),
            "check_urdf ur5_robot.urdf (pip-installed wrapper)":
                _median(max(repeats, 5), [wrapper + [ur5]], env),
            "check_urdf ur5_robot.urdf (native binary)":
                _median(max(repeats, 5), [native + [ur5]], native_env),
        }
    for title, times in (("whole corpus", corpus), ("one UR5", single)):
        print(f"\n{title}")
        base = [wall for wall, _ in times.values()]
        rows = [(name, f"{wall:.3f}", f"{cpu:.3f}", f"{wall / base[0]:.2f}",
                 f"{wall / base[1]:.2f}") for name, (wall, cpu) in times.items()]
        headers = ["command", "median [s]", "CPU [s]", "/ servicebot all rules",
                   "/ URDF rules only"]
        for line in table(headers, rows, max_width=150):
            print(line)


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 3)
