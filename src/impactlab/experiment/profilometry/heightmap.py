"""A profilometer scan as a height map in SI units, and pixel sizes from user input."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from impactlab.units import to_si

__all__ = ["HeightMap", "pixel_pair"]


@dataclass(frozen=True)
class HeightMap:
    """A height map: ``z`` (ny, nx) [m] (NaN = no data; row i is y = i dy, column j is x = j dx),
    pixel sizes ``dx``, ``dy`` [m], ``source`` (file), ``meta`` (reader information)."""

    z: np.ndarray
    dx: float
    dy: float
    source: str = ""
    meta: dict[str, Any] = field(default_factory=dict, compare=False, repr=False)

    def __post_init__(self) -> None:
        z = np.array(self.z, dtype=np.float64)
        where = f" ({self.source})" if self.source else ""
        if z.ndim != 2 or min(z.shape) < 8:
            raise ValueError(
                f"a height map must be 2D with at least 8 x 8 pixels, got shape {z.shape}{where}"
            )
        z[~np.isfinite(z)] = np.nan
        for name, v in (("dx", self.dx), ("dy", self.dy)):
            if not (math.isfinite(float(v)) and float(v) > 0):
                raise ValueError(f"{name} (pixel size) must be > 0 m, got {v!r}{where}")
        if np.isnan(z).all():
            raise ValueError(f"the height map has no valid data{where}")
        z.setflags(write=False)
        object.__setattr__(self, "z", z)
        object.__setattr__(self, "dx", float(self.dx))
        object.__setattr__(self, "dy", float(self.dy))

    @property
    def shape(self) -> tuple[int, int]:
        return (int(self.z.shape[0]), int(self.z.shape[1]))

    @property
    def valid(self) -> np.ndarray:
        return np.isfinite(self.z)

    def flipped(self) -> HeightMap:
        """The same scan the other way up (heights negated): for a file that stores depths as
        positive heights (``meta["flipped"]`` is then True)."""
        return HeightMap(-self.z, self.dx, self.dy, self.source, {**self.meta, "flipped": True})

    def coords(self) -> tuple[np.ndarray, np.ndarray]:
        """Pixel-centre coordinate grids (X, Y) [m]."""
        ny, nx = self.shape
        return np.meshgrid(np.arange(nx) * self.dx, np.arange(ny) * self.dy)


def pixel_pair(pixel_size: Any) -> tuple[float, float]:
    """(dx, dy) [m] from one pixel size or a (dx, dy) pair (quantity strings such as "2 um",
    metres for bare numbers; a pair also as one text, "2 um, 3 um": the command line's form)."""
    if isinstance(pixel_size, str) and "," in pixel_size:
        pixel_size = [p.strip() for p in pixel_size.strip().strip("()[]").split(",")]
    if isinstance(pixel_size, tuple | list):
        if len(pixel_size) != 2:
            raise ValueError(f"pixel_size must be one size or (dx, dy), got {pixel_size!r}")
        dx = to_si(pixel_size[0], "m", name="pixel_size")
        dy = to_si(pixel_size[1], "m", name="pixel_size")
    else:
        dx = dy = to_si(pixel_size, "m", name="pixel_size")
    if not (dx > 0 and dy > 0):
        raise ValueError(f"pixel_size must be > 0, got {pixel_size!r}")
    return dx, dy
