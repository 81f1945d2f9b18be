"""servicebot: check, inspect, move, simulate and drive a differential-drive service robot."""

from servicebot_cli.common import dataclass_code

__version__ = "0.1.0"

dataclass_code.install()  # before any of the package's dataclasses is defined
