"""Targets given in another frame of the robot (``ik --relative-to FRAME``).

A target in a sensor's or the arm base's frame is carried into the root link's frame, where
the solver works, by that frame's pose at the start configuration: the place the frame has
when the command runs, as a perception pipeline reports a detection. Distances and rotation
angles do not change under that rigid transform, so the solve's errors hold in either frame.
Pure.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.forward import transforms
from servicebot_cli.kinematics.frames import frame_id
from servicebot_cli.kinematics.inverse import IkTarget
from servicebot_cli.kinematics.rotations import AXES
from servicebot_cli.kinematics.targets import BadTarget

if TYPE_CHECKING:
    import pinocchio as pin

FloatArray = npt.NDArray[np.float64]

_ALIGNED = 1e-9  # how far from the identity a rotation may be and still count as none


@dataclass(frozen=True)
class TargetFrame:
    """The frame targets are given in, and where it stands in the root link's frame.

    Attributes:
        name: The frame's link name.
        pose: Its homogeneous transform in the root link's frame, shape (4, 4).
    """

    name: str
    pose: FloatArray = field(repr=False)

    @classmethod
    def at(cls, model: pin.Model, q: FloatArray, name: str,
           known: Sequence[str]) -> TargetFrame:
        """``name`` where it stands at configuration ``q`` of ``model``.

        Raises:
            FrameNotFound: ``name`` is not a link (nearest names first).
        """
        # frame 0 is Pinocchio's universe, the frame the solver's targets are in: the root
        # link's (with a mobile base, where the root link stands before the base moves)
        pose = transforms(model, model.createData(), q, [frame_id(model, name, known)], 0)
        return cls(name, pose[0])

    @property
    def turned(self) -> bool:
        """The frame's axes are not the root link's."""
        return not np.allclose(self.pose[:3, :3], np.eye(3), rtol=0.0, atol=_ALIGNED)

    def to_root(self, target: IkTarget) -> IkTarget:
        """``target``, given in this frame, in the root link's frame.

        Raises:
            BadTarget: Some orientation angles left free in a turned frame: roll, pitch and
                yaw are about the root link's axes, which are not this frame's.
        """
        rotation, position = self.pose[:3, :3], self.pose[:3, 3]
        if target.axes and len(target.axes) < len(AXES) and self.turned:
            raise BadTarget(
                f"--orientation-axes {','.join(target.axes)} with --relative-to {self.name}: "
                f"the angles are about the root link's axes, and {self.name} is turned from "
                "them; give the whole orientation, or none")
        return IkTarget(rotation @ target.position_m + position,
                        None if target.rotation is None else rotation @ target.rotation,
                        target.axes)
