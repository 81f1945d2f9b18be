"""The ros2_control controllers a description is used with, from their YAML file.

A URDF does not say which controllers run, but the controller configuration does. It is
found, in this order: the file given with ``--controllers``, the ``<parameters>`` of a
``gazebo_ros2_control`` or ``gz_ros2_control`` plugin (relative to the description; several
are merged as ROS merges ``--params-file`` arguments, later values winning),
``controllers.yaml`` beside the description. The topics each known controller type offers
are documented ROS 2 Humble behaviour, written down here once.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.common.inputs import display_path
from servicebot_cli.description.parameter_files import merged_parameters, parameter_files
from servicebot_cli.description.ros_parameters import (
    controller_types,
    node_parameters,
    read_parameters_file,
)

DEFAULT_NAME = "controllers.yaml"


class ControllersError(DescriptionError):
    """A controller configuration that cannot be read or is not ros2_control YAML."""


@dataclass(frozen=True)
class Controller:
    """One controller: its name, plugin type and ``ros__parameters`` (not in JSON)."""

    name: str
    type: str
    params: dict[str, Any] = field(repr=False, compare=False)


@dataclass(frozen=True)
class Controllers:
    """A controller configuration.

    Attributes:
        file: Where it was read, as the user would type it.
        found_by: How it was found: ``--controllers``, ``gazebo_ros2_control`` or ``beside``.
        controllers: Every controller the controller manager lists, in file order.
    """

    file: str
    found_by: str
    controllers: tuple[Controller, ...]


def candidate_files(description: Path,
                    plugins: tuple[Any, ...]) -> list[tuple[tuple[Path, ...], str]]:
    """Where the controller configuration may be, best first, with how each was found.

    A ros2_control Gazebo plugin's ``<parameters>`` are one candidate, all its files
    together (:func:`~servicebot_cli.description.parameter_files.parameter_files`).

    Args:
        description: The description file (its directory anchors relative paths).
        plugins: The description's Gazebo plugins.
    """
    found: list[tuple[tuple[Path, ...], str]] = []
    named = parameter_files(plugins, description.parent)
    if named:
        found.append((named, "gazebo_ros2_control"))
    found.append(((description.parent / DEFAULT_NAME,), "beside"))
    return found


def read_controllers(path: Path, found_by: str) -> Controllers:
    """Read a ros2_control controller YAML file.

    Raises:
        ControllersError: Unreadable, not YAML, or without ``controller_manager``.
    """
    return read_controllers_files((path,), found_by)


def read_controllers_files(paths: tuple[Path, ...], found_by: str) -> Controllers:
    """Read ros2_control parameter files, later ones overriding earlier ones, as ROS does.

    Raises:
        ControllersError: One is unreadable or not YAML, or together they have no
            ``controller_manager``.
    """
    documents = [_document(path) for path in paths]
    document = documents[0] if len(documents) == 1 else merged_parameters(documents)
    return parse_controllers(document, " + ".join(display_path(p) for p in paths), found_by)


def _document(path: Path) -> Any:
    """One YAML file, parsed.

    Raises:
        ControllersError: Unreadable or not YAML.
    """
    return read_parameters_file(path, ControllersError)


def parse_controllers(document: Any, file: str, found_by: str) -> Controllers:
    """The controllers in a parsed YAML ``document``.

    Nodes and types are read as ros2_control reads them
    (:mod:`~servicebot_cli.description.ros_parameters`): under namespaces too, a type under
    ``controller_manager`` or in the controller's own ``ros__parameters``.

    Raises:
        ControllersError: No ``controller_manager: ros__parameters`` mapping and no
            controller that names its own type.
    """
    nodes = node_parameters(document)
    types = controller_types(nodes)
    if "controller_manager" not in nodes and not types:
        raise ControllersError(
            f"{file}: no 'controller_manager: ros__parameters:' mapping; is this a "
            "ros2_control controller configuration?"
        )
    controllers = [Controller(name, kind, nodes.get(name, {})) for name, kind in types.items()]
    return Controllers(file, found_by, tuple(controllers))


def find_controllers(description: Path, plugins: tuple[Any, ...],
                     explicit: Path | None = None) -> tuple[Controllers | None, tuple[str, ...]]:
    """The controller configuration for a description, and notes on what was not usable.

    Args:
        description: The description file.
        plugins: Its Gazebo plugins (``gazebo_ros2_control`` may name the file).
        explicit: The file given with ``--controllers``; its errors are raised, not noted.

    Raises:
        ControllersError: ``explicit`` cannot be read or is not a controller configuration.
    """
    if explicit is not None:
        return read_controllers(explicit, "--controllers"), ()
    notes = []
    for paths, found_by in candidate_files(description, plugins):
        missing = [path for path in paths if not os.path.isfile(path)]
        if found_by != "beside":
            notes += [f"gazebo_ros2_control names {path}, which does not exist"
                      for path in missing]
        present = tuple(path for path in paths if path not in missing)
        if not present:
            continue
        try:
            return read_controllers_files(present, found_by), tuple(notes)
        except ControllersError as exc:
            notes.append(str(exc))
    notes.append("no controller configuration found (looked for controllers.yaml beside "
                 "the description); give one with --controllers FILE")
    return None, tuple(notes)
