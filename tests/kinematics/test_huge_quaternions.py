"""A quaternion whose length overflows a double is still a direction."""

from __future__ import annotations

from tests.conftest import run_servicebot


def test_a_quaternion_too_long_for_a_double_is_still_a_direction(tmp_path):
    """(1e308, 1e308, 0, 0): numpy's 'overflow encountered in dot' reached stderr, and the
    message said its length was 0. It is a direction: the solve goes on, without numpy."""
    targets = tmp_path / "t.csv"
    targets.write_text("x_m,y_m,z_m,qx,qy,qz,qw\n0.3,0,0.3,1e308,1e308,0,0\n")
    for args in (["--position", "0.3", "0", "0.3", "--quat", "1e308", "1e308", "0", "0"],
                 ["--targets", str(targets)]):
        result = run_servicebot("ik", *args, "--seed", "1")
        assert "Warning" not in result.stderr and "length 0" not in result.stderr, args
        assert "not with that orientation" in result.stdout + result.stderr
