r"""The robot's collision shape: every link's primitives and meshes, posed with the arm.

Each ``<collision>`` shape of each link becomes a :class:`Part`; a mesh is read once, scaled,
and placed in a frame at the centre of its bounding box. Parts are placed on the
base by composing the URDF's joint origins and motions from the root, vectorised over many arm
configurations at once:

.. math:: T_{link \to base}(q) = T_{parent \to base}(q)\, T_{origin}\, M_{joint}(q_j)

Wheel joints count as fixed: a wheel's collision cylinder turns about its own axis, so its
spin does not move its surface. Shapes that cannot be used (a mesh file that cannot be read,
sizes that are not positive) are left out and named in :attr:`RobotShape.skipped`. Pure but
for reading mesh files, which is injected.
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from servicebot_cli.kinematics.transforms import pose_matrix

if TYPE_CHECKING:
    from servicebot_cli.description.elements import Geometry, Joint
    from servicebot_cli.description.robot import RobotDescription

FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]
KINDS = ("box", "cylinder", "sphere")
"""The primitive kinds; a part can also be a ``mesh``."""
MeshReader = Callable[["Geometry"], tuple[FloatArray, IntArray]]
"""A mesh ``<geometry>`` to its vertices [m, scaled] (V, 3) and triangles (F, 3); raises
:class:`MeshUnreadable`."""


class MeshUnreadable(Exception):  # noqa: N818  # a reason, not an error the user sees
    """A mesh collision shape that cannot be used; the message says why."""


@dataclass(frozen=True)
class Part:
    """One collision shape of a link.

    Attributes:
        link: The link it belongs to.
        kind: ``box``, ``cylinder`` (axis along its local z), ``sphere`` or ``mesh``.
        half_m: Box half sizes; ``(r, r, half length)`` for a cylinder; ``(r, r, r)`` for a
            sphere; for a mesh, the half sizes of its bounding box (centred on the part's frame).
        transform_part_to_link: The ``<collision><origin>``, (4, 4); for a mesh, moved to the
            centre of its bounding box.
        vertices_m: A mesh's vertices in the part's frame, scaled, shape (V, 3); else None.
        faces: A mesh's triangles (vertex indices), shape (F, 3); else None.
    """

    link: str
    kind: str
    half_m: FloatArray
    transform_part_to_link: FloatArray
    vertices_m: FloatArray | None = None
    faces: IntArray | None = None

    @functools.cached_property
    def radius_m(self) -> float:
        """Radius of the sphere around the part's centre that holds it."""
        if self.kind == "box":
            return float(np.linalg.norm(self.half_m))
        if self.kind == "cylinder":
            return float(np.hypot(self.half_m[0], self.half_m[2]))
        if self.vertices_m is not None:
            return float(np.sqrt(np.max(np.einsum("ij,ij->i", self.vertices_m,
                                                  self.vertices_m), initial=0.0)))
        return float(self.half_m[0])


@dataclass(frozen=True, eq=False)
class RobotShape:
    """Every collision part of the robot and the joints that move them.

    Attributes:
        root: The base link, whose frame the parts are placed in.
        parts: The shapes (primitives and meshes), in URDF link order.
        joints: Movable joints that move parts (the arm's), in the order of ``q`` columns.
        steps: Per link in tree order: (link, parent link, origin (4, 4), joint or None).
        skipped: ``link: reason`` for collision shapes that are not parts (unreadable meshes,
            bad sizes).
        unread_meshes: The filenames (as written) of the meshes among them, which the
            self-contact check leaves out too.
    """

    root: str
    parts: tuple[Part, ...]
    joints: tuple[str, ...]
    steps: tuple[tuple[str, str, FloatArray, Joint | None], ...]
    skipped: tuple[str, ...]
    unread_meshes: tuple[str, ...] = ()

    @property
    def links(self) -> tuple[str, ...]:
        """The link of each part."""
        return tuple(p.link for p in self.parts)

    def fixed(self) -> npt.NDArray[np.bool_]:
        """Which parts no movable joint moves (fixed on the base), shape (S,)."""
        moved = self._moved_links()
        return np.array([p.link not in moved for p in self.parts])

    def _moved_links(self) -> set[str]:
        moved: set[str] = set()
        for link, parent, _, joint in self.steps:
            if joint is not None or parent in moved:
                moved.add(link)
        return moved

    def transforms_to_base(self, q: FloatArray) -> FloatArray:
        """``transform_part_to_base`` of every part for each configuration.

        Parts no joint moves are placed once and copied to every configuration.

        Args:
            q: Positions of :attr:`joints` [rad or m], shape (P, J).

        Returns:
            Shape (P, S, 4, 4).
        """
        links = self._links(q)
        count = len(links[self.root])
        out = np.empty((count, len(self.parts), 4, 4))
        for i, part in enumerate(self.parts):
            placed = links[part.link]
            if placed.strides[0] == 0:  # the same for every configuration
                out[:, i] = placed[:1] @ part.transform_part_to_link
            else:
                out[:, i] = _each_times(placed, part.transform_part_to_link)
        return out

    def link_to_base(self, q: FloatArray, link: str) -> FloatArray:
        """``transform_link_to_base`` of ``link`` for each configuration, shape (P, 4, 4).

        Raises:
            KeyError: ``link`` is not in the tree below the root.
        """
        return self._links(q)[link]

    def _links(self, q: FloatArray) -> dict[str, FloatArray]:
        """Every link's ``transform_link_to_base`` for each row of ``q``, shape (P, 4, 4).

        A link no joint moves is one matrix broadcast to every row (a zero first stride).
        """
        q = configuration_rows(q, len(self.joints))
        links = {self.root: np.broadcast_to(np.eye(4), (len(q), 4, 4))}
        for link, parent, origin, joint in self.steps:
            before = links[parent]
            if joint is None and before.strides[0] == 0:  # fixed: one matrix for every row
                links[link] = np.broadcast_to(before[:1] @ origin, before.shape)
                continue
            placed = _each_times(before, origin)
            if joint is not None:
                placed = placed @ joint_motions(joint, q[:, self.joints.index(joint.name)])
            links[link] = placed
        return links


def configuration_rows(q: FloatArray, joints: int) -> FloatArray:
    """``q`` as rows of ``joints`` positions, shape (P, joints).

    A robot with no arm has rows of no positions, (P, 0), which ``reshape(-1, 0)`` cannot size.
    """
    q = np.asarray(q, dtype=np.float64)
    return q.reshape(len(q) if q.ndim == 2 else -1, joints)


def _each_times(stack: FloatArray, matrix: FloatArray) -> FloatArray:
    """``stack @ matrix`` for a stack (P, 4, 4) and one (4, 4), as one product.

    numpy multiplies a stack one 4 x 4 product at a time; the stack's rows as one (4P, 4)
    matrix take one product, each element summed in the same order: the same bits, in a
    fifth of the time.
    """
    return np.asarray(np.ascontiguousarray(stack).reshape(-1, 4) @ matrix,
                      dtype=np.float64).reshape(stack.shape)


def joint_motions(joint: Joint, values: FloatArray) -> FloatArray:
    """Motion of a joint at each of ``values``, shape (P, 4, 4) (Rodrigues' formula).

    Rotation by t about unit axis k: ``I + sin t K + (1 - cos t) K^2``; a prismatic joint
    slides along k.
    """
    values = np.asarray(values, dtype=float)
    out = np.broadcast_to(np.eye(4), (len(values), 4, 4)).copy()
    axis = np.array(joint.axis, dtype=float)
    norm = float(np.linalg.norm(axis))
    if norm == 0 or not np.isfinite(norm):
        return out
    axis /= norm
    if joint.type == "prismatic":
        out[:, :3, 3] = values[:, None] * axis
        return out
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    out[:, :3, :3] += np.sin(values)[:, None, None] * k \
        + (1 - np.cos(values))[:, None, None] * (k @ k)
    return out


def robot_shape(robot: RobotDescription, moving_joints: Sequence[str],
                read_mesh: MeshReader | None = None) -> RobotShape:
    """The collision parts of ``robot``; ``moving_joints`` move them, other joints are fixed.

    ``read_mesh`` reads mesh shapes (default: trimesh, with the robot's packages resolved
    from its directory and the environment).
    """
    root = robot.root_link or ""
    children: dict[str, list[Joint]] = {}
    for joint in robot.joints:
        children.setdefault(joint.parent or "", []).append(joint)
    steps: list[tuple[str, str, FloatArray, Joint | None]] = []
    seen, stack = {root}, [root]
    while stack:
        parent = stack.pop()
        for joint in children.get(parent, ()):
            if joint.child and joint.child not in seen:
                seen.add(joint.child)
                moving = joint if joint.name in moving_joints else None
                steps.append((joint.child, parent, pose_matrix(joint.origin), moving))
                stack.append(joint.child)
    parts, skipped, unread = [], [], []
    for link in robot.links:
        for shape in link.collisions if link.name in seen else ():
            origin = pose_matrix(shape.origin)
            if shape.geometry.kind == "mesh":
                if read_mesh is None:
                    read_mesh = _mesh_reader(robot)
                try:
                    parts.append(mesh_part(link.name, *read_mesh(shape.geometry), origin))
                except MeshUnreadable as exc:
                    skipped.append(f"{link.name}: mesh '{shape.geometry.filename}' left out: "
                                   f"{exc}")
                    unread.append(shape.geometry.filename or "")
                continue
            half = half_extents(shape.geometry)
            if half is None:
                skipped.append(f"{link.name}: {shape.geometry.kind or 'unknown'} collision shape")
                continue
            parts.append(Part(link.name, shape.geometry.kind, half, origin))
    return RobotShape(root, tuple(parts), tuple(moving_joints), tuple(steps), tuple(skipped),
                      tuple(unread))


def mesh_part(link: str, vertices_m: FloatArray, faces: IntArray,
              transform_mesh_to_link: FloatArray) -> Part:
    """A mesh as a part: its frame moved to the centre of its bounding box.

    Raises:
        MeshUnreadable: No triangles, or vertices that are not finite.
    """
    vertices_m = np.asarray(vertices_m, dtype=np.float64).reshape(-1, 3)
    faces = np.asarray(faces, dtype=np.int64).reshape(-1, 3)
    if not len(faces):
        raise MeshUnreadable("it has no triangles")
    if not np.all(np.isfinite(vertices_m)):
        raise MeshUnreadable("its vertices are not all finite numbers")
    low, high = vertices_m.min(axis=0), vertices_m.max(axis=0)
    centre = np.eye(4)
    centre[:3, 3] = (low + high) / 2
    return Part(link, "mesh", (high - low) / 2, transform_mesh_to_link @ centre,
                vertices_m - centre[:3, 3], faces)


def _mesh_reader(robot: RobotDescription) -> MeshReader:
    from servicebot_cli.description.packages import PackageResolver
    from servicebot_cli.simulate.world.meshes import link_mesh_reader

    return link_mesh_reader(PackageResolver.from_environment(context=robot.path.parent),
                            robot.path.parent)


def half_extents(geometry: Geometry) -> FloatArray | None:
    """Half sizes of a primitive (see :attr:`Part.half_m`), None for meshes or bad sizes."""
    kind = geometry.kind
    if kind == "box" and geometry.size and min(geometry.size) > 0:
        return np.array(geometry.size, dtype=float) / 2
    if kind == "cylinder" and geometry.radius and geometry.length \
            and geometry.radius > 0 and geometry.length > 0:
        r = geometry.radius
        return np.array([r, r, geometry.length / 2])
    if kind == "sphere" and geometry.radius and geometry.radius > 0:
        return np.full(3, geometry.radius)
    return None


def outlines(parts: Sequence[Part], transforms: FloatArray) -> list[FloatArray]:
    """Each part seen from above: its convex outline on the floor, closed, shape (K, 2).

    Args:
        parts: The parts.
        transforms: ``transform_part_to_world`` of each part, shape (S, 4, 4).
    """
    out = []
    for part, transform in zip(parts, transforms, strict=True):
        points = _surface_points(part) @ transform[:3, :3].T + transform[:3, 3]
        hull = convex_hull(points[:, :2])
        out.append(np.vstack((hull, hull[:1])))
    return out


def _surface_points(part: Part) -> FloatArray:
    """Points of the part's surface whose hull is its shape (circles as 32-gons)."""
    if part.vertices_m is not None:
        return part.vertices_m
    h = part.half_m
    if part.kind == "box":
        signs = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)])
        return signs * h
    angles = np.linspace(0, 2 * np.pi, 32, endpoint=False)
    circle = np.column_stack((np.cos(angles), np.sin(angles))) * h[0]
    if part.kind == "cylinder":
        return np.vstack([np.column_stack((circle, np.full(32, z))) for z in (-h[2], h[2])])
    return np.vstack([np.column_stack((circle, np.zeros(32)))[:, order]
                      for order in ([0, 1, 2], [0, 2, 1], [2, 0, 1])])


def convex_hull(points: FloatArray) -> FloatArray:
    """Convex hull of 2D points, counter-clockwise (Andrew's monotone chain), shape (K, 2)."""
    unique = np.unique(np.round(points, 12), axis=0)
    if len(unique) < 3:
        return unique

    def half(sequence: FloatArray) -> list[FloatArray]:
        chain: list[FloatArray] = []
        for p in sequence:
            while len(chain) >= 2 and _turn(chain[-2], chain[-1], p) <= 0:
                chain.pop()
            chain.append(p)
        return chain

    lower, upper = half(unique), half(unique[::-1])
    return np.array(lower[:-1] + upper[:-1])


def _turn(a: FloatArray, b: FloatArray, c: FloatArray) -> float:
    """Z of ``(b - a) x (c - a)``: positive when a, b, c turn counter-clockwise."""
    return float((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
