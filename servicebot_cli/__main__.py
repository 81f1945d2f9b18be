"""Allow ``python -m servicebot_cli``."""

from servicebot_cli.cli import entry

entry()
