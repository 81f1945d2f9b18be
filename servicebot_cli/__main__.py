"""Allow ``python -m servicebot_cli``."""

from servicebot_cli.cli import main

main(prog_name="servicebot")
