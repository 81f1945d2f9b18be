"""Files that are not UTF-8 text get one line that says what they are, from every reader.

UTF-16 with a byte-order mark (Windows editors), Latin-1 (an é in a comment), an image, an
image or a directory: each YAML or URDF reader says which file, what is wrong and what to do,
with exit 2 (``check urdf``: an SB003 finding, exit 1). UTF-8 with a byte-order mark is read
as UTF-8.
"""

from __future__ import annotations

import codecs
import struct
import zlib
from pathlib import Path

import pytest

from servicebot_cli.common.text_decoding import NotUtf8, decode_utf8
from tests.check.helpers import findings
from tests.conftest import ROBOTS, assert_one_line_error

CONTROLLERS = (ROBOTS / "controllers.yaml").read_text(encoding="utf-8")
YAML = "# r\u00e9glages\ncontroller_manager:\n  ros__parameters:\n    update_rate: 50\n"


def _png() -> bytes:
    header = struct.pack(">IIBBBBB", 1, 1, 8, 0, 0, 0, 0)
    chunk = b"IHDR" + header
    return (b"\x89PNG\r\n\x1a\n" + struct.pack(">I", len(header)) + chunk
            + struct.pack(">I", zlib.crc32(chunk)))


ODD = {  # name: (bytes, what the one line says)
    "utf16.yaml": (YAML.encode("utf-16"), "UTF-16 text (it starts with a UTF-16 byte-order mark)"),
    "latin1.yaml": (YAML.encode("latin-1"),
                    ":1:4: not UTF-8 text (byte 0xe9, '\u00e9' in Latin-1)"),
    "picture.png": (_png(), "a PNG image, not text; give "),
}


@pytest.mark.parametrize(("data", "what"), [
    (codecs.BOM_UTF16_LE + "a: 1".encode("utf-16-le"), "UTF-16 text (it starts with a UTF-16"),
    (codecs.BOM_UTF32_LE + "a: 1".encode("utf-32-le"), "UTF-32 text"),
    ("a: 1\n".encode("utf-16-be"), "UTF-16 text without a byte-order mark"),
    (_png(), "a PNG image"),
    (b"PK\x03\x04\x14\x00\x00\x00\x08\x00", "a ZIP archive"),
    (b"a: 1\n\0\0\0\x01b", "binary data (it holds NUL bytes)"),
])
def test_what_the_bytes_are_instead(data, what):
    with pytest.raises(NotUtf8) as caught:
        decode_utf8(data)
    assert caught.value.what.startswith(what), caught.value.what


def test_a_latin1_byte_is_placed_and_named():
    with pytest.raises(NotUtf8) as caught:
        decode_utf8("a: 1\n# caf\u00e9\n".encode("latin-1"))
    problem = caught.value
    assert (problem.line, problem.column, problem.binary) == (2, 6, False)
    assert problem.what == "byte 0xe9, '\u00e9' in Latin-1"


@pytest.mark.parametrize("before", [
    "\u00e9" * 5000,  # the NUL is within 8192 characters but past byte 8192
    "\ufeff" + "a" * 8188,  # a byte-order mark, then the NUL at bytes 8191 to 8193
])
def test_a_nul_byte_after_multibyte_text_is_told_not_an_internal_error(run, tmp_path, before):
    nul = tmp_path / "nul.urdf"
    nul.write_bytes(f"<robot name='r'><!-- {before} -->\0<link name='a'/></robot>".encode())
    result = run("check", "urdf", nul, "--format", "json")
    assert result.exit_code == 1, result.output  # a finding, whatever the reader says
    assert [f["code"] for f in findings(result.stdout)] in (["SB003"], ["SB004"])


def test_utf8_with_a_byte_order_mark_is_utf8():
    assert decode_utf8(codecs.BOM_UTF8 + "a: \u00e9\n".encode()) == "a: \u00e9\n"


def _odd(tmp_path: Path, name: str) -> Path:
    path = tmp_path / name
    path.write_bytes(ODD[name][0])
    return path


READERS = {  # the command line that reads a file, "{}" for its path
    "check controllers": ("check", "controllers", "{}"),
    "inspect --controllers": ("inspect", "--section", "topics", "--controllers", "{}"),
    "simulate --scenario": ("simulate", "--headless", "--scenario", "{}"),
    "simulate --controllers": ("simulate", "--headless", "--duration-s", "0.5",
                               "--controllers", "{}"),
}


@pytest.mark.parametrize("reader", list(READERS))
@pytest.mark.parametrize("name", list(ODD))
def test_each_reader_says_what_the_file_is(run, tmp_path, reader, name):
    path = _odd(tmp_path, name)
    args = [str(path) if a == "{}" else a for a in READERS[reader]]
    line = assert_one_line_error(run(*args), 2, str(path), ODD[name][1])
    assert "codec" not in line and "position" not in line


@pytest.mark.parametrize("reader", ["check controllers", "inspect --controllers",
                                    "simulate --controllers"])
def test_a_controllers_file_with_a_utf8_byte_order_mark_is_read(run, tmp_path, reader):
    path = tmp_path / "controllers.yaml"
    path.write_bytes(codecs.BOM_UTF8 + CONTROLLERS.encode())
    args = [str(path) if a == "{}" else a for a in READERS[reader]]
    assert run(*args).exit_code == 0


@pytest.mark.parametrize("name", list(ODD))
def test_check_urdf_reports_sb003_with_what_the_file_is(run, tmp_path, name):
    path = tmp_path / f"{name}.urdf"
    path.write_bytes(ODD[name][0])
    result = run("check", "urdf", path, "--format", "json")
    (finding,) = findings(result.stdout)
    assert finding["code"] == "SB003" and result.exit_code == 1
    assert finding["message"].startswith("invalid UTF-8")
    expected = {"utf16.yaml": "UTF-16 text", "latin1.yaml": "byte 0xe9, '\u00e9' in Latin-1",
                "picture.png": "a PNG image, not text"}[name]
    assert expected in finding["message"]


def test_a_directory_is_refused_by_name(run, tmp_path):
    assert_one_line_error(run("check", "controllers", tmp_path), 2, "is a directory")


@pytest.mark.parametrize("device", [True, False])
def test_an_empty_controllers_file_is_refused_by_name(run, tmp_path, device):
    path = Path("/dev/null") if device else tmp_path / "empty.yaml"
    if not device:
        path.write_bytes(b"")
    for reader in ("inspect --controllers", "simulate --controllers"):
        args = [str(path) if a == "{}" else a for a in READERS[reader]]
        assert_one_line_error(run(*args), 2,
                              f"{path}: file is empty; give a ros2_control controllers YAML")


def test_simulate_says_where_a_controllers_file_is_not_yaml(run, tmp_path):
    path = tmp_path / "controllers.yaml"
    path.write_text("controller_manager:\n  ros__parameters:\n    update_rate: [1\n")
    args = [str(path) if a == "{}" else a for a in READERS["simulate --controllers"]]
    line = assert_one_line_error(run(*args), 2, f"{path}:4: not valid YAML")
    assert "<unicode string>" not in line
