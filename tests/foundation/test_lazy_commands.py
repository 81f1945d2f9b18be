"""Subcommands are imported when named; every name still lists and suggests as before."""

from __future__ import annotations

import subprocess
import sys

from servicebot_cli.cli import COMMANDS
from tests.conftest import assert_one_line_error, run_servicebot

_LOADED = """
import sys
from servicebot_cli.cli import main
try:
    main(["check", "--help"])
except SystemExit:
    pass
print(sorted(m.rsplit(".", 1)[1] for m in sys.modules
             if m.startswith("servicebot_cli.commands.") and m.rsplit(".", 1)[1] in {names!r}))
"""


def test_a_command_imports_no_other_command_module():
    code = _LOADED.format(names=set(COMMANDS))
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                            check=True)
    assert result.stdout.strip().splitlines()[-1] == "['check']"


def test_help_lists_every_command():
    result = run_servicebot("--help")
    listed = result.stdout.split("Commands:")[1].split()
    assert all(name in listed for name in COMMANDS)


def test_a_mistyped_command_is_refused_with_the_nearest_name():
    assert_one_line_error(run_servicebot("chekc"), 2, "No such command 'chekc'",
                          "Did you mean 'check'?")
    line = assert_one_line_error(run_servicebot("zzz"), 2, "No such command 'zzz'")
    assert "Did you mean" not in line
