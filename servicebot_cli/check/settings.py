"""Which rules run and how much they matter: defaults, pyproject.toml, the command line.

``[tool.servicebot.check]`` in the nearest ``pyproject.toml`` (searched from the current
directory up) sets the defaults; command-line options override them::

    [tool.servicebot.check]
    select = ["ALL"]            # codes or prefixes ("SB3" is every inertia rule)
    ignore = ["SB309"]
    strict = true               # warnings fail the run too
    inertia-factor = 2.0        # SB301 tolerance, as a ratio of principal moments
    severity = { SB304 = "error", SB112 = "info" }
"""

from __future__ import annotations

import math
import os
import sys
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from datetime import date, datetime, time
from pathlib import Path
from typing import TypeAlias

from servicebot_cli.check.catalogue import RULES, matches, rule, valid_pattern
from servicebot_cli.check.findings import Severity
from servicebot_cli.common.errors import ServicebotError
from servicebot_cli.common.inputs import read_input_text

MAX_SETTINGS_BYTES = 10_000_000
"""A settings file larger than this is not read [bytes] (a pyproject.toml is a few kB)."""
_KEYS = ("select", "ignore", "strict", "inertia-factor", "severity")

TomlValue: TypeAlias = (str | int | float | bool | date | datetime | time
                        | list["TomlValue"] | dict[str, "TomlValue"])
"""Any value a TOML document holds."""


class SettingsError(ServicebotError):
    """A ``[tool.servicebot.check]`` table or option that cannot be used (exit 2)."""


@dataclass(frozen=True)
class Settings:
    """The rules of one run.

    Attributes:
        select: Codes or prefixes to run (``ALL`` for every rule).
        ignore: Codes or prefixes not to run, even if selected.
        strict: Warnings fail the run too.
        inertia_factor: SB301 tolerance (a ratio > 1).
        severity: Per-rule severity overrides.
        source: Where the settings came from (a pyproject.toml), for messages.
    """

    select: tuple[str, ...] = ("ALL",)
    ignore: tuple[str, ...] = ()
    strict: bool = False
    inertia_factor: float = 2.0
    severity: Mapping[str, Severity] = field(default_factory=dict)
    source: str | None = None
    _enabled: dict[str, bool] = field(default_factory=dict, init=False, repr=False,
                                      compare=False)

    def enabled(self, code: str) -> bool:
        """True when rule ``code`` runs (worked out once per code: it is asked per finding)."""
        known = self._enabled.get(code)
        if known is None:
            chosen = "ALL" in (s.upper() for s in self.select) or matches(code, self.select)
            known = self._enabled[code] = chosen and not matches(code, self.ignore)
        return known

    def any_enabled(self, prefix: str) -> bool:
        """True when a rule whose code starts with ``prefix`` runs."""
        key = f"{prefix}*"  # kept beside the codes, which have no '*'
        known = self._enabled.get(key)
        if known is None:
            known = self._enabled[key] = any(self.enabled(code) for code in RULES
                                             if code.startswith(prefix))
        return known

    def severity_of(self, code: str) -> Severity:
        """The severity of ``code`` in this run."""
        return self.severity.get(code, RULES[code].severity)

    def fails(self, severity: Severity) -> bool:
        """True when a finding of ``severity`` fails the run."""
        return severity is Severity.ERROR or (self.strict and severity is Severity.WARNING)

    def with_options(self, select: tuple[str, ...], ignore: tuple[str, ...],
                     strict: bool | None) -> Settings:
        """These settings with command-line ``--select``/``--ignore``/``--strict`` applied."""
        select = tuple(_pattern(p, "--select") for p in select)
        ignore = tuple(_pattern(p, "--ignore") for p in ignore)
        return replace(
            self,
            select=select or self.select,
            ignore=(*self.ignore, *ignore),
            strict=self.strict if strict is None else strict,
        )


def find_pyproject(start: Path) -> Path | None:
    """The nearest ``pyproject.toml`` at or above ``start``."""
    for directory in (start, *start.parents):
        candidate = directory / "pyproject.toml"
        if os.path.isfile(candidate):
            return candidate
    return None


def load_settings(path: Path | None) -> Settings:
    """Settings from ``[tool.servicebot.check]`` of ``path`` (defaults when None or absent).

    Raises:
        SettingsError: Unreadable TOML, unknown keys, unknown codes, wrong types.
    """
    if path is None:
        return Settings()
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover - exercised on Python 3.10 only
        import tomli as tomllib
    text = read_input_text(str(path), kind="a pyproject.toml (--config FILE), or --isolated",
                           error=SettingsError, max_bytes=MAX_SETTINGS_BYTES)
    try:
        document = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SettingsError(f"{path}: cannot read settings: {exc}") from None
    ours = _child(_child(document, "tool"), "servicebot")
    others = sorted(set(ours) - {"check"})
    if others:  # [tool.servicebot] strict = true, [tool.servicebot.checks]: read by nobody
        raise SettingsError(f"{path}: [tool.servicebot] has '{others[0]}', which servicebot does "
                            "not read; its settings go in [tool.servicebot.check] (settings: "
                            f"{', '.join(_KEYS)})")
    table = ours.get("check")
    if table is None:
        return Settings()
    return _from_table(table, str(path))


def _child(table: dict[str, TomlValue], key: str) -> dict[str, TomlValue]:
    """The sub-table ``key`` (empty when absent or not a table)."""
    value = table.get(key, {})
    return value if isinstance(value, dict) else {}


def _from_table(table: TomlValue, where: str) -> Settings:
    if not isinstance(table, dict):
        raise SettingsError(f"{where}: [tool.servicebot.check] must be a table")
    unknown = sorted(set(table) - set(_KEYS))
    if unknown:
        raise SettingsError(f"{where}: [tool.servicebot.check] has no setting '{unknown[0]}' "
                            f"(settings: {', '.join(_KEYS)})")
    select = _codes(table.get("select", ["ALL"]), f"{where}: select")
    ignore = _codes(table.get("ignore", []), f"{where}: ignore")
    strict = table.get("strict", False)
    factor = table.get("inertia-factor", 2.0)
    if not isinstance(strict, bool):
        raise SettingsError(f"{where}: strict must be true or false, not {strict!r}")
    if isinstance(factor, bool) or not isinstance(factor, int | float) or not factor > 1 \
            or not math.isfinite(factor):  # inf would turn SB301 off without a word
        raise SettingsError(f"{where}: inertia-factor must be a finite number above 1, not "
                            f"{factor!r}")
    return Settings(select, ignore, strict, float(factor), _severities(table, where), where)


def _codes(value: TomlValue, where: str) -> tuple[str, ...]:
    if isinstance(value, str) or not isinstance(value, list):
        raise SettingsError(f"{where} must be a list of codes, e.g. [\"SB309\"]")
    return tuple(_pattern(v, where) for v in value)


def _pattern(pattern: TomlValue, where: str) -> str:
    """A code, a code prefix or ``ALL``; a rule's name is turned into its code."""
    if isinstance(pattern, str) and valid_pattern(pattern):
        return pattern.upper()
    try:
        return rule(str(pattern)).code
    except KeyError as exc:
        raise SettingsError(f"{where}: {exc.args[0]}") from None


def _severities(table: dict[str, TomlValue], where: str) -> dict[str, Severity]:
    given = table.get("severity", {})
    if not isinstance(given, dict):
        raise SettingsError(f"{where}: severity must be a table, e.g. {{ SB304 = \"error\" }}")
    result = {}
    for code, level in given.items():
        try:
            known = rule(code).code
        except KeyError as exc:
            raise SettingsError(f"{where}: severity: {exc.args[0]}") from None
        if level not in {s.value for s in Severity}:
            raise SettingsError(f"{where}: severity of {known} must be error, warning or info, "
                                f"not {level!r}")
        result[known] = Severity(level)
    return result
