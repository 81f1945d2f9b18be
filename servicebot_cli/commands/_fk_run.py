"""The two ways ``fk`` runs: one configuration, or a stream of them (``--configs``).

Imported by the command's callback only: it pulls in numpy and Pinocchio.
"""

from __future__ import annotations

from collections.abc import Sequence

import click

from servicebot_cli.batch.fk_rows import FkBatch
from servicebot_cli.batch.stream import stream
from servicebot_cli.common.jsonable import dumps
from servicebot_cli.description.robot import RobotDescription
from servicebot_cli.kinematics.forward import frame_poses
from servicebot_cli.kinematics.frames import link_names
from servicebot_cli.kinematics.user_joints import (
    Mimics,
    unnamed_outside,
    user_values,
    user_vector,
)
from servicebot_cli.output import poses as render


def all_frames(robot: RobotDescription) -> list[str]:
    """Every link, fixed frames included, in URDF order."""
    return list(link_names(robot))


def single(robot: RobotDescription, frames: Sequence[str], reference: str,
           joints: Sequence[tuple[str, float]], *, fmt: str, deg: bool, clamp: bool,
           as_table: bool) -> None:
    """Print the poses of ``frames`` for one configuration."""
    space = robot.joint_space
    values = user_vector(space, joints, deg=deg, clamp=clamp,
                         mimics=Mimics.of(robot.joints, space))
    outside = unnamed_outside(space, values)
    if outside:
        click.echo(f"note: {', '.join(outside)} not given: 0, outside the limits "
                   f"(give {outside[0]}=VALUE for a reachable pose)", err=True)
    poses = frame_poses(robot.model, robot.data, space.to_q(values), frames, reference,
                        link_names(robot))
    if fmt == "json":
        joint_values = user_values(space, values, deg=deg)
        click.echo(dumps(render.fk_json(robot.name, poses, joint_values, reference, deg)),
                   nl=False)
        return
    for line in render.fk_text(poses, deg, as_table):
        click.echo(line)


def batch(robot: RobotDescription, frames: Sequence[str], reference: str, configs: str, *,
          output: str | None, fmt: str, deg: bool, clamp: bool, on_error: str) -> None:
    """Stream poses for every configuration line of ``configs``."""
    stream(FkBatch(robot, frames, reference, deg=deg, clamp=clamp), configs, output=output,
           fmt=fmt, on_error=on_error, warn=lambda message: click.echo(message, err=True))
