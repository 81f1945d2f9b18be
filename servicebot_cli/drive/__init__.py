"""``servicebot drive`` and ``emulate``: the serial link to the motor controller.

Sub-packages: ``protocols`` (framing and messages, host side), ``session`` (one run on an open
port), ``teleop`` (the keyboard) and ``emulator`` (a motor controller on a pseudo-terminal).
Only :mod:`servicebot_cli.drive.transport` imports pyserial, and only when a port is opened.
"""
