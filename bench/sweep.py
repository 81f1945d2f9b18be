"""Speed of `servicebot sweep`: one worker against two, and what a run costs beyond simulate.

A sweep of the default scenario (RUNS runs: 2 grid values x RUNS/2 seeds) runs through the
same function as the command (servicebot_cli.sweep.session.run), in a fresh output directory
each time, with 1 and with 2 local workers, alternately. Beside it, runs alone in this
process (run_and_write, what simulate times; the first, which pays imports, left out).

"others" is how many cores other processes kept busy meanwhile (this machine is shared):
with 2 cores, anything well above 0 makes the 2-worker figure meaningless.
Overhead per run = 1-worker sweep wall time / RUNS - a run alone: starting the worker,
checking and planning, sending tasks and results, records and tables. Goals: overhead at
most 10 % of a run alone; 2 workers at least 1.8x the speed of 1. Medians of --repeat
tries. This process uses one BLAS thread, as the sweep's workers do, so a run alone is the
same work.
Run: python bench/sweep.py [--runs 200] [--duration-s 180] [--repeat 3]
"""

from __future__ import annotations

import argparse
import math
import os
import resource
import statistics
import tempfile
import time
from pathlib import Path

# Workers are spawned and import this file again: heavy imports stay inside the functions.


def busy_cpu_s() -> tuple[float, float]:
    """CPU time [s] used so far by the machine and by this process with its children.

    The machine's from Linux's /proc/stat (NaN elsewhere); the children are the sweep's
    workers, counted once they have ended.
    """
    usages = (resource.getrusage(resource.RUSAGE_SELF),
              resource.getrusage(resource.RUSAGE_CHILDREN))
    own = sum(u.ru_utime + u.ru_stime for u in usages)
    try:
        fields = [int(v) for v in Path("/proc/stat").read_text().split("\n")[0].split()[1:]]
    except (OSError, ValueError):
        return math.nan, own
    busy = sum(fields) - fields[3] - fields[4]  # all but idle and iowait
    return busy / os.sysconf("SC_CLK_TCK"), own


def sweep_wall(sweep_file: Path, jobs: int) -> tuple[float, int, float]:
    """Wall time of the whole sweep [s], its runs, and the cores others kept busy meanwhile.

    Others: the machine's CPU time less ours, over the wall time.
    """
    from servicebot_cli.description.loader import RobotSource
    from servicebot_cli.sweep.session import SweepRequest, run

    with tempfile.TemporaryDirectory() as out:
        machine, own = busy_cpu_s()
        start = time.perf_counter()
        report = run(SweepRequest(str(sweep_file), RobotSource.bundled("sim"), jobs=jobs,
                                  out_dir=out, progress=False))
        wall = time.perf_counter() - start
        machine_after, own_after = busy_cpu_s()
        others = ((machine_after - machine) - (own_after - own)) / wall
        return wall, len(report.results), max(others, 0.0)


def alone_walls(duration_s: float, count: int) -> list[float]:
    """Wall times of ``count`` runs of the default scenario in this process [s]."""
    from servicebot_cli.description.loader import RobotSource, load
    from servicebot_cli.simulate.scenario.definition import load_scenario
    from servicebot_cli.simulate.session import (
        Outputs,
        Overrides,
        run_and_write,
        with_overrides,
    )

    robot = load(RobotSource.bundled("sim"))
    scenario = with_overrides(load_scenario(None), Overrides(duration_s=duration_s))
    walls = []
    for seed in range(count + 1):
        start = time.perf_counter()
        run_and_write(robot, scenario, seed=seed, outputs=Outputs(), scenario_dir=Path.cwd())
        walls.append(time.perf_counter() - start)
    return walls[1:]


def write_sweep(path: Path, runs: int, duration_s: float) -> None:
    """The benchmark's sweep file: 2 slip values x runs/2 seeds, collisions expected none."""
    import yaml

    path.write_text(yaml.safe_dump({
        "scenario": "default", "seeds": runs // 2, "set": {"duration_s": duration_s},
        "grid": {"slip.track_factor": [1.0, 1.1]}, "expect": ["collisions == 0"]}))


def main() -> None:
    """Measure and print the table."""
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("--runs", type=int, default=200)
    parser.add_argument("--duration-s", type=float, default=180.0)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    for name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ.setdefault(name, "1")  # this process only (a benchmark); before numpy
    load_before = os.getloadavg()[0]
    walls: dict[int, list[float]] = {1: [], 2: []}
    others: dict[int, list[float]] = {1: [], 2: []}
    alone: list[float] = []
    with tempfile.TemporaryDirectory() as tmp:
        sweep_file = Path(tmp) / "sweep.yaml"
        write_sweep(sweep_file, args.runs, args.duration_s)
        for _ in range(args.repeat):
            alone += alone_walls(args.duration_s, 3)
            for jobs in (1, 2):
                wall, runs, busy = sweep_wall(sweep_file, jobs)
                walls[jobs].append(wall)
                others[jobs].append(busy)
    one, two = (statistics.median(walls[j]) for j in (1, 2))
    run_s = statistics.median(alone)
    overhead_s = one / runs - run_s
    print(f"default scenario, {args.duration_s:g} s simulated, {runs} runs, median of "
          f"{args.repeat}; load average {load_before:.1f} before, {os.getloadavg()[0]:.1f} "
          f"after, {os.cpu_count()} cores")
    print(f"{'':36}{'wall [s]':>10}{'per run [s]':>13}{'others [cores]':>16}")
    print(f"{'one run alone (run_and_write)':36}{'':>10}{run_s:>13.3f}")
    for jobs, wall in ((1, one), (2, two)):
        label = f"sweep, {jobs} worker{'s' * (jobs > 1)}"
        print(f"{label:36}{wall:>10.2f}{wall / runs:>13.3f}"
              f"{statistics.median(others[jobs]):>16.2f}")
    print(f"2 workers are {one / two:.2f}x faster than 1 (goal >= 1.8x)")
    print(f"overhead per run (1 worker against a run alone) {overhead_s * 1000:+.1f} ms = "
          f"{100 * overhead_s / run_s:+.1f} % (goal <= 10 %)")


if __name__ == "__main__":
    main()
