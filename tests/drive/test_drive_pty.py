"""drive against ``servicebot emulate`` in another process, over a real pseudo-terminal."""

from __future__ import annotations

import csv
import json
import os
import signal
import time

import pytest

from tests.drive.conftest import finish, servicebot, wait_for

LONG = ("--linear", "0.03", "--duration-s", "60")


def state_when(emu, condition, what):
    """The emulator's state once ``condition(state)`` holds (it writes its state at 10 Hz)."""
    def check():
        state = emu.state()
        return state if condition(state) else None

    return wait_for(check, what)


def moving(emu):
    return lambda: emu.state_file.exists() and any(
        w["velocity_rad_s"] for w in emu.state()["wheels"])


def test_a_script_moves_the_encoders_as_commanded(emulator, tmp_path):
    emu = emulator()
    script = tmp_path / "tour.txt"
    script.write_text("twist 0.03 0 1.5\ntwist 0 0.2 1.0  # beyond the limit: scaled\n"
                      "arm arm_base_to_link1=0.4 arm_link2_to_link3=-0.2\nstop 0.6\n")
    log = tmp_path / "run.csv"
    code, stdout, stderr = finish(servicebot("drive", "--port", emu.path, "--script", script,
                                             "--log", log, "--format", "json"))
    assert code == 0, stderr
    summary = json.loads(stdout)
    assert summary["outcome"] == "completed" and summary["stop_confirmed"] is True
    state = state_when(emu, lambda s: s["counters"]["stops"] == 1, "the stop")
    assert not state["moving"] and state["counters"]["max_abs_wheel_command_rad_s"] <= 0.5
    for wheel, reported in zip(state["wheels"], summary["wheels"], strict=True):
        assert wheel["position_rad"] == pytest.approx(reported["commanded_travel_rad"],
                                                      rel=0.03, abs=0.01)
        assert reported["measured_travel_rad"] == pytest.approx(wheel["position_rad"], abs=0.01)
    left, right = (state["wheels"][0]["position_rad"], state["wheels"][1]["position_rad"])
    assert right - left > 0.3  # the turn in place
    assert [a["position_rad"] for a in state["arm"]] == pytest.approx([0.4, 0, -0.2, 0])
    rows = list(csv.DictReader(log.open()))
    assert len(rows) == summary["replies"] and rows[0]["t_s"]
    assert float(rows[-1]["front_left_wheel_joint_vel_rad_s"]) == 0.0  # the stop's reply
    assert "warning: " in stderr and "scaled to" in stderr


@pytest.mark.parametrize(("sig", "code", "words", "outcome"), [
    (signal.SIGINT, 130, "interrupted (Ctrl-C)", "interrupted"),
    (signal.SIGTERM, 143, "terminated (SIGTERM)", "terminated"),
    (signal.SIGHUP, 129, "hung up (SIGHUP)", "hung_up"),
    (signal.SIGQUIT, 131, "quit (SIGQUIT)", "quit"),
])
def test_signals_stop_the_motors_first(emulator, tmp_path, sig, code, words, outcome):
    emu = emulator()
    log = tmp_path / "run.csv"
    drive = servicebot("drive", "--port", emu.path, *LONG, "--log", log, "--format", "json")
    wait_for(moving(emu), "the wheels to turn")
    got, stdout, stderr = finish(drive, sig)
    assert got == code, stderr
    assert stderr.splitlines()[-1] == f"Error: {words}; motors stopped (the firmware confirmed)"
    summary = json.loads(stdout)
    assert summary["outcome"] == outcome and summary["stop_confirmed"] is True
    state = state_when(emu, lambda s: s["counters"]["stops"] == 1, "the stop")
    assert not state["moving"]
    assert state["counters"]["watchdog_trips"] == 0  # stopped by drive, not by the watchdog
    assert len(list(csv.reader(log.open()))) > 2  # the log of an interrupted run is kept
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.csv", "state0.json"]


def test_killing_the_emulator_mid_run_is_link_lost(emulator):
    emu = emulator()
    drive = servicebot("drive", "--port", emu.path, *LONG)
    wait_for(moving(emu), "the wheels to turn")
    emu.proc.kill()
    code, _, stderr = finish(drive)
    assert code == 5, stderr
    assert "Error: link lost: reading" in stderr and "watchdog stops the motors within 500 ms" \
        in stderr


def test_a_silent_firmware_is_link_lost_and_its_watchdog_stops(emulator):
    emu = emulator("--mute-after-s", "1.5")
    code, _, stderr = finish(servicebot("drive", "--port", emu.path, *LONG))
    assert code == 5, stderr
    assert f"no reply from the firmware on {emu.path} at 9600 baud for 1 s" in stderr
    state = state_when(emu, lambda s: s["counters"]["watchdog_trips"], "the watchdog")
    assert not state["moving"]


def test_the_watchdog_stops_the_motors_when_drive_is_killed(emulator):
    emu = emulator()
    drive = servicebot("drive", "--port", emu.path, *LONG)
    wait_for(moving(emu), "the wheels to turn")
    drive.kill()  # SIGKILL: no stop frame can be sent
    drive.communicate()
    state = state_when(emu, lambda s: s["counters"]["watchdog_trips"], "the watchdog")
    assert not state["moving"] and state["counters"]["stops"] == 0
    code, stderr = emu.stop()
    assert "watchdog: no motion command for 500 ms; motors stopped" in stderr


def test_corrupted_bytes_are_rejected_and_never_move_a_motor(emulator):
    emu = emulator("--corrupt", "0.02", "--drop", "0.005", "--seed", "1")
    code, stdout, stderr = finish(servicebot(
        "drive", "--port", emu.path, "--linear", "0", "--duration-s", "2",
        "--connect-timeout-s", "10", "--format", "json"))
    assert code == 0, stderr
    state = state_when(emu, lambda s: s["counters"]["commands"] >= 30, "the commands")
    assert state["wire"]["corrupted"] > 0 and state["counters"]["crc_errors"] > 0
    assert json.loads(stdout)["errors"] > 0  # the host rejected corrupted replies too
    assert state["counters"]["max_abs_wheel_command_rad_s"] == 0.0
    assert [w["position_rad"] for w in state["wheels"]] == [0.0] * 4


def test_reconnect_keeps_the_motors_at_zero_until_the_link_is_back(emulator, tmp_path):
    link = tmp_path / "ttyROBOT"
    first = emulator("--link", link)
    drive = servicebot("drive", "--port", link, "--reconnect", "--linear", "0.02",
                       "--duration-s", "6", "--format", "json")
    wait_for(moving(first), "the wheels to turn")
    first.proc.kill()
    first.proc.communicate()
    second = emulator("--link", link)
    code, stdout, stderr = finish(drive)
    assert code == 0, stderr
    assert "reconnecting (motors at zero" in stderr and "link back" in stderr
    assert json.loads(stdout)["reconnects"] == 1
    state = state_when(second, lambda s: s["counters"]["stops"] >= 2, "the final stop")
    assert state["counters"]["first_command"] == "STOP"  # zero first, before any motion
    assert not state["moving"]


def test_the_time_the_link_was_down_is_no_time_a_wheel_was_commanded(emulator, tmp_path):
    """Encoders that had not counted yet, a reconnect after more than the stall window, and
    a new board counting from zero again: no 'wheels stalled', as the motors were at zero."""
    link = tmp_path / "ttyROBOT"
    first = emulator("--link", link, "--stall-after-s", "0.001")  # answers, never counts
    drive = servicebot("drive", "--port", link, "--reconnect", "--linear", "0.02",
                       "--duration-s", "6", "--format", "json")
    state_when(first, lambda s: s["counters"]["frames"] >= 3, "motion commands")
    first.proc.kill()
    first.proc.communicate()
    time.sleep(1.2)  # longer than stall.WINDOW_S
    second = emulator("--link", link)
    code, stdout, stderr = finish(drive)
    assert code == 0, stderr
    assert json.loads(stdout)["reconnects"] == 1 and "stalled" not in stderr
    assert any(w["position_rad"] > 0 for w in second.state()["wheels"])


def test_the_arduino_protocol_end_to_end(emulator, tmp_path):
    emu = emulator("--protocol", "arduino", "--ticks-per-rev", "3436", "--watchdog-ms", "500")
    log = tmp_path / "run.csv"
    code, stdout, stderr = finish(servicebot(
        "drive", "--port", emu.path, "--protocol", "arduino", "--ticks-per-rev", "3436",
        "--linear", "0.02", "--angular", "0.05", "--duration-s", "1.5", "--format", "json",
        "--log", log))
    assert code == 0, stderr
    summary = json.loads(stdout)
    assert summary["stop_confirmed"] and summary["firmware"].startswith("ROSArduinoBridge")
    # every command's encoder counts come back (after its OK) and are read
    assert summary["replies"] >= summary["commands"] - 1
    assert len(list(csv.DictReader(log.open()))) == summary["replies"]
    state = state_when(emu, lambda s: s["counters"]["stops"] >= 1 and not s["moving"], "stop")
    for wheel, reported in zip(state["wheels"], summary["wheels"], strict=True):
        assert wheel["position_rad"] == pytest.approx(reported["commanded_travel_rad"],
                                                      rel=0.05, abs=0.02)
        assert reported["measured_travel_rad"] == pytest.approx(wheel["position_rad"],
                                                                abs=0.01)
    assert state["wheels"][1]["position_rad"] > state["wheels"][0]["position_rad"] > 0


def test_a_paced_link_carries_the_default_rate(emulator):
    emu = emulator("--pace")
    code, stdout, stderr = finish(servicebot("drive", "--port", emu.path, "--linear", "0.02",
                                             "--duration-s", "2", "--format", "json"))
    assert code == 0, stderr
    summary = json.loads(stdout)
    assert summary["errors"] == 0 and summary["replies"] >= summary["commands"] - 1
    assert emu.state()["wire"]["paced_baud"] == 9600


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM, signal.SIGHUP])
def test_emulate_prints_its_device_and_exits_cleanly(emulator, tmp_path, sig):
    link = tmp_path / "ttyEMU"
    emu = emulator("--link", link)
    assert emu.path == str(link) and link.is_symlink()
    assert emu.state()["port"].startswith("/dev/pts/")
    code, stderr = emu.stop(sig)
    assert code == 0 and stderr.rstrip().endswith("stopped; port closed")
    assert "Traceback" not in stderr and not link.exists()
    assert emu.state()["ended"] == "stopped"


def test_emulate_quit_by_sigquit_still_removes_its_link(emulator, tmp_path):
    link = tmp_path / "ttyEMU"
    emu = emulator("--link", link)
    code, stderr = emu.stop(signal.SIGQUIT)
    assert code == 131 and stderr.splitlines()[-1] == "Error: quit (SIGQUIT)"
    assert not os.path.lexists(link)


def test_emulate_replaces_a_stale_link_and_removes_it_on_exit(emulator, tmp_path):
    """A link left by a killed emulator points to a pty that is gone: it may be replaced."""
    ptys = [int(name) for name in os.listdir("/dev/pts") if name.isdigit()]
    gone = f"/dev/pts/{max(ptys, default=0) + 1000}"
    link = tmp_path / "ttyROBOT"
    os.symlink(gone, link)
    emu = emulator("--link", link)
    assert os.readlink(link) == emu.state()["port"] != gone
    code, stderr = emu.stop()
    assert code == 0, stderr
    assert not os.path.lexists(link)


def test_emulate_dies_on_request(emulator):
    emu = emulator("--die-after-s", "0.5")
    assert emu.proc.wait(timeout=20) == 0
    assert "dying now" in emu.proc.stderr.read()


def test_injected_latency_shows_in_the_round_trip(emulator):
    emu = emulator("--latency-s", "0.3")
    code, stdout, stderr = finish(servicebot("drive", "--port", emu.path, "--linear", "0.02",
                                             "--duration-s", "1.5", "--format", "json"))
    assert code == 0, stderr
    summary = json.loads(stdout)
    assert summary["median_rtt_s"] >= 0.3 and summary["errors"] == 0
