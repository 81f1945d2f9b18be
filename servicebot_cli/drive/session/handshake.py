"""Meeting the firmware on a freshly opened port: let it boot, then ask who it is.

A board that resets when its port opens (an Arduino Uno: opening the port pulls DTR, which
resets it) is deaf while its bootloader runs; what it is sent then is lost, and what it says
then is not a reply. So every open, the first one and every reconnect, waits ``boot_s``
reading and discarding, and only then asks, every :data:`HELLO_PERIOD_S`, until the answer
comes or ``timeout_s`` has passed.
"""

from __future__ import annotations

from collections.abc import Callable

from servicebot_cli.common.errors import LinkError
from servicebot_cli.drive.protocols.events import Hello
from servicebot_cli.drive.session.inbox import Inbox
from servicebot_cli.drive.session.probe import probe_other, silence_error
from servicebot_cli.drive.transport import Port

HELLO_PERIOD_S = 0.25  # handshake retry


def boot_wait(port: Port, boot_s: float, clock: Callable[[], float]) -> None:
    """Let a board that resets on open boot for ``boot_s`` [s]; what it says is dropped."""
    deadline = clock() + boot_s
    while (left := deadline - clock()) > 0:
        port.wait(left)
        port.read_available()


def handshake(port: Port, inbox: Inbox, timeout_s: float,
              clock: Callable[[], float]) -> Hello:
    """Ask the firmware who it is until it answers; ``inbox.hello`` is the answer.

    ``inbox.hello`` keeps an earlier open's answer until this one comes (the summary of a
    run that lost its link names the firmware it drove).

    Raises:
        LinkError: No answer within ``timeout_s`` (the message names the other protocol
            when the device answers that one), or a firmware speaking another version.
    """
    link = inbox.link
    start = clock()
    received_before, errors_before = inbox.received_bytes, link.errors
    inbox.greeted, next_hello = False, start
    while not inbox.greeted or inbox.hello is None:
        now = clock()
        if now - start >= timeout_s:
            received = inbox.received_bytes - received_before
            raise silence_error(inbox.where, link.name, timeout_s, received,
                                link.errors - errors_before,
                                None if received else probe_other(port, link.name))
        if now >= next_hello:
            port.write(link.hello())
            next_hello = now + HELLO_PERIOD_S
        port.wait(min(next_hello, start + timeout_s) - now)
        inbox.receive(port, clock())
    if not inbox.hello.compatible:
        raise LinkError(f"the firmware on {inbox.where} speaks {inbox.hello.description}; "
                        "this servicebot speaks protocol v1: update one of them")
    inbox.last_rx_s = clock()
    return inbox.hello
