"""captured_fd2: what is written to file descriptor 2 is collected, and fd 2 restored."""

from __future__ import annotations

import os

import pytest

from servicebot_cli.common import native_stderr


def _write_and_capture() -> list[str]:
    before = os.fstat(2)
    with native_stderr.captured_fd2() as lines:
        os.write(2, "Error: Mesh scale was specified\nsecond line é\n".encode())
        assert lines == []  # filled when the block ends
    after = os.fstat(2)
    assert (after.st_dev, after.st_ino) == (before.st_dev, before.st_ino)
    return lines


def test_lines_written_to_fd2_are_collected_and_fd2_restored():
    assert _write_and_capture() == ["Error: Mesh scale was specified", "second line é"]


def test_each_capture_starts_empty():
    _write_and_capture()
    with native_stderr.captured_fd2() as lines:
        pass
    assert lines == []


def test_without_memfd_a_temporary_file_serves(monkeypatch: pytest.MonkeyPatch):
    def refused(*_args: object) -> int:
        raise OSError(38, "Function not implemented")

    monkeypatch.setattr(os, "memfd_create", refused)
    assert _write_and_capture() == ["Error: Mesh scale was specified", "second line é"]
