"""Every run of a sweep, each with its scenario built and checked before the first one starts.

Runs are ordered grid point by grid point (the first axis varies slowest), then draw, then
seed. Each distinct scenario is read by the scenario reader with the swept values in place;
an error names the sweep file's line of the value that caused it.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import random
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path as FsPath

from servicebot_cli import __version__
from servicebot_cli.simulate.scenario.definition import Scenario, read_scenario
from servicebot_cli.simulate.scenario.fields import FieldPathError, with_values
from servicebot_cli.simulate.scenario.located import Located, Path, ScenarioError, Value
from servicebot_cli.sweep.definition import Setting, SweepDefinition, SweepError

Values = tuple[tuple[str, Value], ...]
"""Scenario fields, as written in the sweep file, and their values, in file order."""


@dataclass(frozen=True)
class Run:
    """One simulation of the sweep.

    Attributes:
        index: Position in the sweep's order.
        point: Index of its grid point.
        draw: Index of its random draw (0 without ``sample``).
        grid: The grid point's values.
        drawn: The draw's values.
        seed: The noise seed.
        scenario: The scenario with every value in place.
        key: Identity of the run over robot, scenario, values and seed (hex).
    """

    index: int
    point: int
    draw: int
    grid: Values
    drawn: Values
    seed: int
    scenario: Scenario
    key: str

    @property
    def values(self) -> Values:
        """Grid values, then drawn values."""
        return self.grid + self.drawn


def draws(definition: SweepDefinition) -> list[Values]:
    """``sample``'s draws, repeatable by its seed; one empty draw without ``sample``."""
    if not definition.sample_n:
        return [()]
    rng = random.Random(definition.sample_seed)
    result = []
    for _ in range(definition.sample_n):
        result.append(tuple((s.name, _draw(s, rng)) for s in definition.draws))
    return result


def _draw(setting: Setting, rng: random.Random) -> Value:
    if setting.distribution == "uniform":
        low, high = (float(v) for v in setting.values)  # type: ignore[arg-type]
        return low + (high - low) * rng.random()
    return setting.values[int(rng.random() * len(setting.values))]


def grid_points(definition: SweepDefinition) -> list[Values]:
    """Every combination of the grid's values, the first axis varying slowest."""
    axes = [[(axis.name, v) for v in axis.values] for axis in definition.grid]
    return [tuple(combination) for combination in itertools.product(*axes)]


def plan(definition: SweepDefinition, base: Scenario, robot_xml: str) -> list[Run]:
    """Every run, its scenario read and checked (not yet against the robot).

    Args:
        definition: The sweep.
        base: The scenario the values go into; ``base.source`` must be set.
        robot_xml: The robot's URDF text, part of each run's key.

    Raises:
        SweepError: A value the scenario refuses, naming the sweep file's line.
    """
    robot_hash = hashlib.sha256(robot_xml.encode()).hexdigest()
    fixed = tuple((s.name, s.values[0]) for s in definition.fixed)
    runs: list[Run] = []
    for point, grid in enumerate(grid_points(definition)):
        for draw, drawn in enumerate(draws(definition)):
            scenario = build_scenario(definition, base, fixed + grid + drawn)
            identity = _identity(scenario, robot_hash)
            first = len(runs)
            runs.extend(Run(first + i, point, draw, grid, drawn, seed, scenario,
                            _key(identity, seed)) for i, seed in enumerate(definition.seeds))
    return runs


@dataclass(frozen=True)
class SweptDocument(Located):
    """A scenario document with swept values: their lines are the sweep file's.

    Attributes:
        swept: The sweep file's line of each swept field, keyed by the field's path.
    """

    swept: Located = field(default_factory=lambda: Located({}, {}, ""))

    def where(self, path: Path) -> str:
        """``sweep.yaml:line`` within a swept field, the scenario's ``file:line`` elsewhere."""
        for end in range(len(path), 0, -1):
            if path[:end] in self.swept.positions:
                return self.swept.where(path[:end])
        return super().where(path)


def build_scenario(definition: SweepDefinition, base: Scenario, values: Values) -> Scenario:
    """``base`` with ``values`` in place, read (and so checked) by the scenario reader.

    Raises:
        SweepError: A path the document cannot take or a value the reader refuses, at the
            sweep file's line of that value.
    """
    settings = {s.name: s for s in (*definition.fixed, *definition.grid, *definition.draws)}
    located = definition.located
    positions: dict[Path, tuple[int, int]] = {}
    for name, value in values:
        setting = settings[name]
        where = setting.where
        if setting in definition.grid:
            where = (*where, setting.values.index(value))
        line = located.positions.get(where) or located.positions.get(setting.where, (0, 0))
        positions[setting.path] = line
    assert base.source is not None  # scenarios are loaded with their document
    try:
        document = with_values(base.source.value,
                               {settings[name].path: value for name, value in values})
    except FieldPathError as exc:
        name = next(n for n, _ in values if settings[n].path == exc.path)
        raise definition.error(settings[name].where, f"{exc}; the scenario has no such "
                               "field") from None
    try:
        return read_scenario(SweptDocument(document, base.source.positions, base.source.display,
                                           Located({}, positions, located.display)),
                             name=base.name,
                             cut_short=any(settings[n].path == ("duration_s",) for n, _ in values))
    except ScenarioError as exc:
        raise SweepError(f"{exc}{_context(values)}") from None


def _context(values: Values) -> str:
    """`` (with a=1, b=2)``: the combination a refused value came in."""
    if len(values) <= 1:
        return ""
    shown = ", ".join(f"{name}={_show(value)}" for name, value in values)
    return f" (with {shown})"


def _show(value: Value) -> str:
    return f"{value:g}" if isinstance(value, float) else json.dumps(value, default=str)


def _identity(scenario: Scenario, robot_hash: str) -> str:
    assert scenario.source is not None
    return json.dumps({"servicebot": __version__, "robot": robot_hash, "name": scenario.name,
                       "scenario": scenario.source.value}, sort_keys=True, default=str)


def _key(identity: str, seed: int) -> str:
    return hashlib.sha256(f"{identity}\nseed={seed}".encode()).hexdigest()[:20]


def scenario_dir(definition: SweepDefinition) -> FsPath:
    """Where the scenario's relative paths (meshes) start: its file's directory, or here."""
    file = definition.scenario_file
    return FsPath(file).parent if file else FsPath.cwd()


def distinct_scenarios(runs: Sequence[Run]) -> list[Run]:
    """The first run of each grid point and draw: one per distinct scenario."""
    seen: set[tuple[int, int]] = set()
    firsts = []
    for run in runs:
        if (run.point, run.draw) not in seen:
            seen.add((run.point, run.draw))
            firsts.append(run)
    return firsts
