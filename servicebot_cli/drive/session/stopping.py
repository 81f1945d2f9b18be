"""Confirming a stop: send it, and resend it until the firmware reports the wheels stopped.

What counts as stopped is the protocol's (:meth:`~servicebot_cli.drive.session.commander.
HostLink.still`): telemetry with the wheels at zero, or encoder counts that stop changing. An
``OK`` proves nothing, so the stop is resent every ``link.stop_resend_s`` until the report
comes, for at most ``link.stop_timeout_s``.
"""

from __future__ import annotations

from collections.abc import Callable

from servicebot_cli.common.errors import LinkError
from servicebot_cli.drive.session.inbox import Inbox
from servicebot_cli.drive.transport import Port


def stop_until_still(port: Port, inbox: Inbox, send_stop: Callable[[], int],
                     clock: Callable[[], float]) -> bool:
    """Send the stop until the firmware reports the wheels stopped; True once it did.

    Args:
        port: The open port.
        inbox: Where the replies go.
        send_stop: Sends one stop; returns its token.
        clock: Monotonic time [s].

    Returns:
        Whether the firmware reported the wheels stopped; False also when the port failed.
    """
    link = inbox.link
    try:
        tokens = {send_stop()}
        deadline = clock() + link.stop_timeout_s
        resend = clock() + link.stop_resend_s
        while (now := clock()) < deadline:
            inbox.receive(port, now)
            if link.still(tokens, now):
                return True
            if now >= resend:
                tokens.add(send_stop())
                resend = now + link.stop_resend_s
            port.wait(min(resend, deadline) - clock())
        inbox.receive(port, clock())
        return link.still(tokens, clock())
    except LinkError:
        return False
