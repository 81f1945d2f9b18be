"""Files that are something else than what they were meant to be, whatever their format.

A Git LFS pointer where the file should be (the repository's large files not fetched), and a
merge conflict's markers left in. Pure.
"""

from __future__ import annotations

import re

LFS_POINTER = "version https://git-lfs.github.com/spec/"
_CONFLICT = re.compile(r"^(?:<{7}|>{7})(?: |$)", re.MULTILINE)


def accident(text: str) -> tuple[str, int] | None:
    """What ``text`` is instead of the file meant, and the line that shows it; or None."""
    if text.startswith(LFS_POINTER):
        return ("a Git LFS pointer, not the file: the repository's large files were not "
                "fetched (run 'git lfs pull' in it)"), 1
    conflict = _CONFLICT.search(text)
    if conflict is not None:
        line = text.count("\n", 0, conflict.start()) + 1
        return (f"a merge conflict left in the file ('{conflict[0].strip()}' line): keep one "
                "side and remove the markers"), line
    return None


_FIXES = (
    ("a Git LFS pointer", "run 'git lfs pull' in the repository that holds the file"),
    ("a merge conflict", "keep the side you mean between the <<<<<<<, ======= and >>>>>>> "
     "lines, and delete the three markers"),
    ("an HTML page", "download the raw file (GitHub's Raw button, or raw.githubusercontent.com)"),
)
"""What to do about each accident (by the start of its message)."""


def accident_fix(message: str) -> str | None:
    """What to do about the accident ``message`` says (safe_xml's too); None for another."""
    return next((fix for start, fix in _FIXES if message.startswith(start)), None)
