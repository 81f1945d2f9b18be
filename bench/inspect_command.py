"""servicebot inspect beside the tools people use for the same look at a URDF.

Each row runs one command as a fresh process (what a user waits for), N times; the table
gives medians and the ratio to check_urdf. Peers: check_urdf and urdf_to_graphviz (urdfdom,
installed with Pinocchio) and yourdfpy (load plus a scene bounding box, as a Python user
would measure it).

    python bench/inspect_command.py [REPEATS]
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
URDF = REPO / "robots" / "service_robot.urdf.xml"
BIN = Path(sys.executable).parent
YOURDFPY = (f"import yourdfpy; r = yourdfpy.URDF.load({str(URDF)!r}, load_meshes=False, "
            "build_scene_graph=True); print(r.scene.bounds)")


def _time(command: list[str], cwd: str) -> float:
    start = time.perf_counter()
    done = subprocess.run(command, cwd=cwd, capture_output=True)
    elapsed = time.perf_counter() - start
    if done.returncode not in (0, 1):  # inspect --diff exits 1 when the files differ
        raise SystemExit(f"{command}: exit {done.returncode}: {done.stderr.decode()[-300:]}")
    return elapsed


def main() -> None:
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 7
    servicebot = [sys.executable, "-m", "servicebot_cli", "inspect", str(URDF)]
    rows = [
        ("check_urdf (tree)", [str(BIN / "check_urdf"), str(URDF)]),
        ("urdf_to_graphviz (dot)", [str(BIN / "urdf_to_graphviz"), str(URDF), "g"]),
        ("yourdfpy load + bounds", [sys.executable, "-c", YOURDFPY]),
        ("servicebot inspect --help", [*servicebot[:4], "--help"]),
        ("servicebot inspect --section tree", [*servicebot, "--section", "tree"]),
        ("servicebot inspect --format dot", [*servicebot, "--format", "dot"]),
        ("servicebot inspect --section totals", [*servicebot, "--section", "totals"]),
        ("servicebot inspect (all sections)", servicebot),
        ("servicebot inspect --format json", [*servicebot, "--format", "json"]),
        ("servicebot inspect --render x.png", [*servicebot, "--render", "x.png"]),
        ("servicebot inspect --diff (sim, real)",
         [*servicebot, "--diff", str(REPO / "robots" / "service_robot_real.urdf.xml")]),
    ]
    with tempfile.TemporaryDirectory() as cwd:
        medians = {}
        for name, command in rows:
            medians[name] = statistics.median(_time(command, cwd) for _ in range(repeats))
    base = medians["check_urdf (tree)"]
    print(f"{'command':40}  {'median [s]':>10}  {'x check_urdf':>12}")
    for name, value in medians.items():
        print(f"{name:40}  {value:10.3f}  {value / base:12.1f}")


if __name__ == "__main__":
    main()
