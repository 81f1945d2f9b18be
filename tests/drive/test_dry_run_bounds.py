"""A dry run of a plan too long to list is refused at once, not computed until memory runs out.

``--duration-s 1e300`` is a valid run (it drives until stopped), but its dry run held every
one of its 2e301 frames before printing the first.
"""

from __future__ import annotations

import resource
from pathlib import Path

import pytest

from tests.conftest import assert_one_line_error, run_servicebot


def _memory_capped() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (3 << 30, 3 << 30))


@pytest.mark.parametrize("extra", [[], ["--format", "json"]])
def test_a_one_shot_too_long_to_list(extra: list[str]) -> None:
    result = run_servicebot("drive", "--dry-run", "--linear", "0", "--angular", "0",
                            "--duration-s", "1e300", *extra, timeout=30,
                            preexec_fn=_memory_capped)
    assert_one_line_error(result, 2, "--dry-run: the plan lasts 1e+300 s, 2e+301 frames at "
                          "20 Hz, over the 1000000 a dry run lists")


def test_a_script_too_long_to_list(tmp_path: Path) -> None:
    (tmp_path / "long.txt").write_text("twist 0 0 1\nstop 1e9\n")
    result = run_servicebot("drive", "--dry-run", "--script", "long.txt", cwd=tmp_path,
                            timeout=30, preexec_fn=_memory_capped)
    assert_one_line_error(result, 2, "the plan lasts 1e+09 s")
    assert result.stdout == ""
