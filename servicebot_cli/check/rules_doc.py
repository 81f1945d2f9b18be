"""``docs/rules.md``, made from the catalogue (a test keeps the committed file identical).

Regenerate with ``python -m servicebot_cli.check.rules_doc > docs/rules.md``.
"""

from __future__ import annotations

from servicebot_cli.check.catalogue import FAMILIES, RULES

_INTRO = """\
# servicebot check: rules

Generated from the rule catalogue by `python -m servicebot_cli.check.rules_doc`; do not edit.
`servicebot check --list-rules` prints the same list, `servicebot check --explain CODE` one rule.

Severities: **error** fails the run (exit 1), **warning** fails it with `--strict`, **info**
never fails. Change a rule's severity, or select and ignore rules, in `[tool.servicebot.check]`
of `pyproject.toml` (see README.md). Silence one rule on one element with a comment just
before the element (or before an element that contains it):

```xml
<!-- servicebot: ignore SB301 -->
<link name="gripper_finger">
```

In a xacro file, put the comment inside the macro, just before the element: xacro drops
comments that precede a macro call.
"""


def _md(text: str) -> str:
    """Text with ``<`` escaped, so element names show instead of vanishing as HTML."""
    return text.replace("<", "&lt;")


def markdown() -> str:
    """The whole rules page."""
    lines = [_INTRO]
    for prefix, title in FAMILIES.items():
        rules = [r for r in RULES.values() if r.code.startswith(prefix)]
        lines.append(f"## {title}\n")
        lines.append("| code | name | severity | finds |")
        lines.append("|---|---|---|---|")
        lines += [f"| [{r.code}](#{r.code.lower()}) | {r.name} | {r.severity.value} | "
                  f"{_md(r.summary)} |" for r in rules]
        lines.append("")
        for rule in rules:
            lines.append(f"### {rule.code}\n")
            lines.append(f"**{rule.name}** ({rule.severity.value}): {_md(rule.summary)}.\n")
            lines.append(_md(rule.explanation) + "\n")
            if rule.breaks:
                lines.append(f"What breaks: {_md(rule.breaks)}.\n")
            if rule.fix:
                lines.append(f"Fix: {_md(rule.fix)}\n")
            lines.append(f"Fixture: `tests/check/fixtures/{rule.code}_*`.\n")
    return "\n".join(lines).rstrip() + "\n"


if __name__ == "__main__":
    print(markdown(), end="")
