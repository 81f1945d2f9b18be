"""Mutations of real URDFs for the property tests: bad numbers, lost and stray elements."""

from __future__ import annotations

import random
import xml.etree.ElementTree as ET

BAD_NUMBERS = ["nan", "inf", "-inf", "1e200", "-1e200", "0", "-1", "1e-300", "", " ", "0 0",
               "1 2 3 4", "\uff11", "\u0661.\u0665", "1e", "0x10", "1,5"]


def mutate(root: ET.Element, rng: random.Random, steps: int) -> None:
    """Change ``steps`` random things in the tree under ``root``, in place."""
    elements = list(root.iter())
    for _ in range(steps):
        element = rng.choice(elements)
        choice = rng.random()
        if choice < 0.6 and element.attrib:
            key = rng.choice(sorted(element.attrib))
            element.set(key, rng.choice(BAD_NUMBERS))
        elif choice < 0.8 and len(element):
            element.remove(rng.choice(list(element)))
            elements = list(root.iter())
        elif choice < 0.9:
            element.append(ET.Element(rng.choice(["plane", "mesh", "origin", "inertial", "limit"]),
                                      {"filename": "", "xyz": rng.choice(BAD_NUMBERS)}))
            elements = list(root.iter())
        else:
            element.tag = rng.choice(["mesh", "box", "cylinder", "sphere", "plane", "capsule"])
