"""Shell completion answers what users type most, fast: nothing heavy is imported.

Joint names, frame names, serial ports, inspect's sections and check's rule codes, read from
the robot file on the command line (or the bundled one) without building a Pinocchio model.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from tests.conftest import XACRO_SOURCE

HEAVY = {"pinocchio", "trimesh", "yourdfpy", "matplotlib", "numpy", "scipy", "serial", "lxml"}

_PROBE = """
import atexit, json, sys
before = set(sys.modules)  # what the interpreter's start-up imported (site, .pth files)
atexit.register(lambda: print("MODULES=" + json.dumps(sorted(set(sys.modules) - before)),
                              file=sys.stderr))
from servicebot_cli.cli import main
main([], prog_name="servicebot")
"""


def complete(words: str) -> tuple[list[str], set[str]]:
    """What bash completion offers for ``words`` (the last one being typed), and the modules
    the process imported."""
    parts = words.split(" ")
    env = {**os.environ, "_SERVICEBOT_COMPLETE": "bash_complete", "COMP_WORDS": words,
           "COMP_CWORD": str(len(parts) - 1)}
    result = subprocess.run([sys.executable, "-c", _PROBE], capture_output=True, text=True,
                            env=env, timeout=60)
    line = next(ln for ln in result.stderr.splitlines() if ln.startswith("MODULES="))
    modules = {name.split(".")[0] for name in json.loads(line[len("MODULES="):])}
    return [item.split(",", 1)[1] for item in result.stdout.split()], modules


@pytest.mark.parametrize("words", ["servicebot fk -j arm_", "servicebot inspect --joint arm_",
                                   "servicebot fk --robot real -j arm_"])
def test_joint_names(words):
    offered, modules = complete(words)
    assert offered == ["arm_base_to_link1=", "arm_link1_to_link2=", "arm_link2_to_link3=",
                       "arm_link3_to_link4="]
    assert not HEAVY & modules, HEAVY & modules


def test_joint_names_of_a_xacro_file_with_its_arguments():
    offered, modules = complete(f"servicebot fk {XACRO_SOURCE} hardware:=real -j front_")
    assert offered == ["front_left_wheel_joint=", "front_right_wheel_joint="]
    assert not HEAVY & modules, HEAVY & modules


def test_a_file_that_cannot_be_read_completes_nothing_and_says_nothing():
    offered, _ = complete("servicebot fk /no/such.urdf -j arm_")
    assert offered == []


def test_inspect_sections():
    offered, modules = complete("servicebot inspect --section t")
    assert offered == ["tree", "topics", "totals"]
    assert not HEAVY & modules


def test_help_imports_only_the_standard_library_and_click():
    """An allowlist, not a denylist: a new heavy import fails here whatever its name."""
    probe = _PROBE.replace("main([]", "main(['--help']")
    result = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                            timeout=60)
    line = next(ln for ln in result.stderr.splitlines() if ln.startswith("MODULES="))
    modules = {name.split(".")[0] for name in json.loads(line[len("MODULES="):])}
    allowed = set(sys.stdlib_module_names) | {"click", "servicebot_cli"}
    assert modules <= allowed, sorted(modules - allowed)


def test_serial_ports_complete_the_devices_present_else_paths():
    import glob

    from servicebot_cli.commands.options import SERIAL_PATTERNS

    present = [p for pattern in SERIAL_PATTERNS for p in sorted(glob.glob(pattern))]
    env = {**os.environ, "_SERVICEBOT_COMPLETE": "bash_complete",
           "COMP_WORDS": "servicebot drive --port /dev/tty", "COMP_CWORD": "3"}
    result = subprocess.run([sys.executable, "-m", "servicebot_cli"], capture_output=True,
                            text=True, env=env, timeout=60)
    offered = result.stdout.split()
    wanted = [p for p in present if p.startswith("/dev/tty")]
    assert offered == ([f"plain,{p}" for p in wanted] if wanted else ["file,/dev/tty"])
