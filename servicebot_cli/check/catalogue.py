"""The rule catalogue: every rule's stable code, default severity, explanation and fix.

Plain data, importable without any numeric library: ``--list-rules``, ``--explain`` and
``docs/rules.md`` are made from it. The texts live in :mod:`catalogue_urdf` (the URDF
itself) and :mod:`catalogue_ros` (Gazebo, ros2_control, controllers, the model).
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass, replace

from servicebot_cli.check.findings import Severity

FAMILIES = {
    "SB0": "Parse and safety",
    "SB1": "Tree and names",
    "SB2": "Joints",
    "SB3": "Inertia",
    "SB4": "Geometry and files",
    "SB5": "Gazebo, ros2_control and transmissions",
    "SB6": "Controller configuration",
    "SB7": "Model",
}


@dataclass(frozen=True)
class Rule:
    """A rule of the catalogue.

    Attributes:
        code: Stable code, ``SB`` and three digits; never reused for another meaning.
        name: Short kebab-case name.
        severity: Default severity (``[tool.servicebot.check] severity`` overrides it).
        summary: One line: what the rule finds.
        explanation: Why it matters, and what exactly triggers it.
        fix: How to fix it, when there is a general answer.
        breaks: For a rule that is (or can be) an error, the standard consumer that refuses
            the file or silently changes the robot (from :mod:`catalogue_breaks`).
    """

    code: str
    name: str
    severity: Severity
    summary: str
    explanation: str
    fix: str | None = None
    breaks: str | None = None

    @property
    def family(self) -> str:
        """The family title, from the code's first digit."""
        return FAMILIES[self.code[:3]]


def _all_rules() -> dict[str, Rule]:
    from servicebot_cli.check.catalogue_breaks import BREAKS
    from servicebot_cli.check.catalogue_ros import ROS_RULES
    from servicebot_cli.check.catalogue_urdf import URDF_RULES

    rules = (*URDF_RULES, *ROS_RULES)
    return {rule.code: replace(rule, breaks=BREAKS.get(rule.code))
            for rule in sorted(rules, key=lambda r: r.code)}


RULES: dict[str, Rule] = _all_rules()
"""Every rule, by code, in code order."""


def rule(code: str) -> Rule:
    """The rule with ``code`` (case-insensitive).

    Raises:
        KeyError: No such rule; the message suggests close codes or names.
    """
    key = code.strip().upper()
    if key in RULES:
        return RULES[key]
    by_name = {r.name: r for r in RULES.values()}
    if code in by_name:
        return by_name[code]
    close = difflib.get_close_matches(key, list(RULES), n=3, cutoff=0.6)
    close += difflib.get_close_matches(code, list(by_name), n=3, cutoff=0.6)
    hint = f"; did you mean {' or '.join(close)}?" if close else "; --list-rules lists them"
    raise KeyError(f"no rule '{code}'{hint}")


def matches(code: str, patterns: tuple[str, ...]) -> bool:
    """True when ``code`` starts with one of ``patterns`` (``SB3`` selects SB300-SB399)."""
    return any(code.startswith(p.upper()) for p in patterns)


def valid_pattern(pattern: str) -> bool:
    """True when ``pattern`` selects at least one rule (``ALL`` selects every rule)."""
    key = pattern.strip().upper()
    return key == "ALL" or (len(key) >= 2 and any(c.startswith(key) for c in RULES))
