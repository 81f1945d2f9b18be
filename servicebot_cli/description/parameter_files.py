"""The parameter files a ros2_control Gazebo plugin loads, merged as ROS loads them.

gazebo_ros2_control (Gazebo Classic) and gz_ros2_control (gz-sim; ``ign_ros2_control`` in
Fortress) pass every ``<parameters>`` of their plugin, in document order, to the controller
manager's node as ``--params-file FILE`` arguments (``gazebo_ros2_control_plugin.cpp``,
``gz_ros2_control_plugin.cpp``: a loop over ``GetNextElement("parameters")``). rcl reads
the files in that order and a parameter a later file sets replaces the earlier value, each
parameter on its own: articubot_one's ``my_controllers.yaml`` names the controllers and
its ``use_sim.yaml`` adds ``use_sim_time`` to the same ``controller_manager`` node.

:func:`merged_parameters` gives one document in the layout of a single file, so what reads
one file (``inspect --controllers``, the simulator's controller) reads the merged set alike.
Pure but for :func:`parameter_files`' existence test.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

from servicebot_cli.description.extensions import Plugin, params_all
from servicebot_cli.description.install_layout import installed_source
from servicebot_cli.description.ros_parameters import node_parameters, overlaid

ROS2_CONTROL_PLUGINS = ("gazebo_ros2_control", "gz_ros2_control", "ign_ros2_control")
"""Names (in a plugin's file name or name) of the Gazebo plugins that run ros2_control."""


def is_ros2_control_plugin(plugin: Plugin) -> bool:
    """Whether ``plugin`` runs a ros2_control controller manager inside Gazebo."""
    return any(name in plugin.filename or name in plugin.name for name in ROS2_CONTROL_PLUGINS)


def parameter_files(plugins: Iterable[Plugin], directory: Path) -> tuple[Path, ...]:
    """Every ``<parameters>`` of the first ros2_control plugin that names one, in order.

    Relative paths are taken from ``directory`` (the description's); ``file://`` is dropped
    and ``~`` expanded; a path only the package's ``install(DIRECTORY)`` fills is its source
    file (:mod:`.install_layout`). Values still holding a ``$(...)`` substitution are left out: they
    name no file without the launch system.
    """
    for plugin in plugins:
        if not is_ros2_control_plugin(plugin):
            continue
        paths = [path for text in params_all(plugin.params, "parameters")
                 if (path := written_path(text)) is not None]
        if paths:  # a file the package's install(DIRECTORY) puts there: its source
            return tuple(Path(installed_source(str(p if p.is_absolute() else directory / p)))
                         for p in paths)
    return ()


def written_path(text: str | None) -> Path | None:
    """The path a ``<parameters>`` text names: ``file://`` dropped, ``~`` expanded; None for
    an empty one, or one still holding a ``$(...)`` substitution.
    """  # noqa: D205
    text = (text or "").strip()
    if not text or "$(" in text:
        return None
    return Path(text.removeprefix("file://")).expanduser()


def merged_parameters(documents: Sequence[Any]) -> dict[str, dict[str, Any]]:
    """The parameters of several files read in order, as one file's document.

    Each node's ``ros__parameters`` (:func:`~.ros_parameters.node_parameters`, by node name)
    are overlaid file by file: a parameter a later file sets replaces the earlier value, a
    group of parameters (a nested mapping) is overlaid key by key, and the others stay.
    Nodes keep the order in which they first appear.
    """
    merged: dict[str, dict[str, Any]] = {}
    for document in documents:
        for node, params in node_parameters(document).items():
            merged[node] = overlaid(merged.get(node, {}), params)
    return {node: {"ros__parameters": params} for node, params in merged.items()}
