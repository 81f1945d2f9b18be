"""Tree rules: joints name real links, one root, one parent per link, no loops (SB103-SB108).

Graph code is iterative and linear in the number of joints: a 3000-joint chain or a file
full of loops takes milliseconds, never a recursion error or a hang.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator
from typing import TYPE_CHECKING

from servicebot_cli.check.findings import Issue
from servicebot_cli.common.errors import NameNotFound
from servicebot_cli.description.parents import second_parents

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Joint
    from servicebot_cli.description.robot import RobotDescription


def check(robot: RobotDescription) -> Iterator[Issue]:
    """Every tree issue of ``robot``."""
    links = [link.name for link in robot.links if link.name]
    known = set(links)
    edges: list[Joint] = []
    half_joined: set[str] = set()  # links a joint with a missing end names: SB103 says so
    for joint in robot.joints:
        missing = [end for end in (joint.parent, joint.child) if end and end not in known]
        unnamed = not joint.parent or not joint.child  # a name of blanks is a name
        if missing or unnamed:  # an end unnamed: SB012 says so
            half_joined |= {end for end in (joint.parent, joint.child) if end in known}
        for name in missing:
            role = "parent" if name == joint.parent else "child"
            hint = str(NameNotFound.for_name(name, links)).split("; ", 1)[-1]
            yield Issue("SB103", f"joint '{joint.name}' has {role} link '{name}', which does not "
                        f"exist; {hint}", joint.element)
        if not (missing or unnamed):
            edges.append(joint)
    yield from _parents(edges)
    yield from _loops(edges)
    yield from _roots(robot, links, edges, half_joined)


def _parents(edges: list[Joint]) -> Iterator[Issue]:
    children = {joint.child for joint in edges}
    out = Counter(joint.parent for joint in edges)
    several_roots = len(set(out) - children) > 1  # one root: a loop, no joint turned round
    for first, joint in second_parents(edges):
        if (first.name, first.parent) == (joint.name, joint.parent):
            continue  # the same joint written twice: SB102 says so
        # a joint written the wrong way round: its parent, a leaf, became a second root
        swapped = [j for j in (joint, first) if several_roots and j.parent not in children
                   and out[j.parent] == 1]
        fix = (f"swap <parent> and <child> of joint '{swapped[0].name}' ('{swapped[0].parent}' "
               f"then hangs from '{swapped[0].child}'), or remove joint '{joint.name}'"
               if swapped else f"remove joint '{joint.name}' or give it its own child link")
        yield Issue("SB106", f"link '{joint.child}' has two parents: joint '{first.name}' "
                    f"(from '{first.parent}') and joint '{joint.name}' (from "
                    f"'{joint.parent}')", joint.element, fix=fix)


def _loops(edges: list[Joint]) -> Iterator[Issue]:
    """Each cycle of the parent -> child graph once, printed link by link."""
    out: dict[str, list[Joint]] = {}
    for joint in edges:
        out.setdefault(joint.parent or "", []).append(joint)
    state: dict[str, int] = {}  # 1 on the DFS path, 2 done
    seen: set[frozenset[str]] = set()
    for start in list(out):
        if start in state:
            continue
        path: list[Joint] = []
        stack = [(start, iter(out.get(start, ())))]
        state[start] = 1
        while stack:
            node, todo = stack[-1]
            step = next(todo, None)
            if step is None:
                state[node] = 2
                stack.pop()
                if path:
                    path.pop()
                continue
            child = step.child or ""
            if state.get(child) == 1:
                cycle = _cycle(path + [step], child)
                key = frozenset(j.name for j in cycle)
                if key not in seen:
                    seen.add(key)
                    yield _loop_issue(cycle)
            elif child not in state:
                state[child] = 1
                path.append(step)
                stack.append((child, iter(out.get(child, ()))))


def _cycle(path: list[Joint], start: str) -> list[Joint]:
    for i, joint in enumerate(path):
        if joint.parent == start:
            return path[i:]
    return path[-1:]


def _loop_issue(cycle: list[Joint]) -> Issue:
    if len(cycle) == 1:
        joint = cycle[0]
        return Issue("SB107", f"joint '{joint.name}' connects link '{joint.parent}' to itself",
                     joint.element, fix=f"remove joint '{joint.name}'")
    text = cycle[0].parent or ""
    shown = cycle if len(cycle) <= 12 else [*cycle[:6], None, *cycle[-5:]]
    for hop in shown:
        text += f" ... ({len(cycle) - 11} more joints)" if hop is None else \
            f" -[{hop.name}]-> {hop.child}"
    return Issue("SB107", f"kinematic loop: {text}", cycle[-1].element,
                 fix=f"remove one joint of the loop, e.g. '{cycle[-1].name}'")


def _roots(robot: RobotDescription, links: list[str], edges: list[Joint],
           half_joined: set[str]) -> Iterator[Issue]:
    children = {j.child for j in edges}
    connected = children | {j.parent for j in edges}
    roots = [name for name in dict.fromkeys(links) if name not in children]
    if links and not roots:
        yield Issue("SB104", "every link is a joint's child, so there is no root link; the "
                    "joints form a loop", robot.root)
        return
    trees = [r for r in roots if r in connected]
    main = trees[0] if trees else (roots[0] if roots else None)
    if len(trees) > 1:
        sizes = _subtree_sizes(edges, trees)
        listed = ", ".join(f"'{r}' ({sizes[r]} links)" for r in trees)
        yield Issue("SB105", f"{len(trees)} root links: {listed}; a URDF has exactly one",
                    robot.root, fix="attach each extra root to the robot with a joint")
    by_name = {link.name: link for link in robot.links}
    for name in roots:
        if name != main and name not in connected and name not in half_joined:
            yield Issue("SB108", f"link '{name}' is connected to nothing (no joint names it)",
                        by_name[name].element,
                        fix=f"attach '{name}' with a joint (fixed if it does not move)")


def _subtree_sizes(edges: list[Joint], roots: list[str]) -> dict[str, int]:
    out: dict[str, list[str]] = {}
    for joint in edges:
        out.setdefault(joint.parent or "", []).append(joint.child or "")
    sizes = {}
    for root in roots:
        seen, stack = {root}, [root]
        while stack:
            for child in out.get(stack.pop(), ()):
                if child not in seen:
                    seen.add(child)
                    stack.append(child)
        sizes[root] = len(seen)
    return sizes
