"""Reading the user's input files: one set of one-line errors for every command."""

from __future__ import annotations

import pytest

from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.common.inputs import (
    display_path,
    open_input_text,
    read_input_bytes,
    read_input_text,
)


class _Wrong(ServicebotError):
    pass


def test_each_way_a_file_cannot_be_read(tmp_path):
    kind = "a test file"
    with pytest.raises(_Wrong, match=r"nope.txt: no such file; give a test file"):
        read_input_text(str(tmp_path / "nope.txt"), kind=kind, error=_Wrong)
    with pytest.raises(_Wrong, match="is a directory; give a test file"):
        read_input_bytes(tmp_path, str(tmp_path), kind=kind, error=_Wrong)
    with pytest.raises(_Wrong, match="is a directory"):
        open_input_text(str(tmp_path), kind=kind, error=_Wrong)
    big = tmp_path / "big.txt"
    big.write_bytes(b"x" * 3_000_000)
    with pytest.raises(_Wrong, match=r"3.0 MB, over the 2 MB limit"):
        read_input_text(str(big), kind=kind, error=_Wrong, max_bytes=2_000_000)
    latin = tmp_path / "latin.txt"
    latin.write_bytes("ok\ncaf\u00e9\n".encode("latin-1"))
    with pytest.raises(_Wrong, match=r"latin.txt:2:4: not UTF-8 text \(byte 0xe9, 'é' in "):
        read_input_text(str(latin), kind=kind, error=_Wrong)


def test_streaming_read_survives_bad_bytes(tmp_path):
    mixed = tmp_path / "rows.csv"
    mixed.write_bytes(b"a,b\n1,\xff\n")
    with open_input_text(str(mixed), kind="rows") as handle:
        assert handle.read().splitlines() == ["a,b", "1,\ufffd"]


def test_display_path(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "sub").mkdir()
    assert display_path(tmp_path / "sub" / "x.urdf") == "sub/x.urdf"
    assert display_path(tmp_path.parent / "y.urdf") == str((tmp_path.parent / "y.urdf").resolve())


def test_a_directory_refused_leaves_no_descriptor_open(tmp_path):
    import os

    from servicebot_cli.common.errors import ServicebotError
    from servicebot_cli.common.inputs import read_input_bytes

    before = len(os.listdir("/proc/self/fd"))
    for _ in range(20):
        with pytest.raises(ServicebotError, match="is a directory"):
            read_input_bytes(tmp_path, "d", kind="a file")
    assert len(os.listdir("/proc/self/fd")) == before
