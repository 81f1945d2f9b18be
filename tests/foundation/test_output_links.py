"""Outputs named through symbolic links: written where the link leads, the link kept.

``servicebot check urdf F --output /dev/stdout > out.txt`` run as root replaced the
``/dev/stdout`` link with a regular file: the link resolves to the regular file out.txt,
so the output looked like a plain file and a temporary was renamed over the link, and
out.txt stayed empty. These tests build the same chains with links of their own in
tmp_path, never touching /dev.
"""

from __future__ import annotations

import os
import stat
import subprocess
import sys
import threading
from pathlib import Path

from tests.conftest import REPO

ROBOT = REPO / "tests" / "realworld" / "ws" / "src" / "urdf_tutorial" / "urdf" / "01-myfirst.urdf"


def _servicebot(*args: object, stdout: int | None = None) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run([sys.executable, "-m", "servicebot_cli", *map(str, args)],
                          stdout=stdout, stderr=subprocess.PIPE, timeout=60, check=False)


def test_a_link_to_the_fd_of_a_redirected_stdout_writes_into_the_redirect(tmp_path: Path) -> None:
    link = tmp_path / "stdout"
    link.symlink_to("/proc/self/fd/1")  # as /dev/stdout is
    out = tmp_path / "out.json"
    with out.open("wb") as handle:
        result = _servicebot("check", "urdf", ROBOT, "--format", "json", "--output", link,
                             stdout=handle.fileno())
    assert result.returncode == 0, result.stderr
    assert link.is_symlink() and os.readlink(link) == "/proc/self/fd/1", "the link was replaced"
    assert b'"format_version"' in out.read_bytes()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.json", "stdout"]


def test_a_link_to_a_named_pipe_writes_into_the_pipe(tmp_path: Path) -> None:
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    link = tmp_path / "report.json"
    link.symlink_to(fifo)
    received: list[bytes] = []
    reader = threading.Thread(target=lambda: received.append(fifo.read_bytes()))
    reader.start()
    try:
        result = _servicebot("check", "urdf", ROBOT, "--format", "json", "--output", link)
    finally:
        if reader.is_alive() and not received:
            with open(fifo, "wb"):  # let the reader go if nothing ever opened the pipe
                pass
        reader.join(10)
    assert result.returncode == 0, result.stderr
    assert link.is_symlink() and stat.S_ISFIFO(fifo.lstat().st_mode)
    assert b'"format_version"' in received[0]


def test_a_link_to_a_regular_file_replaces_that_file_and_keeps_the_link(tmp_path: Path) -> None:
    # as xacro -o, cp and > do: the output lands in the file the link names
    (tmp_path / "reports").mkdir()
    kept = tmp_path / "reports" / "report.json"
    kept.write_text("old\n")
    link = tmp_path / "report.json"
    link.symlink_to(Path("reports") / "report.json")
    result = _servicebot("check", "urdf", ROBOT, "--format", "json", "--output", link)
    assert result.returncode == 0, result.stderr
    assert link.is_symlink() and link.resolve() == kept.resolve()
    assert b'"format_version"' in kept.read_bytes()
    assert sorted(p.name for p in (tmp_path / "reports").iterdir()) == ["report.json"]


def test_a_file_replaced_keeps_its_mode_and_owner(tmp_path: Path) -> None:
    """expand -o onto a 0600 file left it 0644 (and, as root, root's): a private report or
    URDF became world-readable. xacro -o, cp and > keep the mode; a new file is 0644."""
    kept = tmp_path / "private.urdf"
    kept.write_text("secret\n")
    kept.chmod(0o600)
    if os.getuid() == 0:
        os.chown(kept, 1234, 1234)
    result = _servicebot("expand", ROBOT, "-o", kept)
    assert result.returncode == 0, result.stderr
    assert "<robot" in kept.read_text()
    mode = kept.stat()
    assert stat.S_IMODE(mode.st_mode) == 0o600
    if os.getuid() == 0:
        assert (mode.st_uid, mode.st_gid) == (1234, 1234)
    if os.getuid() == 0:  # chown clears set-id bits: the mode is set after the owner
        kept.chmod(0o6755)
        assert _servicebot("expand", ROBOT, "-o", kept).returncode == 0
        assert stat.S_IMODE(kept.stat().st_mode) == 0o6755
    new = tmp_path / "new.urdf"
    assert _servicebot("expand", ROBOT, "-o", new).returncode == 0
    assert stat.S_IMODE(new.stat().st_mode) == 0o644 & ~_umask()


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
