"""The sections of a ros2_control controllers YAML, as rcl and the controller manager read them.

Each node's ``ros__parameters``, under namespaces or not, merged with its ``/**`` sections;
each controller's type, nested or as a dotted ``NAME.type`` key. Or the SB601 issue that
makes the text no controllers file at all. Pure: YAML text in, nodes out.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterator

import yaml  # type: ignore[import-untyped]  # PyYAML ships no types

from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.check.rcl_layout import layout_issue
from servicebot_cli.check.substitutions import substituted
from servicebot_cli.common.accidents import accident, accident_fix
from servicebot_cli.description.ros_parameters import tab_indented
from servicebot_cli.description.yaml_size import MOST_NODES, unfolded_nodes

_NAMESPACE_DEPTH = 3

Sections = dict[str, list[yaml.MappingNode]]
"""Each node's ``ros__parameters`` sections by node name, in file order (one per namespace)."""


def sections(text: str, display: str) -> Sections | Issue:
    """The controller sections of ``text``, read once for every robot it is checked against.

    Or the SB601 issue that makes ``text`` no controllers file at all, whatever the robot:
    not YAML, empty, or without a ``NAME: ros__parameters:`` section.
    """
    instead = accident(text)
    if instead is not None:
        return Issue("SB601", instead[0], where=(display, instead[1], 1),
                     fix=accident_fix(instead[0]))
    try:
        root = _composed(text)
    except yaml.YAMLError as exc:
        mark = getattr(exc, "problem_mark", None)
        where = (display, mark.line + 1, mark.column + 1) if mark else (display, 0, 0)
        problem = getattr(exc, "problem", None) or str(exc).splitlines()[0]
        tabbed = tab_indented(text, mark)
        return Issue("SB601", f"not valid YAML: {problem}" + (
            " (a tab in the indentation: YAML indents with spaces only)" if tabbed else ""),
            where=where, fix="indent with spaces" if tabbed else None)
    except RecursionError:  # PyYAML's composer recurses once per level of nesting
        return Issue("SB601", "not valid YAML: lists and mappings nested too deep to read",
                     where=(display, 0, 0))
    if root is not None and unfolded_nodes(root) is None:
        return Issue("SB601", f"its aliases (*name) unfold to over {MOST_NODES:,} items (an "
                     "alias bomb?); no controllers file is that large", where=(display, 0, 0))
    if root is None:
        return Issue("SB601", "the file holds no YAML (it is empty, or only comments)",
                     where=(display, 0, 0),
                     fix="write each controller's parameters under NAME: ros__parameters:")
    sections = _sections(root)
    misread = _misspelled_parameters(root, display) or (
        None if sections else _key_not_a_name(root, display))
    if misread is not None:  # says more than 'no controller here'
        return misread
    if not sections:
        ros1 = _ros1_controllers(root)
        found, fix = "", ("name the ros2_control controllers file (each controller's "
                          "parameters under NAME: ros__parameters:)")
        if ros1:
            found = (f"a ROS 1 ros_control file ('{ros1}: type: ...' with no "
                     "ros__parameters), which ros2_control does not read; ")
            fix = ("check ROS 2 controllers files only, or port this one: each controller's "
                   "parameters under NAME: ros__parameters:")
        elif get(root, "controller_list") is not None:
            found = ("a MoveIt controller_list (moveit_simple_controller_manager's), which "
                     "names controllers for MoveIt and configures none; ")
        return Issue("SB601", f"{found}no controller sections (NAME: ros__parameters: ...) "
                     "found", where=(display, 1, 1), fix=fix)
    if not controller_types(sections) and not any(
            get(section, key) is not None for found in sections.values() for section in found
            for key in JOINT_KEYS):
        names = ", ".join(sorted(sections)[:3]) + (", ..." if len(sections) > 3 else "")
        return Issue("SB601", f"no controller here: its sections ({names}) give no controller "
                     "type and name no joint (a node's parameters?); nothing was checked",
                     where=(display, 1, 1), severity=Severity.INFO,
                     fix="name the ros2_control controllers file")
    return sections


def _composed(text: str) -> yaml.Node | None:
    """The YAML node tree of ``text``; several documents (``---``) as one, as rcl reads them."""
    try:
        return yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.composer.ComposerError as exc:
        if "expected a single document" not in str(exc):
            raise
    documents = [d for d in yaml.compose_all(text, Loader=yaml.SafeLoader) if d is not None]
    if not all(isinstance(d, yaml.MappingNode) for d in documents):
        raise yaml.YAMLError("several documents that are not all mappings")
    return yaml.MappingNode(documents[0].tag, [pair for d in documents for pair in d.value],
                            documents[0].start_mark, documents[-1].end_mark)


def file_issues(text: str, display: str) -> list[Issue]:
    """SB601 for what rcl makes of the file itself, which the checks of its content go past.

    rcl refuses aliases (``*name``, "Will not support aliasing"), keys that are lists or
    mappings and values outside every node's ``ros__parameters`` (:mod:`.rcl_layout`); it
    reads several documents as one file, which the controller spawner's ``--param-file``
    (``yaml.safe_load``) refuses.
    """
    issues: list[Issue] = []
    try:
        events = list(yaml.parse(text, Loader=yaml.SafeLoader))
    except yaml.YAMLError:
        return issues  # sections() says it is not YAML
    alias = next((e for e in events if isinstance(e, yaml.AliasEvent)), None)
    if alias is not None:
        template = "${" in text  # launch_pal's parse_parametric_yaml rewrites it, aliases out
        issues.append(Issue("SB601", f"an alias (*{alias.anchor}): rcl refuses the whole file "
                            "('Will not support aliasing'), so ros2_control_node cannot load it"
                            + (" unless a launch file rewrites this template first (launch_pal's "
                               "parse_parametric_yaml writes the values out)" if template else ""),
                            where=at(display, alias.start_mark),
                            severity=Severity.WARNING if template else None,
                            fix="write the values out where the alias stands"))
    misplaced = layout_issue(events, display) if alias is None else None
    if misplaced is not None:
        issues.append(misplaced)
    starts = [e for e in events if isinstance(e, yaml.DocumentStartEvent)]
    if len(starts) > 1:
        issues.append(Issue("SB601", f"{len(starts)} YAML documents (---): rcl reads them as "
                            "one file, the controller spawner's --param-file refuses it",
                            where=at(display, starts[1].start_mark), severity=Severity.WARNING,
                            fix="keep one document"))
    root = _composed(text)
    # a misspelled ros__parameters is sections()'s own answer: checks of content never follow
    issues += [i for i in (_key_not_a_name(root, display), _key_twice(root, display))
               if i is not None]
    return issues


def _key_twice(root: yaml.Node | None, display: str) -> Issue | None:
    """SB601 (a warning) for the first parameter written twice in one mapping.

    rcl keeps the last value of a parameter; a node or namespace key written twice
    (``/**`` twice) is one node, whose blocks rcl reads both.
    """
    parameters = [value for node in _nodes(root) if isinstance(node, yaml.MappingNode)
                  for key, value in node.value
                  if isinstance(key, yaml.ScalarNode) and key.value == "ros__parameters"]
    for node in (inner for block in parameters for inner in _nodes(block)):
        if isinstance(node, yaml.MappingNode):
            first: dict[str, yaml.Node] = {}
            for key, _ in node.value:
                if not isinstance(key, yaml.ScalarNode):
                    continue
                if key.value in first and key.value != "<<":
                    return Issue("SB601", f"'{key.value}' is written twice in one mapping "
                                 f"(first at line {first[key.value].start_mark.line + 1}): rcl "
                                 "keeps the values of the last one",
                                 where=at(display, key.start_mark),
                                 severity=Severity.WARNING, fix="keep one of the two")
                first.setdefault(str(key.value), key)
    return None


def _nodes(root: yaml.Node | None) -> Iterator[yaml.Node]:
    """Every node under ``root``, each once (an alias's target too), parents first."""
    stack, seen = [root], set()
    while stack:
        node = stack.pop()
        if node is None or id(node) in seen:
            continue
        seen.add(id(node))
        yield node
        if isinstance(node, yaml.MappingNode):
            stack.extend(value for _, value in reversed(node.value))
        elif isinstance(node, yaml.SequenceNode):
            stack.extend(reversed(node.value))


def _misspelled_parameters(root: yaml.Node | None, display: str) -> Issue | None:
    near = _near_ros_parameters(root)
    if near is None:
        return None
    return Issue("SB601", f"'{near.value}' is not ros__parameters (two underscores): rcl does "
                 "not read what it holds as the node's parameters (and refuses the file where "
                 "a list sits under it)", where=at(display, near.start_mark),
                 fix="ros__parameters:")


def _key_not_a_name(root: yaml.Node | None, display: str) -> Issue | None:
    key = _collection_key(root)
    if key is None:
        return None
    return Issue("SB601", "a list or mapping used as a key: rcl refuses the whole file",
                 where=at(display, key.start_mark), fix="write each parameter under a name")


def _near_ros_parameters(root: yaml.Node | None, depth: int = 0) -> yaml.ScalarNode | None:
    """A key a node's parameters are meant under, misspelled (``ros_parameters``)."""
    if not isinstance(root, yaml.MappingNode) or depth > _NAMESPACE_DEPTH + 1:
        return None
    for key, value in root.value:
        if not isinstance(key, yaml.ScalarNode) or key.value == "ros__parameters":
            continue
        squeezed = str(key.value).lower().replace("_", "").replace("-", "")
        if squeezed in ("rosparameters", "rosparams", "rosparameter", "rosparam") or (
                squeezed.startswith("ros") and difflib.SequenceMatcher(
                    None, squeezed, "rosparameters").ratio() >= 0.85):  # ros__paramters
            return key
        found = _near_ros_parameters(value, depth + 1)
        if found is not None:
            return found
    return None


def _collection_key(root: yaml.Node | None) -> yaml.Node | None:
    """The first key of a mapping under ``root`` that is a list or a mapping, if any."""
    return next((key for node in _nodes(root) if isinstance(node, yaml.MappingNode)
                 for key, _ in node.value if not isinstance(key, yaml.ScalarNode)), None)


def at(display: str, mark: yaml.Mark) -> tuple[str, int, int]:
    """``(file, line, column)`` of a YAML position, 1-based."""
    return (display, mark.line + 1, mark.column + 1)


JOINT_KEYS = (
    "left_wheel_names", "right_wheel_names", "joints", "joint",
    # steering_controllers_library (Ackermann, bicycle, tricycle steering): Jazzy, Humble
    "traction_joints_names", "steering_joints_names", "rear_wheels_names", "front_wheels_names",
    "traction_joint_name", "steering_joint_name",  # tricycle_controller
    "wheel_names",  # omni_wheel_drive_controller
    *(f"{corner}_wheel_command_joint_name" for corner in (  # mecanum_drive_controller
        "front_left", "front_right", "rear_left", "rear_right")),
)
"""The parameters of ros2_controllers that name URDF joints."""


def named_joints(found: Sections) -> list[str]:
    """Every joint name the controller sections ``found`` write (:data:`JOINT_KEYS`), once,
    in file order; launch substitutions left out.
    """  # noqa: D205
    names: dict[str, None] = {}
    for sections in found.values():
        for params in sections:
            for key in JOINT_KEYS:
                node = get(params, key)
                items = node.value if isinstance(node, yaml.SequenceNode) else [node]
                names.update((str(item.value), None) for item in items
                             if isinstance(item, yaml.ScalarNode) and str(item.value).strip()
                             and not substituted(str(item.value)))
    return list(names)


def _ros1_controllers(root: yaml.Node | None, depth: int = 0) -> str | None:
    """The first controller a ROS 1 file declares (``NAME: {type: pkg/Class}``), or None.

    Under a namespace too (op3_gazebo's ``robotis: joint_state_controller: type: ...``).
    """
    if not isinstance(root, yaml.MappingNode):
        return None
    for key, value in root.value:
        kind = get(value, "type")
        if isinstance(kind, yaml.ScalarNode) and "/" in str(kind.value):
            return str(key.value)
    for _, value in root.value if depth < 2 else ():
        found = _ros1_controllers(value, depth + 1)
        if found is not None:
            return found
    return None


def _sections(root: yaml.Node | None) -> Sections:
    """Each node's ``ros__parameters`` sections by node name, in file order.

    A node may sit under namespaces, as ROS 2 parameter files allow: ``/**:`` (any
    namespace, as irobot_create_control's ``control.yaml``) or ``robot1:`` above the node's
    own key. A node keyed by a path (``/robot1/controller_manager``) is named by its last part.
    One file may configure the same controller in several namespaces (ros2_control_demos'
    example 15: ``/rrbot_1/forward_position_controller`` and ``/rrbot_2/...``): each is kept,
    with what the ``/**`` sections of that node give it, as rcl merges them (its own values
    win).
    """
    found: Sections = {}
    for name, parts in _collect(root, 0, False).items():
        anywhere = [node for wild, node in parts if wild]
        own = [node for wild, node in parts if not wild]
        found[name] = [_merged([*anywhere, node]) for node in own] if anywhere and own \
            else [node for _, node in parts]
    return found


def _collect(root: yaml.Node | None, depth: int,
             wild: bool) -> dict[str, list[tuple[bool, yaml.MappingNode]]]:
    """:func:`_sections` before merging: each section, and whether a ``**`` key holds it."""
    found: dict[str, list[tuple[bool, yaml.MappingNode]]] = {}
    if not isinstance(root, yaml.MappingNode) or depth > _NAMESPACE_DEPTH:
        return found
    here: dict[str, int] = {}  # a key of this mapping written again: rcl merges, last wins
    for key, value in root.value:
        if not isinstance(key, yaml.ScalarNode):
            continue  # a list or mapping as a key: file_issues says rcl refuses it
        text = str(key.value)
        params = get(value, "ros__parameters")
        if isinstance(params, yaml.MappingNode):
            name = text.rstrip("/").rpartition("/")[2]
            sections = found.setdefault(name, [])
            if text in here:
                kept_wild, kept = sections[here[text]]
                merged = _merged([kept, params])
                merged.section_key = getattr(kept, "section_key", key)  # its first writing
                sections[here[text]] = (kept_wild, merged)
                continue
            here[text] = len(sections)
            params.section_key = key  # where its name is written: yaml nodes take attributes
            sections.append((wild or "**" in text, params))
        elif isinstance(value, yaml.MappingNode):
            for name, inner in _collect(value, depth + 1, wild or "**" in text).items():
                found.setdefault(name, []).extend(inner)
    return found


def _merged(nodes: list[yaml.MappingNode]) -> yaml.MappingNode:
    """One mapping of ``nodes``' entries, a later node's value winning for a key."""
    if len(nodes) == 1:
        return nodes[0]
    entries: dict[object, tuple[yaml.Node, yaml.Node]] = {}
    for node in nodes:
        for key, value in node.value:
            entries[key.value if isinstance(key, yaml.ScalarNode) else id(key)] = (key, value)
    last = nodes[-1]
    merged = yaml.MappingNode(last.tag, list(entries.values()), last.start_mark, last.end_mark)
    merged.section_key = getattr(last, "section_key", None)
    return merged


def named_at(section: yaml.MappingNode) -> yaml.Mark:
    """Where the name of a node's ``ros__parameters`` ``section`` is written (its key)."""
    key = getattr(section, "section_key", None)
    return key.start_mark if isinstance(key, yaml.Node) else section.start_mark


def controller_types(sections: Sections) -> dict[str, str]:
    """Each controller's ``type`` (``package/Class``), by controller name.

    Declared in ``controller_manager``'s parameters (nested, or as a dotted ``NAME.type``
    key: rcl flattens both to one parameter), or in the controller's own (ros2_control since
    Jazzy).
    """
    return {name: str(node.value) for name, node in type_nodes(sections).items()}


def type_nodes(sections: Sections) -> dict[str, yaml.ScalarNode]:
    """Where each controller's ``type`` is written (the last one rcl reads), by name."""
    types: dict[str, yaml.ScalarNode] = {}
    for manager in sections.get("controller_manager", []):
        # "NAME.type:" is the same parameter as "NAME: {type:}" (Clearpath's control.yaml);
        # a controller declared here needs no section of its own to have its type
        for key, value in manager.value:
            if not isinstance(key, yaml.ScalarNode):
                continue
            name, dotted = (str(key.value)[:-len(".type")], True) \
                if str(key.value).endswith(".type") else (str(key.value), False)
            node = value if dotted else get(value, "type")
            if isinstance(node, yaml.ScalarNode) and node.value and name:
                types.pop(name, None)  # the last one written is the one rcl reads
                types[name] = node
    for name, params in sections.items():
        for node in [get(section, "type") for section in params]:  # "/**/NAME": every namespace
            if isinstance(node, yaml.ScalarNode) and node.value:
                types[name] = node
    return types


def get(node: yaml.Node | None, key: str) -> yaml.Node | None:
    """The value of ``key`` in the mapping ``node``; None when it is not one, or has none.

    A key written twice has its last value, as rcl reads it.
    """
    found = None
    if isinstance(node, yaml.MappingNode):
        for k, v in node.value:
            if isinstance(k, yaml.ScalarNode) and k.value == key:
                found = v
    return found
