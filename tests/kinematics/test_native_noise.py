"""urdfdom's own error lines, printed on fd 2 while Pinocchio reads the collision geometry.

pybullet's racecar_differential gives a mesh ``scale="1 1 1 1"``: urdfdom prints
"Error: Mesh scale was specified, but could not be parsed" and two source lines, then goes on
without the shape. ik's collision check read it and the lines reached the terminal.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.conftest import run_servicebot


def test_ik_on_racecar_differential_prints_only_its_own_lines():
    pybullet_data = pytest.importorskip("pybullet_data")
    racecar = Path(pybullet_data.getDataPath()) / "racecar" / "racecar_differential.urdf"
    result = run_servicebot("ik", racecar, "--frame", "diff2_sideB", "--position", "0", "0",
                            "0.1", "--seed", "1")
    assert result.returncode == 1, result.stderr  # the frame only spins: out of reach
    assert result.stderr.splitlines() == [line for line in result.stderr.splitlines()
                                          if line.startswith("Error: no IK solution")], \
        result.stderr
    assert "urdfdom" not in result.stderr and "Mesh scale" not in result.stderr
