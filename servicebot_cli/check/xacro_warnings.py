"""SB017: what to do about each warning xacro (or the loader, about xacro) gave.

xacro's own warnings say what is wrong and not what to change; the loader's say both, and
their fix is the advice they end with.
"""

from __future__ import annotations

import re

# xacro's own warning texts (xacro/__init__.py), each with its fix; \1 is what it names
_XACRO: tuple[tuple[re.Pattern[str], str], ...] = tuple((re.compile(p), f) for p, f in (
    (r"redefining global symbol: (\S+)",
     r"define '\1' once, or rename it: a second definition replaces the first everywhere"),
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
# the loader's own warnings end with their advice (servicebot_cli.description)
_ADVICE = (
    re.compile(r"\((name it \.urdf\.xacro[^)]*)\)$"),
    re.compile(r"; (write <xacro:.*/>)$"),
)


def xacro_fix(warning: str) -> str | None:
    """What to change for ``warning``, if it is one of the warnings known here."""
    for pattern, fix in _XACRO:
        found = pattern.search(warning)
        if found:
            return found.expand(fix)
    for advice in _ADVICE:
        found = advice.search(warning)
        if found:
            return found[1]
    if "is not declared or read by this file" in warning:
        name = re.search(r"xacro argument '([^']*)'", warning)
        return (f"drop {name[1] if name else 'the argument'}:=VALUE, or declare it with "
                "<xacro:arg name=...> where the file reads it")
    return None
