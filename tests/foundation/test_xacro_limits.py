"""A xacro file that asks for more than a machine has ends in one error line, quickly.

Before these bounds each case below ran until memory or the test's timeout ran out: macros
that call the next twice (xacro's billion laughs), properties that double the one before,
``${9**9**9}``, ``${'a' * 10**10}`` and an include of ``/dev/zero``.
"""

from __future__ import annotations

import resource
from pathlib import Path

import pytest

from tests.conftest import assert_one_line_error, run_servicebot

HEAD = '<?xml version="1.0"?>\n<robot name="x" xmlns:xacro="http://www.ros.org/wiki/xacro">\n'

MACROS = HEAD + '<xacro:macro name="m0"><link name="l"/></xacro:macro>\n' + "".join(
    f'<xacro:macro name="m{i}"><xacro:m{i - 1}/><xacro:m{i - 1}/></xacro:macro>\n'
    for i in range(1, 40)) + "<xacro:m39/>\n</robot>\n"

PROPERTIES = HEAD + '<xacro:property name="p0" value="aaaaaaaaaa"/>\n' + "".join(
    f'<xacro:property name="p{i}" value="${{p{i - 1}}}${{p{i - 1}}}"/>\n'
    for i in range(1, 40)) + '<link name="${p39}"/>\n</robot>\n'

CASES = {
    # the call being expanded when the bound was hit: in m2's body, its second call of m1
    "macros": (MACROS, ":5:35: xacro: over 20000 macro calls"),
    "properties": (PROPERTIES, ":43:1: xacro: a value of over 10000000 characters"),
    "power": (HEAD + '<link name="${9**9**9}"/>\n</robot>\n',
              ":3:1: xacro: 9 ** 387420489 has over 100000 bits"),
    "repeat": (HEAD + "<link name=\"${'a' * 10**10}\"/>\n</robot>\n",
               ":3:1: xacro: repeating str of 1 items 10000000000 times"),
    "shift": (HEAD + '<link name="${1 &lt;&lt; 10**12}"/>\n</robot>\n', ":3:1: xacro: 1 << "),
    "include": (HEAD + '<xacro:include filename="huge.xacro"/>\n<link name="a"/>\n</robot>\n',
                ":3:1: xacro: 'huge.xacro' holds over 32 MiB"),
    # a device is no file to include: it was read to the limit
    "device": (HEAD + '<xacro:include filename="/dev/zero"/>\n<link name="a"/>\n</robot>\n',
               ":3:1: xacro: cannot include '/dev/zero': it is a device, not a file"),
}


def _memory_capped() -> None:
    """3 GB of address space: a case that grows without end fails instead of the machine."""
    resource.setrlimit(resource.RLIMIT_AS, (3 << 30, 3 << 30))


@pytest.mark.parametrize("case", sorted(CASES))
def test_a_xacro_file_too_large_to_expand_is_one_line(tmp_path: Path, case: str) -> None:
    text, needle = CASES[case]
    (tmp_path / "bomb.urdf.xacro").write_text(text)
    with (tmp_path / "huge.xacro").open("wb") as huge:  # sparse: 33 MiB that take no room
        huge.truncate(33 << 20)
    result = run_servicebot("expand", "bomb.urdf.xacro", cwd=tmp_path, timeout=60,
                            preexec_fn=_memory_capped)
    assert_one_line_error(result, 2, "bomb.urdf.xacro" + needle)


def test_check_reports_it_as_a_finding(tmp_path: Path) -> None:
    (tmp_path / "bomb.urdf.xacro").write_text(CASES["power"][0])
    result = run_servicebot("check", "bomb.urdf.xacro", cwd=tmp_path, timeout=60,
                            preexec_fn=_memory_capped)
    assert result.returncode == 1, result.stderr
    assert "SB006" in result.stdout and "has over 100000 bits" in result.stdout


def test_the_guarded_operators_compute_what_python_does(tmp_path: Path) -> None:
    expressions = ["2**10", "2.5**2", "(-2)**3", "2**-1", "'ab'*3", "3*'ab'", "[1, 2]*2",
                   "7*6", "0.5*3", "1 &lt;&lt; 4", "-3 * -4", "True * 5", "2**3**2"]
    links = "".join(f'<link name="l{i}" type="${{{e}}}"/>\n' for i, e in enumerate(expressions))
    (tmp_path / "ok.urdf.xacro").write_text(HEAD + links + "</robot>\n")
    result = run_servicebot("expand", "ok.urdf.xacro", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    for i, expression in enumerate(expressions):
        expected = eval(expression.replace("&lt;", "<"))  # noqa: S307 (constants)
        assert f'name="l{i}" type="{expected}"' in result.stdout, expression
