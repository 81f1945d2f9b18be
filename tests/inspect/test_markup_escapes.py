"""Names and notes stand for themselves in inspect's Markdown, Mermaid and dot.

Markdown passed ``<inertial>`` of a note through as an HTML tag (shown as nothing), put a
link named ``_frame_`` in italics, made ``a&gt;b`` show ``a>b`` and a link named
``tool<img src=x onerror=...>`` a live element; Mermaid showed ``&gt;`` as ``>``; graphviz
drew a node named ``%tool`` as ``%3``. Read back by markdown-it (CommonMark, with tables) and
graphviz's own parser.
"""

from __future__ import annotations

import json
import shutil
import subprocess

import pytest

from tests.conftest import run_servicebot

NAMES = ("tool<img src=x onerror=alert(1)>", "_frame_", "a&gt;b", "s`t`", "%tool")


def _robot(tmp_path):
    from xml.sax.saxutils import quoteattr

    links = "".join(f"<link name={quoteattr(name)}/>" for name in NAMES)
    joints = "".join(f'<joint name="j{k}" type="fixed"><parent link="base"/><child '
                     f"link={quoteattr(name)}/></joint>" for k, name in enumerate(NAMES))
    path = tmp_path / "names.urdf"
    path.write_text(f'<robot name="md"><link name="base"/>{links}{joints}</robot>')
    return path


def test_markdown_shows_every_name_and_note_as_written(tmp_path):
    markdown_it = pytest.importorskip("markdown_it")
    result = run_servicebot("inspect", _robot(tmp_path), "--format", "markdown", "--section",
                            "links")
    assert result.returncode == 0, result.stderr
    html = markdown_it.MarkdownIt("commonmark").enable("table").render(result.stdout)
    assert "<img" not in html and "<em>frame</em>" not in html and "<code>t</code>" not in html
    for name in NAMES:
        shown = name.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
        assert f"<td>{shown}</td>" in html, name
    assert "no &lt;inertial&gt; (frames)" in html


def test_mermaid_keeps_an_ampersand_and_dot_a_percent(tmp_path):
    robot = _robot(tmp_path)
    mermaid = run_servicebot("inspect", robot, "--format", "mermaid").stdout
    assert '["a#38;gt;b"]' in mermaid
    if shutil.which("dot") is None:
        pytest.skip("graphviz's dot is not installed (.ci/run installs it)")
    dot = run_servicebot("inspect", robot, "--format", "dot").stdout
    drawn = json.loads(subprocess.run(["dot", "-Tjson"], input=dot, capture_output=True,
                                      text=True, check=True).stdout)
    labels = [o["label"] if o.get("label", "\\N") != "\\N" else o["name"]
              for o in drawn["objects"]]  # graphviz names '%tool' '%3'; its label says it
    assert sorted(labels) == sorted(("base", *NAMES))


def test_a_line_break_in_a_name_stays_in_its_table_row(tmp_path):
    """A link named with &#10; split inspect's tables: its second line started with the
    rest of the name ('::error ...', a workflow command in a CI log)."""
    path = tmp_path / "break.urdf"
    path.write_text('<robot name="r"><link name="base"/><link name="arm&#10;::error x"/>'
                    '<joint name="j" type="fixed"><parent link="base"/>'
                    '<child link="arm&#10;::error x"/></joint></robot>')
    result = run_servicebot("inspect", path)
    assert result.returncode == 0, result.stderr
    assert not [line for line in result.stdout.splitlines() if line.startswith("::")]
    assert "arm\\n::error x" in result.stdout
