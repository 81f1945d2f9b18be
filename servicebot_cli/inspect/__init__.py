"""What a robot description holds, as plain values: tree, tables, totals and differences.

Each module summarises one part of a :class:`~servicebot_cli.description.robot.RobotDescription`
and returns frozen dataclasses; ``output/`` turns them into text, JSON, Markdown or graphs.
"""

SCHEMA = "servicebot.inspect/1"
"""Version of the JSON that ``servicebot inspect --format json`` prints; bumped on any change
that is not a pure addition."""

SECTIONS = ("tree", "links", "joints", "frames", "sensors", "plugins", "interfaces", "topics",
            "totals")
"""The parts of ``servicebot inspect``, in the order they are shown."""
