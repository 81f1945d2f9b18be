"""Files that are something else: a web page, a Git LFS pointer, a merge conflict, comments.

Each was 'XML is not well-formed' at some column, with the fix to close a tag: the user was
not told that the file is a GitHub page saved instead of the raw file, a pointer whose large
file was never fetched, or a conflict left in.
"""

from __future__ import annotations

import pytest

from tests.check.helpers import findings

ROBOT = '<robot name="r">\n  <link name="base"/>\n</robot>\n'
LFS = ("version https://git-lfs.github.com/spec/v1\noid sha256:4d7a2146\nsize 12345\n")


@pytest.mark.parametrize(("text", "code", "line", "says", "fix"), [
    ('<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8"><link rel="x">\n</head>'
     "<body><p>robot.urdf</body></html>\n", "SB004", 1, "an HTML page, not a URDF",
     "download the raw file"),
    (LFS, "SB004", 1, "a Git LFS pointer, not the file", "run 'git lfs pull'"),
    (ROBOT.replace("  <link", "<<<<<<< HEAD\n  <link", 1).replace(
        "</robot>", '=======\n  <link name="b"/>\n>>>>>>> feature\n</robot>'),
     "SB004", 2, "a merge conflict left in the file ('<<<<<<<' line)", "keep the side you mean"),
    ('<?xml version="1.0"?>\n<!-- robot.urdf, generated -->\n', "SB002", 1,
     "file is empty but for comments", "Write a <robot"),
])
def test_what_a_broken_download_is_is_said(run, tmp_path, text, code, line, says, fix):
    path = tmp_path / "robot.urdf"
    path.write_text(text)
    result = run("check", "urdf", path, "--format", "json", "--isolated")
    (found,) = findings(result.stdout)
    assert (found["code"], found["line"]) == (code, line)
    assert found["message"].startswith(says) and found["fix"].startswith(fix)


def test_a_controllers_file_that_is_an_lfs_pointer_says_so(run, tmp_path):
    path = tmp_path / "controllers.yaml"
    path.write_text(LFS)
    result = run("check", "controllers", path, "--robot", "sim", "--format", "json",
                 "--isolated")
    (found,) = findings(result.stdout)
    assert found["code"] == "SB601" and found["message"].startswith("a Git LFS pointer")
