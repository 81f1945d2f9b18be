"""The serial link to the motor controller: framing, messages, port, emulator, drive loop.

Named ``link`` rather than ``serial`` so it never reads like pyserial's package; only
:mod:`servicebot_cli.link.transport` imports pyserial, and only when a port is opened.
"""
