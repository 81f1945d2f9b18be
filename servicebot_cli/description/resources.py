"""Where the bundled robot files live: the only module that knows the layout.

Installed from a wheel they sit in ``servicebot_cli/robots``; from a source checkout
(editable install or plain ``PYTHONPATH``) in the top-level ``robots/`` directory.
"""

from __future__ import annotations

from pathlib import Path

from servicebot_cli.common.errors import ServicebotError

BUNDLED_ROBOTS = {
    "sim": "service_robot.urdf.xml",
    "real": "service_robot_real.urdf.xml",
}
"""Bundled description by name; ``sim`` is the default robot of every command."""
DEFAULT_ROBOT = "sim"
XACRO_SOURCE = "service_robot.urdf.xacro"
CONTROLLERS_YAML = "controllers.yaml"


def robots_dir() -> Path:
    """The directory holding the bundled robot files.

    Found beside this package rather than through :mod:`importlib.resources`, whose import
    (with tempfile and zipfile) costs every command about 4 ms: a wheel installs as files.
    """
    installed = Path(__file__).resolve().parents[1] / "robots"
    if installed.is_dir():
        return installed
    return Path(__file__).resolve().parents[2] / "robots"


def bundled_robot(name: str) -> Path:
    """Path of the bundled description called ``name`` (``sim`` or ``real``).

    Raises:
        ServicebotError: Unknown name, listing the known ones.
    """
    if name not in BUNDLED_ROBOTS:
        known = ", ".join(BUNDLED_ROBOTS)
        raise ServicebotError(f"no bundled robot '{name}'; choose one of: {known}")
    return robots_dir() / BUNDLED_ROBOTS[name]


def bundled_file(filename: str) -> Path:
    """Path of another bundled file (the xacro source, ``controllers.yaml``)."""
    return robots_dir() / filename
