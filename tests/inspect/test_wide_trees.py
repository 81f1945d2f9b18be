"""inspect's arm reach reads the tree once, not once per arm joint.

A hand of 2000 fingers off one palm (a star of revolute joints) took 11 s in
``--section totals`` and a 5000-link one 70 s: each arm joint's chain rebuilt the whole tree.
Counted here rather than timed: the tree is listed a few times, however
many arm joints there are.
"""

from __future__ import annotations

from servicebot_cli.description.loader import RobotSource, read_description
from servicebot_cli.inspect import tree as tree_module
from servicebot_cli.inspect.report import Request, inspect_robot


def _star(tmp_path, fingers: int):
    joints = "".join(f'<link name="l{i}"/><joint name="j{i}" type="revolute"><parent '
                     f'link="l0"/><child link="l{i}"/><origin xyz="0.01 0 0"/><axis '
                     'xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/>'
                     "</joint>" for i in range(1, fingers + 1))
    path = tmp_path / f"star{fingers}.urdf"
    path.write_text(f'<robot name="star"><link name="l0"/>{joints}</robot>')
    return read_description(RobotSource.of(str(path)))


def test_the_tree_is_listed_a_fixed_number_of_times(tmp_path, monkeypatch):
    counts = []
    for fingers in (200, 1000):
        listed = 0
        original = tree_module.KinematicTree.rows

        def counting(self, _original=original):
            nonlocal listed
            listed += 1
            return _original(self)

        monkeypatch.setattr(tree_module.KinematicTree, "rows", counting)
        inspection = inspect_robot(_star(tmp_path, fingers), Request(sections=("totals",)))
        assert inspection.totals is not None and inspection.totals.arm is not None
        counts.append(listed)
    assert max(counts) <= 5, counts  # it was once per arm joint and more: 202 and 2004
