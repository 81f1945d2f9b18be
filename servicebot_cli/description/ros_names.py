"""ROS 2 names of a gazebo_ros plugin's node: its namespace, name expansion and remapping.

gazebo_ros's ``Node::Get`` (``gazebo_ros/src/node.cpp``) names the node after the plugin's
``name`` attribute, puts it in ``<ros><namespace>`` (made absolute; ``/`` without one) and
hands rcl each ``<ros><argument>`` as a command-line argument, then ``--ros-args`` and
``-r RULE`` for each ``<ros><remapping>``. rcl (``arguments.c``, ``remap.c``) reads a bare
``match:=replacement`` argument as a remap rule in its deprecated form (still accepted);
after ``--ros-args`` a rule follows ``-r`` or ``--remap``. To resolve a topic name rcl
expands it to a fully qualified name (``/x`` as is, ``~/x`` under ``NAMESPACE/NODE``, ``x``
under ``NAMESPACE``); the first rule whose match, expanded alike, equals it wins (a rule
written ``node:match:=replacement`` counts only for that node), and its replacement is
expanded the same way. ``__ns:=`` and ``__node:=`` rules rename the node's namespace and name.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from servicebot_cli.description.extensions import Plugin, param, params_all
from servicebot_cli.description.parameter_files import is_ros2_control_plugin

Rule = tuple[str | None, str, str]
"""A remap rule: the node it is for (None: any), its match and its replacement."""


def _rule(text: str) -> Rule | None:
    """``[node:]match:=replacement``; None for anything else (rcl ignores it with a warning)."""
    left, sep, replacement = text.strip().partition(":=")
    if not sep or not left or not replacement or any(c.isspace() for c in text.strip()):
        return None
    node, colon, match = left.partition(":")
    return (node, match, replacement) if colon else (None, left, replacement)


def _argument_rules(arguments: tuple[str, ...]) -> list[Rule]:
    """The remap rules among the node's arguments, in order."""
    rules: list[Rule] = []
    ros_args = expect_rule = False
    for token in (a.strip() for a in arguments):
        if expect_rule:
            expect_rule = False
            rule = _rule(token)
        elif token == "--ros-args" or (ros_args and token == "--"):
            ros_args = token == "--ros-args"
            continue
        elif ros_args:
            expect_rule = token in ("-r", "--remap")
            continue
        else:
            rule = _rule(token)
        if rule is not None:
            rules.append(rule)
    return rules


@dataclass(frozen=True)
class PluginNode:
    """A gazebo_ros plugin's ROS 2 node.

    Attributes:
        name: The node's name (the plugin's ``name``, unless a ``__node:=`` rule renames it).
        namespace: Absolute, ``/`` at the root.
        rules: Its topic remap rules, in the order rcl tries them.
    """

    name: str
    namespace: str
    rules: tuple[Rule, ...]

    @classmethod
    def of(cls, plugin: Plugin) -> PluginNode:
        """The node gazebo_ros makes for ``plugin``."""
        namespace = (param(plugin.params, "ros/namespace") or "").strip()
        rules = _argument_rules(params_all(plugin.params, "ros/argument")) + [
            rule for text in params_all(plugin.params, "ros/remapping")
            if (rule := _rule(text)) is not None]
        renames = {match: replacement for node, match, replacement in reversed(rules)
                   if match in ("__node", "__ns") and node in (None, plugin.name)}
        name = renames.get("__node", plugin.name)  # the first rule for each wins, as in rcl
        namespace = "/" + renames.get("__ns", namespace).strip("/")
        topic_rules = tuple(rule for rule in rules if rule[1] not in ("__node", "__ns"))
        return cls(name, namespace, topic_rules)  # a node's own rules: by its new name

    def expand(self, name: str) -> str:
        """The fully qualified name of ``name`` in this node (``~/out`` -> ``/ns/node/out``)."""
        if name.startswith("/"):
            return name
        if name == "~" or name.startswith("~/"):
            name = f"{self.name}{name[1:]}"
        return f"{self.namespace.rstrip('/')}/{name}"

    def remapped(self, name: str) -> str | None:
        """The replacement, as written, of the first rule matching ``name``; None: no rule."""
        full = self.expand(name)
        return next((replacement for node, match, replacement in self.rules
                     if node in (None, self.name) and self.expand(match) == full), None)


def manager_node(plugins: Iterable[Plugin]) -> PluginNode | None:
    """The node of the first ros2_control Gazebo plugin, whose controllers share its names.

    gazebo_ros2_control and gz_ros2_control hand its ``<ros><namespace>`` (as ``__ns:=``)
    and ``<ros><remapping>`` rules to rcl for the whole process: every controller runs in
    that namespace, under those rules. None without such a plugin.
    """
    return next((PluginNode.of(plugin) for plugin in plugins if is_ros2_control_plugin(plugin)),
                None)


def controller_topic(manager: PluginNode | None, controller: str, topic: str) -> str:
    """The fully qualified, remapped name of ``topic`` of the controller node ``controller``.

    ``~/odom`` of ``diff_controller`` is ``/diff_controller/odom`` at the root, and
    ``/robot1/odom`` under a plugin in namespace ``robot1`` with ``~/odom:=odom``.
    """
    node = PluginNode(controller, manager.namespace if manager else "/",
                      manager.rules if manager else ())
    return node.expand(node.remapped(topic) or topic)
