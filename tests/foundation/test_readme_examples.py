"""Every console example in README.md prints what README shows (see readme_examples.py)."""

from __future__ import annotations

import difflib
import json

import pytest

from tests.conftest import REPO
from tests.foundation.readme_examples import Sandbox, console_blocks, matches, normalise

README = REPO / "README.md"


@pytest.fixture(scope="module")
def sandbox(tmp_path_factory):
    box = Sandbox(REPO, tmp_path_factory.mktemp("readme"))
    yield box
    box.close()


def test_readme_has_examples():
    assert sum(len(block) for block in console_blocks(README)) >= 30


def test_every_console_example_prints_what_readme_shows(sandbox):
    mismatches = []
    for block in console_blocks(README):
        for example in block:
            actual = sandbox.run(example)
            if not matches(example.expected, actual):
                want, got = normalise(example.expected), normalise(actual)
                diff = "\n".join(difflib.unified_diff(want, got, "README", "actual", lineterm=""))
                mismatches.append(f"README.md:{example.line}: $ {example.command}\n{diff}")
    assert not mismatches, "\n\n".join(mismatches)


def test_the_check_json_example_matches_a_real_run(run):
    text = README.read_text()
    start = text.index("JSON (`servicebot check FILE --format json`)")
    opening = text.index("```json\n", start) + len("```json\n")
    block = text[opening:text.index("```", opening)]
    shown = json.loads(block)
    file = shown["files"][0]["file"]
    real = json.loads(run("check", file, "--format", "json").stdout)
    assert shown["summary"] == real["summary"]
    assert shown["files"][0]["findings"] == [
        f for f in real["files"][0]["findings"] if f["code"] in
        {g["code"] for g in shown["files"][0]["findings"]}]
