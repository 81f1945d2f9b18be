"""The URDF specification as data: elements, their attributes, required parts, number kinds.

From the URDF XML specification (wiki.ros.org/urdf/XML) and what urdfdom enforces.
Number kinds: ``1`` a scalar, ``3`` a vector of three, ``4`` rgba.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class ElementSpec:
    """What a core URDF element may hold.

    Attributes:
        attributes: Allowed attribute names, with the number kind of numeric ones (else 0).
        required: Attributes that must be present (names are checked by the name rules).
        children: Allowed child elements.
        required_children: Child elements that must be present.
        extensions: Child elements other tools define; allowed, never inspected.
    """

    attributes: dict[str, int] = field(default_factory=dict)
    required: tuple[str, ...] = ()
    children: tuple[str, ...] = ()
    required_children: tuple[str, ...] = ()
    extensions: tuple[str, ...] = ()


_POSE = {"xyz": 3, "rpy": 3}

SPEC: dict[str, ElementSpec] = {
    "link": ElementSpec({"name": 0}, children=("inertial", "visual", "collision"),
                        # Pinocchio's (and HPP's): a capsule or convex hull for a shape
                        extensions=("contact", "self_collision_checking", "surface",
                                    "collision_checking")),
    "inertial": ElementSpec(children=("origin", "mass", "inertia"),
                            required_children=("mass", "inertia")),
    "origin": ElementSpec(dict(_POSE)),
    "mass": ElementSpec({"value": 1}, required=("value",)),
    "inertia": ElementSpec({k: 1 for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz")},
                           required=("ixx", "ixy", "ixz", "iyy", "iyz", "izz")),
    "visual": ElementSpec({"name": 0}, children=("origin", "geometry", "material"),
                          required_children=("geometry",)),
    "collision": ElementSpec({"name": 0, "concave": 0}, children=("origin", "geometry"),
                             required_children=("geometry",),
                             extensions=("verbose", "contact_coefficients")),
    "geometry": ElementSpec(children=("box", "cylinder", "sphere", "mesh", "capsule")),
    "box": ElementSpec({"size": 3}, required=("size",)),
    "cylinder": ElementSpec({"radius": 1, "length": 1}, required=("radius", "length")),
    "sphere": ElementSpec({"radius": 1}, required=("radius",)),
    "capsule": ElementSpec({"radius": 1, "length": 1}),
    "mesh": ElementSpec({"filename": 0, "scale": 3}, required=("filename",)),
    "material": ElementSpec({"name": 0}, required=("name",), children=("color", "texture")),
    "color": ElementSpec({"rgba": 4}, required=("rgba",)),
    "texture": ElementSpec({"filename": 0}),
    "joint": ElementSpec(
        {"name": 0, "type": 0}, required=("type",),
        children=("origin", "parent", "child", "axis", "calibration", "dynamics", "limit",
                  "mimic", "safety_controller"),
        required_children=("parent", "child"),
    ),
    "parent": ElementSpec({"link": 0}, required=("link",)),
    "child": ElementSpec({"link": 0}, required=("link",)),
    "axis": ElementSpec({"xyz": 3}),
    "calibration": ElementSpec({"rising": 1, "falling": 1, "reference_position": 1}),
    "dynamics": ElementSpec({"damping": 1, "friction": 1}),
    "limit": ElementSpec({"lower": 1, "upper": 1, "effort": 1, "velocity": 1},
                         required=("effort", "velocity")),
    "mimic": ElementSpec({"joint": 0, "multiplier": 1, "offset": 1}, required=("joint",)),
    "safety_controller": ElementSpec(
        {"soft_lower_limit": 1, "soft_upper_limit": 1, "k_position": 1, "k_velocity": 1},
        required=("k_velocity",),
    ),
}
"""Core elements below ``<robot>``, by tag. ``<material>`` at the top and in a visual share one."""

TOP_LEVEL = ("link", "joint", "material")
"""Core elements directly under ``<robot>``."""

EXTENSIONS = ("gazebo", "transmission", "ros2_control", "sensor", "plugin", "mujoco", "webots",
              "klampt", "physics", "sdf", "group_state", "disable_collisions", "camera",
              "actuator", "hardware", "xacro")
"""Top-level extension elements known to pass quietly (so do namespaced ones)."""
