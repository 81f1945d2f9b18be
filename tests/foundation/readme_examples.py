"""Run the ``console`` examples of README.md as a user who followed its install would.

Each ``$ COMMAND`` line runs in a shell, in a directory laid out like the repository (the
package, ``robots/`` and the test fixtures the examples name), and what it prints (stdout and
stderr, as a terminal shows them) is compared with the lines below it. A few things differ
from run to run and are normalised on both sides: times, the real-time factor, pseudo-terminal
numbers and the machine's list of serial ports. An expected line ``...`` stands for any number
of lines: an abridged output.

Lines that set up an example are understood as a person would read them:

- A fenced block whose info string names a file (```` ```yaml run.yaml ````) is that file: it
  is written before any example runs. ``$ cat FILE`` shows one too.
- ``$ COMMAND &`` starts a background process (``servicebot emulate``): its first stdout line
  is the device that later commands name as ``/dev/pts/0``.
- A comment after a command says what happens meanwhile: ``# then Ctrl-C`` (SIGINT once
  connected), ``# the emulator is killed``, ``# while another drive runs``, ``# nothing
  answers there`` (a pseudo-terminal nobody serves).
"""

from __future__ import annotations

import math
import os
import pty
import re
import shutil
import signal
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

COPIED = ("servicebot_cli", "robots", "tests/fixtures", "tests/check/fixtures")
DEVICE = "/dev/pts/0"
VOLATILE = [
    (re.compile(r"/dev/pts/\d+"), "/dev/pts/N"),
    (re.compile(r"emulate\s+\d+\.\d+s:"), "emulate T:"),
    (re.compile(r"\bin \d+(\.\d+)? s\b"), "in T s"),
    (re.compile(r"real-time factor \d+"), "real-time factor N"),
    (re.compile(r"serial ports here: [^(]*\("), "serial ports here: ... ("),
    (re.compile(r"attempts?, \d+(\.\d+)? ms"), "attempts, T ms"),
    (re.compile(r'"solve_time_s": [0-9.e-]+'), '"solve_time_s": T'),
]


@dataclass
class Example:
    """One ``$`` line of a console block and the lines it should print."""

    command: str
    comment: str
    line: int
    expected: list[str] = field(default_factory=list)


def console_blocks(readme: Path) -> list[list[Example]]:
    """The README's console blocks, each a list of examples, with README line numbers."""
    blocks: list[list[Example]] = []
    current: list[Example] | None = None
    for number, text in enumerate(readme.read_text().splitlines(), start=1):
        if text.startswith("```console"):
            current = []
        elif text.startswith("```") and current is not None:
            blocks.append(current)
            current = None
        elif current is not None and text.startswith("$ "):
            command, _, comment = text[2:].partition("    #")
            current.append(Example(command.strip(), comment.strip(), number))
        elif current is not None and current:
            current[-1].expected.append(text)
    return blocks


def matches(expected: list[str], actual: list[str]) -> bool:
    """Whether ``actual`` is ``expected``, where a line ``...`` stands for any lines (none too).

    Both sides are normalised first (see :func:`normalise`).
    """
    want, got = normalise(expected), normalise(actual)
    if "..." not in (line.strip() for line in want):
        return len(want) == len(got) and all(map(same_line, want, got))
    memo: dict[tuple[int, int], bool] = {}

    def match(i: int, j: int) -> bool:
        if (i, j) not in memo:
            if i == len(want):
                memo[i, j] = j == len(got)
            elif want[i].strip() == "...":
                memo[i, j] = match(i + 1, j) or (j < len(got) and match(i, j + 1))
            else:
                memo[i, j] = j < len(got) and same_line(want[i], got[j]) and match(i + 1, j + 1)
        return memo[i, j]

    return match(0, 0)


_NUMBER = re.compile(r"-?\d+\.\d+(?:[eE][-+]?\d+)?|-?\d+[eE][-+]?\d+")
_FULL_PRECISION_DIGITS = 12
"""A number printed with this many digits is a float's full precision (Python's repr): its
last digits are the machine's (an iterative solver's residual, a sum in BLAS's order)."""


def same_line(want: str, got: str) -> bool:
    """Whether two lines are the same, but for the last digits of full-precision numbers.

    Such numbers (``0.1999999980590933`` against ``0.19999999805909238``) agree to a relative
    1e-7 or within 1e-9; every other character, and every shorter number, exactly.
    """
    if want == got:
        return True
    wants, gots = _NUMBER.findall(want), _NUMBER.findall(got)
    if len(wants) != len(gots) or _NUMBER.sub("#", want) != _NUMBER.sub("#", got):
        return False
    for a, b in zip(wants, gots, strict=True):
        if a == b:
            continue
        digits = len(re.sub(r"[eE].*|\D", "", a).lstrip("0"))
        if digits < _FULL_PRECISION_DIGITS and "e" not in a.lower():
            return False
        if not math.isclose(float(a), float(b), rel_tol=1e-7, abs_tol=1e-9):
            return False
    return True


def named_files(readme: Path) -> dict[str, str]:
    """The fenced blocks whose info string is a language and a file name, by file name."""
    files: dict[str, str] = {}
    name: str | None = None
    lines: list[str] = []
    for text in readme.read_text().splitlines():
        if name is None and text.startswith("```") and len(text[3:].split()) == 2:
            name, lines = text[3:].split()[1], []
        elif name is not None and text.startswith("```"):
            files[name] = "\n".join(lines) + "\n"
            name = None
        elif name is not None:
            lines.append(text)
    return files


def normalise(lines: list[str]) -> list[str]:
    """Lines with the run-to-run differences replaced by placeholders."""
    out = []
    for line in lines:
        for pattern, placeholder in VOLATILE:
            line = pattern.sub(placeholder, line)
        out.append(line.rstrip())
    return out


class Sandbox:
    """A directory laid out like the repository, with ``servicebot`` on the PATH."""

    def __init__(self, repo: Path, root: Path) -> None:
        self.root = root
        for name in COPIED:
            shutil.copytree(repo / name, root / name,
                            ignore=shutil.ignore_patterns("__pycache__"))
        for name, text in named_files(repo / "README.md").items():
            (root / name).write_text(text)
        bin_dir = root / "bin"
        bin_dir.mkdir()
        shim = bin_dir / "servicebot"
        shim.write_text(f'#!/bin/sh\nexec "{sys.executable}" -m servicebot_cli "$@"\n')
        shim.chmod(0o755)
        self.env = {**os.environ, "PATH": f"{bin_dir}:{os.environ['PATH']}",
                    "PYTHONPATH": str(root), "COLUMNS": "100", "CI": "true"}
        self.env.pop("SERVICEBOT_ROBOT", None)
        self.device = DEVICE
        self.background: list[subprocess.Popen[str]] = []
        self.ptys: list[int] = []

    def close(self) -> None:
        """Stop every background process and close the pseudo-terminals."""
        for process in self.background:
            if process.poll() is None:
                process.send_signal(signal.SIGINT)
                try:
                    process.wait(timeout=10)
                except subprocess.TimeoutExpired:
                    process.kill()
        for fd in self.ptys:
            os.close(fd)

    def run(self, example: Example) -> list[str]:
        """Run one example; what it printed, stdout and stderr interleaved as lines."""
        command = example.command
        if command.startswith("cat "):
            (self.root / command[4:].strip()).write_text("\n".join(example.expected) + "\n")
            return example.expected
        if command.endswith("&"):
            return self._start_background(command[:-1].strip(), len(example.expected))
        if "nothing answers" in example.comment:
            master, slave = pty.openpty()
            self.ptys += [master, slave]
            # its own pty, which may be /dev/pts/0 itself: then not the emulator's after all
            return self._finish(self._popen(command.replace(DEVICE, os.ttyname(slave))))
        command = command.replace(DEVICE, self.device)
        if "Ctrl-C" in example.comment or "emulator is killed" in example.comment:
            return self._interrupted(command, example.comment)
        if "another drive runs" in example.comment:
            if not any(process.poll() is None for process in self.background):
                self._start_background("servicebot emulate", 1)  # the last one was killed
                command = example.command.replace(DEVICE, self.device)
            holder = self._popen(command.replace("--duration-s 1", "--duration-s 30")
                                 .replace("--duration 1", "--duration 30"))
            self._wait_for(holder, "connected")
            try:
                return self._finish(self._popen(command))
            finally:
                holder.send_signal(signal.SIGINT)
                holder.wait(timeout=20)
        return self._finish(self._popen(command))

    def _popen(self, command: str) -> subprocess.Popen[str]:
        script = command if "|" in command or ";" in command else f"exec {command}"
        return subprocess.Popen(["bash", "-c", script], cwd=self.root, env=self.env,
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                stdin=subprocess.DEVNULL)

    def _finish(self, process: subprocess.Popen[str]) -> list[str]:
        out, _ = process.communicate(timeout=300)
        return out.splitlines()

    def _start_background(self, command: str, count: int) -> list[str]:
        process = subprocess.Popen(["bash", "-c", f"exec {command}"], cwd=self.root,
                                   env=self.env, stdout=subprocess.PIPE,
                                   stderr=subprocess.PIPE, text=True)
        self.background.append(process)
        assert process.stdout is not None and process.stderr is not None
        self.device = process.stdout.readline().strip()
        lines = [self.device]
        while len(lines) < count:
            lines.append(process.stderr.readline().rstrip("\n"))
        return lines

    def _wait_for(self, process: subprocess.Popen[str], needle: str) -> list[str]:
        assert process.stdout is not None
        lines = []
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline:
            line = process.stdout.readline()
            if not line:
                break
            lines.append(line.rstrip("\n"))
            if needle in line:
                break
        return lines

    def _interrupted(self, command: str, comment: str) -> list[str]:
        process = self._popen(command)
        lines = self._wait_for(process, "connected")
        time.sleep(0.3)
        if "Ctrl-C" in comment:
            process.send_signal(signal.SIGINT)
        else:
            for emulator in self.background:
                emulator.kill()
                emulator.wait()
        return lines + self._finish(process)
