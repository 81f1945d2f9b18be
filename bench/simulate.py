"""Real-time factor of `servicebot simulate` beside pybullet and ir-sim, in one run.

The same scenario (the built-in default: a loop in a room, arm moving, every sensor on) runs
  - in servicebot, in-process, with the MCAP bag written,
  - in servicebot as a process, `servicebot simulate --headless --bag DIR`: the real-time
    factor it prints (the issue's >= 1,000) and that of the whole process, start to exit
    (the issue's >= 500); and the same with the CSV files (`--out DIR`) as well,
  - in pybullet (DIRECT mode, husky from pybullet_data, 240 Hz physics, wheel velocity control,
    a 360-ray LIDAR by rayTestBatch at 10 Hz), and
  - in ir-sim (diff-drive rectangle robot, lidar2d with 360 rays, 0.1 s steps, no display),
  - in MuJoCo, kinematic mode: the same URDF, poses set at the same 100 Hz control rate with
    MuJoCo's kinematics and collision detection, the LIDAR's 360 rays by mj_multiRay at 10 Hz.
Peers come from the `bench` extra: pip install '.[bench]'. A missing peer is reported, not
faked. Run: python bench/simulate.py [--repeat N]

With --memory it measures instead how peak memory (maximum resident set size) and the
real-time factor go with the simulated duration: `servicebot simulate --headless
--duration-s D --out --bag --plot` as a process, for D = 600 s and 7,200 s (the issue's
bound: the longer run within 1.3 times the shorter's memory).
"""

from __future__ import annotations

import argparse
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from servicebot_cli.description.loader import RobotSource, load
from servicebot_cli.simulate.scenario.definition import load_scenario
from servicebot_cli.simulate.session import Outputs, run_and_write


def servicebot_run(scenario, robot) -> float:
    with tempfile.TemporaryDirectory() as tmp:
        start = time.perf_counter()
        run_and_write(robot, scenario, seed=0, outputs=Outputs(bag=f"{tmp}/bag"),
                      scenario_dir=Path.cwd())
        return time.perf_counter() - start


def cli_run(duration_s: float, out: bool = False) -> tuple[float, float]:
    """The real-time factor `servicebot simulate --headless --bag` prints, and its process's.

    With ``out``, the CSV files (``--out``) are written too.
    """
    with tempfile.TemporaryDirectory() as tmp:
        start = time.perf_counter()
        csv = ["--out", f"{tmp}/out"] if out else []
        done = subprocess.run([sys.executable, "-m", "servicebot_cli", "simulate", "--headless",
                               "--bag", f"{tmp}/bag", *csv], capture_output=True, text=True)
        wall = time.perf_counter() - start
    if done.returncode:
        raise SystemExit(f"servicebot simulate failed: {done.stderr}")
    printed = re.search(r"real-time factor (\d+)", done.stderr)
    return float(printed.group(1)) if printed else math.nan, duration_s / wall


def _command_at(scenario, t: float) -> tuple[float, float]:
    for seg in scenario.cmd_vel:
        if seg.start_s <= t < seg.end_s + scenario.controller.cmd_vel_timeout_s:
            return seg.linear_m_s, seg.angular_rad_s
    return 0.0, 0.0


def _boxes(scenario):
    """Walls and boxes as (centre x, y, z, half x, y, z, yaw); cylinders as (x, y, r, h)."""
    from servicebot_cli.simulate.world.solids import world_solids

    out = []
    for s in world_solids(scenario.world):
        yaw = math.atan2(s.rotation[1, 0], s.rotation[0, 0])
        out.append((s.kind, *s.center_m, *s.half_m, yaw))
    return out


def pybullet_run(scenario) -> float:
    import pybullet as p
    import pybullet_data

    client = p.connect(p.DIRECT)
    p.setAdditionalSearchPath(pybullet_data.getDataPath())
    p.setGravity(0, 0, -9.8)
    p.loadURDF("plane.urdf")
    start = scenario.initial_pose
    husky = p.loadURDF("husky/husky.urdf", [start.x_m, start.y_m, 0.2],
                       p.getQuaternionFromEuler([0, 0, start.yaw_rad]))
    for kind, x, y, z, hx, hy, hz, yaw in _boxes(scenario):
        shape = (p.createCollisionShape(p.GEOM_BOX, halfExtents=[hx, hy, hz]) if kind == "box"
                 else p.createCollisionShape(p.GEOM_CYLINDER, radius=hx, height=2 * hz))
        p.createMultiBody(0, shape, basePosition=[x, y, z],
                          baseOrientation=p.getQuaternionFromEuler([0, 0, yaw]))
    wheels, radius, track = [2, 3, 4, 5], 0.1651, 0.555  # husky: left 2, 4; right 3, 5
    dt, steps = 1.0 / 240.0, int(scenario.duration_s * 240)
    angles = [2 * math.pi * i / 360 for i in range(360)]
    began = time.perf_counter()
    for k in range(steps):
        t = k * dt
        if k % 2 == 0:  # controller at 120 Hz
            v, w = _command_at(scenario, t)
            left, right = (v - w * track / 2) / radius, (v + w * track / 2) / radius
            p.setJointMotorControlArray(husky, wheels, p.VELOCITY_CONTROL,
                                        targetVelocities=[left, right, left, right],
                                        forces=[50] * 4)
        p.stepSimulation()
        if k % 24 == 0:  # LIDAR at 10 Hz
            pos, orn = p.getBasePositionAndOrientation(husky)
            yaw = p.getEulerFromQuaternion(orn)[2]
            origin = [pos[0], pos[1], pos[2] + 0.3]
            ends = [[origin[0] + 12 * math.cos(yaw + a), origin[1] + 12 * math.sin(yaw + a),
                     origin[2]] for a in angles]
            p.rayTestBatch([origin] * 360, ends)
        if k % 2 == 0:  # IMU-like reading at 120 Hz
            p.getBaseVelocity(husky)
    wall = time.perf_counter() - began
    p.disconnect(client)
    return wall


def mujoco_run(scenario, robot) -> float:
    """MuJoCo, kinematic mode: the same URDF, poses set at the control rate, the same rays.

    The robot's root gets a free joint; each control tick integrates the commanded twist
    (as a kinematic simulator does), writes the base pose, wheel and arm angles into qpos and
    runs MuJoCo's kinematics and collision detection (mj_kinematics, mj_collision); the
    LIDAR's 360 rays are cast with mj_multiRay at 10 Hz from the LIDAR's place on the base,
    seeing the robot's own geometry as servicebot's rays do.
    """
    import mujoco
    import numpy as np

    from servicebot_cli.kinematics.forward import transforms
    from servicebot_cli.kinematics.frames import frame_id, link_names

    spec = mujoco.MjSpec.from_file(str(robot.path))
    spec.worldbody.first_body().add_freejoint()
    floor = spec.worldbody.add_geom()
    floor.type, floor.size = mujoco.mjtGeom.mjGEOM_PLANE, [20, 20, 0.1]
    for kind, x, y, z, hx, hy, hz, yaw in _boxes(scenario):
        geom = spec.worldbody.add_geom()
        geom.pos, geom.quat = [x, y, z], [math.cos(yaw / 2), 0, 0, math.sin(yaw / 2)]
        if kind == "box":
            geom.type, geom.size = mujoco.mjtGeom.mjGEOM_BOX, [hx, hy, hz]
        else:
            geom.type, geom.size = mujoco.mjtGeom.mjGEOM_CYLINDER, [hx, hz, 0]
    model = spec.compile()
    data = mujoco.MjData(model)
    names = link_names(robot)
    lidar = transforms(robot.model, robot.data, np.zeros(robot.model.nq),
                       [frame_id(robot.model, "lidar_link", names)],
                       frame_id(robot.model, robot.root_link, names))[0]
    angles = np.linspace(-math.pi, math.pi, 360)
    geomid, distance = np.zeros(360, dtype=np.int32), np.zeros(360)
    dt, ticks = 0.01, int(scenario.duration_s * 100)
    start = scenario.initial_pose
    x, y, heading = start.x_m, start.y_m, start.yaw_rad
    wheel, radius, track = 0.0, 0.05, 0.3
    def multi_ray(*args):  # MuJoCo 4 added the normals out-argument before nray
        try:
            mujoco.mj_multiRay(*args[:9], None, *args[9:])
        except TypeError:
            mujoco.mj_multiRay(*args)

    began = time.perf_counter()
    for k in range(ticks):
        v, w = _command_at(scenario, k * dt)
        x, y = x + v * math.cos(heading) * dt, y + v * math.sin(heading) * dt
        heading += w * dt
        wheel += v / radius * dt
        data.qpos[:7] = [x, y, 0.0, math.cos(heading / 2), 0, 0, math.sin(heading / 2)]
        data.qpos[7:11] = wheel + np.array([-1, 1, -1, 1]) * w * track / (2 * radius) * k * dt
        data.qpos[11:15] = 0.3 * math.sin(0.1 * k * dt)
        mujoco.mj_kinematics(model, data)
        mujoco.mj_collision(model, data)
        if k % 10 == 0:  # LIDAR at 10 Hz
            c, s = math.cos(heading), math.sin(heading)
            origin = np.array([x + c * lidar[0, 3] - s * lidar[1, 3],
                               y + s * lidar[0, 3] + c * lidar[1, 3], lidar[2, 3]])
            rays = np.stack([np.cos(angles + heading), np.sin(angles + heading),
                             np.zeros(360)], axis=1).ravel()
            multi_ray(model, data, origin, rays, None, 1, -1, geomid, distance, 360, 12.0)
    return time.perf_counter() - began


def irsim_run(scenario) -> float:
    import irsim
    import numpy as np

    start = scenario.initial_pose
    lines = ["world:", "  height: 4", "  width: 4", "  step_time: 0.1", "  sample_time: 0.1",
             "  offset: [-2, -2]", "  collision_mode: 'stop'", "robot:",
             "  - kinematics: {name: 'diff'}",
             "    shape: {name: 'rectangle', length: 0.55, width: 0.58}",
             f"    state: [{start.x_m}, {start.y_m}, {start.yaw_rad}]",
             "    vel_max: [0.0308, 0.114]", "    sensors:", "      - name: 'lidar2d'",
             "        range_min: 0.12", "        range_max: 12", "        angle_range: 6.2832",
             "        number: 360", "obstacle:"]
    for kind, x, y, _, hx, hy, _, yaw in _boxes(scenario):
        shape = (f"{{name: 'rectangle', length: {2 * hx}, width: {2 * hy}}}" if kind == "box"
                 else f"{{name: 'circle', radius: {hx}}}")
        lines += [f"  - shape: {shape}", f"    state: [{x}, {y}, {yaw}]"]
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "world.yaml")
        Path(path).write_text("\n".join(lines) + "\n")
        import logging

        logging.disable(logging.WARNING)
        env = irsim.make(path, display=False)
        steps = int(scenario.duration_s / 0.1)
        began = time.perf_counter()
        for k in range(steps):
            v, w = _command_at(scenario, k * 0.1)
            env.step(action=np.array([[v], [w]]))
            env.get_lidar_scan()
        wall = time.perf_counter() - began
        env.end(0) if hasattr(env, "end") else None
    return wall


def _try(name, fn, repeat):
    try:
        walls = [fn() for _ in range(repeat)]
    except ImportError as exc:
        print(f"{name}: not installed ({exc}); pip install '.[bench]'", file=sys.stderr)
        return None
    return statistics.median(walls)


def process_run(duration_s: float) -> tuple[float, float]:
    """Peak RSS [MB] and printed real-time factor of one `servicebot simulate` process."""
    with tempfile.TemporaryDirectory() as tmp:
        process = subprocess.Popen(
            [sys.executable, "-m", "servicebot_cli", "simulate", "--headless", "--duration-s",
             str(duration_s), "--out", f"{tmp}/out", "--bag", f"{tmp}/bag", "--plot",
             f"{tmp}/run.png"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        assert process.stderr is not None
        stderr = process.stderr.read()
        _, status, usage = os.wait4(process.pid, 0)
        process.returncode = os.waitstatus_to_exitcode(status)
        if process.returncode:
            raise SystemExit(f"servicebot simulate failed: {stderr}")
    factor = re.search(r"real-time factor (\d+)", stderr)
    return usage.ru_maxrss / 1024, float(factor.group(1)) if factor else math.nan


def memory(repeat: int) -> None:
    """Peak memory and real-time factor against the simulated duration (medians)."""
    print(f"servicebot simulate --headless --out --bag --plot, median of {repeat}")
    print(f"{'simulated [s]':>13} {'peak RSS [MB]':>14} {'RTF':>6}")
    peaks = {}
    for duration in (600.0, 7200.0):
        runs = [process_run(duration) for _ in range(repeat)]
        peaks[duration] = statistics.median(r[0] for r in runs)
        print(f"{duration:13.0f} {peaks[duration]:14.0f} "
              f"{statistics.median(r[1] for r in runs):6.0f}")
    print(f"7200 s / 600 s peak memory: {peaks[7200.0] / peaks[600.0]:.2f} (bound 1.3)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5, help="runs of servicebot (median)")
    parser.add_argument("--memory", action="store_true",
                        help="peak memory and RTF of 600 s and 7200 s runs instead")
    args = parser.parse_args()
    if args.memory:
        memory(args.repeat)
        return
    scenario, robot = load_scenario(None), load(RobotSource.bundled("sim"))
    servicebot_run(scenario, robot)  # warm caches (imports, model) once
    rows = [("servicebot simulate (bag written)", _try("servicebot",
             lambda: servicebot_run(scenario, robot), args.repeat))]
    rows.append(("pybullet DIRECT, husky", _try("pybullet", lambda: pybullet_run(scenario), 1)))
    rows.append(("ir-sim, no display", _try("ir-sim", lambda: irsim_run(scenario), 1)))
    rows.append(("MuJoCo, kinematic, same URDF and rays", _try(
        "mujoco", lambda: mujoco_run(scenario, robot), args.repeat)))
    ours = rows[0][1]
    cli = [cli_run(scenario.duration_s) for _ in range(args.repeat)]
    printed, process = (statistics.median(r[i] for r in cli) for i in (0, 1))
    print(f"default scenario: {scenario.duration_s:g} s simulated, median wall time")
    print(f"{'simulator':<36} {'wall [s]':>9} {'RTF':>8} {'servicebot is':>15}")
    for name, wall in rows:
        if wall is None:
            print(f"{name:<36} {'-':>9} {'-':>8} {'not installed':>15}")
            continue
        ratio = "-" if name.startswith("servicebot") else f"{wall / ours:.1f}x faster" \
            if wall >= ours else f"{ours / wall:.1f}x slower"
        print(f"{name:<36} {wall:9.3f} {scenario.duration_s / wall:8.0f} {ratio:>15}")
    print(f"servicebot simulate --headless --bag, median of {args.repeat} processes: "
          f"real-time factor {printed:.0f} as printed, {process:.0f} start to exit")
    with_csv = [cli_run(scenario.duration_s, out=True) for _ in range(args.repeat)]
    print(f"  with --out as well: {statistics.median(r[0] for r in with_csv):.0f} as printed, "
          f"{statistics.median(r[1] for r in with_csv):.0f} start to exit")
    mujoco = rows[-1][1]
    if mujoco is not None:
        print(f"printed real-time factor / MuJoCo kinematic: "
              f"{printed / (scenario.duration_s / mujoco):.2f}")


if __name__ == "__main__":
    main()
