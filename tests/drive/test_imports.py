"""The drive package's layering: pure core modules, one pyserial importer, light commands."""

from __future__ import annotations

import ast

from tests.conftest import REPO

DRIVE = REPO / "servicebot_cli" / "drive"
PURE = ["protocols/framing", "protocols/messages", "motors", "protocols/events",
        "protocols/binary", "protocols/arduino", "emulator/arduino_firmware", "emulator/firmware",
        "emulator/wire", "plan", "script", "shaping", "session/commander", "dry_run",
        "request", "link_setup", "plans", "emulator/board", "session/inbox",
        "session/reconnect", "arm_motion", "arm_guard"]
IO = {"os", "sys", "select", "serial", "time", "pty", "tty", "termios", "subprocess", "socket",
      "click", "signal"}


def imported(path):
    names = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names |= {alias.name.split(".")[0] for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
            names.add(node.module.split(".")[0])
    return names


def test_core_modules_do_no_io():
    for name in PURE:
        assert not imported(DRIVE / f"{name}.py") & IO, name


def test_only_transport_imports_pyserial():
    importers = {path.relative_to(REPO).as_posix()
                 for path in (REPO / "servicebot_cli").rglob("*.py") if "serial" in imported(path)}
    assert importers == {"servicebot_cli/drive/transport.py"}
