"""The inspect section of README.md shows real output: a changed output fails here."""

from __future__ import annotations

import pytest

from tests.conftest import REPO

SECTION = (REPO / "README.md").read_text().split("<!-- section: inspect -->")[1].split(
    "<!-- end: inspect -->")[0]


def test_the_mermaid_diagram_is_current(run):
    block = SECTION.split("```mermaid\n")[1].split("```")[0]
    assert block == run("inspect", "--format", "mermaid").stdout


@pytest.mark.parametrize("section", ["tree", "totals"])
def test_the_shown_sections_are_current(run, section):
    shown = run("inspect", "--section", section).stdout
    assert f"$ servicebot inspect --section {section}\n{shown}" in SECTION


def test_the_shown_errors_are_current(run):
    for args in (["--section", "link"],
                 ["--render", "robot.png", "--joint", "arm_link1_to_lnk2=0.8"]):
        line = run("inspect", *args).stderr
        assert f"$ servicebot inspect {' '.join(args)}\n{line}" in SECTION
