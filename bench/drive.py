"""Benchmark: command rate against the 9600-baud limit, and Ctrl-C to the stop on the wire.

Everything runs for real: ``servicebot emulate --pace`` (bytes paced at 9600 baud, 10 bits
each, both ways) in one process, ``servicebot drive`` in another, over a pty. The two
protocols run side by side: the servicebot binary frames and ROSArduinoBridge text.

1. Rate: drive asks for R commands per second for a few seconds; the table gives the rate
   achieved, the reply rate, the median round trip and the ratio to the limit the frame
   sizes allow at 9600 baud. Rates above the limit (which ``drive`` refuses) are run through
   the library to show where the wire saturates.
2. Stop latency: drive runs, SIGINT is sent at a recorded CLOCK_MONOTONIC time, and the
   emulator records (on the same system-wide clock) when the last byte of the stop command
   came off the paced wire. Medians over repeated runs.

    .venv/bin/python bench/drive.py [--repeat 5] [--seconds 3]

It needs the test extra (``pip install -e '.[test]'``): it runs the emulator through the
tests' helper. No peer tool needs installing: the two protocols are the comparison.
"""

from __future__ import annotations

import argparse
import json
import os
import signal
import statistics
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))  # the tests' helpers run the emulator and drive for real

from tests.drive.conftest import Emulator as TestEmulator  # noqa: E402
from tests.drive.conftest import servicebot, wait_for  # noqa: E402

TICKS = ("--ticks-per-rev", "3436")
PROTOCOLS = {"servicebot": (), "arduino": ("--protocol", "arduino", *TICKS)}


class Emulator(TestEmulator):
    """``servicebot emulate --pace`` in another process (the tests' helper, paced)."""

    def __init__(self, protocol: str, state: Path) -> None:
        super().__init__(state, "--pace", "--watchdog-ms", "500", *PROTOCOLS[protocol])

    def close(self) -> None:
        self.stop()


def limit_hz(protocol: str) -> float:
    from servicebot_cli.description.loader import RobotSource, load
    from servicebot_cli.drive.link_setup import link_capacity_hz, make_link
    from servicebot_cli.drive.motors import motor_map
    from servicebot_cli.drive.protocols.arduino import ArduinoConfig

    motors = motor_map(load(RobotSource.bundled("real")))
    link = make_link(protocol, motors, ArduinoConfig(3436, 30.0))
    return link_capacity_hz(link, 9600)


def rate_run(emu: Emulator, protocol: str, rate: float, seconds: float) -> dict:
    drive = servicebot("drive", "--port", emu.path, *PROTOCOLS[protocol], "--rate", rate,
                       "--linear", "0.02", "--duration-s", seconds, "--format", "json")
    stdout, stderr = drive.communicate(timeout=60)
    if drive.returncode != 0:
        raise SystemExit(f"drive failed ({drive.returncode}): {stderr}")
    return json.loads(stdout)


def library_run(emu: Emulator, protocol: str, rate: float, seconds: float) -> dict:
    """Above the limit drive refuses the rate: run the same loop through the library."""
    import dataclasses

    from servicebot_cli.description.loader import RobotSource, load
    from servicebot_cli.drive.driving import StopUnconfirmed, StreamSettings, run_drive
    from servicebot_cli.drive.link_setup import make_link
    from servicebot_cli.drive.motors import motor_map
    from servicebot_cli.drive.plan import Plan, Step
    from servicebot_cli.drive.protocols.arduino import ArduinoConfig

    motors = motor_map(load(RobotSource.bundled("real")))
    link = make_link(protocol, motors, ArduinoConfig(3436, 30.0))
    settings = StreamSettings(emu.path, 9600, rate, 1.0, link_timeout_s=5.0,
                              connect_timeout_s=3.0)
    statuses = []
    driven = run_drive(settings, link, motors, Plan([Step(seconds, 0.02, 0.0)]),
                       log=lambda line: None, on_tick=statuses.append)
    unconfirmed = isinstance(driven.failure, StopUnconfirmed)  # replies queued on the wire
    if driven.summary is None or (driven.failure is not None and not unconfirmed):
        raise SystemExit(f"the library run failed: {driven.failure}")
    summary = driven.summary
    # replies in the last second of the stream: the rate the wire settled at
    return {**dataclasses.asdict(summary), "reply_hz": statuses[-1].reply_rate_hz}


def rate_table(repeat: int, seconds: float) -> list[list[str]]:
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for protocol in PROTOCOLS:
            limit = limit_hz(protocol)
            emu = Emulator(protocol, Path(tmp) / f"{protocol}.json")
            try:
                for rate in (10.0, 20.0, 25.0, 30.0):
                    runs = [rate_run(emu, protocol, rate, seconds) for _ in range(repeat)]
                    rows.append(_rate_row(protocol, rate, limit, runs, "drive"))
            finally:
                emu.close()
            for rate in (40.0, 60.0):  # a fresh emulator each time: the backlog stays behind
                runs = []
                for k in range(repeat):
                    emu = Emulator(protocol, Path(tmp) / f"{protocol}-{rate:g}-{k}.json")
                    try:
                        runs.append(library_run(emu, protocol, rate, seconds))
                    finally:
                        emu.close()
                rows.append(_rate_row(protocol, rate, limit, runs, "library"))
    return rows


def _rate_row(protocol: str, rate: float, limit: float, runs: list[dict], how: str
              ) -> list[str]:
    sent = statistics.median(r["commands"] / r["duration_s"] for r in runs)
    replies = statistics.median(  # replies to the stream's commands (not to the stop)
        r.get("reply_hz", min(r["replies"], r["commands"]) / r["duration_s"]) for r in runs)
    rtts = [r["median_rtt_s"] for r in runs if r["median_rtt_s"] is not None]
    rtt = f"{statistics.median(rtts) * 1000:.0f}" if rtts else "-"
    confirmed = sum(bool(r["stop_confirmed"]) for r in runs)
    return [protocol, f"{rate:g}", how, f"{sent:.1f}", f"{replies:.1f}", f"{limit:.1f}",
            f"{replies / limit:.2f}", rtt, f"{confirmed}/{len(runs)}"]


def stop_latency(protocol: str, repeat: int) -> list[float]:
    latencies = []
    with tempfile.TemporaryDirectory() as tmp:
        emu = Emulator(protocol, Path(tmp) / "state.json")
        try:
            for _ in range(repeat):
                drive = servicebot("drive", "--port", emu.path, *PROTOCOLS[protocol],
                                   "--linear", "0.02", "--duration-s", "60")
                wait_for(lambda: any(w["velocity_rad_s"] for w in emu.state()["wheels"]),
                         "the wheels to turn")
                time.sleep(0.3)
                sent_s = time.monotonic()
                os.kill(drive.pid, signal.SIGINT)
                drive.communicate(timeout=20)
                # the first stop after the signal: drive resends it until the firmware's
                # report shows the wheels still (arduino: counts that stop changing), and
                # before the signal, m 0 0 at the start of a ramp counts as a stop too
                first = wait_for(lambda sent_s=sent_s: min((t for t in emu.state()["counters"][
                    "recent_stops_s"] if t > sent_s), default=None), "the stop")
                latencies.append(first - sent_s)
                wait_for(lambda: not emu.state()["moving"], "the motors to stop")
        finally:
            emu.close()
    return latencies


def markdown(headers: list[str], rows: list[list[str]]) -> str:
    lines = ["| " + " | ".join(headers) + " |", "|" + "---|" * len(headers)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--seconds", type=float, default=3.0)
    args = parser.parse_args()
    print(f"servicebot drive against servicebot emulate --pace (9600 baud, 8N1), "
          f"medians of {args.repeat} runs of {args.seconds:g} s\n")
    print(markdown(["protocol", "asked Hz", "via", "sent Hz", "replies Hz", "limit Hz",
                    "replies / limit", "median rtt ms", "stop confirmed"],
                   rate_table(args.repeat, args.seconds)))
    print("\nlimit: 960 bytes/s over the larger of the command and the reply of one tick "
          "(servicebot: 32-byte TELEMETRY; arduino: the worst-case encoder line, 25 bytes, "
          "plus OK; real encoder lines are shorter, so arduino goes past its bound). "
          "Above the limit drive refuses --rate; the library runs show the wire saturating, "
          "and the reply that confirms their stop may wait behind the backlog of replies "
          "for longer than drive waits (stop confirmed: runs that saw it).")
    rows = []
    for protocol in PROTOCOLS:
        latencies = [x * 1000 for x in stop_latency(protocol, args.repeat)]
        rows.append([protocol, f"{statistics.median(latencies):.1f}",
                     f"{min(latencies):.1f}", f"{max(latencies):.1f}"])
    ratio = float(rows[1][1]) / float(rows[0][1])
    print("\nSIGINT to the last byte of the stop command off the paced wire, "
          f"{args.repeat} runs each\n")
    print(markdown(["protocol", "median ms", "min ms", "max ms"], rows))
    print(f"\narduino / servicebot median: {ratio:.2f}")


if __name__ == "__main__":
    main()
