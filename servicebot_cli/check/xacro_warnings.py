"""SB017: what to do about each warning xacro (or the loader, about xacro) gave.

A package the loader did not find for a ``$(find)`` it left as written is SB007.

xacro's own warnings say what is wrong and not what to change; the loader's carry their fix.
A file's own ``xacro.message()``, ``xacro.error()`` and ``xacro.warning()`` say what its
author meant to.
"""

from __future__ import annotations

import re

from servicebot_cli.check.findings import Issue, Severity
from servicebot_cli.description.load_warnings import LoadWarning

# xacro's own warning texts (xacro/__init__.py), each with its fix; \1 is what it names
_XACRO: tuple[tuple[re.Pattern[str], str], ...] = tuple((re.compile(p), f) for p, f in (
    (r"redefining global symbol: (\S+)",  # a name xacro defines itself (Python's, math's)
     r"rename the property: it hides xacro's own '\1' in every ${} expression that follows"),
    (r"Cannot remove global symbol: (\S+)", r"leave '\1' defined, or rename the property"),
    (r"(\S+): unknown attribute\(s\): (.+)",
     r"remove \2 from <\1>, or spell it as xacro names it"),
    (r"Include tag's filename spec \"(.*)\" matched no files\.",
     r"fix the pattern '\1': it includes nothing"),
    (r"inconsistent namespace redefinitions for (\S+):",
     r"declare \1 with one namespace URI in every included file"),
    (r"Child elements of a <xacro:include> tag are ignored",
     "remove them: the included file already sees the includer's arguments and properties"),
    (r"macro names must not contain prefix 'xacro:': xacro:(\S+)",
     r"name the macro '\1'"),
    (r"(\S+): default property value can only be defined on local scope",
     r"give '\1' its value with value=, or define it inside the macro"),
    (r"(\S+): no parent scope at global scope",
     r"drop scope=\"parent\" from '\1': at the top it has no parent"),
    (r"Using (\w+)\(\) directly is deprecated\. Use ([\w.]+)\(\) instead\.",
     r"write \2()"),
))


def xacro_warning(warning: LoadWarning, display: str) -> Issue:
    """The SB017 finding for ``warning``, placed where it says, with what to change.

    A file's ``xacro.message()`` is information; its ``xacro.error()`` a warning, as xacro
    goes on and writes the robot.
    """
    where = (warning.file or display, warning.line, warning.column)
    if warning.said_as == "package":
        return Issue("SB007", warning.text, where=where, fix=warning.fix)
    if warning.said_as == "installed":
        return Issue("SB001", warning.text, where=where, fix=warning.fix)
    if warning.said_as == "message":
        return Issue("SB017", f"the file's xacro.message(): {warning.text}", where=where,
                     fix="nothing to change: the file prints this while xacro expands it",
                     severity=Severity.INFO)
    if warning.said_as == "error":
        return Issue("SB017", f"the file's xacro.error(), after which xacro goes on: "
                     f"{warning.text}", where=where,
                     fix="do what it says: xacro still writes the robot, as the file stands")
    return Issue("SB017", warning.text, where=where, fix=warning.fix or _xacro_fix(warning.text)
                 or "do what the warning says: the file wrote it with xacro.warning(), or "
                 "xacro did")


def _xacro_fix(warning: str) -> str | None:
    """What to change for one of xacro's own warnings, when it is known here."""
    for pattern, fix in _XACRO:
        found = pattern.search(warning)
        if found:
            return found.expand(fix)
    return None
