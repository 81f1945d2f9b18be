"""inspect and fk report a frame's orientation with the same roll-pitch-yaw."""

from __future__ import annotations

import numpy as np
import pytest

from servicebot_cli.inspect.numbers import rpy_of
from servicebot_cli.kinematics.rotations import matrix_from_rpy, rpy_from_matrix


@pytest.mark.parametrize("rpy", [(0.3, -0.4, 2.0), (0.7, np.pi / 2, -0.2), (-0.5, -np.pi / 2, 0.9)])
def test_inspect_angles_match_fk_even_at_gimbal_lock(rpy):
    rotation = matrix_from_rpy(np.array(rpy))
    shown = rpy_of(rotation)
    assert shown == pytest.approx(rpy_from_matrix(rotation), abs=1e-12)
    assert matrix_from_rpy(np.array(shown)) == pytest.approx(rotation, abs=1e-9)
