"""servicebot: check, inspect, move, simulate and drive a differential-drive service robot."""

__version__ = "0.1.0"
