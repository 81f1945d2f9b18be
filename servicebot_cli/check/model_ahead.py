"""SB701's Pinocchio model built by a forked process while one file's other rules run.

Importing Pinocchio is a quarter of a one-file check from a cold process. On a machine where
the process may run on a second core, a worker (:mod:`~servicebot_cli.common.forked`) forked
once the file is read builds the model (only Pinocchio's verdict comes back: built, or the
error line) while the parent reads the meshes. The parent takes the verdict only where a
serial run would build the model (no error found before); otherwise it stops the worker. A
worker that ends without a verdict (killed, a crash in a library) makes the parent build the
model itself, as a serial run does.
"""

from __future__ import annotations

import sys
from functools import partial

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.common.forked import Worker, second_core

ModelAhead = Worker[None, "str | None"]
"""A worker with one job: Pinocchio's error line for the URDF, or None when it builds."""


def worth_forking() -> bool:
    """A worker would save time: Pinocchio not imported yet, and a core for it to run on."""
    return "pinocchio" not in sys.modules and second_core()


def start(xml_text: str, display: str) -> ModelAhead | None:
    """Fork the worker building ``xml_text``'s model; None when the fork fails."""
    try:
        ahead: ModelAhead = Worker(partial(_verdict, xml_text, display), forked=True,
                                   name="model-building")
    except OSError:
        return None
    ahead.submit(None)
    ahead.no_more_jobs()
    return ahead


def _verdict(xml_text: str, display: str, _job: None) -> str | None:
    """Pinocchio's error line for the URDF, or None when it builds the model."""
    from servicebot_cli.description.model import build_model

    try:
        build_model(xml_text, display)
    except DescriptionError as exc:
        return str(exc)
    return None
