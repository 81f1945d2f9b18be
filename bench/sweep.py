"""Speed of `servicebot sweep`: one worker against two, and what a run costs beyond simulate.

A sweep of the default scenario (RUNS runs: 2 grid values x RUNS/2 seeds) runs through the
same function as the command (servicebot_cli.sweep.session.run), in a fresh output directory
each time, with 1 and with 2 local workers, alternately. Beside it, runs alone in this
process (run_and_write, what simulate times; the first, which pays imports, left out).

Overhead per run = 1-worker sweep wall time / RUNS - a run alone: starting the worker,
checking and planning, sending tasks and results, records and tables. Goals: overhead at
most 10 % of a run alone; 2 workers at least 1.8x the speed of 1. Medians of --repeat
tries. This process uses one BLAS thread, as the sweep's workers do, so a run alone is the
same work.
Run: python bench/sweep.py [--runs 200] [--duration-s 180] [--repeat 3]
"""

from __future__ import annotations

import argparse
import os
import statistics
import tempfile
import time
from pathlib import Path

# Workers are spawned and import this file again: heavy imports stay inside the functions.


def sweep_wall(sweep_file: Path, jobs: int) -> tuple[float, int]:
    """Wall time of the whole sweep [s] and its number of runs."""
    from servicebot_cli.description.loader import RobotSource
    from servicebot_cli.sweep.session import SweepRequest, run

    with tempfile.TemporaryDirectory() as out:
        start = time.perf_counter()
        report = run(SweepRequest(str(sweep_file), RobotSource.bundled("sim"), jobs=jobs,
                                  out_dir=out, progress=False))
        return time.perf_counter() - start, len(report.results)


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
    alone: list[float] = []
    with tempfile.TemporaryDirectory() as tmp:
        sweep_file = Path(tmp) / "sweep.yaml"
        write_sweep(sweep_file, args.runs, args.duration_s)
        for _ in range(args.repeat):
            alone += alone_walls(args.duration_s, 3)
            for jobs in (1, 2):
                wall, runs = sweep_wall(sweep_file, jobs)
                walls[jobs].append(wall)
    one, two = (statistics.median(walls[j]) for j in (1, 2))
    run_s = statistics.median(alone)
    overhead_s = one / runs - run_s
    print(f"default scenario, {args.duration_s:g} s simulated, {runs} runs, median of "
          f"{args.repeat}; load average {load_before:.1f} before, {os.getloadavg()[0]:.1f} "
          f"after, {os.cpu_count()} cores")
    print(f"{'':36}{'wall [s]':>10}{'per run [s]':>13}")
    print(f"{'one run alone (run_and_write)':36}{'':>10}{run_s:>13.3f}")
    print(f"{'sweep, 1 worker':36}{one:>10.2f}{one / runs:>13.3f}")
    print(f"{'sweep, 2 workers':36}{two:>10.2f}{two / runs:>13.3f}")
    print(f"2 workers are {one / two:.2f}x faster than 1 (goal >= 1.8x)")
    print(f"overhead per run (1 worker against a run alone) {overhead_s * 1000:+.1f} ms = "
          f"{100 * overhead_s / run_s:+.1f} % (goal <= 10 %)")


if __name__ == "__main__":
    main()
