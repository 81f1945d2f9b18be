"""Build Pinocchio models from URDF text; the only place a ``pin.Model`` is made.

urdfdom, underneath Pinocchio, prints its complaints straight to file descriptor 2. They are
captured here and folded into one error line instead of spilling onto the terminal.
"""

from __future__ import annotations

import contextlib
import os
import sys
import tempfile
from collections.abc import Iterator
from typing import TYPE_CHECKING

from servicebot_cli.common.errors import DescriptionError

if TYPE_CHECKING:
    import pinocchio as pin

BASES = ("fixed", "planar", "free")
"""Root joints: ``fixed`` (the root link is the world), ``planar`` (x, y, yaw on the floor),
``free`` (a 6-DoF floating base)."""


@contextlib.contextmanager
def _captured_stderr_fd() -> Iterator[list[str]]:
    """Redirect fd 2 into a list of lines while the block runs."""
    lines: list[str] = []
    sys.stderr.flush()
    with tempfile.TemporaryFile() as sink:
        saved = os.dup(2)
        os.dup2(sink.fileno(), 2)
        try:
            yield lines
        finally:
            os.dup2(saved, 2)
            os.close(saved)
            sink.seek(0)
            lines.extend(sink.read().decode("utf-8", "replace").splitlines())


def build_model(xml_text: str, display: str, base: str = "fixed") -> pin.Model:
    """A Pinocchio model of the URDF in ``xml_text``.

    Args:
        xml_text: The URDF.
        display: File name used in error messages.
        base: One of :data:`BASES`.

    Raises:
        DescriptionError: urdfdom or Pinocchio rejected the description.
    """
    import pinocchio as pin

    root_joint = {"fixed": None, "planar": pin.JointModelPlanar, "free": pin.JointModelFreeFlyer}[
        base
    ]
    with _captured_stderr_fd() as noise:
        try:
            if root_joint is None:
                return pin.buildModelFromXML(xml_text)
            return pin.buildModelFromXML(xml_text, root_joint())
        except (ValueError, RuntimeError) as exc:
            failure: Exception = exc
    reasons = [line.split("Error:", 1)[1].strip() for line in noise if "Error:" in line]
    reason = reasons[0] if reasons else " ".join(str(failure).split())
    raise DescriptionError(
        f"{display}: not a valid URDF: {reason} (run 'servicebot check {display}' for details)"
    )
