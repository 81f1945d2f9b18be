"""Numbers as CSV, JSON, YAML and ROS write them, not as Python's ``float()`` reads text.

``float()`` also reads ``1_000`` (digit groups) and digits of other scripts (``０.１``): a
typo ``0_1`` became 1 and a joint moved to it. Pure.
"""

from __future__ import annotations


def plain_float(text: str) -> float:
    """``float(text)``, refusing ``_`` and characters beyond ASCII.

    Raises:
        ValueError: Not a number so written.
    """
    if "_" in text or not text.isascii():
        raise ValueError(f"could not convert string to float: {text!r}")
    return float(text)


def plainly_written(texts: list[str]) -> bool:
    """Whether none of ``texts`` holds a ``_`` or a character beyond ASCII."""
    joined = "".join(texts)
    return "_" not in joined and joined.isascii()
