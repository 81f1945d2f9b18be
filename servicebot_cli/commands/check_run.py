"""What ``servicebot check`` does between parsing and rendering: settings, files, output.

Imported by the check callbacks only (it loads the rules and numpy).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import click

from servicebot_cli.check import files
from servicebot_cli.check.env import CheckEnv
from servicebot_cli.check.findings import Issue
from servicebot_cli.check.result import CheckResult
from servicebot_cli.check.runner import FileReport, check_source, place_issues
from servicebot_cli.check.settings import Settings, find_pyproject, load_settings
from servicebot_cli.commands.options import RobotArgs, split_robot_args
from servicebot_cli.common.errors import DescriptionError, ExitCode
from servicebot_cli.description.loader import RobotSource, read_description
from servicebot_cli.description.packages import PackageResolver
from servicebot_cli.description.resources import (
    BUNDLED_ROBOTS,
    CONTROLLERS_YAML,
    DEFAULT_ROBOT,
    bundled_file,
)


def settings_for(report: dict[str, Any]) -> Settings:
    """The settings file (unless --isolated), then the command-line options over it."""
    path = None
    if not report["isolated"]:
        path = Path(report["config"]) if report["config"] else find_pyproject(Path.cwd())
    return load_settings(path).with_options(report["select"], report["ignore"], report["strict"])


def _env(packages: tuple[tuple[str, str], ...], settings: Settings) -> CheckEnv:
    resolver = PackageResolver.from_environment({k: Path(v) for k, v in packages})
    return CheckEnv(resolver=resolver, inertia_factor=settings.inertia_factor)


def _sources(robot_args: RobotArgs) -> list[tuple[RobotSource, bool]]:
    """Each source to check, and whether the user named it (else it was found in a directory)."""
    if not robot_args.files:
        return [(robot_args.source(), True)]
    if robot_args.bundled:
        raise click.UsageError(f"give FILEs or --robot {robot_args.bundled}, not both")
    found: list[tuple[RobotSource, bool]] = []
    for name in robot_args.files:
        path = Path(name)
        if not path.is_dir():
            found.append((RobotSource.of(name, xacro_args=robot_args.xacro_args,
                                         packages=robot_args.packages), True))
            continue
        inside = list(files.walk(path))
        if not inside:
            raise DescriptionError(f"{name}: is a directory with no robot files "
                                   f"({', '.join('*' + s for s in files.SUFFIXES)})")
        for file in inside:
            args = robot_args.xacro_args if file.suffix == ".xacro" else ()
            found.append((RobotSource.of(file, xacro_args=args, packages=robot_args.packages),
                          False))
    return found


def check_urdf_files(robot_args: RobotArgs, settings: Settings) -> CheckResult:
    """Check every description the arguments name."""
    env = _env(robot_args.packages, settings)
    reports = []
    for source, named in _sources(robot_args):
        try:
            reports.append(check_source(source, settings, env))
        except DescriptionError as exc:
            if named:
                raise
            issue = Issue("SB001", str(exc).split(": ", 1)[-1], where=(source.display, 0, 0))
            reports.append(FileReport(source.display, tuple(place_issues(None, [issue],
                                                                         settings))))
    return CheckResult(tuple(reports), settings.strict)


def check_controller_files(values: tuple[str, ...], urdfs: tuple[str, ...], bundled: str | None,
                           packages: tuple[tuple[str, str], ...],
                           settings: Settings) -> CheckResult:
    """Check a controllers YAML against each URDF."""
    from servicebot_cli.check import controllers
    from servicebot_cli.common.inputs import display_path, read_input_text

    yaml_files, xacro_args = split_robot_args(values)
    if len(yaml_files) > 1:
        raise click.UsageError(f"one controllers YAML at a time, got {len(yaml_files)}")
    if urdfs and bundled:
        raise click.UsageError(f"give --urdf or --robot {bundled}, not both")
    yaml_path = Path(yaml_files[0]) if yaml_files else bundled_file(CONTROLLERS_YAML)
    display = yaml_files[0] if yaml_files else display_path(yaml_path)
    text = read_input_text(str(yaml_path), kind="a ros2_control controllers YAML",
                           error=DescriptionError)
    sources = [RobotSource.of(u, xacro_args=xacro_args, packages=packages) for u in urdfs]
    if not urdfs:
        if xacro_args:
            raise click.UsageError("xacro arguments need a xacro --urdf FILE")
        sources = [RobotSource.bundled(name) for name in ([bundled] if bundled else BUNDLED_ROBOTS)]
    reports = []
    for source in sources:
        robot = read_description(source)
        issues = controllers.check(text, display, robot)
        reports.append(FileReport(f"{display} against {source.display}",
                                  tuple(place_issues(robot, issues, settings))))
    return CheckResult(tuple(reports), settings.strict)


def emit(result: CheckResult, fmt: str, output: str) -> None:
    """Render ``result`` to stdout or ``output`` (atomically); exit 1 when it fails."""
    from servicebot_cli.common.files import atomic_output
    from servicebot_cli.output import findings, junit, sarif

    to_stdout = output == "-"
    if fmt == "text":
        text = "\n".join(findings.text_lines(result, colour=to_stdout)) + "\n"
    elif fmt == "github":
        text = "\n".join(findings.github_lines(result)) + "\n"
    else:
        render = {"json": findings.json_text, "sarif": sarif.sarif_text, "junit": junit.junit_text}
        text = render[fmt](result)
    if to_stdout:
        click.echo(text, nl=False)
    else:
        with atomic_output(output) as handle:
            handle.write(click.unstyle(text))
        click.echo(result.summary(), err=True)
    if result.failed:
        raise click.exceptions.Exit(ExitCode.FAILED)


__all__ = ["DEFAULT_ROBOT"]
