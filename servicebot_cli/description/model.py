"""Build Pinocchio models from URDF text; the only place a ``pin.Model`` is made.

urdfdom, underneath Pinocchio, prints its complaints straight to file descriptor 2. They are
captured here and folded into one error line instead of spilling onto the terminal.
"""

from __future__ import annotations

import re
import shlex
from collections.abc import Sequence
from typing import TYPE_CHECKING

from servicebot_cli.common.errors import DescriptionError
from servicebot_cli.common.native_stderr import captured_fd2

if TYPE_CHECKING:
    import pinocchio as pin

BASES = ("fixed", "planar", "free")
"""Root joints: ``fixed`` (the root link is the world), ``planar`` (x, y, yaw on the floor),
``free`` (a 6-DoF floating base)."""


def check_hint(display: str, xacro_args: Sequence[tuple[str, str]] = ()) -> str:
    """``(run 'servicebot check FILE NAME:=VALUE...' for details)``.

    A word a shell would split is put in double quotes (the hint's own are single).
    """
    words = [display, *(f"{name}:={value}" for name, value in xacro_args)]
    return f"(run 'servicebot check {' '.join(map(_shell_word, words))}' for details)"


def _shell_word(word: str) -> str:
    if shlex.quote(word) == word:
        return word
    return '"' + re.sub(r'(["\\$`])', r"\\\1", word) + '"'


def build_model(xml_text: str, display: str, base: str = "fixed",
                xacro_args: Sequence[tuple[str, str]] = ()) -> pin.Model:
    """A Pinocchio model of the URDF in ``xml_text``.

    Args:
        xml_text: The URDF.
        display: File name used in error messages.
        base: One of :data:`BASES`.
        xacro_args: The arguments the URDF was expanded with, for the error's hint.

    Raises:
        DescriptionError: urdfdom or Pinocchio rejected the description.
    """
    import pinocchio as pin

    root_joint = {"fixed": None, "planar": pin.JointModelPlanar, "free": pin.JointModelFreeFlyer}[
        base
    ]
    with captured_fd2() as noise:
        try:
            if root_joint is None:
                return pin.buildModelFromXML(xml_text)
            return pin.buildModelFromXML(xml_text, root_joint())
        except (ValueError, RuntimeError) as exc:
            failure: Exception = exc
    reasons = [line.split("Error:", 1)[1].strip() for line in noise if "Error:" in line]
    reason = reasons[0] if reasons else " ".join(str(failure).split())
    raise DescriptionError(
        f"{display}: not a valid URDF: {reason} {check_hint(display, xacro_args)}")
