"""The lab's up direction, gravity and the rod's dimensions for the kinematics."""

from __future__ import annotations

import math
import re
from typing import Any

import numpy as np

__all__ = ["G0", "parse_up", "rod_dimensions"]

#: Standard gravity [m/s^2].
G0 = 9.80665


def parse_up(up: Any) -> np.ndarray:
    """The lab's upward unit vector from "+z", "-y", "z" ..., a 3-vector, or a 3-vector as
    text ("0, 0.83, 0.56", brackets and spaces allowed: the command line's form)."""
    if (
        isinstance(up, str)
        and re.fullmatch(r"\s*[\[(]?[^a-zA-Z]*[\])]?\s*", up)
        and any(c.isdigit() for c in up)
    ):
        parts = [p for p in re.split(r"[\s,;]+", up.strip().strip("[]()").strip()) if p]
        try:
            up = [float(p) for p in parts]
        except ValueError:
            raise ValueError(f"up as a vector must be three numbers, got {up!r}") from None
    if isinstance(up, str):
        s = up.strip().lower()
        sign = -1.0 if s.startswith("-") else 1.0
        s = s.lstrip("+-")
        if s not in ("x", "y", "z"):
            raise ValueError(
                f"up must be one of '+x', '-x', '+y', '-y', '+z', '-z' or a 3-vector "
                f"(e.g. '0, 0.83, 0.56'), got {up!r}"
            )
        v = np.zeros(3)
        v["xyz".index(s)] = sign
        return v
    v = np.asarray(up, dtype=np.float64).reshape(-1)
    if v.shape != (3,) or not np.all(np.isfinite(v)) or np.linalg.norm(v) == 0:
        raise ValueError(f"up must be an axis name such as '+z' or a non-zero 3-vector, got {up!r}")
    return v / np.linalg.norm(v)


def rod_dimensions(rod: Any) -> tuple[float, float]:
    """(half length L/2 = distance C -> tip-sphere centre [m], tip radius R [m]) of a rod-like
    object (``impactlab.bodies.Rod``: ``half_length``/``L``; ``analytic.RodProperties``:
    ``length``)."""
    if hasattr(rod, "half_length"):
        h = float(rod.half_length)
    elif hasattr(rod, "L"):
        h = 0.5 * float(rod.L)
    elif hasattr(rod, "length"):
        h = 0.5 * float(rod.length)
    else:
        raise ValueError(f"rod must have a length (L, length or half_length), got {rod!r}")
    R = float(rod.tip_radius)
    if not (math.isfinite(h) and h > 0 and math.isfinite(R) and R > 0):
        raise ValueError(f"rod half length and tip radius must be > 0, got {h!r}, {R!r}")
    return h, R
