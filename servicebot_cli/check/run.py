"""One run of ``servicebot check``: a request in, every file's findings out.

Click-free: the command turns its options into a :class:`CheckRequest`, calls :func:`run`
and hands the :class:`~servicebot_cli.check.result.CheckResult` to ``output/findings``.
Problems with the command line itself (two YAMLs, FILEs and ``--robot`` together) are
refused by the command before a request is made.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from servicebot_cli.check import files, model_ahead, workers
from servicebot_cli.check.findings import Finding, Issue
from servicebot_cli.check.result import CheckResult
from servicebot_cli.check.runner import FileReport, place_issues
from servicebot_cli.check.settings import Settings, find_pyproject, load_settings
from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.common.listing import some_of
from servicebot_cli.description.loader import RobotSource, read_description
from servicebot_cli.description.resources import BUNDLED_ROBOTS, CONTROLLERS_YAML, bundled_file
from servicebot_cli.description.robot import is_xacro_name

if TYPE_CHECKING:
    from servicebot_cli.check.controller_sections import Sections
    from servicebot_cli.description.robot import RobotDescription


@dataclass(frozen=True)
class SettingsChoice:
    """Where the settings come from, and the command-line options over them.

    Attributes:
        select: ``--select`` codes or prefixes (empty: the settings' own).
        ignore: ``--ignore`` codes or prefixes, added to the settings' own.
        strict: ``--strict``/``--no-strict``, or None for the settings' own.
        config: A pyproject.toml to read instead of the nearest one.
        isolated: Read no pyproject.toml at all.
        cwd: Where the search for the nearest pyproject.toml starts.
    """

    select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()
    strict: bool | None = None
    config: Path | None = None
    isolated: bool = False
    cwd: Path = Path(".")


@dataclass(frozen=True)
class UrdfTargets:
    """``check urdf``: description files and directories of them.

    Attributes:
        paths: Files and directories, as given; empty means :attr:`default`.
        xacro_args: ``name:=value`` pairs for every xacro file.
        packages: ``--package NAME=DIR`` pairs.
        default: The description checked when no path is given.
        jobs: Worker processes for several files; None: one per available core.
        mesh_cache: Where mesh summaries are kept between runs; None: not kept.
    """

    paths: tuple[str, ...] = ()
    xacro_args: tuple[tuple[str, str], ...] = ()
    packages: tuple[tuple[str, str], ...] = ()
    default: RobotSource | None = None
    jobs: int | None = None
    mesh_cache: Path | None = None


@dataclass(frozen=True)
class ControllerTargets:
    """``check controllers``: one controllers YAML against one or more URDFs.

    Attributes:
        yaml_file: The YAML as given, or None for the bundled ``controllers.yaml``.
        urdfs: Descriptions to check it against; empty means both bundled robots.
        spawned: The controllers checked against them (those a launch spawns); empty means
            every controller of the file.
    """

    yaml_file: str | None = None
    urdfs: tuple[RobotSource, ...] = ()
    spawned: tuple[str, ...] = ()


@dataclass(frozen=True)
class CheckRequest:
    """What to check and with which settings."""

    targets: UrdfTargets | ControllerTargets
    settings: SettingsChoice = SettingsChoice()


def settings_of(choice: SettingsChoice) -> Settings:
    """The settings file (unless ``isolated``), then the command-line options over it.

    Raises:
        SettingsError: An unreadable settings file or an unknown rule code.
    """
    path = None
    if not choice.isolated:
        path = choice.config or find_pyproject(choice.cwd.resolve())
    return load_settings(path).with_options(choice.select, choice.ignore, choice.strict)


def run(request: CheckRequest) -> CheckResult:
    """Check what ``request`` names; every finding is collected, none raised.

    Raises:
        SettingsError: Bad settings (exit 2).
        DescriptionError: A file the user named cannot be read at all (exit 2).
    """
    settings = settings_of(request.settings)
    if not isinstance(request.targets, UrdfTargets):
        return CheckResult(tuple(_check_controllers(request.targets, settings)), settings.strict)
    sources, includes_only, left_out = _sources(request.targets)
    reports = _check_urdfs(sources, request.targets, settings)
    unexpanded = {report.file for report, (_, named) in zip(reports, sources, strict=True)
                  if not named and any(f.code in _NOT_EXPANDED for f in report.findings)}
    alone = [_walked(path, request.targets) for path, by in left_out.items()
             if by and {str(includer) for includer in by} <= unexpanded]
    reports += [report for report in _check_urdfs(alone, request.targets, settings)
                if not any(_no_robot_alone(f) for f in report.findings)]
    return CheckResult(tuple(reports), settings.strict, includes_only)


def _no_robot_alone(finding: Finding) -> bool:
    """Whether a file its includers could not expand is, by ``finding``, no robot alone.

    A part that hangs from links of the robot including it (stretch's aruco markers) gets
    SB103 on those parents; a file of constants (unitree's const.xacro, properties and an
    include) gets SB109; a part that reads its includer's properties (TIAGo's
    gazebo.urdf.xacro: 'is_multiple', where a package its includer needs is missing) gets
    SB006 for a name not defined. A whole robot (andino) gets none, and is checked alone.
    """
    return finding.code == "SB109" or (finding.code == "SB103"
                                        and " has parent link '" in finding.message) or (
        finding.code == "SB006" and " is not defined" in finding.message)


_NOT_EXPANDED = ("SB001", "SB006", "SB007")  # an include missing, xacro failed, no package


def _walked(file: Path, targets: UrdfTargets) -> tuple[RobotSource, bool]:
    """A file a directory walk found, as a source to check."""
    args = targets.xacro_args if is_xacro_name(file) else ()
    return RobotSource(file, str(file), args, targets.packages), False


def _sources(targets: UrdfTargets) -> tuple[list[tuple[RobotSource, bool]],
                                            tuple[tuple[str, int], ...], dict[Path, set[Path]]]:
    """Each source to check, and whether the user named it (else it was found in a directory).

    Also each named directory that holds only xacro includes, with how many; and each named
    robot a walk left out as an include, with the files that include it.
    """
    if not targets.paths:
        return [(targets.default or RobotSource.bundled(), True)], (), {}
    found: list[tuple[RobotSource, bool]] = []
    includes_only: list[tuple[str, int]] = []
    left_out: dict[Path, set[Path]] = {}
    for name in targets.paths:
        path = Path(name)
        if not os.path.isdir(path):
            found.append((RobotSource(path, name, targets.xacro_args, targets.packages), True))
            continue
        inside, parts = files.walk_robots(path)
        left_out.update(parts)
        if not inside:
            held = files.robot_file_count(path)
            if not held:
                semantic = files.semantic_file_count(path)
                raise DescriptionError(
                    f"{name}: is a directory with no robot files "
                    f"({', '.join('*' + s for s in files.SUFFIXES)})"
                    + (f"; its {semantic} *.srdf.xacro file(s) are MoveIt semantic "
                       "descriptions, not URDF" if semantic else ""))
            includes_only.append((name, held))
        found += [_walked(file, targets) for file in inside]
    return found, tuple(includes_only), left_out


def _check_urdfs(every: list[tuple[RobotSource, bool]], targets: UrdfTargets,
                 settings: Settings) -> list[FileReport]:
    """A report per description; a file found in a directory that cannot be read is SB001.

    A xacro include named on the command line gets its SB018 note instead of a check.
    """
    from servicebot_cli.check.named_includes import include_reports

    includes = include_reports(every, settings)
    sources = [source for index, source in enumerate(every) if index not in includes]
    checked = iter(_checked(sources, targets, settings))
    return [includes[index] if index in includes else next(checked)
            for index in range(len(every))]


def _checked(sources: list[tuple[RobotSource, bool]], targets: UrdfTargets,
             settings: Settings) -> list[FileReport]:
    """The report of each of ``sources``, checked serially or by worker processes."""
    if not sources:
        return []
    jobs = min(targets.jobs or workers.available_cores(), len(sources))
    if jobs > 1:
        outcomes: Iterable[workers.Outcome] = workers.check_in_workers(
            sources, settings, targets.packages, jobs, targets.mesh_cache)
    else:
        if len(sources) > 1:
            workers.collect_garbage_rarely()
        env = workers.env_for(targets.packages, settings, targets.mesh_cache)
        env.model_ahead = (len(sources) == 1 and targets.jobs != 1  # --jobs 1: one process
                           and model_ahead.worth_forking())
        outcomes = (workers.check_one(source, named, settings, env) for source, named in sources)
    return [workers.report_of(outcome, settings) for outcome in outcomes]


def _spawned(names: tuple[str, ...], found: Sections, display: str) -> frozenset[str] | None:
    """The controllers ``--spawned`` names, each one the file configures; None: every one.

    Raises:
        DescriptionError: A name the file neither declares nor configures.
    """
    if not names:
        return None
    from servicebot_cli.check.controller_sections import controller_types

    # a parameter wildcard section ('/**') configures every node: no controller's name
    known = {name for name in (set(found) | set(controller_types(found)))
             if "*" not in name} - {"controller_manager"}
    unknown = [name for name in names if name not in known]
    if unknown:
        raise DescriptionError(
            f"{display}: --spawned {', '.join(unknown)}: no such controller in the file "
            f"(it has: {', '.join(sorted(known)) or 'none'}); give the names the file gives")
    return frozenset(names)


def _plugin_parameters_file(robot: RobotDescription,
                            xacro_args: Sequence[tuple[str, str]] = ()) -> Path:
    """The controllers YAML of ``robot``: its ros2_control plugin's, else the one beside it.

    The file its Gazebo ros2_control plugin loads (``<parameters>``); without one,
    ``controllers.yaml`` beside the description, as simulate and inspect take it.

    Raises:
        DescriptionError: It names none that exists, or several: the user says which.
    """
    from servicebot_cli.description.parameter_files import parameter_files

    named = parameter_files(robot.plugins, robot.path.parent)
    present = [path for path in named if os.path.isfile(path)]
    beside = robot.path.parent / "controllers.yaml"
    if not named and os.path.isfile(beside):
        return beside
    if len(present) == 1:
        return present[0]
    usage = " ".join(["servicebot check controllers FILE.yaml --urdf", robot.display,
                      *(f"{name}:={value}" for name, value in xacro_args)])
    if present:
        raise DescriptionError(f"{robot.display}'s ros2_control plugin loads "
                               f"{len(present)} parameter files ({', '.join(map(str, present))})"
                               f": name the one to check: {usage}")
    said = (f"names {', '.join(map(str, named))}, which does not exist" if named else
            "names no controllers file (no Gazebo ros2_control plugin with <parameters>, no "
            "controllers.yaml beside it)")
    raise DescriptionError(f"{robot.display} {said}: give the controllers YAML: {usage}")


def _refuse_another_robots(found: Sections, display: str,
                           robots: Sequence[RobotDescription]) -> None:
    """Refuse a file naming joints, none of which the bundled robots have: another robot's.

    Checked against the bundled robots (no ``--urdf``), its every joint would be an error.

    Raises:
        DescriptionError: Saying to give the robot with ``--urdf``.
    """
    from servicebot_cli.check.controller_sections import named_joints

    named = named_joints(found)
    if not named:
        return
    joints = {joint.name for robot in robots for joint in robot.joints}
    if any(name in joints for name in named):
        return
    raise DescriptionError(
        f"{display} names none of the bundled robots' joints ({some_of(named, 3)}): it "
        f"configures another robot; give that robot: servicebot check controllers {display} "
        "--urdf ROBOT.urdf.xacro")


def _refuse_a_packages_file(yaml_path: Path, display: str) -> None:
    """Refuse a ROS package's controllers file given with no robot to check it against.

    A package's file configures that package's robot (husky_control's control.yaml: the
    same wheel joint names as the bundled robot, another wheel radius); judged against the
    bundled robots, its every number would be wrong.

    Raises:
        DescriptionError: Saying to give its robot, or a bundled one by name.
    """
    from servicebot_cli.description.package_dirs import holding_package

    holder = holding_package(yaml_path.resolve().parent)
    if holder is not None:
        raise DescriptionError(
            f"{display} belongs to package '{holder[0]}': give the robot it configures: servicebot "
            f"check controllers {display} --urdf ROBOT.urdf.xacro (or --robot sim|real for a "
            "bundled robot)")


def _check_controllers(targets: ControllerTargets, settings: Settings) -> list[FileReport]:
    """A report per URDF the controllers YAML is checked against."""
    from servicebot_cli.check import (
        controller_manager_params,
        controller_params,
        controller_sections,
        controllers,
    )
    from servicebot_cli.common.inputs import display_path, read_input_text
    from servicebot_cli.description.ros_parameters import MAX_PARAMETERS_BYTES
    from servicebot_cli.kinematics.mesh_wheels import file_points

    sources = targets.urdfs or tuple(RobotSource.bundled(name) for name in BUNDLED_ROBOTS)
    read: dict[int, RobotDescription] = {}

    def robot_of(index: int) -> RobotDescription:
        """Source ``index``'s description, read once."""
        if index not in read:
            read[index] = read_description(sources[index])
        return read[index]

    if targets.yaml_file:
        yaml_path, display = Path(targets.yaml_file), targets.yaml_file
    elif targets.urdfs:  # the user's robot: the file its Gazebo ros2_control plugin loads
        yaml_path = _plugin_parameters_file(robot_of(0), sources[0].xacro_args)
        display = display_path(yaml_path)
    else:
        yaml_path = bundled_file(CONTROLLERS_YAML)
        display = display_path(yaml_path)
    text = read_input_text(str(yaml_path), kind="a ros2_control controllers YAML",
                           error=DescriptionError, max_bytes=MAX_PARAMETERS_BYTES)
    found = controller_sections.sections(text, display)
    if isinstance(found, Issue):  # the YAML itself, the same against every robot: said once
        return [FileReport(display, tuple(place_issues(robot_of(0), [found], settings)))]
    if targets.yaml_file and not targets.urdfs:
        _refuse_another_robots(found, display, [robot_of(i) for i in range(len(sources))])
        _refuse_a_packages_file(yaml_path, display)
    spawned = _spawned(targets.spawned, found, display)
    reports = []
    whole_file = [*controller_sections.file_issues(text, display),  # said once, in the first
                  *controller_params.parameter_issues(found, display),
                  *controller_manager_params.manager_issues(found, display)]
    for index, source in enumerate(sources):
        robot = robot_of(index)
        issues = [*whole_file, *controllers.check(
            found, display, robot, file_points(source.resolver(), robot.path.parent), spawned)]
        whole_file = []
        reports.append(FileReport(f"{display} against {source.display}",
                                  tuple(place_issues(robot, issues, settings))))
    return reports
