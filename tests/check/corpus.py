"""The real URDF corpus: files that ship with PyPI packages, and check_urdf as the oracle."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path


def site_packages() -> Path:
    """The site-packages directory holding the installed data packages."""
    import cmeel

    return Path(cmeel.__file__).resolve().parents[1]


def erd_root() -> Path:
    """example-robot-data's share directory (``package://example-robot-data`` resolves here)."""
    return site_packages() / "cmeel.prefix" / "share" / "example-robot-data"


def erd_urdfs() -> list[Path]:
    """Every URDF of example-robot-data."""
    return sorted((erd_root() / "robots").rglob("*.urdf"))


def pybullet_urdfs() -> list[Path]:
    """Every URDF of pybullet_data (pybullet has wheels for CPython 3.10 and 3.11 only)."""
    try:
        import pybullet_data
    except ImportError:
        return []
    return sorted(Path(pybullet_data.getDataPath()).rglob("*.urdf"))


def check_urdf_commands() -> tuple[list[str], list[str], dict[str, str]]:
    """The pip-installed ``check_urdf`` and the native binary it wraps, with its environment."""
    wrapper = shutil.which("check_urdf") or str(Path(sys.executable).parent / "check_urdf")
    prefix = site_packages() / "cmeel.prefix"
    env = {**os.environ, "LD_LIBRARY_PATH": str(prefix / "lib")}
    return [wrapper], [str(prefix / "bin" / "check_urdf")], env


def check_urdf_rejects(path: Path, timeout_s: float = 3.0) -> bool:
    """True when check_urdf fails on ``path`` (a loop makes it print forever: a timeout)."""
    _, native, env = check_urdf_commands()
    try:
        result = subprocess.run([*native, str(path)], stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL, env=env, timeout=timeout_s)
    except subprocess.TimeoutExpired:
        return True
    return result.returncode != 0


def check_urdf_drops(path: Path, timeout_s: float = 3.0) -> bool:
    """True when check_urdf fails on ``path`` or drops a part of it.

    urdfdom logs "Could not parse visual/collision element" and carries on without the shape
    (exit 0): the robot it returns is not the one in the file.
    """
    _, native, env = check_urdf_commands()
    try:
        result = subprocess.run([*native, str(path)], capture_output=True, text=True, env=env,
                                timeout=timeout_s)
    except subprocess.TimeoutExpired:
        return True
    return result.returncode != 0 or "Could not parse" in result.stdout + result.stderr
