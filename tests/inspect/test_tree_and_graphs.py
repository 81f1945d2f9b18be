"""The kinematic tree as text, dot and Mermaid: the same graph as check_urdf and
urdf_to_graphviz, on odd graphs too.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pydot
import pytest

from servicebot_cli.description.elements import Joint, Pose
from servicebot_cli.inspect.tree import kinematic_tree
from tests.conftest import REAL_URDF, SIM_URDF
from tests.inspect.conftest import write_chain

TOOLS = Path(sys.executable).parent
# pydot's parser still uses pyparsing's old camelCase names; not ours to fix
pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")


def _urdf_to_graphviz_edges(urdf: Path, tmp_path: Path) -> set[tuple[str, str, str]]:
    """(parent link, joint, child link) from urdf_to_graphviz, which draws joints as nodes."""
    subprocess.run([str(TOOLS / "urdf_to_graphviz"), str(urdf), "g"], cwd=tmp_path,
                   capture_output=True, timeout=60, env={"PATH": ""})
    (graph,) = pydot.graph_from_dot_file(str(tmp_path / "g.gv"))
    links = {n.get_name().strip('"') for n in graph.get_nodes()
             if n.get_name().strip('"') not in ("node", "edge")}
    into, out_of = {}, {}
    for edge in graph.get_edges():
        src, dst = edge.get_source().strip('"'), edge.get_destination().strip('"')
        if dst in links:
            into[src] = dst
        else:
            out_of[dst] = src
    return {(out_of[joint], joint, child) for joint, child in into.items()}


def _our_dot(run, *args) -> pydot.Dot:
    result = run("inspect", *args, "--format", "dot")
    assert result.exit_code == 0, result.stderr
    graphs = pydot.graph_from_dot_data(result.stdout)
    assert graphs and len(graphs) == 1, "not valid dot"
    return graphs[0]


@pytest.mark.parametrize("urdf", [SIM_URDF, REAL_URDF])
def test_dot_is_the_graph_urdf_to_graphviz_draws(run, urdf, tmp_path):
    graph = _our_dot(run, urdf)
    ours = set()
    for edge in graph.get_edges():
        label = edge.get("label").strip('"').split("\\n")
        ours.add((edge.get_source().strip('"'), label[0], edge.get_destination().strip('"')))
    assert ours == _urdf_to_graphviz_edges(urdf, tmp_path)
    nodes = {n.get_name().strip('"') for n in graph.get_nodes()} - {"node", "edge"}
    assert len(nodes) == 15 and "arm_tool_link" in nodes


def test_dot_edges_carry_motion_and_limits(run):
    graph = _our_dot(run)
    labels = {e.get_destination().strip('"'): e.get("label") for e in graph.get_edges()}
    assert labels["arm_link2"] == '"arm_link1_to_link2\\nrevolute y\\n[-1.57, 1.57] rad, 1 rad/s"'
    assert labels["front_left_wheel"].endswith('continuous y\\n0.44 rad/s"')


def test_mermaid_has_every_link_and_joint(run):
    result = run("inspect", "--format", "mermaid")
    assert result.exit_code == 0
    lines = result.stdout.splitlines()
    assert lines[0] == "flowchart TD"
    nodes = dict(re.findall(r'^  (n\d+)\["([^"]+)"\]$', result.stdout, re.M))
    edges = re.findall(r'^  (n\d+) (-->|-\.->)\|"([^"]+)"\| (n\d+)$', result.stdout, re.M)
    assert len(nodes) == 15 and len(edges) == 14 and len(lines) == 1 + 15 + 14
    by_child = {nodes[child]: (nodes[parent], arrow, label)
                for parent, arrow, label, child in edges}
    assert by_child["arm_link1"] == (
        "arm_base_link", "-->", "arm_base_to_link1<br/>revolute z<br/>[-1.57, 1.57] rad, 1 rad/s")
    assert by_child["lidar_link"] == ("base_link", "-.->", "lidar_joint<br/>fixed")


def test_mermaid_and_dot_escape_awkward_names(run, tmp_path):
    urdf = tmp_path / "odd.urdf"
    urdf.write_text('<robot name="odd &quot;bot&quot;"><link name="end"/><link name="a&lt;b&gt;"/>'
                    '<link name="c|d#e"/>'
                    '<joint name="j &quot;1&quot;" type="fixed"><parent link="end"/>'
                    '<child link="a&lt;b&gt;"/></joint>'
                    '<joint name="j2" type="fixed"><parent link="a&lt;b&gt;"/>'
                    '<child link="c|d#e"/></joint></robot>')
    mermaid = run("inspect", urdf, "--format", "mermaid").stdout
    assert 'n0["end"]' in mermaid and 'n1["a#lt;b#gt;"]' in mermaid
    assert 'n2["c#124;d#35;e"]' in mermaid and '|"j #quot;1#quot;<br/>fixed"|' in mermaid
    graph = _our_dot(run, urdf)
    assert {n.get_name() for n in graph.get_nodes()} >= {'"end"', '"a<b>"', '"c|d#e"'}
    assert graph.get_name() == '"odd \\"bot\\""'


def test_text_tree_matches_check_urdf(run):
    """Same parent of every link as check_urdf prints, and every line within 100 columns."""
    result = run("inspect", "--section", "tree")
    lines = result.stdout.splitlines()
    assert max(map(len, lines)) <= 100
    body = lines[lines.index(next(ln for ln in lines if ln.startswith("base_link"))):]
    ours, stack = {}, []
    for line in body:
        if not line or line.startswith("  note"):
            break
        match = re.match(r"^([│ ├└─]*)(\S+)", line)
        depth = len(match.group(1)) // 3
        stack[depth:] = [match.group(2)]
        if depth:
            ours[match.group(2)] = stack[depth - 1]
    check = subprocess.run([str(TOOLS / "check_urdf"), str(SIM_URDF)], capture_output=True,
                           text=True, timeout=60).stdout
    theirs, stack = {}, ["base_link"]
    for line in check.splitlines():
        match = re.match(r"^(\s*)child\(\d+\):\s+(\S+)", line)
        if match:
            depth = len(match.group(1)) // 4
            stack[depth:] = [match.group(2)]
            theirs[match.group(2)] = stack[depth - 1]
    assert ours == theirs and len(ours) == 14


def test_tree_rows_show_motion_and_limits(run):
    out = run("inspect", "--section", "tree").stdout
    row = next(ln for ln in out.splitlines() if "arm_link1_to_link2" in ln)
    assert re.search(r"└─ arm_link2\s+arm_link1_to_link2\s+revolute y\s+"
                     r"\[-1\.57, 1\.57\] rad, 1 rad/s$", row)
    wheel = next(ln for ln in out.splitlines() if "front_left_wheel_joint" in ln)
    assert wheel.split()[-4:] == ["continuous", "y", "0.44", "rad/s"]


def test_a_deep_chain_needs_no_recursion_and_stays_narrow(run, tmp_path):
    deep = write_chain(tmp_path / "deep.urdf", 1500)
    result = run("inspect", deep, "--section", "tree", "--section", "totals")
    assert result.exit_code == 0, result.stderr
    lines = result.stdout.splitlines()
    assert max(map(len, lines)) <= 100
    assert any(line.startswith("1500… ") and "l1500" in line for line in lines)
    assert "1500: 0 wheels + 1500 arm" in result.stdout


def _joint(name: str, parent: str, child: str) -> Joint:
    return Joint(name, "fixed", parent, child, Pose(), (1.0, 0.0, 0.0), None)


def test_odd_graphs_keep_every_link():
    """Two roots, a cycle no root reaches, a joint to a missing link: nothing lost, no loop."""
    links = ("a", "b", "r2", "c1", "c2")
    joints = (_joint("ab", "a", "b"), _joint("c12", "c1", "c2"), _joint("c21", "c2", "c1"),
              _joint("ghost", "a", "nowhere"))
    tree = kinematic_tree(links, joints)
    assert tree.roots == ("a", "r2")
    assert [row.link for row in tree.rows()] == ["a", "b", "r2"]
    assert tree.unreachable == ("c1", "c2")
    assert [j.name for j in tree.edges] == ["ab"]


def test_a_deep_humanoids_tree_keeps_every_link_name_whole(run):
    """example-robot-data's Alex with Psyonic hands: 13 levels deep. Its link column was cut
    to 'To…', and past depth 10 to the depth alone, while the joint column kept 35
    characters. The tree draws at most five levels, and link names are cut last."""
    from servicebot_cli.description.loader import RobotSource, load
    from tests.kinematics.robots import example_robot

    path = example_robot("alex_description/urdf/alex_psyonic_hands.urdf")
    result = run("inspect", path, "--section", "tree")
    assert result.exit_code == 0, result.stderr
    lines = result.stdout.split("Kinematic tree")[1].splitlines()
    assert max(map(len, lines)) <= 100  # the table's, below the file's path
    names = {link.name for link in load(RobotSource.of(path), as_written=True).links}
    width = len(next(line for line in lines if line.startswith("---")).split()[0])
    shown = {line[:width].split("─ ")[-1].strip() for line in lines}
    assert names <= shown, sorted(names - shown)[:5]
