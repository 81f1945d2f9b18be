"""What a command that is not built yet says: plainly that, after checking its input."""

from __future__ import annotations

from servicebot_cli.errors import ExitCode, ServicebotError
from servicebot_cli.options import RobotArgs


class NotAvailableYet(ServicebotError):
    """The command exists in the interface but does not work yet."""

    exit_code = ExitCode.INTERNAL


def pending(command: str, robot_args: RobotArgs) -> None:
    """Load the robot (so bad input is reported as everywhere), then refuse plainly."""
    from servicebot_cli.description.loader import load

    load(robot_args.source())
    raise NotAvailableYet(f"'servicebot {command}' is not available in this version yet")
