"""The sweep file: which scenario, which seeds, which values, what to expect of every run.

A sweep file is YAML or JSON, read with the line of every value, so a bad field is one error
naming the file, the line and the field (as scenario files are)::

    scenario: default            # a scenario file (relative to this file) or the built-in one
    seeds: 10                    # 0..9, or a list of seeds
    set: {duration_s: 60}        # optional: one value for every run
    grid:                        # every combination of these values
      slip.track_factor: [0.9, 1.0, 1.1]
    sample:                      # optional: n random draws, the same for every grid point
      n: 20
      seed: 0                    # the draws' own seed (default 0)
      initial_pose.yaw_rad: {uniform: [-3.14, 3.14]}
      controller.saturation: {choice: [keep-curvature, per-wheel]}
    expect:                      # per run, over the summary's fields
      - collisions == 0
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path as FsPath

from servicebot_cli.common.inputs import read_input_text
from servicebot_cli.simulate.scenario.fields import FieldPathError, parse_field
from servicebot_cli.simulate.scenario.located import Located, Path, ScenarioError, Value, parse
from servicebot_cli.simulate.scenario.schema import Reader

MAX_SWEEP_BYTES = 1_000_000
MAX_RUNS = 100_000
DISTRIBUTIONS = ("uniform", "choice")


class SweepError(ScenarioError):
    """A sweep file that cannot be read or has a bad field; names the file and line."""


@dataclass(frozen=True)
class Setting:
    """Values for one scenario field, as written in the sweep file.

    Attributes:
        name: The field as written, e.g. ``slip.track_factor``.
        path: The field as a path into the scenario document.
        where: Path of its value(s) in the sweep file, for lines in messages.
        values: The grid's values; one value for ``set``; the distribution's arguments for
            ``sample`` (two bounds for ``uniform``, the choices for ``choice``).
        distribution: ``uniform`` or ``choice`` for ``sample``, empty otherwise.
    """

    name: str
    path: Path
    where: Path
    values: tuple[Value, ...]
    distribution: str = ""


@dataclass(frozen=True)
class Expectation:
    """One ``expect`` line: its text and where it was written."""

    text: str
    where: Path


@dataclass(frozen=True)
class SweepDefinition:
    """A whole sweep file, checked field by field (not yet against the scenario).

    Attributes:
        scenario_file: The scenario, relative to the current directory; None: built-in.
        seeds: The noise seeds every combination runs with.
        fixed: ``set``: one value per field for every run.
        grid: One setting per grid axis, in file order.
        draws: ``sample``'s fields, in file order.
        sample_n: How many draws (0 without ``sample``).
        sample_seed: Seed of the draws.
        expectations: ``expect``, in file order.
        located: The file as read, for errors with lines.
    """

    scenario_file: str | None
    seeds: tuple[int, ...]
    fixed: tuple[Setting, ...]
    grid: tuple[Setting, ...]
    draws: tuple[Setting, ...]
    sample_n: int
    sample_seed: int
    expectations: tuple[Expectation, ...]
    located: Located

    @property
    def run_count(self) -> int:
        """Grid points x draws x seeds."""
        points = 1
        for axis in self.grid:
            points *= len(axis.values)
        return points * max(self.sample_n, 1) * len(self.seeds)

    def error(self, where: Path, message: str) -> SweepError:
        """``file:line: field: message``."""
        return SweepError(str(self.located.error(where, message)))


def load_sweep(path: str) -> SweepDefinition:
    """Read and check a sweep file (``.json`` is JSON, anything else YAML).

    Raises:
        SweepError: Unreadable, not well-formed, or a bad field (with file and line).
    """
    text = read_input_text(path, kind="a sweep file (YAML or JSON)", error=SweepError,
                           max_bytes=MAX_SWEEP_BYTES)
    try:
        located = parse(text, path, json_syntax=path.lower().endswith(".json"))
    except ScenarioError as exc:
        raise SweepError(str(exc)) from None
    try:
        return read_sweep(located, FsPath(path).parent)
    except ScenarioError as exc:
        raise SweepError(str(exc)) from None


_TOP = ("scenario", "seeds", "set", "grid", "sample", "expect")


def read_sweep(located: Located, base_dir: FsPath) -> SweepDefinition:
    """The sweep in a parsed document; ``scenario`` is relative to ``base_dir``.

    Raises:
        ScenarioError: The first bad field, with its line.
    """
    _refuse_empty(located)
    r = Reader(located)
    r.mapping((), _TOP)
    scenario = r.string(("scenario",), "default")
    draws, n, sample_seed = _sample(r)
    definition = SweepDefinition(
        scenario_file=None if scenario == "default" else str(base_dir / scenario),
        seeds=_seeds(r), fixed=_fixed(r), grid=_grid(r), draws=draws, sample_n=n,
        sample_seed=sample_seed, expectations=_expectations(r), located=located)
    _refuse_overlaps(r, (*definition.fixed, *definition.grid, *definition.draws))
    if definition.run_count > MAX_RUNS:
        raise SweepError(f"{located.where(())}: {definition.run_count} runs is over the limit "
                         f"of {MAX_RUNS}; use fewer seeds, grid values or draws")
    return definition


def _refuse_empty(located: Located) -> None:
    """A sweep file must be a mapping, and one that says something (not the default run)."""
    value = located.value
    if isinstance(value, dict) and value:
        return
    got = "nothing" if value in ({}, None) else "a list" if isinstance(value, list) \
        else repr(value)
    raise SweepError(f"{located.where(())}: expected a sweep, a mapping of "
                     f"{', '.join(_TOP)}, got {got}; e.g. 'seeds: 10' runs the default "
                     "scenario with seeds 0 to 9")


def _seeds(r: Reader) -> tuple[int, ...]:
    path: Path = ("seeds",)
    if not r.has(path):
        return (0,)
    value = r.get(path)
    if isinstance(value, list):
        seeds = r.items(path, lambda p: _integer(r, p, "a seed", maximum=2**63 - 1))
        if not seeds:
            raise r.error(path, "an empty list; give at least one seed")
        if len(set(seeds)) != len(seeds):
            raise r.error(path, "a seed is given twice; give each once")
        return seeds
    return tuple(range(_integer(r, path, "a count of seeds", minimum=1, maximum=MAX_RUNS)))


def _integer(r: Reader, path: Path, what: str, *, minimum: int = 0,
             maximum: int = MAX_RUNS) -> int:
    value = r.get(path)
    if isinstance(value, bool) or not isinstance(value, int) \
            or not minimum <= value <= maximum:
        raise r.error(path, f"expected {what}: an integer from {minimum} to {maximum}, "
                      f"got {value!r}")
    return value


def _field(r: Reader, where: Path, name: str) -> Path:
    try:
        return parse_field(name)
    except FieldPathError as exc:
        raise r.error(where, str(exc)) from None


def _keys(r: Reader, path: Path) -> list[str]:
    value = r.get(path)
    if not isinstance(value, dict):
        raise r.error(path, "expected a mapping of scenario fields, e.g. slip.track_factor")
    return list(value)


def _fixed(r: Reader) -> tuple[Setting, ...]:
    if not r.has(("set",)):
        return ()
    return tuple(Setting(name, _field(r, ("set", name), name), ("set", name),
                         (r.get(("set", name)),)) for name in _keys(r, ("set",)))


def _grid(r: Reader) -> tuple[Setting, ...]:
    if not r.has(("grid",)):
        return ()
    axes = []
    for name in _keys(r, ("grid",)):
        where: Path = ("grid", name)
        values = r.get(where)
        if not isinstance(values, list) or not values:
            raise r.error(where, "expected a non-empty list of values")
        if len({repr(v) for v in values}) != len(values):
            raise r.error(where, "a value is given twice; give each once")
        axes.append(Setting(name, _field(r, where, name), where, tuple(values)))
    return tuple(axes)


def _sample(r: Reader) -> tuple[tuple[Setting, ...], int, int]:
    if not r.has(("sample",)):
        return (), 0, 0
    names = [k for k in _keys(r, ("sample",)) if k not in ("n", "seed")]
    if not r.has(("sample", "n")):
        raise r.error(("sample",), "'n' is required: how many random draws")
    n = _integer(r, ("sample", "n"), "a number of draws", minimum=1)
    seed = _integer(r, ("sample", "seed"), "a seed", maximum=2**63 - 1) \
        if r.has(("sample", "seed")) else 0
    if not names:
        raise r.error(("sample",), "no field to draw; add one, e.g. "
                      "initial_pose.yaw_rad: {uniform: [-3.14, 3.14]}")
    return tuple(_draw(r, name) for name in names), n, seed


def _draw(r: Reader, name: str) -> Setting:
    where: Path = ("sample", name)
    spec = r.get(where)
    if not isinstance(spec, dict) or len(spec) != 1 or next(iter(spec)) not in DISTRIBUTIONS:
        raise r.error(where, "expected {uniform: [LOW, HIGH]} or {choice: [A, B, ...]}")
    kind = next(iter(spec))
    if kind == "uniform":
        low, high = r.vector((*where, kind), 2)
        if not low < high:
            raise r.error((*where, kind), f"LOW {low:g} must be below HIGH {high:g}")
        return Setting(name, _field(r, where, name), where, (low, high), kind)
    choices = spec[kind]
    if not isinstance(choices, list) or not choices:
        raise r.error((*where, kind), "expected a non-empty list of values")
    return Setting(name, _field(r, where, name), where, tuple(choices), kind)


def _expectations(r: Reader) -> tuple[Expectation, ...]:
    return r.items(("expect",), lambda p: Expectation(r.string(p), p))


def _refuse_overlaps(r: Reader, settings: tuple[Setting, ...]) -> None:
    """A field set in two places, or inside another set field, would be ambiguous."""
    for i, a in enumerate(settings):
        for b in settings[:i]:
            if a.path[:len(b.path)] == b.path or b.path[:len(a.path)] == a.path:
                raise r.error(a.where, f"'{a.name}' overlaps '{b.name}' (line "
                              f"{r.located.where(b.where).rsplit(':', 1)[-1]}); set each "
                              "field in one place")
