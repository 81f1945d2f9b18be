"""Speed of `servicebot sweep`: one worker against two, and what a run costs beyond simulate.

A sweep of the default scenario (RUNS runs: 2 grid values x RUNS/2 seeds) runs through the
same function as the command (servicebot_cli.sweep.session.run), in a fresh output directory
each time, with 1 and with 2 local workers. Beside it, the same run alone in this process
(run_and_write, what simulate times). Overhead per run = (sweep wall time with one worker -
the sum of its runs' own wall times) / RUNS, beside one run alone. Medians of --repeat tries.
Run: python bench/sweep.py [--runs 200] [--duration-s 180] [--repeat 3]
"""

from __future__ import annotations

import os

# As `servicebot sweep` does: one run per core, so numpy's BLAS threads do not fight the workers.
for _name in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import argparse  # noqa: E402
import statistics  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import yaml  # noqa: E402

from servicebot_cli.description.loader import RobotSource, load  # noqa: E402
from servicebot_cli.simulate.scenario.definition import load_scenario  # noqa: E402
from servicebot_cli.simulate.session import Outputs, Overrides, run_and_write, with_overrides  # noqa: E402
from servicebot_cli.sweep.session import SweepRequest, run  # noqa: E402


def sweep_wall(sweep_file: Path, jobs: int) -> tuple[float, int, float]:
    """Wall time of the whole sweep, its runs, and the sum of the runs' own wall times [s]."""
    with tempfile.TemporaryDirectory() as out:
        start = time.perf_counter()
        report = run(SweepRequest(str(sweep_file), RobotSource.bundled("sim"), jobs=jobs,
                                  out_dir=out, progress=False))
        wall = time.perf_counter() - start
        return wall, len(report.results), sum(r.record.wall_s for r in report.results)


def alone_wall(duration_s: float, repeat: int) -> float:
    robot = load(RobotSource.bundled("sim"))
    scenario = with_overrides(load_scenario(None), Overrides(duration_s=duration_s))
    walls = []
    for seed in range(repeat):
        start = time.perf_counter()
        run_and_write(robot, scenario, seed=seed, outputs=Outputs(), scenario_dir=Path.cwd())
        walls.append(time.perf_counter() - start)
    return statistics.median(walls)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=200)
    parser.add_argument("--duration-s", type=float, default=180.0)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        sweep_file = Path(tmp) / "sweep.yaml"
        sweep_file.write_text(yaml.safe_dump({
            "scenario": "default", "seeds": args.runs // 2,
            "set": {"duration_s": args.duration_s},
            "grid": {"slip.track_factor": [1.0, 1.1]}, "expect": ["collisions == 0"]}))
        alone = alone_wall(args.duration_s, 2 * args.repeat + 1)
        walls: dict[int, list[float]] = {1: [], 2: []}
        overheads: list[float] = []
        load = os.getloadavg()[0]
        for _ in range(args.repeat):
            for jobs in (1, 2):
                wall, runs, simulating = sweep_wall(sweep_file, jobs)
                walls[jobs].append(wall)
                if jobs == 1:  # what the sweep adds to its runs, per run
                    overheads.append((wall - simulating) / runs)
    one, two = (statistics.median(walls[j]) for j in (1, 2))
    overhead = statistics.median(overheads)
    print(f"default scenario, {args.duration_s:g} s simulated, {runs} runs, median of "
          f"{args.repeat}; load average {load:.1f} before, {os.getloadavg()[0]:.1f} after "
          f"on {os.cpu_count()} cores")
    print(f"{'':34}{'wall [s]':>10}{'per run [s]':>13}")
    print(f"{'one run alone (run_and_write)':34}{'':>10}{alone:>13.3f}")
    print(f"{'sweep, 1 worker':34}{one:>10.2f}{one / runs:>13.3f}")
    print(f"{'sweep, 2 workers':34}{two:>10.2f}{two / runs:>13.3f}")
    print(f"2 workers are {one / two:.2f}x faster than 1; overhead per run "
          f"{overhead * 1000:.1f} ms = {100 * overhead / alone:.1f} % of a run")


if __name__ == "__main__":
    main()
